# The app `openswarm build` builds. The tool gives its name, from
# openswarm.json (OPENSWARM_APP_NAME: the one place it is written), and its
# folder (OPENSWARM_APP_DIR). An app needs no CMakeLists.txt of its own: the
# tool writes one that calls openswarm_app(). One the user writes calls it
# too, then adds to the target ${OPENSWARM_APP} (cli/README.md, "An app's
# own CMakeLists.txt").

# Every C and C++ file of the app: src/ and its subfolders, and the app's
# own folder (today's templates keep main.c there), not the app's other
# subfolders (tests/, experiments/, plain/ hold other things).
# CONFIGURE_DEPENDS: a file added later is built by the next build, with
# nothing re-run by hand.
function(openswarm_app_sources out)
  set(root_patterns)
  set(src_patterns)
  foreach(extension c cpp cc cxx)
    list(APPEND root_patterns ${OPENSWARM_APP_DIR}/*.${extension})
    list(APPEND src_patterns ${OPENSWARM_APP_DIR}/src/*.${extension})
  endforeach()
  file(GLOB root CONFIGURE_DEPENDS ${root_patterns})
  file(GLOB_RECURSE below CONFIGURE_DEPENDS ${src_patterns})
  set(${out} ${root} ${below} PARENT_SCOPE)
endfunction()

# The firmware `name`'s sources: those given, and, when it is the app the
# tool builds, every source of the app (openswarm_app_sources). A name
# other than openswarm.json's is refused here: the tool would look for an
# image of the other name and not find it.
function(openswarm_firmware_sources name given out)
  if(NOT OPENSWARM_APP_NAME)
    set(${out} ${given} PARENT_SCOPE)
    return()
  endif()
  if(NOT name STREQUAL OPENSWARM_APP_NAME)
    message(FATAL_ERROR "the app is named \"${OPENSWARM_APP_NAME}\" in ${OPENSWARM_APP_DIR}/openswarm.json "
      "but \"${name}\" in ${CMAKE_CURRENT_LIST_FILE}: give it one name, openswarm.json's "
      "(write openswarm_app() there, which takes it from openswarm.json, or delete that "
      "CMakeLists.txt: openswarm build makes one)")
  endif()
  set(sources)
  foreach(file IN LISTS given)
    get_filename_component(file "${file}" ABSOLUTE)
    list(APPEND sources ${file})
  endforeach()
  openswarm_app_sources(found)
  list(APPEND sources ${found})
  list(REMOVE_DUPLICATES sources)
  set(${out} ${sources} PARENT_SCOPE)
endfunction()

# openswarm_app([SOURCES <more files...>])
# The app's firmware, named as openswarm.json says, for OPENSWARM_PORT,
# from every source of the app and the files given (e.g. one outside the
# app's folder). Sets OPENSWARM_APP to the target's name.
function(openswarm_app)
  cmake_parse_arguments(A "" "" "SOURCES" ${ARGN})
  if(NOT OPENSWARM_APP_NAME OR NOT OPENSWARM_APP_DIR)
    message(FATAL_ERROR "openswarm_app(): build the app with `openswarm build`, which gives its name "
      "and folder (or configure with -DOPENSWARM_APP_NAME=<openswarm.json's name> "
      "-DOPENSWARM_APP_DIR=<the app's folder>)")
  endif()
  if(NOT OPENSWARM_PORT)
    message(FATAL_ERROR "openswarm_app(): OPENSWARM_PORT is not set: build with `openswarm build`, "
      "or configure with -DOPENSWARM_PORT=kilobot (or another port: `openswarm ports`)")
  endif()
  openswarm_add_firmware(${OPENSWARM_APP_NAME} PORT ${OPENSWARM_PORT} SOURCES ${A_SOURCES})
  set(OPENSWARM_APP ${OPENSWARM_APP_NAME} PARENT_SCOPE)
endfunction()

# The OpenSwarm CMake package. An application's CMakeLists.txt:
#
#   cmake_minimum_required(VERSION 3.20)
#   project(blinky C ASM)
#   find_package(OpenSwarm REQUIRED)          # -DOpenSwarm_DIR=<openswarm>/sdk/cmake
#   openswarm_add_firmware(blinky PORT kilobot SOURCES main.c)
#
# Configure with the robot's toolchain:
#   PORT kilobot: -DCMAKE_TOOLCHAIN_FILE=<openswarm>/ports/kilobot/cmake/avr-gcc.cmake
#   PORT epuck2:  -DCMAKE_TOOLCHAIN_FILE=<openswarm>/ports/cortex_m4/cmake/arm-none-eabi.cmake
#   PORT epuck:   -DCMAKE_TOOLCHAIN_FILE=<openswarm>/ports/epuck/dspic/cmake/xc16.cmake (Microchip XC16)
#   PORT epuck_world (an e-puck app as a robot of the world simulator, on
#   the host port): the host's compiler, no toolchain file
# (the openswarm tool does both for you).

get_filename_component(OPENSWARM_SDK_ROOT "${CMAKE_CURRENT_LIST_DIR}/../.." ABSOLUTE)
include(${OPENSWARM_SDK_ROOT}/cmake/OpenSwarmKernel.cmake)
include(${CMAKE_CURRENT_LIST_DIR}/OpenSwarmApp.cmake)
set(OpenSwarm_FOUND TRUE)

# The app's own code is built with warnings on (`if (count = 3)` says so);
# OPENSWARM_WERROR (openswarm build --werror) makes them errors.
option(OPENSWARM_WERROR "the app's warnings are errors" OFF)
# PORT epuck2: also the image for the real robot (<name>-robot.elf), not
# only QEMU's (off for `openswarm size`'s measuring build: one map).
option(OPENSWARM_ROBOT_IMAGE "PORT epuck2: build the robot's image too" ON)
# PORT epuck_world with the ARM toolchain (openswarm build --qemu): the app
# as the e-puck2's image for the world, <name>.elf on the board that
# speaks the world's link under QEMU (ports/epuck/epuck2/qemu_world),
# instead of the host program; a plain controller likewise.
option(OPENSWARM_EPUCK2_WORLD "PORT epuck_world: the e-puck2 image for the world under QEMU" OFF)
function(openswarm_app_warnings target)
  set(flags -Wall -Wextra)
  if(OPENSWARM_WERROR)
    list(APPEND flags -Werror)
  endif()
  target_compile_options(${target} PRIVATE $<$<COMPILE_LANGUAGE:C,CXX>:${flags}>)
endfunction()

# The app's parameters (openswarm.json's "parameters", docs/openswarm-json.md):
# every C and C++ source of the app includes the generated
# openswarm_parameters.h first (their defaults), and OPENSWARM_PARAMETERS
# ("NAME=VALUE;...", from `openswarm build -D` or a sweep) defines other
# values before it. Only the app's own sources: the kernel never sees them.
set(OPENSWARM_PARAMETERS "" CACHE STRING "the app's parameters' values, NAME=VALUE;... (openswarm build -D)")
function(openswarm_app_parameters sources)
  if(NOT OPENSWARM_GENERATED_DIR OR NOT EXISTS ${OPENSWARM_GENERATED_DIR}/openswarm_parameters.h)
    return()
  endif()
  set(compiled)
  foreach(source ${sources})
    if(source MATCHES "\\.(c|cc|cpp|cxx)$")
      list(APPEND compiled ${source})
    endif()
  endforeach()
  if(compiled)
    set_property(SOURCE ${compiled} APPEND PROPERTY COMPILE_OPTIONS
      -include${OPENSWARM_GENERATED_DIR}/openswarm_parameters.h) # gcc takes it joined
    set_property(SOURCE ${compiled} APPEND PROPERTY COMPILE_DEFINITIONS ${OPENSWARM_PARAMETERS})
  endif()
endfunction()

# The app's C++ is C++14 without exceptions, RTTI or guarded statics:
# avr-g++ 5.4 has no library to support them, and the SDK needs none.
function(openswarm_app_flags target)
  openswarm_app_warnings(${target})
  set_target_properties(${target} PROPERTIES CXX_STANDARD 14)
  target_compile_options(${target} PRIVATE
    $<$<COMPILE_LANGUAGE:CXX>:-fno-exceptions -fno-rtti -fno-threadsafe-statics>)
endfunction()

# openswarm_add_firmware(<name> PORT <kilobot|epuck2|epuck|epuck_world|host> SOURCES <files...>
#                        [CONFIG <header>])
# Built by `openswarm build`, <name> must be openswarm.json's name, and
# every source of the app is added to the files given (OpenSwarmApp.cmake).
# Builds the kernel for the port and configuration, and the application
# against it: <name>.elf for a robot, <name> for the host and epuck_world
# (a process the world simulator runs, ports/epuck/host). For epuck2,
# <name>.elf runs in QEMU and <name>-robot.elf (and .bin) is for the robot.
# For epuck_world with OPENSWARM_EPUCK2_WORLD: <name>.elf, the e-puck2 image
# the world runs under QEMU.
function(openswarm_add_firmware name)
  cmake_parse_arguments(F "" "PORT;CONFIG" "SOURCES" ${ARGN})
  openswarm_firmware_sources(${name} "${F_SOURCES}" F_SOURCES)
  if(NOT F_PORT)
    message(FATAL_ERROR "openswarm_add_firmware(${name}): PORT is required (kilobot, epuck2, epuck, epuck_world or host)")
  endif()
  if(NOT F_SOURCES)
    message(FATAL_ERROR "openswarm_add_firmware(${name}): no sources: give SOURCES, or, built by "
      "`openswarm build`, put the app's .c or .cpp files in its src/ folder")
  endif()
  if(OPENSWARM_NATIVE AND NOT F_PORT MATCHES "^(kilobot|epuck_world)$")
    message(FATAL_ERROR "openswarm_add_firmware(${name}): the native mode (OPENSWARM_NATIVE) runs "
      "Kilobot apps and e-pucks of the world (PORT epuck_world), not PORT ${F_PORT}: build it "
      "without OPENSWARM_NATIVE, or for PORT kilobot or epuck_world")
  endif()
  if(F_PORT STREQUAL "kilobot" AND NOT OPENSWARM_NATIVE AND NOT CMAKE_SYSTEM_PROCESSOR STREQUAL "avr")
    message(FATAL_ERROR "openswarm_add_firmware(${name}): PORT kilobot needs the AVR toolchain: "
      "configure with -DCMAKE_TOOLCHAIN_FILE=${OPENSWARM_SDK_ROOT}/ports/kilobot/cmake/avr-gcc.cmake "
      "(or build with `openswarm build`)")
  endif()
  if((F_PORT STREQUAL "epuck2" OR OPENSWARM_EPUCK2_WORLD) AND NOT CMAKE_SYSTEM_PROCESSOR STREQUAL "arm")
    message(FATAL_ERROR "openswarm_add_firmware(${name}): PORT epuck2 needs the ARM toolchain: "
      "configure with -DCMAKE_TOOLCHAIN_FILE=${OPENSWARM_SDK_ROOT}/ports/cortex_m4/cmake/arm-none-eabi.cmake "
      "(or build with `openswarm build`)")
  endif()
  if(F_PORT STREQUAL "epuck" AND NOT CMAKE_SYSTEM_PROCESSOR STREQUAL "dspic")
    message(FATAL_ERROR "openswarm_add_firmware(${name}): PORT epuck needs Microchip XC16: "
      "configure with -DCMAKE_TOOLCHAIN_FILE=${OPENSWARM_SDK_ROOT}/ports/epuck/dspic/cmake/xc16.cmake "
      "(or build with `openswarm build`)")
  endif()
  # `openswarm build` generates the pool sizes, event ids and start-up code
  # from openswarm.json into OPENSWARM_GENERATED_DIR.
  set(generated_sources)
  if(OPENSWARM_GENERATED_DIR AND EXISTS ${OPENSWARM_GENERATED_DIR}/openswarm_app.c)
    if(NOT F_CONFIG)
      set(F_CONFIG ${OPENSWARM_GENERATED_DIR}/openswarm_config.h)
    endif()
    set(generated_sources ${OPENSWARM_GENERATED_DIR}/openswarm_app.c)
  endif()
  openswarm_app_parameters("${F_SOURCES}")
  set(config_args)
  if(F_CONFIG)
    get_filename_component(config "${F_CONFIG}" ABSOLUTE)
    set(config_args CONFIG ${config})
  endif()
  if(OPENSWARM_NATIVE)
    openswarm_add_native_robot(${name} BOARD ${F_PORT} SOURCES ${F_SOURCES} ${generated_sources}
      ${config_args} INCLUDES ${OPENSWARM_GENERATED_DIR})
    openswarm_app_flags(${name})
    return()
  endif()
  set(host_world FALSE) # the host program the world runs, its main renamed
  if(F_PORT STREQUAL "epuck_world" AND OPENSWARM_EPUCK2_WORLD)
    openswarm_add_kernel(${name}_openswarm PORT epuck2 BOARD world ${config_args})
  elseif(F_PORT STREQUAL "epuck_world")
    set(host_world TRUE)
    openswarm_add_kernel(${name}_openswarm PORT host BOARD epuck_world ${config_args})
  else()
    openswarm_add_kernel(${name}_openswarm PORT ${F_PORT} ${config_args})
  endif()
  add_executable(${name} ${F_SOURCES} ${generated_sources})
  target_link_libraries(${name} PRIVATE ${name}_openswarm)
  openswarm_app_flags(${name})
  if(host_world)
    # The process's main is the world link's (ports/epuck/host); the app's
    # own, renamed, is what it runs on the simulated CPU.
    set_property(SOURCE ${F_SOURCES} TARGET_DIRECTORY ${name} APPEND PROPERTY
      COMPILE_DEFINITIONS main=openswarm_robot_main)
    set_property(SOURCE ${F_SOURCES} TARGET_DIRECTORY ${name} APPEND PROPERTY
      COMPILE_OPTIONS -include openswarm/epuck_world_app.h)
  endif()
  if(generated_sources)
    target_include_directories(${name} PRIVATE ${OPENSWARM_GENERATED_DIR})
  endif()
  if(F_PORT STREQUAL "kilobot")
    # <name>.hex is what KiloGUI uploads: flash only, without the .mmcu
    # record the simulator reads (at 0x910000 it would make no sense to a
    # programmer) and without EEPROM, which holds the robot's calibration.
    # No avr-size here: its percentage is of the chip's 32 KB, and the
    # tool's, of the 28 KB below the bootloader, followed on the same screen.
    add_custom_command(TARGET ${name} POST_BUILD
      COMMAND ${CMAKE_OBJCOPY} -O ihex -j .text -j .data $<TARGET_FILE:${name}>
              $<TARGET_FILE_DIR:${name}>/${name}.hex)
  elseif(F_PORT STREQUAL "epuck2")
    add_custom_command(TARGET ${name} POST_BUILD COMMAND ${CMAKE_SIZE} $<TARGET_FILE:${name}>)
    if(OPENSWARM_ROBOT_IMAGE)
      openswarm_add_robot_image(${name} "${F_SOURCES}" "${generated_sources}" "${config_args}")
    endif()
  endif()
endfunction()

# OPENSWARM_NATIVE (openswarm build --native): the app for the host as a
# robot of the simulator's native mode, <name>.so (cmake/OpenSwarmNative.cmake).
option(OPENSWARM_NATIVE "build the app for the host, as a native-mode robot (<name>.so)" OFF)

# The e-puck2's robot image beside the QEMU one: the same app on the
# robot board (ports/epuck/epuck2/robot), <name>-robot.elf linked where
# OPENSWARM_EPUCK2_BOOTLOADER says (none: 0x08000000; aseba: 0x08020000,
# after the Aseba bootloader), and <name>-robot.bin, the flash's bytes from
# there (what `st-flash write <name>-robot.bin <that address>` or a
# bootloader takes; gdb loads the ELF where it is linked).
function(openswarm_add_robot_image name sources generated_sources config_args)
  set(robot ${name}-robot)
  openswarm_add_kernel(${robot}_openswarm PORT epuck2 BOARD robot ${config_args})
  add_executable(${robot} ${sources} ${generated_sources})
  target_link_libraries(${robot} PRIVATE ${robot}_openswarm)
  openswarm_app_flags(${robot})
  if(generated_sources)
    target_include_directories(${robot} PRIVATE ${OPENSWARM_GENERATED_DIR})
  endif()
  add_custom_command(TARGET ${robot} POST_BUILD
    COMMAND ${CMAKE_OBJCOPY} -O binary $<TARGET_FILE:${robot}> $<TARGET_FILE_DIR:${robot}>/${robot}.bin)
endfunction()

# openswarm_add_plain_controller(<name> SOURCES <files...>)
# A controller without the OS for the world simulator's e-pucks (the
# hardware-near baseline, openswarm/epuck_plain.h): its own main() loops
# on epuck_plain_wait_frame() and epuck_plain_set_wheels(); it may use the
# e-puck layer's plain functions (epuck_classify_frame), nothing of the
# kernel. Builds the host program <name>, or, with OPENSWARM_NATIVE, the
# native-mode robot <name>.so (board epuck_plain: the kernel is linked for
# the native port's clock, never started), or, with OPENSWARM_EPUCK2_WORLD,
# its e-puck2 image for the world under QEMU, <name>.elf.
function(openswarm_add_plain_controller name)
  cmake_parse_arguments(F "" "" "SOURCES" ${ARGN})
  if(NOT F_SOURCES)
    message(FATAL_ERROR "openswarm_add_plain_controller(${name}): SOURCES is required")
  endif()
  if(OPENSWARM_NATIVE)
    openswarm_add_native_robot(${name} BOARD epuck_plain SOURCES ${F_SOURCES})
    openswarm_app_warnings(${name})
    return()
  endif()
  if(OPENSWARM_EPUCK2_WORLD)
    # <name>.elf: the link over semihosting as the kernel's board world has
    # it; the kernel gives the start-up, the console and the exit, and is
    # never started.
    openswarm_add_kernel(${name}_openswarm PORT epuck2 BOARD world)
    add_executable(${name} ${F_SOURCES} ${OPENSWARM_SDK_ROOT}/ports/epuck/epuck2/qemu_world/plain_world_qemu.c)
    target_link_libraries(${name} PRIVATE ${name}_openswarm)
    openswarm_app_warnings(${name})
    return()
  endif()
  add_executable(${name} ${F_SOURCES}
    ${OPENSWARM_SDK_ROOT}/ports/epuck/src/camera_classifier.c
    ${OPENSWARM_SDK_ROOT}/ports/epuck/host/src/plain_world.c
    ${OPENSWARM_SDK_ROOT}/ports/epuck/host/src/link_io.c)
  openswarm_app_warnings(${name})
  # The e-puck layer's header names kernel types: the host port's headers
  # give them (nothing of the kernel is linked).
  target_include_directories(${name} PRIVATE ${OPENSWARM_SDK_ROOT}/kernel/include
    ${OPENSWARM_SDK_ROOT}/ports/host/include ${OPENSWARM_SDK_ROOT}/ports/epuck/include
    ${OPENSWARM_SDK_ROOT}/ports/epuck/host/include ${OPENSWARM_SDK_ROOT}/ports/epuck/host/src)
  target_compile_definitions(${name} PRIVATE PORT_EVENT_COUNT=16)
endfunction()

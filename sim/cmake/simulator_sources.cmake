# include(): SIMULATOR_SOURCES, every source of openswarm-sim but
# src/main.c and the generated viewer page, as absolute paths, so the
# simulator and sim/fuzz (a project of its own, built with clang) compile
# the same list; SIMULATOR_INCLUDES, the folders they include from.
include(${CMAKE_CURRENT_LIST_DIR}/world_file_sources.cmake)
set(SIM_ROOT ${CMAKE_CURRENT_LIST_DIR}/..)
set(REPO_ROOT ${SIM_ROOT}/..)
# The rooms of src/: board (one simulated robot: MCU, pins, EEPROM,
# sensors), air (what travels between robots: IR, the overhead
# controller), faults (what --faults injects, and when), world (where
# robots are and how they move), output (what a run in a world leaves
# behind), tools (debugging and measuring).
set(SIMULATOR_SOURCES)
foreach(piece options options_usage options_outputs progress warning_groups written interrupt inputs lockstep loop_skip window_workers
    board/firmware board/console board/robot_trace board/kilobot_board board/adc_trigger
    board/power_down board/analog_noise board/main_stack board/interrupt_watch
    board/firmware_symbols board/elf_check board/ihex_check board/power_cycle
    board/firmware_counters board/firmware_warnings board/handler_watch board/event_names board/code_place board/wide_memories board/thread_stacks board/stack_watch board/register_store_watch
    board/invalid_opcode
    air/ir_channel air/ir_receiver air/ir_distance_error air/ir_frame air/ir_log air/overhead_controller air/ir_faults
    faults/fault_spec faults/fault_plan faults/fault_log
    world/placement world/world_random world/kilobot_motion world/kilobot_light world/world_refusals world/world_run
    world/world_stepper world/world_avr native/native_load native/native_apps native/native_swarm native/native_image_copy
    native/native_air native/native_ohc native/native_frame_faults native/native_faults native/native_counters native/native_askers native/native_handlers native/native_run world/epuck_sensors world/epuck_camera_noise world/epuck_link world/epuck_pipes world/epuck_run native/native_epuck
    tools/debug tools/profile tools/measure)
  list(APPEND SIMULATOR_SOURCES ${SIM_ROOT}/src/${piece}.c)
endforeach()
# The world file's reader names a mistyped key's nearest valid one with
# the tool's suggest.cpp (MIT, compiled in as it is); the e-puck world
# link's format and whole-message I/O are the controllers' own (MIT,
# ports/epuck/host).
list(APPEND SIMULATOR_SOURCES ${WORLD_FILE_SOURCES} ${SIM_ROOT}/src/world/world.cpp
  ${SIM_ROOT}/src/world/box2d_timer.cpp
  ${REPO_ROOT}/cli/src/suggest.cpp ${REPO_ROOT}/ports/epuck/host/src/link_io.c)
# What a run in a world leaves behind (also a library of its own for
# tests/world's driver).
set(SIMULATOR_OUTPUT_SOURCES)
foreach(piece output history trajectories ir_table picture picture_footer video video_clock viewer part_file)
  list(APPEND SIMULATOR_OUTPUT_SOURCES ${SIM_ROOT}/src/output/${piece}.c)
endforeach()
set(SIMULATOR_INCLUDES ${SIM_ROOT}/src ${REPO_ROOT}/cli/src ${REPO_ROOT}/ports/native/include
  ${REPO_ROOT}/ports/kilobot/src
  ${REPO_ROOT}/ports/epuck/host/include ${REPO_ROOT}/ports/epuck/host/src)
# viewer.html's player is built into the simulator from viewer_page.html:
# simulator_viewer_page(OUT) makes the command that writes it as C.
function(simulator_viewer_page out)
  add_custom_command(OUTPUT ${out}
    COMMAND ${CMAKE_COMMAND} -DINPUT=${SIM_ROOT}/src/output/viewer_page.html
            -DOUTPUT=${out} -DNAME=output_viewer_page -P ${SIM_ROOT}/cmake/embed_text.cmake
    DEPENDS ${SIM_ROOT}/src/output/viewer_page.html ${SIM_ROOT}/cmake/embed_text.cmake)
endfunction()

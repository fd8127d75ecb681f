# openswarm_add_native_robot(<name> BOARD <kilobot|epuck_world|epuck_plain> SOURCES <files...> [CONFIG <header>]
#                            [INCLUDES <dirs...>])
#
# The native mode (ports/native): an app's sources, the kernel and the
# robot's board compiled for the host into <name>.so, a robot that
# openswarm-sim runs by the thousand in one process. Everything the robot
# runs on its MCU - the app, the kernel, kilolib, the board's portable
# device code - is compiled with a callback at each basic block that
# charges its work in the robot's cycles (-fsanitize-coverage=trace-pc);
# the native port and board, which charge their own time, are not.

set(OPENSWARM_NATIVE_PORT_SOURCES native_cpu.c native_context.c native_switch.S native_robot.c
    native_handlers.c)
list(TRANSFORM OPENSWARM_NATIVE_PORT_SOURCES PREPEND ${OPENSWARM_ROOT}/ports/native/src/)

# The Kilobot: its board at message level, and the robot's own device,
# kilolib and overhead-controller code as it is.
set(OPENSWARM_NATIVE_kilobot_BOARD_SOURCES kilobot_board.c kilobot_ir.c kilobot_adc.c
    kilobot_system.c kilobot_eeprom.c kilobot_console.c)
list(TRANSFORM OPENSWARM_NATIVE_kilobot_BOARD_SOURCES PREPEND ${OPENSWARM_ROOT}/ports/native/kilobot/src/)
set(OPENSWARM_NATIVE_kilobot_ROBOT_SOURCES
    ${OPENSWARM_ROOT}/ports/kilobot/src/clock_hooks.c
    ${OPENSWARM_ROOT}/ports/kilobot/src/overhead_control.c
    ${OPENSWARM_ROOT}/ports/kilobot/src/overhead_calibration.c
    ${OPENSWARM_ROOT}/ports/kilobot/src/battery_light.c
    ${OPENSWARM_ROOT}/ports/kilobot/src/devices/devices.c
    ${OPENSWARM_ROOT}/ports/kilobot/src/devices/led.c
    ${OPENSWARM_ROOT}/ports/kilobot/src/devices/motors.c
    ${OPENSWARM_ROOT}/ports/kilobot/src/devices/motor_processors.c
    ${OPENSWARM_ROOT}/ports/kilobot/src/devices/ir_device.c
    ${OPENSWARM_ROOT}/ports/kilobot/src/devices/ir_distance.c
    ${OPENSWARM_ROOT}/ports/kilobot/src/devices/sensors.c
    ${OPENSWARM_ROOT}/ports/kilobot/src/devices/sensor_processors.c
    ${OPENSWARM_ROOT}/ports/kilobot/kilolib/src/kilolib.c
    ${OPENSWARM_ROOT}/ports/kilobot/kilolib/src/overhead_controller.c
    ${OPENSWARM_ROOT}/ports/kilobot/kilolib/src/calibration.c
    ${OPENSWARM_ROOT}/ports/kilobot/kilolib/src/status_lights.c)
# The native headers first: they stand in for the robot's port_arch.h,
# port_config.h, kilobot_sim.h and avr-libc's.
set(OPENSWARM_NATIVE_kilobot_INCLUDES ${OPENSWARM_ROOT}/ports/native/include
    ${OPENSWARM_ROOT}/ports/native/kilobot/include ${OPENSWARM_ROOT}/ports/native/kilobot/avr
    ${OPENSWARM_ROOT}/ports/kilobot/include ${OPENSWARM_ROOT}/ports/kilobot/kilolib/include)
set(OPENSWARM_NATIVE_kilobot_DEFINITIONS F_CPU=8000000UL NATIVE_CPU_HZ=8000000u
    OPENSWARM_MCU_NAME=atmega328p)

# The e-puck as the world simulator's native mode runs it (PORT
# epuck_world built natively): its board at message level, the device
# layer as it is, the pipe mode's record of what it shows. And the same
# for a controller without the OS (openswarm_add_plain_controller): the
# plain link, the camera's classifier.
set(OPENSWARM_NATIVE_epuck_world_BOARD_SOURCES
    ${OPENSWARM_ROOT}/ports/native/epuck/src/epuck_native_board.c
    ${OPENSWARM_ROOT}/ports/epuck/host/src/world_outputs.c)
set(OPENSWARM_NATIVE_epuck_world_ROBOT_SOURCES ${OPENSWARM_EPUCK_SOURCES})
set(OPENSWARM_NATIVE_epuck_world_INCLUDES ${OPENSWARM_ROOT}/ports/native/include
    ${OPENSWARM_ROOT}/ports/native/epuck/include ${OPENSWARM_ROOT}/ports/epuck/include
    ${OPENSWARM_ROOT}/ports/epuck/host/include ${OPENSWARM_ROOT}/ports/epuck/host/src
    ${OPENSWARM_ROOT}/ports/epuck/src)
set(OPENSWARM_NATIVE_epuck_world_DEFINITIONS NATIVE_CPU_HZ=168000000u)
set(OPENSWARM_NATIVE_epuck_plain_BOARD_SOURCES ${OPENSWARM_ROOT}/ports/native/epuck/src/epuck_native_plain.c)
set(OPENSWARM_NATIVE_epuck_plain_ROBOT_SOURCES ${OPENSWARM_ROOT}/ports/epuck/src/camera_classifier.c)
set(OPENSWARM_NATIVE_epuck_plain_INCLUDES ${OPENSWARM_NATIVE_epuck_world_INCLUDES})
set(OPENSWARM_NATIVE_epuck_plain_DEFINITIONS ${OPENSWARM_NATIVE_epuck_world_DEFINITIONS})

set(OPENSWARM_NATIVE_WORK_CALLBACK -fsanitize-coverage=trace-pc)
# Hidden symbols: the robot's code binds to itself (and to its own printf),
# whichever copy of the object the simulator loaded; one symbol is
# exported (ports/native/robot.map). glibc's checked printf would bypass
# the robot's.
set(OPENSWARM_NATIVE_FLAGS -fPIC -fvisibility=hidden -U_FORTIFY_SOURCE)

function(openswarm_add_native_robot name)
  cmake_parse_arguments(N "" "BOARD;CONFIG" "SOURCES;INCLUDES" ${ARGN})
  if(NOT DEFINED OPENSWARM_NATIVE_${N_BOARD}_BOARD_SOURCES)
    message(FATAL_ERROR "openswarm_add_native_robot(${name}): unknown BOARD '${N_BOARD}' (known: kilobot, epuck_world, epuck_plain)")
  endif()
  set(includes ${OPENSWARM_NATIVE_${N_BOARD}_INCLUDES} ${OPENSWARM_ROOT}/kernel/include
      ${OPENSWARM_ROOT}/sdk/include ${N_INCLUDES})
  set(definitions ${OPENSWARM_NATIVE_${N_BOARD}_DEFINITIONS})
  if(N_CONFIG)
    list(APPEND definitions "OS_CONFIG_FILE=\"${N_CONFIG}\"")
  endif()
  # The port and board: compiled plain, every object linked (nothing calls
  # the entry the simulator looks up by name).
  add_library(${name}_native_board OBJECT ${OPENSWARM_NATIVE_PORT_SOURCES}
    ${OPENSWARM_NATIVE_${N_BOARD}_BOARD_SOURCES})
  target_include_directories(${name}_native_board PRIVATE ${includes} ${OPENSWARM_ROOT}/ports/native/src
    ${OPENSWARM_ROOT}/ports/${N_BOARD}/src)
  target_compile_definitions(${name}_native_board PRIVATE ${definitions})
  target_compile_options(${name}_native_board PRIVATE ${OPENSWARM_NATIVE_FLAGS} -O2
    $<$<COMPILE_LANGUAGE:C>:${OPENSWARM_WARNINGS} -std=gnu11>)
  # What runs on the robot's MCU, charged by the callback.
  add_library(${name} MODULE ${N_SOURCES} ${OPENSWARM_KERNEL_SOURCES}
    ${OPENSWARM_NATIVE_${N_BOARD}_ROBOT_SOURCES})
  target_link_libraries(${name} PRIVATE ${name}_native_board m)
  target_include_directories(${name} PRIVATE ${includes} ${OPENSWARM_ROOT}/ports/${N_BOARD}/src)
  target_compile_definitions(${name} PRIVATE ${definitions})
  target_compile_options(${name} PRIVATE ${OPENSWARM_NATIVE_FLAGS} ${OPENSWARM_NATIVE_WORK_CALLBACK} -O2)
  set_source_files_properties(${OPENSWARM_KERNEL_SOURCES} ${OPENSWARM_NATIVE_${N_BOARD}_ROBOT_SOURCES}
    TARGET_DIRECTORY ${name} PROPERTIES COMPILE_OPTIONS "${OPENSWARM_WARNINGS};-std=gnu99")
  target_link_options(${name} PRIVATE -Wl,--version-script=${OPENSWARM_ROOT}/ports/native/robot.map
    -Wl,-z,now -Wl,-z,relro -Wl,--no-undefined)
  set_target_properties(${name} PROPERTIES PREFIX "" SUFFIX ".so")
endfunction()

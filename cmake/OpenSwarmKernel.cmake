# openswarm_add_kernel(<target> PORT <port> [BOARD <board>] [CONFIG <header>] [SANITIZE])
#
# The kernel's pools are sized at compile time, so each application (or
# test suite) builds its own kernel library from the sources, for one port
# and one configuration header.

set(OPENSWARM_ROOT ${CMAKE_CURRENT_LIST_DIR}/..)

set(OPENSWARM_KERNEL_SOURCES
    kernel.c process.c stack_pool.c scheduler.c scheduler_round_robin.c
    scheduler_priority.c event_table.c event_queue.c event_dispatch.c wait.c
    system_time.c system_program.c hal.c fault.c status_names.c)
list(TRANSFORM OPENSWARM_KERNEL_SOURCES PREPEND ${OPENSWARM_ROOT}/kernel/src/)

set(OPENSWARM_PORT_host_SOURCES
    ${OPENSWARM_ROOT}/ports/host/src/host_cpu.c
    ${OPENSWARM_ROOT}/ports/host/src/host_context.c
    ${OPENSWARM_ROOT}/ports/host/src/host_fault.c)

set(OPENSWARM_PORT_kilobot_SOURCES
    ${OPENSWARM_ROOT}/ports/kilobot/src/port.c
    ${OPENSWARM_ROOT}/ports/kilobot/src/clock_hooks.c
    ${OPENSWARM_ROOT}/ports/kilobot/src/switch.S
    ${OPENSWARM_ROOT}/ports/kilobot/src/tickless_idle.c
    ${OPENSWARM_ROOT}/ports/kilobot/src/mcu_tag.c
    ${OPENSWARM_ROOT}/ports/kilobot/src/fault_report.c
    ${OPENSWARM_ROOT}/ports/kilobot/src/system_control.c
    ${OPENSWARM_ROOT}/ports/kilobot/src/overhead_control.c
    ${OPENSWARM_ROOT}/ports/kilobot/src/devices/devices.c
    ${OPENSWARM_ROOT}/ports/kilobot/src/devices/led.c
    ${OPENSWARM_ROOT}/ports/kilobot/src/devices/motors.c
    ${OPENSWARM_ROOT}/ports/kilobot/src/devices/motor_processors.c
    ${OPENSWARM_ROOT}/ports/kilobot/src/devices/debug_uart.c
    ${OPENSWARM_ROOT}/ports/kilobot/src/devices/ir.c
    ${OPENSWARM_ROOT}/ports/kilobot/src/devices/ir_device.c
    ${OPENSWARM_ROOT}/ports/kilobot/src/devices/ir_distance.c
    ${OPENSWARM_ROOT}/ports/kilobot/src/devices/adc.c
    ${OPENSWARM_ROOT}/ports/kilobot/src/devices/sensors.c
    ${OPENSWARM_ROOT}/ports/kilobot/src/devices/sensor_processors.c
    ${OPENSWARM_ROOT}/ports/kilobot/kilolib/src/kilolib.c
    ${OPENSWARM_ROOT}/ports/kilobot/kilolib/src/overhead_controller.c
    ${OPENSWARM_ROOT}/ports/kilobot/kilolib/src/calibration.c
    ${OPENSWARM_ROOT}/ports/kilobot/kilolib/src/status_lights.c
    ${OPENSWARM_ROOT}/ports/kilobot/src/overhead_calibration.c
    ${OPENSWARM_ROOT}/ports/kilobot/src/battery_light.c)

# The e-puck's device layer, the same on both e-pucks; each board supplies
# its lower layer (ports/epuck/src/epuck_board.h).
set(OPENSWARM_EPUCK_SOURCES
    ${OPENSWARM_ROOT}/ports/epuck/src/devices.c
    ${OPENSWARM_ROOT}/ports/epuck/src/wheels.c
    ${OPENSWARM_ROOT}/ports/epuck/src/proximity.c
    ${OPENSWARM_ROOT}/ports/epuck/src/camera_classifier.c
    ${OPENSWARM_ROOT}/ports/epuck/src/selector.c)

# The e-puck2 (STM32F407, Cortex-M4F): the CPU port, the chip's vector
# table, the device layer, printf on the console, and a board: qemu
# (QEMU's netduinoplus2, for running and testing) or robot (the real
# e-puck2: its clock tree, drivers and console, linked after the
# bootloader).
set(OPENSWARM_PORT_epuck2_SOURCES
    ${OPENSWARM_ROOT}/ports/cortex_m4/src/port.c
    ${OPENSWARM_ROOT}/ports/cortex_m4/src/tickless_idle.c
    ${OPENSWARM_ROOT}/ports/cortex_m4/src/switch.S
    ${OPENSWARM_ROOT}/ports/cortex_m4/src/faults.c
    ${OPENSWARM_ROOT}/ports/cortex_m4/src/fault_report.c
    ${OPENSWARM_ROOT}/ports/cortex_m4/src/reset.c
    ${OPENSWARM_ROOT}/ports/cortex_m4/src/console_print.c
    ${OPENSWARM_ROOT}/ports/epuck/epuck2/startup/stm32f407_vectors.c
    ${OPENSWARM_ROOT}/ports/epuck/epuck2/stdio/console_stdio.c
    ${OPENSWARM_EPUCK_SOURCES})
set(OPENSWARM_BOARD_epuck2_qemu_SOURCES
    ${OPENSWARM_ROOT}/ports/epuck/epuck2/qemu/board_qemu.c
    ${OPENSWARM_ROOT}/ports/epuck/epuck2/qemu/semihosting.c
    ${OPENSWARM_ROOT}/ports/epuck/epuck2/qemu/board_record.c
    ${OPENSWARM_ROOT}/ports/epuck/epuck2/qemu/board_devices.c)
set(OPENSWARM_BOARD_epuck2_qemu_LINKER_SCRIPT
    ${OPENSWARM_ROOT}/ports/epuck/epuck2/qemu/qemu_netduinoplus2.ld)
# The same image as a robot of the world simulator (board world): the
# link to the world on QEMU's standard input and output (semihosting) in
# place of the records (ports/epuck/epuck2/qemu_world); the console and
# the exit status as on the qemu board.
set(OPENSWARM_BOARD_epuck2_world_SOURCES
    ${OPENSWARM_ROOT}/ports/epuck/epuck2/qemu/board_qemu.c
    ${OPENSWARM_ROOT}/ports/epuck/epuck2/qemu/semihosting.c
    ${OPENSWARM_ROOT}/ports/epuck/epuck2/qemu/board_record.c
    ${OPENSWARM_ROOT}/ports/epuck/epuck2/qemu_world/board_world_link.c
    ${OPENSWARM_ROOT}/ports/epuck/epuck2/qemu_world/cpu_account.c
    ${OPENSWARM_ROOT}/ports/epuck/epuck2/qemu_world/world_link_io.c
    ${OPENSWARM_ROOT}/ports/epuck/host/src/world_outputs.c)
set(OPENSWARM_BOARD_epuck2_world_LINKER_SCRIPT ${OPENSWARM_BOARD_epuck2_qemu_LINKER_SCRIPT})
set(OPENSWARM_BOARD_epuck2_world_INCLUDES ${OPENSWARM_ROOT}/ports/epuck/host/include
    ${OPENSWARM_ROOT}/ports/epuck/host/src)
set(OPENSWARM_EPUCK2_DRIVER_SOURCES steppers.c proximity.c camera.c po8030.c i2c_master.c
    esp32_link.c selector.c leds.c clock_tree.c console_usart.c)
list(TRANSFORM OPENSWARM_EPUCK2_DRIVER_SOURCES PREPEND ${OPENSWARM_ROOT}/ports/epuck/epuck2/drivers/)
set(OPENSWARM_BOARD_epuck2_robot_SOURCES
    ${OPENSWARM_ROOT}/ports/epuck/epuck2/robot/board_robot.c
    ${OPENSWARM_ROOT}/ports/epuck/epuck2/robot/board_devices.c
    ${OPENSWARM_ROOT}/ports/epuck/epuck2/robot/robot_identity.c
    ${OPENSWARM_EPUCK2_DRIVER_SOURCES})
set(OPENSWARM_BOARD_epuck2_robot_LINKER_SCRIPT
    ${OPENSWARM_ROOT}/ports/epuck/epuck2/robot/epuck2_robot.ld)
# Where the robot image is linked, by what the robot keeps at the flash's
# start (openswarm build sets it from openswarm.json's "epuck2":
# {"bootloader"}): none, the image at 0x08000000 with the whole 1 MB
# (GCtronic's standard firmware's way); aseba, at 0x08020000 after the
# Aseba bootloader's 128 KB. The linker script gives the image the rest.
set(OPENSWARM_EPUCK2_BOOTLOADER none CACHE STRING
  "e-puck2 robot image: none (linked at 0x08000000) or aseba (at 0x08020000, after the Aseba bootloader)")
set_property(CACHE OPENSWARM_EPUCK2_BOOTLOADER PROPERTY STRINGS none aseba)
set(OPENSWARM_EPUCK2_FLASH_ORIGIN_none 0x08000000)
set(OPENSWARM_EPUCK2_FLASH_ORIGIN_aseba 0x08020000)
set(OPENSWARM_PORT_epuck2_INCLUDES ${OPENSWARM_ROOT}/ports/cortex_m4/include
    ${OPENSWARM_ROOT}/ports/epuck/include)

# The e-puck on the host port, as a robot of the world simulator (board
# epuck_world): the device layer over a board that takes its inputs from
# the world and answers with its outputs (ports/epuck/host). The process's
# main is the world link's; the app's own runs on the simulated CPU. Event
# ids and pool sizes as on the e-puck2 (16 ids reserved for the port).
set(OPENSWARM_BOARD_host_epuck_world_SOURCES
    ${OPENSWARM_ROOT}/ports/epuck/host/src/board_world.c
    ${OPENSWARM_ROOT}/ports/epuck/host/src/world_outputs.c
    ${OPENSWARM_ROOT}/ports/epuck/host/src/link_io.c
    ${OPENSWARM_ROOT}/ports/epuck/host/src/world_link_main.c
    ${OPENSWARM_ROOT}/ports/epuck/host/src/robot_world.c
    ${OPENSWARM_EPUCK_SOURCES})
set(OPENSWARM_BOARD_host_epuck_world_INCLUDES ${OPENSWARM_ROOT}/ports/epuck/include
    ${OPENSWARM_ROOT}/ports/epuck/host/include)
set(OPENSWARM_BOARD_host_epuck_world_DEFINITIONS PORT_EVENT_COUNT=16
    "OPENSWARM_HOST_BOARD_CONFIG=\"openswarm/epuck_world_config.h\"")

# The e-puck (dsPIC30F6014A, Microchip XC16): the CPU port, the board and
# the device layer. Never built here: XC16 is not in Debian; the sources are
# type-checked with 16-bit int and pointers instead (ctest -L dspic).
set(OPENSWARM_PORT_epuck_SOURCES
    ${OPENSWARM_ROOT}/ports/epuck/dspic/src/port.c
    ${OPENSWARM_ROOT}/ports/epuck/dspic/src/switch.s
    ${OPENSWARM_ROOT}/ports/epuck/dspic/src/traps.s
    ${OPENSWARM_ROOT}/ports/epuck/dspic/src/traps.c
    ${OPENSWARM_ROOT}/ports/epuck/dspic/src/stop.c
    ${OPENSWARM_ROOT}/ports/epuck/dspic/src/console_uart1.c
    ${OPENSWARM_ROOT}/ports/epuck/dspic/src/fault_report.c
    ${OPENSWARM_ROOT}/ports/epuck/dspic/src/board_epuck.c
    ${OPENSWARM_ROOT}/ports/epuck/dspic/src/board_leds.c
    ${OPENSWARM_ROOT}/ports/epuck/dspic/src/board_steppers.c
    ${OPENSWARM_ROOT}/ports/epuck/dspic/src/board_proximity.c
    ${OPENSWARM_ROOT}/ports/epuck/dspic/src/board_selector.c
    ${OPENSWARM_ROOT}/ports/epuck/dspic/src/robot_identity.c
    ${OPENSWARM_ROOT}/ports/epuck/dspic/src/step_schedule.c
    ${OPENSWARM_ROOT}/ports/epuck/dspic/src/board_camera.c
    ${OPENSWARM_ROOT}/ports/epuck/dspic/src/camera_capture.S
    ${OPENSWARM_ROOT}/ports/epuck/dspic/src/camera_frame.c
    ${OPENSWARM_ROOT}/ports/epuck/dspic/src/po3030k_setup.c
    ${OPENSWARM_ROOT}/ports/epuck/dspic/src/i2c_master.c
    ${OPENSWARM_EPUCK_SOURCES})
set(OPENSWARM_PORT_epuck_INCLUDES ${OPENSWARM_ROOT}/ports/epuck/dspic/include
    ${OPENSWARM_ROOT}/ports/epuck/include)

# Our own code builds warning-free.
set(OPENSWARM_WARNINGS -Wall -Wextra -Werror -Wshadow -Wundef)
set(OPENSWARM_SANITIZERS -fsanitize=address,undefined -fno-sanitize-recover=all
    -fno-omit-frame-pointer)

function(openswarm_add_kernel target)
  cmake_parse_arguments(K "SANITIZE" "PORT;CONFIG;BOARD" "" ${ARGN})
  if(NOT K_PORT)
    message(FATAL_ERROR "openswarm_add_kernel(${target}): PORT is required (host)")
  endif()
  if(NOT DEFINED OPENSWARM_PORT_${K_PORT}_SOURCES)
    message(FATAL_ERROR "openswarm_add_kernel(${target}): unknown PORT '${K_PORT}' (known: host, kilobot, epuck2, epuck)")
  endif()
  set(board_sources)
  if(K_PORT STREQUAL "epuck2" AND NOT K_BOARD)
    set(K_BOARD qemu)
  endif()
  if(K_BOARD)
    if(NOT DEFINED OPENSWARM_BOARD_${K_PORT}_${K_BOARD}_SOURCES)
      message(FATAL_ERROR "openswarm_add_kernel(${target}): unknown BOARD '${K_BOARD}' for ${K_PORT} "
        "(known: qemu, world and robot for epuck2, epuck_world for host)")
    endif()
    set(board_sources ${OPENSWARM_BOARD_${K_PORT}_${K_BOARD}_SOURCES})
  endif()
  add_library(${target} STATIC ${OPENSWARM_KERNEL_SOURCES} ${OPENSWARM_PORT_${K_PORT}_SOURCES}
    ${board_sources})
  if(DEFINED OPENSWARM_PORT_${K_PORT}_INCLUDES)
    set(port_includes ${OPENSWARM_PORT_${K_PORT}_INCLUDES})
  else()
    set(port_includes ${OPENSWARM_ROOT}/ports/${K_PORT}/include)
  endif()
  target_include_directories(${target} PUBLIC
    ${OPENSWARM_ROOT}/kernel/include ${port_includes} ${OPENSWARM_ROOT}/sdk/include)
  if(K_PORT STREQUAL "kilobot")
    target_include_directories(${target} PUBLIC ${OPENSWARM_ROOT}/ports/kilobot/kilolib/include)
  endif()
  if(DEFINED OPENSWARM_BOARD_${K_PORT}_${K_BOARD}_INCLUDES)
    target_include_directories(${target} PUBLIC ${OPENSWARM_BOARD_${K_PORT}_${K_BOARD}_INCLUDES})
  endif()
  if(DEFINED OPENSWARM_BOARD_${K_PORT}_${K_BOARD}_DEFINITIONS)
    target_compile_definitions(${target} PUBLIC ${OPENSWARM_BOARD_${K_PORT}_${K_BOARD}_DEFINITIONS})
  endif()
  target_compile_options(${target} PRIVATE ${OPENSWARM_WARNINGS})
  # The kernel is C99 (it must build with every robot's compiler); the
  # host port uses C11 atomics.
  set_source_files_properties(${OPENSWARM_KERNEL_SOURCES} TARGET_DIRECTORY ${target}
    PROPERTIES COMPILE_OPTIONS "-std=c99")
  if(K_PORT STREQUAL "host")
    set_source_files_properties(${OPENSWARM_PORT_host_SOURCES} ${board_sources} TARGET_DIRECTORY ${target}
      PROPERTIES COMPILE_OPTIONS "-std=gnu11")
  elseif(K_PORT STREQUAL "kilobot")
    set(_c ${OPENSWARM_PORT_kilobot_SOURCES})
    list(FILTER _c INCLUDE REGEX "\\.c$")
    set_source_files_properties(${_c} TARGET_DIRECTORY ${target}
      PROPERTIES COMPILE_OPTIONS "-std=gnu99")
    target_compile_definitions(${target} PRIVATE OPENSWARM_MCU_NAME=${OPENSWARM_MCU})
  elseif(K_PORT STREQUAL "epuck")
    set(_c ${OPENSWARM_PORT_epuck_SOURCES})
    list(FILTER _c INCLUDE REGEX "\\.c$")
    set_source_files_properties(${_c} TARGET_DIRECTORY ${target}
      PROPERTIES COMPILE_OPTIONS "-std=gnu99")
    # The traps are reached through the vector table only.
    target_link_options(${target} INTERFACE -Wl,--undefined=__StackError)
  elseif(K_PORT STREQUAL "epuck2")
    set(_c ${OPENSWARM_PORT_epuck2_SOURCES} ${board_sources})
    list(FILTER _c INCLUDE REGEX "\\.c$")
    set_source_files_properties(${_c} TARGET_DIRECTORY ${target}
      PROPERTIES COMPILE_OPTIONS "-std=gnu99")
    # The image's layout, and the pieces nothing calls by name: the vector
    # table and the fault handlers (a static library's members are linked
    # only when referenced).
    get_filename_component(script_dir ${OPENSWARM_BOARD_epuck2_${K_BOARD}_LINKER_SCRIPT} DIRECTORY)
    # newlib-nano's C library (memcpy, strcmp, ...) and none of its start
    # files or system calls: no heap, no files.
    target_link_options(${target} INTERFACE
      -mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16 --specs=nano.specs -nostartfiles
      -T${OPENSWARM_BOARD_epuck2_${K_BOARD}_LINKER_SCRIPT}
      -L${OPENSWARM_ROOT}/ports/cortex_m4/ld -L${script_dir}
      -Wl,--undefined=stm32f407_vectors -Wl,--undefined=HardFault_Handler)
    if(K_BOARD STREQUAL "robot")
      if(NOT DEFINED OPENSWARM_EPUCK2_FLASH_ORIGIN_${OPENSWARM_EPUCK2_BOOTLOADER})
        message(FATAL_ERROR "openswarm_add_kernel(${target}): OPENSWARM_EPUCK2_BOOTLOADER is "
          "'${OPENSWARM_EPUCK2_BOOTLOADER}'; give none (the robot image at 0x08000000, no bootloader) "
          "or aseba (at 0x08020000, after the Aseba bootloader): -DOPENSWARM_EPUCK2_BOOTLOADER=none, "
          "or \"epuck2\": {\"bootloader\": ...} in openswarm.json with `openswarm build`")
      endif()
      target_link_options(${target} INTERFACE
        -Wl,--defsym=EPUCK2_FLASH_ORIGIN=${OPENSWARM_EPUCK2_FLASH_ORIGIN_${OPENSWARM_EPUCK2_BOOTLOADER}})
    endif()
  endif()
  if(K_CONFIG)
    target_compile_definitions(${target} PUBLIC "OS_CONFIG_FILE=\"${K_CONFIG}\"")
  endif()
  if(K_PORT STREQUAL "host")
    find_package(Threads REQUIRED)
    target_link_libraries(${target} PUBLIC Threads::Threads)
  endif()
  if(K_SANITIZE)
    target_compile_options(${target} PUBLIC ${OPENSWARM_SANITIZERS})
    target_link_options(${target} PUBLIC ${OPENSWARM_SANITIZERS})
  endif()
endfunction()
include(${CMAKE_CURRENT_LIST_DIR}/OpenSwarmNative.cmake)

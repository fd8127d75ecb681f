# Fast-forwarded loops are exact (sim/src/loop_skip.h): each run below, with
# the repeats of loops skipped and with --no-loop-skip, prints the same
# bytes and writes the same files (avr/check_loop_skip.py), and skipped at
# least the share of cycles given (a run that skipped nothing would prove
# nothing). Included by tests/CMakeLists.txt with the AVR tests.
set(SKIP_CHECK ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/avr/check_loop_skip.py $<TARGET_FILE:openswarm-sim>)
set(SKIP_OUT ${CMAKE_CURRENT_BINARY_DIR}/loop_skip)
set(WORLDS ${CMAKE_CURRENT_SOURCE_DIR}/world/worlds)
# loop_skip_test(<name> <label> <min %> <simulator arguments...>)
function(loop_skip_test name label min_percent)
  add_test(NAME ${label}.loop_skip_${name} COMMAND ${SKIP_CHECK} ${SKIP_OUT}/${name} ${min_percent} ${ARGN})
  set_tests_properties(${label}.loop_skip_${name} PROPERTIES LABELS ${label} TIMEOUT 300)
endfunction()
# Messaging: three busy robots, one talking; consoles, trace, counters.
loop_skip_test(ping avr 80 --robots 3 --distance 70 --time 3 --counters 0.5 --ir-log --timestamps
  --trace-csv {out}/trace.csv --console-csv {out}/console.csv ${AVR_TESTS_DIR}/kilolib_ping.elf)
# The kernel suite: threads, events, faults, its own exit status.
loop_skip_test(kernel_suite avr 0 --expect-stop --allow-faults --time 20 ${AVR_TESTS_DIR}/kernel_suite.elf)
# A classic busy loop that moves: motors, the LED, IR in a crowd of nine,
# clocks a few percent apart, resets and brown-outs (a parked robot is
# settled first), frames cut and pulses added.
loop_skip_test(disperse_busy world 40 --world ${WORLDS}/crowd.json --time 4 --out {out}
  --trace-csv {out}/trace.csv --clock-spread 3
  --faults reset=600,brownout=600,flip=0.5,seed=4 --fault-log {out}/faults.log
  ${AVR_TESTS_DIR}/disperse_busy.elf)
# The classic labs' orbit (loop() returns at once) and synchronisation.
loop_skip_test(orbit world 50 --world ${WORLDS}/orbit.json --time 6 --out {out}
  --trace-csv {out}/trace.csv --console-csv {out}/console.csv ${AVR_TESTS_DIR}/world_orbit.elf)
loop_skip_test(synchronise world 0 --world ${WORLDS}/synchronise.json --time 6 --out {out}
  ${AVR_TESTS_DIR}/synchronise.elf)

# Run a firmware with a trace, then compare the trace with what is expected.
execute_process(COMMAND ${SIM} ${SIM_ARGS} --trace-csv ${CSV} ${ELF} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${ELF}: the simulator exited with ${rc}")
endif()
execute_process(COMMAND ${PYTHON} ${CHECK} ${EXPECTED} ${CSV} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the trace of ${ELF} differs from ${EXPECTED}")
endif()

# Run COMMAND (a ;-list); pass if it exits with EXPECT_RC and its stderr
# (its stdout with -DSTREAM=stdout: a console under QEMU) matches
# EXPECT_MESSAGE.
if(STREAM STREQUAL "stdout")
  execute_process(COMMAND ${COMMAND} RESULT_VARIABLE rc OUTPUT_VARIABLE err ERROR_QUIET)
else()
  execute_process(COMMAND ${COMMAND} RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
endif()
if(NOT rc EQUAL EXPECT_RC)
  message(FATAL_ERROR "exit status ${rc}, expected ${EXPECT_RC}; output:\n${err}")
endif()
if(NOT err MATCHES "${EXPECT_MESSAGE}")
  message(FATAL_ERROR "output does not match '${EXPECT_MESSAGE}':\n${err}")
endif()
message(STATUS "exit ${rc}: ${err}")

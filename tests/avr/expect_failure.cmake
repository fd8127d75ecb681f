# Run COMMAND (a ;-list); pass if it exits with EXPECT_RC and its stderr
# matches EXPECT_MESSAGE.
execute_process(COMMAND ${COMMAND} RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
if(NOT rc EQUAL EXPECT_RC)
  message(FATAL_ERROR "exit status ${rc}, expected ${EXPECT_RC}; stderr:\n${err}")
endif()
if(NOT err MATCHES "${EXPECT_MESSAGE}")
  message(FATAL_ERROR "stderr does not match '${EXPECT_MESSAGE}':\n${err}")
endif()
message(STATUS "exit ${rc}: ${err}")

# Run COMMAND (a ;-list); pass if it exits 0, its output matches every
# regular expression in PATTERNS (a ;-list, in any order) and none in
# ABSENT (an optional ;-list).
execute_process(COMMAND ${COMMAND} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "exit status ${rc}:\n${out}${err}")
endif()
foreach(pattern IN LISTS PATTERNS)
  if(NOT out MATCHES "${pattern}")
    message(FATAL_ERROR "output does not match '${pattern}':\n${out}")
  endif()
endforeach()
foreach(pattern IN LISTS ABSENT)
  if(out MATCHES "${pattern}")
    message(FATAL_ERROR "output matches '${pattern}', which it must not:\n${out}")
  endif()
endforeach()
message(STATUS "${out}")

# Fails if the kernel library refers to any heap allocator: the kernel's
# memory is static pools only (see kernel/include/openswarm/config.h).
execute_process(COMMAND ${NM} -u ${LIB} OUTPUT_VARIABLE undefined RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "nm failed on ${LIB}")
endif()
string(REGEX MATCHALL "[ \t](malloc|calloc|realloc|free|aligned_alloc|posix_memalign|_Znwm|_Znam)\n" found "${undefined}")
if(found)
  message(FATAL_ERROR "the kernel uses the heap: ${found}")
endif()
message(STATUS "no heap allocator referenced by ${LIB}")

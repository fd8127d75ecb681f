# The e-puck's dsPIC port checked here without XC16: the kernel, the
# e-puck's device layer and every C file of the port, compiled (syntax and
# types only, warnings as errors) by a compiler with XC16's sizes: 16-bit
# int and 16-bit pointers (avr-gcc for the ATmega328P). XC16-only
# constructs are stand-ins (ports/epuck/dspic/include/dspic_compiler.h).
#   cmake -DCOMPILER=avr-gcc -DROOT=<openswarm> [-DFILES=<files>] [-DDEFINES=<macros>]
#         -P syntax_check.cmake
# Without FILES, every file is checked, and the 16-bit assertions with them;
# DEFINES (e.g. EPUCK_DSPIC_CAMERA=0, the build without the camera) adds -D each.
string(REPLACE "," ";" FILES "${FILES}") # a list passed through ctest, comma-separated
if(NOT FILES)
  file(GLOB FILES ${ROOT}/kernel/src/*.c ${ROOT}/ports/epuck/src/*.c
       ${ROOT}/ports/epuck/dspic/src/*.c)
  list(APPEND FILES ${ROOT}/tests/dspic/sixteen_bit.c)
endif()
set(flags -mmcu=atmega328p -fsyntax-only -std=c11 -Wall -Wextra -Werror -Wshadow -Wundef
    -DDSPIC_SYNTAX_CHECK)
foreach(define IN LISTS DEFINES)
  list(APPEND flags -D${define})
endforeach()
foreach(dir kernel/include kernel/src ports/epuck/dspic/include ports/epuck/dspic/src
        ports/epuck/include ports/epuck/src sdk/include)
  list(APPEND flags -I${ROOT}/${dir})
endforeach()
set(failed 0)
list(LENGTH FILES count)
foreach(file IN LISTS FILES)
  execute_process(COMMAND ${COMPILER} ${flags} ${file} RESULT_VARIABLE rc
                  OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc EQUAL 0)
    math(EXPR failed "${failed} + 1")
    message("FAILED: ${file}\n${out}")
  endif()
endforeach()
if(failed)
  message(FATAL_ERROR "${failed} of ${count} files failed the 16-bit check")
endif()
message("${count} files pass the 16-bit check (${COMPILER})")

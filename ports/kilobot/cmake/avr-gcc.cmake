# CMake toolchain for the Kilobot's ATmega328P with Debian's gcc-avr.
#   cmake -S <app> -B build -DCMAKE_TOOLCHAIN_FILE=ports/kilobot/cmake/avr-gcc.cmake
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR avr)

find_program(AVR_GCC avr-gcc)
if(NOT AVR_GCC)
  message(FATAL_ERROR "avr-gcc not found: run ./setup.sh (or: sudo apt-get install gcc-avr avr-libc binutils-avr)")
endif()
set(CMAKE_C_COMPILER avr-gcc)
set(CMAKE_CXX_COMPILER avr-g++)
set(CMAKE_ASM_COMPILER avr-gcc)
# The gcc-ar wrappers keep the link-time-optimisation objects usable.
set(CMAKE_AR avr-gcc-ar CACHE FILEPATH "")
set(CMAKE_RANLIB avr-gcc-ranlib CACHE FILEPATH "")
set(CMAKE_SIZE avr-size CACHE FILEPATH "")
set(CMAKE_OBJCOPY avr-objcopy CACHE FILEPATH "")
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

set(OPENSWARM_MCU atmega328p CACHE STRING "AVR part")
set(OPENSWARM_F_CPU 8000000 CACHE STRING "CPU clock in Hz")

# Link-time optimisation lets the kernel's one-concern-per-file sources
# inline across files: it shrinks the image and the switch path. (Off for
# `openswarm size`'s attribution build, whose link map must name each file.)
option(OPENSWARM_LTO "link-time optimisation" ON)
# A debug image (openswarm build --debug): -Og and no LTO, so avr-gdb
# finds every line and variable where the source has them (-Os and LTO
# move, merge and inline code, so a line's variables are often gone).
option(OPENSWARM_DEBUG "debug image: -Og, no link-time optimisation" OFF)
set(_lto "")
# -g in every image: the simulator names a fault's or a warning's code by
# file:line (avr-addr2line on the ELF). The debug sections stay in the
# ELF: the flash image (.hex, what avr-size counts) is the same byte for
# byte, and avr-gcc 5.4 keeps the line table through LTO when -g is given
# at compile and link time alike.
set(_opt "-Os -g")
if(OPENSWARM_DEBUG)
  set(_opt "-Og -g")
elseif(OPENSWARM_LTO)
  set(_lto "-flto")
endif()
# -mrelax lets the linker shorten calls and jumps that reach (rcall/rjmp):
# two bytes and a cycle each.
set(_avr_flags "-mmcu=${OPENSWARM_MCU} -DF_CPU=${OPENSWARM_F_CPU}UL ${_opt} ${_lto} -mrelax -ffunction-sections -fdata-sections")
set(CMAKE_C_FLAGS_INIT "${_avr_flags}")
set(CMAKE_CXX_FLAGS_INIT "${_avr_flags} -fno-exceptions -fno-rtti")
set(CMAKE_ASM_FLAGS_INIT "-mmcu=${OPENSWARM_MCU} -DF_CPU=${OPENSWARM_F_CPU}UL")
# --undefined keeps the .mmcu record simavr reads; it must sit where
# simavr 1.6 looks for it, or it crashes at load. The program may use the
# flash below the Kilobot's bootloader (0x7000, the ATmega328P's 4 KB boot
# section): a bigger image fails at link time instead of on the robot.
set(OPENSWARM_FLASH_BYTES 0x7000 CACHE STRING "flash the program may use (below the bootloader)")
# No heap on the robot (2 KB hold the kernel's pools and the stacks):
# avr-libc's malloc returned NULL there, stored through unchecked. Every
# call of malloc, calloc, realloc or free goes to a __wrap_ function nobody
# defines, so the link stops at the caller, and `openswarm build` says "no
# heap on this robot" (cli/src/link_errors.cpp). A port's own malloc would
# not do: with LTO the call appears after the linker takes LTO code.
set(_no_heap "-Wl,--wrap=malloc,--wrap=calloc,--wrap=realloc,--wrap=free")
set(CMAKE_EXE_LINKER_FLAGS_INIT
    "-mmcu=${OPENSWARM_MCU} ${_opt} ${_lto} -mrelax -Wl,--gc-sections -Wl,--undefined=_mmcu,--section-start=.mmcu=0x910000 -Wl,--defsym=__TEXT_REGION_LENGTH__=${OPENSWARM_FLASH_BYTES} ${_no_heap}")
set(CMAKE_EXECUTABLE_SUFFIX_C .elf)
set(CMAKE_EXECUTABLE_SUFFIX_CXX .elf)
set(CMAKE_EXECUTABLE_SUFFIX_ASM .elf)

set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)

# CMake toolchain for the e-puck's dsPIC30F6014A with Microchip XC16.
#   cmake -S <app> -B build -DCMAKE_TOOLCHAIN_FILE=ports/epuck/dspic/cmake/xc16.cmake
# Never run here: XC16 is not in Debian (see ../README.md).
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR dspic)

find_program(XC16_GCC xc16-gcc)
if(NOT XC16_GCC)
  message(FATAL_ERROR "xc16-gcc not found: the e-puck (dsPIC30F6014A) port needs Microchip XC16, "
    "which is not in Debian: install it from https://www.microchip.com/xc16 and put its bin "
    "folder on PATH")
endif()
get_filename_component(_xc16_bin ${XC16_GCC} DIRECTORY)
set(CMAKE_C_COMPILER ${XC16_GCC})
set(CMAKE_ASM_COMPILER ${XC16_GCC})
set(CMAKE_AR ${_xc16_bin}/xc16-ar CACHE FILEPATH "")
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
# The assembler files are plain .s (no C preprocessor).
set(CMAKE_ASM_SOURCE_FILE_EXTENSIONS s)

set(OPENSWARM_MCU 30F6014A CACHE STRING "dsPIC part")
# -omf=elf: ELF objects, as CMake and the size report expect. The device's
# linker script (p30F6014A.gld) comes with XC16, chosen by -mcpu.
set(_xc16_flags "-mcpu=${OPENSWARM_MCU} -omf=elf -Os -ffunction-sections -fdata-sections")
set(CMAKE_C_FLAGS_INIT "${_xc16_flags}")
set(CMAKE_ASM_FLAGS_INIT "-mcpu=${OPENSWARM_MCU} -omf=elf")
set(CMAKE_EXE_LINKER_FLAGS_INIT
    "-mcpu=${OPENSWARM_MCU} -omf=elf -Wl,--script=p30F6014A.gld,--gc-sections,--heap=0")
set(CMAKE_EXECUTABLE_SUFFIX_C .elf)
set(CMAKE_EXECUTABLE_SUFFIX_ASM .elf)

set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)

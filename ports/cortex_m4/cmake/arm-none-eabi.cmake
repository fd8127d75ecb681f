# CMake toolchain file for Cortex-M4F firmware (the e-puck2's STM32F407)
# with Debian's gcc-arm-none-eabi and libnewlib-arm-none-eabi.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)
set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_CXX_COMPILER arm-none-eabi-g++)
set(CMAKE_ASM_COMPILER arm-none-eabi-gcc)
set(CMAKE_AR arm-none-eabi-gcc-ar CACHE FILEPATH "")
set(CMAKE_RANLIB arm-none-eabi-gcc-ranlib CACHE FILEPATH "")
set(CMAKE_OBJCOPY arm-none-eabi-objcopy CACHE FILEPATH "")
set(CMAKE_SIZE arm-none-eabi-size CACHE FILEPATH "")
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
set(CMAKE_EXECUTABLE_SUFFIX_C .elf)
set(CMAKE_EXECUTABLE_SUFFIX_CXX .elf)
set(CMAKE_EXECUTABLE_SUFFIX_ASM .elf)

# Link-time optimisation lets the kernel's one-concern-per-file sources
# inline across files. (Off for `openswarm size`'s attribution build,
# whose link map must name each file.)
option(OPENSWARM_LTO "link-time optimisation" ON)
# A debug image (openswarm build --debug): -Og and no LTO, so the debugger
# finds every line and variable where the source has them.
option(OPENSWARM_DEBUG "debug image: -Og, no link-time optimisation" OFF)
set(_lto "")
set(_opt "-Os")
if(OPENSWARM_DEBUG)
  set(_opt "-Og")
elseif(OPENSWARM_LTO)
  set(_lto "-flto")
endif()
set(OPENSWARM_CPU_FLAGS "-mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16")
# -g: line tables for gdb-multiarch (openswarm run --gdb); none of it is in
# what is flashed.
set(CMAKE_C_FLAGS_INIT "${OPENSWARM_CPU_FLAGS} ${_opt} -g ${_lto} -ffunction-sections -fdata-sections")
set(CMAKE_CXX_FLAGS_INIT
    "${OPENSWARM_CPU_FLAGS} ${_opt} -g ${_lto} -ffunction-sections -fdata-sections -fno-exceptions -fno-rtti")
set(CMAKE_ASM_FLAGS_INIT "${OPENSWARM_CPU_FLAGS}")
# The link options every image needs (newlib-nano's C library, no start
# files of newlib's) are the kernel library's (OpenSwarmKernel.cmake), so
# a -DCMAKE_EXE_LINKER_FLAGS of the user's does not drop them.
set(CMAKE_EXE_LINKER_FLAGS_INIT "${_opt} ${_lto} -Wl,--gc-sections")
# The C++ SDK is freestanding (no exceptions, RTTI or library calls): C++
# apps are linked by the C driver, without libstdc++ (which Debian ships
# apart for this target, and GCC 12 has no -nostdlib++).
set(CMAKE_CXX_LINK_EXECUTABLE
    "arm-none-eabi-gcc <FLAGS> <CMAKE_CXX_LINK_FLAGS> <LINK_FLAGS> <OBJECTS> -o <TARGET> <LINK_LIBRARIES>")

set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)

# Toolchain file for Cortex-M firmware: arm-none-eabi GCC, bare metal, one CPU per build tree.
#   cmake -S . -B build-fw-m7 -G Ninja -DCMAKE_TOOLCHAIN_FILE=hal/cortex_m/arm-none-eabi.cmake -DSPANLIGHT_CPU=cortex-m7
# SPANLIGHT_CPU picks the core flags; the host build (cmake/FirmwareTargets.cmake) makes one tree per CPU.
# Installed with the CMake package (share/cmake/spanlight/arm-none-eabi.cmake) for firmware projects
# of any M7, M4 or M0+ part: it sets compiler and flags only; start-up and linker script are the project's.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)

set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_CXX_COMPILER arm-none-eabi-g++)
set(CMAKE_ASM_COMPILER arm-none-eabi-gcc)
# Compiler checks cannot link a bare-metal executable without our startup and linker script.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

set(SPANLIGHT_CPU cortex-m7 CACHE STRING "Firmware CPU: cortex-m7, cortex-m4 or cortex-m0plus")
set_property(CACHE SPANLIGHT_CPU PROPERTY STRINGS cortex-m7 cortex-m4 cortex-m0plus)
# try_compile projects re-read this file; they must see the same CPU.
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES SPANLIGHT_CPU SPANLIGHT_FIRMWARE_OPT)

# Core flags, and the optimisation each CPU is built with by default:
#   M7/M4: -O2. These are the cores with room for speed, and the instruction count is the metric.
#   M0+:   -Os. M0+ parts have 16-256 KiB of flash; size is what they run out of first.
# Override with -DSPANLIGHT_FIRMWARE_OPT=-O2 (or -Os) to compare like with like.
if(SPANLIGHT_CPU STREQUAL "cortex-m7")
  set(spanlight_cpu_flags "-mcpu=cortex-m7 -mfpu=fpv5-d16 -mfloat-abi=hard")
  set(spanlight_default_opt "-O2")
elseif(SPANLIGHT_CPU STREQUAL "cortex-m4")
  set(spanlight_cpu_flags "-mcpu=cortex-m4 -mfpu=fpv4-sp-d16 -mfloat-abi=hard")
  set(spanlight_default_opt "-O2")
elseif(SPANLIGHT_CPU STREQUAL "cortex-m0plus")
  # ARMv6-M: no FPU, no hardware divide (libgcc's __aeabi_uidiv does it).
  set(spanlight_cpu_flags "-mcpu=cortex-m0plus -mfloat-abi=soft")
  set(spanlight_default_opt "-Os")
else()
  message(FATAL_ERROR "SPANLIGHT_CPU must be cortex-m7, cortex-m4 or cortex-m0plus, not '${SPANLIGHT_CPU}'")
endif()
set(SPANLIGHT_FIRMWARE_OPT "${spanlight_default_opt}" CACHE STRING "Optimisation flag for Release firmware")

# -ffunction-sections/-fdata-sections let --gc-sections drop what no app uses;
# -fstack-usage writes a .su file per object (worst-case frame of each function), and
# -fcallgraph-info=su a .ci file with those frames on the call graph (scripts/stack-path.sh).
# Neither changes the code.
set(spanlight_common "-mthumb ${spanlight_cpu_flags} -ffunction-sections -fdata-sections -fstack-usage -fcallgraph-info=su")
set(CMAKE_C_FLAGS_INIT "${spanlight_common}")
# No exceptions/RTTI: no unwinder, no typeinfo. No thread-safe statics: there is one thread
# and the guards would pull in __cxa_guard_*.
set(CMAKE_CXX_FLAGS_INIT "${spanlight_common} -fno-exceptions -fno-rtti -fno-threadsafe-statics")
set(CMAKE_ASM_FLAGS_INIT "-mthumb ${spanlight_cpu_flags}")
# -nostartfiles: the project's start-up (here hal/cortex_m/startup) replaces newlib's crt0, which would call
# its own init/exit path. No --specs: nothing links newlib's syscalls, so anything that
# needs _sbrk/_write (malloc, printf) fails to link instead of growing a heap.
set(CMAKE_EXE_LINKER_FLAGS_INIT "-nostartfiles -Wl,--gc-sections")

# Per-configuration flags as normal variables: they shadow the cache entries CMake's GNU module
# creates (with its -O3), and follow SPANLIGHT_FIRMWARE_OPT when it changes on a re-configure.
# -g costs no flash: debug info stays in the ELF.
foreach(lang C CXX ASM)
  set(CMAKE_${lang}_FLAGS_RELEASE "${SPANLIGHT_FIRMWARE_OPT} -g -DNDEBUG")
  set(CMAKE_${lang}_FLAGS_RELWITHDEBINFO "${SPANLIGHT_FIRMWARE_OPT} -g")
  set(CMAKE_${lang}_FLAGS_MINSIZEREL "-Os -g -DNDEBUG")
  set(CMAKE_${lang}_FLAGS_DEBUG "-Og -g")
endforeach()
set(CMAKE_BUILD_TYPE Release CACHE STRING "Firmware build type")

# Libraries and headers come from the cross toolchain only; programs from the host.
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

# Firmware from the host build: one cross-compiled build tree per CPU, configured from this same
# source tree with hal/cortex_m/arm-none-eabi.cmake, plus the QEMU instruction-count plugin.
#   <build>/firmware-<cpu>/bin/<app>.elf|.bin|.map     for cpu in SPANLIGHT_FIRMWARE_CPUS
#   <build>/tools/qemu_icount/libspanlight_icount.so  (target spanlight_icount)
# Each tree bakes its scenes itself (spanlight_bake) with this build's `spanlight`, which it
# finds through SPANLIGHT_HOST_TOOLS_DIR. Included by the root CMakeLists when SPANLIGHT_FIRMWARE
# is on (host builds); tests/firmware reads what it sets.
include_guard(GLOBAL)
include(ExternalProject)
include(${PROJECT_SOURCE_DIR}/firmware/apps/render_baked/scenes.cmake)

set(SPANLIGHT_FIRMWARE_BUILD_TYPE Release CACHE STRING "CMAKE_BUILD_TYPE of the firmware trees")
# Each firmware tree builds with this many jobs. 1 by default: up to three trees build side by
# side as jobs of the outer build, so the outer -j still bounds the load.
set(SPANLIGHT_FIRMWARE_JOBS 1 CACHE STRING "Parallel jobs inside each firmware build tree")
set(SPANLIGHT_FIRMWARE_CPUS cortex-m7 cortex-m4 cortex-m0plus)
set(SPANLIGHT_SWEEP_BENCH_SCENES "spot_shadow" CACHE STRING
    "Scenes to build sweep benches for (firmware/apps/sweep_bench), or all: docs/sweep/regenerate.sh needs all")

set(SPANLIGHT_FIRMWARE_ENABLED OFF)
if(NOT SPANLIGHT_APPS)
  message(STATUS "spanlight: SPANLIGHT_APPS is OFF; no firmware trees (they build the apps)")
else()
  find_program(SPANLIGHT_ARM_GXX arm-none-eabi-g++)
  if(SPANLIGHT_ARM_GXX)
    set(SPANLIGHT_FIRMWARE_ENABLED ON)
  else()
    message(STATUS "spanlight: arm-none-eabi-g++ not found; skipping the firmware builds and tests")
  endif()
endif()

# spanlight_firmware_elf(<var> <cpu> <app>): where the firmware tree of <cpu> puts <app>.elf.
function(spanlight_firmware_elf var cpu app)
  set(${var} ${PROJECT_BINARY_DIR}/firmware-${cpu}/bin/${app}.elf PARENT_SCOPE)
endfunction()

if(NOT SPANLIGHT_FIRMWARE_ENABLED)
  return()
endif()

add_subdirectory(${PROJECT_SOURCE_DIR}/tools/qemu_icount ${PROJECT_BINARY_DIR}/tools/qemu_icount)

# A list in CMAKE_ARGS would split at its semicolons (only the first scene would reach the
# firmware trees): it travels with '|' between its items (LIST_SEPARATOR below).
string(REPLACE ";" "|" sweep_bench_scenes "${SPANLIGHT_SWEEP_BENCH_SCENES}")
foreach(cpu IN LISTS SPANLIGHT_FIRMWARE_CPUS)
  set(byproducts)
  set(apps selftest icount_calibration fault_check pose_bench live_spotlight)
  foreach(entry IN LISTS SPANLIGHT_BAKED_SCENES)
    spanlight_baked_scene_fields("${entry}" name file options)
    list(APPEND apps render_${name})
  endforeach()
  foreach(app IN LISTS apps)
    spanlight_firmware_elf(elf ${cpu} ${app})
    list(APPEND byproducts ${elf})
  endforeach()
  ExternalProject_Add(firmware-${cpu}
    SOURCE_DIR ${PROJECT_SOURCE_DIR}
    BINARY_DIR ${PROJECT_BINARY_DIR}/firmware-${cpu}
    PREFIX ${PROJECT_BINARY_DIR}/firmware-${cpu}-ep
    CMAKE_ARGS
      -DCMAKE_TOOLCHAIN_FILE=${PROJECT_SOURCE_DIR}/hal/cortex_m/arm-none-eabi.cmake
      -DSPANLIGHT_CPU=${cpu}
      -DCMAKE_BUILD_TYPE=${SPANLIGHT_FIRMWARE_BUILD_TYPE}
      -DSPANLIGHT_HOST_TOOLS_DIR=$<TARGET_FILE_DIR:spanlight>
      -DSPANLIGHT_QEMU_ICOUNT_PLUGIN=$<TARGET_FILE:spanlight_icount>
      "-DSPANLIGHT_SWEEP_BENCH_SCENES=${sweep_bench_scenes}"
    LIST_SEPARATOR |
    BUILD_COMMAND ${CMAKE_COMMAND} --build <BINARY_DIR> --parallel ${SPANLIGHT_FIRMWARE_JOBS}
    # Always run the inner build: the outer build cannot see which sources the firmware uses.
    BUILD_ALWAYS ON
    BUILD_BYPRODUCTS ${byproducts}
    INSTALL_COMMAND ""
    DEPENDS spanlight)
endforeach()

# `cmake --install <build> --prefix <prefix>` installs what a firmware project needs:
#   include/{fixedpoint,spanlight,hal}/   the headers (all header-only)
#   bin/spanlight                         the host CLI (with SPANLIGHT_HOST_TOOLS)
#   share/cmake/spanlight/                the CMake package: find_package(spanlight) with its
#                                         exported targets, version file, spanlight_bake() and
#                                         the toolchain file arm-none-eabi.cmake
# share/, not lib/: a cross build (whose CMAKE_LIBRARY_ARCHITECTURE is not the host's) finds it there.
include(CMakePackageConfigHelpers)

set(package_dir ${CMAKE_INSTALL_DATADIR}/cmake/spanlight)
set(exported spanlight_fixedpoint spanlight_pipeline spanlight_hal)
if(SPANLIGHT_HOST_TOOLS)
  list(APPEND exported spanlight)
endif()
install(TARGETS ${exported} EXPORT spanlightTargets RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/fixedpoint/include/ ${PROJECT_SOURCE_DIR}/pipeline/include/
                  ${PROJECT_SOURCE_DIR}/hal/include/
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT spanlightTargets NAMESPACE spanlight:: DESTINATION ${package_dir})

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/spanlightConfig.cmake.in
  ${PROJECT_BINARY_DIR}/spanlightConfig.cmake INSTALL_DESTINATION ${package_dir})
# ARCH_INDEPENDENT: the libraries are headers, and the CLI runs on the build machine, so a
# 32-bit cross build may use a package installed by a 64-bit host build.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/spanlightConfigVersion.cmake
  COMPATIBILITY SameMinorVersion ARCH_INDEPENDENT)
install(FILES ${PROJECT_BINARY_DIR}/spanlightConfig.cmake ${PROJECT_BINARY_DIR}/spanlightConfigVersion.cmake
              ${PROJECT_SOURCE_DIR}/cmake/SpanlightBake.cmake
              ${PROJECT_SOURCE_DIR}/hal/cortex_m/arm-none-eabi.cmake
        DESTINATION ${package_dir})

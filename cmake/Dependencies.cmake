# Host-side dependencies, all from Debian 12 packages (see scripts/packages.txt): those of the
# host tools, and Catch2 and Google Benchmark only when the tests or benchmarks are built.
find_package(glm REQUIRED)
find_package(OpenImageIO REQUIRED)
find_package(nlohmann_json REQUIRED)
find_package(tinyobjloader REQUIRED)
find_package(CLI11 REQUIRED)
if(SPANLIGHT_TESTS)
  find_package(Catch2 REQUIRED)
endif()
if(SPANLIGHT_BENCHMARKS)
  find_package(benchmark REQUIRED)
endif()

# Debian's OpenImageIO config names /usr/include/opencv4, which no package we use installs;
# drop that one path so configuration does not fail on a machine without OpenCV.
foreach(prop INTERFACE_INCLUDE_DIRECTORIES INTERFACE_SYSTEM_INCLUDE_DIRECTORIES)
  get_target_property(dirs OpenImageIO::OpenImageIO ${prop})
  if(dirs)
    list(FILTER dirs EXCLUDE REGEX "opencv4")
    set_target_properties(OpenImageIO::OpenImageIO PROPERTIES ${prop} "${dirs}")
  endif()
endforeach()

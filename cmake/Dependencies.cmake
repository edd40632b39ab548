# Host-side dependencies, all from Debian 12 packages (see scripts/packages.txt).
find_package(glm REQUIRED)
find_package(Catch2 REQUIRED)
find_package(OpenImageIO REQUIRED)
find_package(nlohmann_json REQUIRED)
find_package(tinyobjloader REQUIRED)
find_package(CLI11 REQUIRED)
find_package(benchmark REQUIRED)

# Debian's OpenImageIO config names /usr/include/opencv4, which no package we use installs;
# drop that one path so configuration does not fail on a machine without OpenCV.
foreach(prop INTERFACE_INCLUDE_DIRECTORIES INTERFACE_SYSTEM_INCLUDE_DIRECTORIES)
  get_target_property(dirs OpenImageIO::OpenImageIO ${prop})
  if(dirs)
    list(FILTER dirs EXCLUDE REGEX "opencv4")
    set_target_properties(OpenImageIO::OpenImageIO PROPERTIES ${prop} "${dirs}")
  endif()
endforeach()

# Sanitizer flags for the *_asan twins of the test executables.
set(SPANLIGHT_SANITIZE_FLAGS -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)

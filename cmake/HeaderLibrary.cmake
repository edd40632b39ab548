# spanlight_header_library(<name>): the header-only library spanlight_<name> of the headers in
# the calling folder's include/, C++20, exported (and aliased here) as spanlight::<name>.
function(spanlight_header_library name)
  add_library(spanlight_${name} INTERFACE)
  target_include_directories(spanlight_${name} INTERFACE
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_compile_features(spanlight_${name} INTERFACE cxx_std_20)
  set_target_properties(spanlight_${name} PROPERTIES EXPORT_NAME ${name})
  add_library(spanlight::${name} ALIAS spanlight_${name})
endfunction()

# Sanitizer flags for the *_asan twins of the test executables and of the host libraries.
set(SPANLIGHT_SANITIZE_FLAGS -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)

# spanlight_add_library_with_asan(name sources...): a static library plus name_asan, the same
# sources built with the sanitizers, for the test twins. The twin builds by default only when
# the tests do (SPANLIGHT_TESTS); otherwise only when something links it.
function(spanlight_add_library_with_asan name)
  add_library(${name} STATIC ${ARGN})
  add_library(${name}_asan STATIC ${ARGN})
  target_compile_options(${name}_asan PRIVATE ${SPANLIGHT_SANITIZE_FLAGS} -O1)
  target_link_options(${name}_asan INTERFACE ${SPANLIGHT_SANITIZE_FLAGS})
  if(NOT SPANLIGHT_TESTS)
    set_target_properties(${name}_asan PROPERTIES EXCLUDE_FROM_ALL ON)
  endif()
  spanlight_warnings(${name})
  spanlight_warnings(${name}_asan)
endfunction()

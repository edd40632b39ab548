# spanlight_add_test(NAME name SOURCES a.cpp ... LIBS lib ...)
# Builds a Catch2 test executable and its ASan+UBSan twin (name_asan), and
# registers both with CTest, one ctest entry per Catch2 test case, plus a check
# that no test case name holds a ';' (cmake/CheckTestNames.cmake).
include(Catch)
include(Sanitizers)

function(spanlight_add_test)
  cmake_parse_arguments(T "" "NAME" "SOURCES;LIBS;ASAN_LIBS" ${ARGN})
  add_executable(${T_NAME} ${T_SOURCES})
  target_link_libraries(${T_NAME} PRIVATE ${T_LIBS} Catch2::Catch2WithMain)
  spanlight_warnings(${T_NAME})
  catch_discover_tests(${T_NAME} TEST_PREFIX "${T_NAME}: " PROPERTIES LABELS host)
  # A ';' in a test case name would leave its ctest entry running nothing.
  # The twin has the same sources, so the plain executable is checked alone.
  add_test(NAME "${T_NAME}: no test case name holds a semicolon"
    COMMAND ${CMAKE_COMMAND} -DTEST_EXECUTABLE=$<TARGET_FILE:${T_NAME}>
            -P ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/CheckTestNames.cmake)
  set_tests_properties("${T_NAME}: no test case name holds a semicolon" PROPERTIES LABELS host)

  # The sanitizer twin: same sources; libraries listed in ASAN_LIBS (the
  # *_asan builds of our own libraries) replace LIBS so all of our code is instrumented.
  if(T_ASAN_LIBS)
    set(asan_libs ${T_ASAN_LIBS})
  else()
    set(asan_libs ${T_LIBS})
  endif()
  add_executable(${T_NAME}_asan ${T_SOURCES})
  target_link_libraries(${T_NAME}_asan PRIVATE ${asan_libs} Catch2::Catch2WithMain)
  target_compile_options(${T_NAME}_asan PRIVATE ${SPANLIGHT_SANITIZE_FLAGS} -O1)
  target_link_options(${T_NAME}_asan PRIVATE ${SPANLIGHT_SANITIZE_FLAGS})
  spanlight_warnings(${T_NAME}_asan)
  catch_discover_tests(${T_NAME}_asan TEST_PREFIX "${T_NAME}_asan: " PROPERTIES LABELS asan
                       ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0;UBSAN_OPTIONS=print_stacktrace=1")
endfunction()


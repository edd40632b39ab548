# cmake -DTEST_EXECUTABLE=path -P CheckTestNames.cmake
# Fails when a Catch2 test case name holds a ';'. catch_discover_tests splits
# names there, so such a ctest entry matches no test case, and Catch2 exits 0
# without running anything: a test that passes without running.
execute_process(COMMAND "${TEST_EXECUTABLE}" --list-test-names-only
                OUTPUT_VARIABLE names RESULT_VARIABLE result)
# Catch2 2.x returns the number of test cases listed; a crash returns a message.
if(NOT result MATCHES "^[0-9]+$")
  message(FATAL_ERROR "${TEST_EXECUTABLE} --list-test-names-only failed: ${result}")
endif()
# Mark the semicolons first: CMake lists are ';'-separated, the names must not split.
string(REPLACE ";" "<semicolon>" names "${names}")
string(REGEX MATCHALL "[^\n]*<semicolon>[^\n]*" bad "${names}")
if(bad)
  list(JOIN bad "\n  " bad)
  string(REPLACE "<semicolon>" ";" bad "${bad}")
  message(FATAL_ERROR "test case names with ';' (ctest would run nothing for them; use ' - ' or ','):\n  ${bad}")
endif()
message(STATUS "no test case name of ${TEST_EXECUTABLE} holds a semicolon")

# ctest driver for one bounded libFuzzer run (tests/fuzz/CMakeLists.txt):
#   cmake -DFUZZER=exe -DSEEDS=dir -DSCRATCH=dir -DDICT=file -DRUNS=n -DSECONDS=s -P run_fuzzer.cmake
# Copies the seeds to a fresh scratch folder, runs the fuzzer on it, fails on a crash.
if(NOT EXISTS ${FUZZER})
  message(FATAL_ERROR "${FUZZER} is not built: cmake --build <build dir> --target spanlight_fuzzers")
endif()
file(REMOVE_RECURSE ${SCRATCH})
file(MAKE_DIRECTORY ${SCRATCH}/corpus ${SCRATCH}/artifacts)
file(GLOB seeds ${SEEDS}/*)
file(COPY ${seeds} DESTINATION ${SCRATCH}/corpus)
set(args -runs=${RUNS} -max_total_time=${SECONDS} -seed=1 -max_len=4096 -timeout=20 -rss_limit_mb=3072 -print_final_stats=1
         -artifact_prefix=${SCRATCH}/artifacts/)
if(EXISTS ${DICT})
  list(APPEND args -dict=${DICT})
endif()
execute_process(COMMAND ${FUZZER} ${args} ${SCRATCH}/corpus RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${FUZZER} failed (exit ${result}); the input is in ${SCRATCH}/artifacts")
endif()

# CI-sized check of `cloudbench --scenes random:SEED:N` (ctest Cloudbench.QuickRandomScenes,
# label gpu): two random scenes at 16x9 with the quick sweep, a 1-ray reference and one timed
# frame, then the same command again (the references must come from the cache, keyed by the
# full scene), then a malformed --scenes value (exit 2 and a message naming the syntax).
# Usage: cmake -DCLOUDBENCH=<binary> -DOUT=<scratch dir> -P check_cloudbench_random.cmake
file(REMOVE_RECURSE "${OUT}")
set(args --quick --scenes random:1:2 --size 16x9 --time-size 16x9 --frames 1 --ref-samples 1 --out "${OUT}")

function(fail msg)
  message(FATAL_ERROR "cloudbench --scenes random: ${msg}")
endfunction()

execute_process(COMMAND "${CLOUDBENCH}" ${args} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  fail("first run exited with ${rc}\n${out}\n${err}")
endif()
string(REGEX MATCHALL "reference rendered" rendered "${out}")
list(LENGTH rendered n_rendered)
if(NOT n_rendered EQUAL 2)
  fail("first run rendered ${n_rendered} references, expected 2\n${out}")
endif()

# report.md: the seed and N, both scenes' parameters, the over-scenes aggregation
file(READ "${OUT}/report.md" md)
foreach(needle "Random scene set: seed 1, N = 2" "| r1-0 |" "| r1-1 |" "## Over scenes (per configuration)"
               "RMSE/naive p90" "Default preset ≤ naive march over 2 scenes" "## Skips" "## Per scene")
  string(FIND "${md}" "${needle}" at)
  if(at EQUAL -1)
    fail("report.md lacks '${needle}'")
  endif()
endforeach()

# report.csv: one row per scene x configuration, 20 columns, the naive rows at RMSE / naive = 1
file(STRINGS "${OUT}/report.csv" csv)
list(GET csv 0 header)
if(NOT header MATCHES ",opacity_rmse,rmse_over_naive,cloud_pixels,cloud_relative_error,opacity_bias$")
  fail("report.csv header: ${header}")
endif()
set(rows_0 0)
set(rows_1 0)
set(naive 0)
list(REMOVE_AT csv 0)
foreach(line IN LISTS csv)
  string(REGEX MATCHALL "," commas "${line}")
  list(LENGTH commas n_commas)
  if(NOT n_commas EQUAL 18)
    fail("report.csv row with ${n_commas} commas (expected 18): ${line}")
  endif()
  if(line MATCHES "^\"r1-0\",")
    math(EXPR rows_0 "${rows_0} + 1")
  elseif(line MATCHES "^\"r1-1\",")
    math(EXPR rows_1 "${rows_1} + 1")
  else()
    fail("report.csv row of an unknown scene: ${line}")
  endif()
  if(line MATCHES ",naive,")
    if(NOT line MATCHES ",1,[0-9]+,[^,]*,[^,]*$")
      fail("naive row without rmse_over_naive = 1: ${line}")
    endif()
    math(EXPR naive "${naive} + 1")
  endif()
endforeach()
if(rows_0 LESS 10 OR NOT rows_0 EQUAL rows_1 OR NOT naive EQUAL 2)
  fail("report.csv: ${rows_0} rows of r1-0, ${rows_1} of r1-1, ${naive} naive rows")
endif()
file(STRINGS "${OUT}/scenes.csv" scenes)
list(LENGTH scenes n_scenes)
if(NOT n_scenes EQUAL 3)
  fail("scenes.csv has ${n_scenes} lines, expected 3")
endif()

# the same command again: both references from the cache
execute_process(COMMAND "${CLOUDBENCH}" ${args} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(REGEX MATCHALL "reference \\(cached\\)" cached "${out}")
list(LENGTH cached n_cached)
if(NOT rc EQUAL 0 OR NOT n_cached EQUAL 2)
  fail("second run: exit ${rc}, ${n_cached} cached references (expected 0 and 2)\n${out}\n${err}")
endif()

# malformed values: exit 2 with the syntax in the message
foreach(bad "random:1" "random:x:2" "random:1:0" "random:-1:2" "random:1:2:3" "randomly")
  execute_process(COMMAND "${CLOUDBENCH}" --scenes "${bad}" --out "${OUT}/bad" RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  if(NOT rc EQUAL 2 OR NOT err MATCHES "--scenes expects core or random:SEED:N")
    fail("--scenes ${bad}: exit ${rc}, stderr '${err}'")
  endif()
endforeach()
message(STATUS "cloudbench --scenes random: ok")

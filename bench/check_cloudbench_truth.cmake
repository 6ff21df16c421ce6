# CI-sized check of `cloudbench --truth` (ctest Cloudbench.TruthBatches, label gpu): the first
# scene of random:2026 (scattered cumulus near the pole, sun 10.6 deg) at 8x5, first with one
# batch of 8 paths per pixel, then with up to 256: the second run reuses the first batch from
# the cache, adds batches of other seeds because one batch is too noisy to resolve the cloud
# radiance, and its truth's relative noise falls about as 1/sqrt(paths).
# Then truth_scene_probe on the same scene: the shares of its kinds of contribution add up to
# 100 % and the cloud next events carry radiance.
# Usage: cmake -DCLOUDBENCH=<binary> -DPROBE=<truth_scene_probe> -DOUT=<scratch dir> -P check_cloudbench_truth.cmake
file(REMOVE_RECURSE "${OUT}")
set(args --truth --scenes random:2026:1 --size 8x5 --spp 8 --ref-samples 1 --max-collisions 20000 --out "${OUT}")

function(fail msg)
  message(FATAL_ERROR "cloudbench --truth: ${msg}")
endfunction()

# The scene's row of report.md's per-scene table: "| r2026-0 | spp | incomplete | noise | ..."
function(scene_row var)
  file(READ "${OUT}/report.md" md)
  if(NOT md MATCHES "\n\\| r2026-0 \\| ([0-9]+) \\| [0-9.]+ % \\| ([0-9.]+) \\|")
    fail("report.md has no per-scene row for r2026-0 with spp and noise:\n${md}")
  endif()
  set(${var}_spp ${CMAKE_MATCH_1} PARENT_SCOPE)
  set(${var}_noise ${CMAKE_MATCH_2} PARENT_SCOPE)
endfunction()

execute_process(COMMAND "${CLOUDBENCH}" ${args} --max-spp 8 RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  fail("one batch: exit ${rc}\n${out}\n${err}")
endif()
scene_row(one)
if(NOT one_spp EQUAL 8 OR one_noise LESS_EQUAL 0.25)
  fail("one batch: ${one_spp} spp, noise ${one_noise} (expected 8 and > 0.25: too noisy to resolve)")
endif()

execute_process(COMMAND "${CLOUDBENCH}" ${args} --max-spp 256 RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT out MATCHES "truth rendered")
  fail("batches: exit ${rc}, expected new batches rendered\n${out}\n${err}")
endif()
scene_row(more)
if(NOT more_spp GREATER 8 OR more_spp GREATER 256)
  fail("batches: ${more_spp} spp, expected in (8, 256]")
endif()
file(READ "${OUT}/report.md" md)
string(FIND "${md}" "--max-spp 256" at)
if(at EQUAL -1)
  fail("report.md does not give the command with --max-spp 256")
endif()
# noise x sqrt(spp) within a factor 1.6 of one batch's (1/sqrt(N), with a heavy tail);
# compared in integer thousandths
string(REGEX REPLACE "^0*([0-9]*)\\.([0-9][0-9][0-9]).*" "\\1\\2" one_m "${one_noise}")
string(REGEX REPLACE "^0*([0-9]*)\\.([0-9][0-9][0-9]).*" "\\1\\2" more_m "${more_noise}")
# more_noise^2 * spp_more <= (1.6 * one_noise)^2 * 8  and  more_noise < one_noise
math(EXPR lhs "${more_m} * ${more_m} * ${more_spp}")
math(EXPR rhs "${one_m} * ${one_m} * 8 * 256 / 100")
if(NOT more_m LESS one_m OR lhs GREATER rhs)
  fail("noise ${one_noise} at 8 spp -> ${more_noise} at ${more_spp} spp: not falling as 1/sqrt(paths)")
endif()

execute_process(COMMAND "${PROBE}" --scenes random:2026:1 --scene 0 --size 8x5 --spp 4 RESULT_VARIABLE rc
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT out MATCHES "^r2026-0: .* evals/px, per camera path: .* relative noise")
  fail("truth_scene_probe: exit ${rc}\n${out}\n${err}")
endif()
string(REGEX MATCHALL "([0-9]+\\.[0-9]) % of the sum," shares "${out}")
set(total 0)
foreach(share IN LISTS shares)
  string(REGEX REPLACE "^([0-9]+)\\.([0-9]) .*" "\\1\\2" tenths "${share}")
  math(EXPR total "${total} + ${tenths}")
endforeach()
list(LENGTH shares kinds)
if(NOT kinds EQUAL 8 OR total LESS 995 OR total GREATER 1005 OR NOT out MATCHES "next event, cloud, guided +[1-9]")
  fail("truth_scene_probe: ${kinds} kinds whose shares add to ${total} tenths of a percent\n${out}")
endif()
message(STATUS "cloudbench --truth: noise ${one_noise} at 8 spp -> ${more_noise} at ${more_spp} spp")

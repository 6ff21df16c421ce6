# CI-sized check of `cloudbench --morphology` (ctest Cloudbench.Morphology, label gpu): the
# scattered-cumulus preset at 96 px from 20 km writes its table, CSV and contact sheet, with
# clouds counted and a perimeter-area dimension between the smooth and the space-filling
# limits (1 and 2); an unknown weather preset exits 2 naming it.
# Usage: cmake -DCLOUDBENCH=<binary> -DOUT=<scratch dir> -P check_cloudbench_morphology.cmake
file(REMOVE_RECURSE "${OUT}")

function(fail msg)
  message(FATAL_ERROR "cloudbench --morphology: ${msg}")
endfunction()

execute_process(COMMAND "${CLOUDBENCH}" --morphology --size 96 --presets scattered-cumulus --out "${OUT}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  fail("exited with ${rc}\n${out}\n${err}")
endif()
foreach(f morphology.md morphology.csv morphology_sheet.png)
  if(NOT EXISTS "${OUT}/${f}")
    fail("no ${f} in ${OUT}")
  endif()
endforeach()
file(READ "${OUT}/morphology.md" md)
string(FIND "${md}" "| scattered-cumulus |" at)
if(at EQUAL -1)
  fail("morphology.md has no scattered-cumulus row\n${md}")
endif()
file(STRINGS "${OUT}/morphology.csv" csv)
list(LENGTH csv n)
if(NOT n EQUAL 2)
  fail("morphology.csv: ${n} lines, expected a header and one row")
endif()
list(GET csv 1 row)
string(REPLACE "," ";" cols "${row}")
list(GET cols 2 clouds)
list(GET cols 3 dimension)
if(clouds LESS 5)
  fail("only ${clouds} clouds measured: ${row}")
endif()
if(NOT dimension GREATER 1.0 OR NOT dimension LESS 2.0)
  fail("perimeter-area dimension ${dimension} outside (1, 2): ${row}")
endif()

execute_process(COMMAND "${CLOUDBENCH}" --morphology --presets no-such-preset --out "${OUT}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 2)
  fail("an unknown preset exited with ${rc}, expected 2")
endif()
string(FIND "${err}" "no-such-preset" at)
if(at EQUAL -1)
  fail("the error does not name the preset: ${err}")
endif()

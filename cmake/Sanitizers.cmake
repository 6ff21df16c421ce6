# Compiler and linker flags of the sanitizer build (CLOUDSVC_SANITIZE) and of the fuzzing
# build (CLOUDSVC_FUZZ), for every target of the project. Included by the top CMakeLists.txt
# after its warning flags.
#
# CLOUDSVC_SANITIZE: AddressSanitizer (out-of-bounds, use-after-free, leaks at exit) and
# UndefinedBehaviorSanitizer (signed overflow, bad shifts, float-to-int overflow, misaligned
# or null access, invalid enum/bool loads, ...). -fno-sanitize-recover=all makes every UBSan
# report abort the process, as AddressSanitizer does by default, so a report always fails
# the test or fuzz run that caused it. _GLIBCXX_ASSERTIONS adds libstdc++'s bounds checks
# (operator[] of vector, string, span, array; front/back of empty containers).
#
# CLOUDSVC_FUZZ: coverage instrumentation for libFuzzer on every object file
# (-fsanitize=fuzzer-no-link), so the fuzz targets of fuzz/ are guided by the code they
# call; only the fuzz targets link libFuzzer itself (-fsanitize=fuzzer, fuzz/CMakeLists.txt).
# Other executables get the sanitizer runtimes' no-op coverage callbacks.

if(CLOUDSVC_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all
                      -fno-omit-frame-pointer)
  add_compile_definitions(_GLIBCXX_ASSERTIONS)
  add_link_options(-fsanitize=address,undefined)
endif()

if(CLOUDSVC_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "CLOUDSVC_FUZZ needs clang (libFuzzer); configure with "
                        "-DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_COMPILER=clang")
  endif()
  if(NOT CLOUDSVC_SANITIZE)
    message(WARNING "CLOUDSVC_FUZZ without CLOUDSVC_SANITIZE finds crashes only, not memory "
                    "errors or undefined behaviour")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()

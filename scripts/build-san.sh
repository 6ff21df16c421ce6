#!/usr/bin/env bash
# Installs dependencies and builds the sanitizer and fuzzing configuration into build-san/:
# clang, CLOUDSVC_BUILD_GL=OFF (the GL-free libraries, their tests and sim_client),
# CLOUDSVC_SANITIZE=ON (AddressSanitizer + UndefinedBehaviorSanitizer) and CLOUDSVC_FUZZ=ON
# (the libFuzzer targets of fuzz/), at -O1 with line tables for readable sanitizer stacks.
# Used by scripts/test.sh (then ctest) and scripts/fuzz.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
mkdir -p build-san
flags="-O1 -gline-tables-only -DNDEBUG"
cmake -S . -B build-san -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_COMPILER=clang \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=$flags" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=$flags" \
  -DCLOUDSVC_BUILD_GL=OFF -DCLOUDSVC_BUILD_BENCH=OFF \
  -DCLOUDSVC_SANITIZE=ON -DCLOUDSVC_FUZZ=ON > build-san/configure.log 2>&1 || { cat build-san/configure.log; exit 1; }
cmake --build build-san -j "$(nproc)"

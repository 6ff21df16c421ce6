#!/usr/bin/env bash
# README command 2: install, build, run every test (ctest, headless on EGL/llvmpipe); then
# the sanitizer build of the GL-free code (scripts/build-san.sh: clang, AddressSanitizer +
# UndefinedBehaviorSanitizer, in build-san/) and its ctest, which also runs every fuzz
# target of fuzz/ for a few seconds (label "fuzz").
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j "$(nproc)" "$@"
bash scripts/build-san.sh
UBSAN_OPTIONS=print_stacktrace=1 ctest --test-dir build-san --output-on-failure -j "$(nproc)" "$@"

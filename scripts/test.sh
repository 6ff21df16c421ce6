#!/usr/bin/env bash
# README command 2: install, build, run every test (ctest, headless on EGL/llvmpipe); then
# the sanitizer build of the GL-free code (scripts/build-san.sh: clang, AddressSanitizer +
# UndefinedBehaviorSanitizer, in build-san/) and its ctest, which also runs every fuzz
# target of fuzz/ for a few seconds (label "fuzz"). Each phase's wall time is printed at
# its end ("test.sh: <phase> took M min S s"), so a CI log shows where the time goes.
set -euo pipefail
cd "$(dirname "$0")/.."
phase() {  # phase NAME COMMAND...: runs the command and prints its wall time
  local name=$1 start=$SECONDS
  shift
  "$@"
  local s=$((SECONDS - start))
  echo "test.sh: $name took $((s / 60)) min $((s % 60)) s"
}
phase "install and release build" bash scripts/build.sh
phase "release ctest" ctest --test-dir build --output-on-failure -j "$(nproc)" "$@"
phase "sanitizer build" bash scripts/build-san.sh
export UBSAN_OPTIONS=print_stacktrace=1
phase "sanitizer ctest" ctest --test-dir build-san --output-on-failure -j "$(nproc)" "$@"

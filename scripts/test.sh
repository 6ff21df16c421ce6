#!/usr/bin/env bash
# README command 2: install, build, run every test (ctest, headless on EGL/llvmpipe).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j "$(nproc)" "$@"

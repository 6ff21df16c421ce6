#!/usr/bin/env bash
# README command 1: install, build, render the embedded demo scenes to out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
./build/bin/cloudsvc demo --out-dir out "$@"

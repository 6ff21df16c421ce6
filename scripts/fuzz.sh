#!/usr/bin/env bash
# Fuzzes every target of fuzz/ (fuzz/CMakeLists.txt) for SECONDS each (default 60):
#   bash scripts/fuzz.sh [SECONDS]
# Builds build-san/ first (scripts/build-san.sh: clang, ASan + UBSan, libFuzzer), then runs
# the targets nproc at a time through fuzz/run_fuzzer.sh. Seeds, only read: fuzz/corpus/<t>/,
# build-san/fuzz/seeds/<t>/ and, for the IGC and ACMI readers, the real flight logs in
# ../shared/data/flightlogs when present. New inputs are kept in build-san/fuzz/runs/<t>/
# (so later runs start from them), crash inputs in build-san/fuzz/runs/<t>/artifacts/.
# Prints one line per target (execs, exec/s, coverage, features, corpus, crashes) and exits
# non-zero if any target crashed; the end of a crashed target's libFuzzer log is in
# build-san/fuzz/runs/<t>.stderr, the whole log in build-san/fuzz/runs/<t>/log.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
bash scripts/build-san.sh

runs=build-san/fuzz/runs
mkdir -p "$runs"
mapfile -t targets < <(cd fuzz && ls ./*_fuzz.cpp | sed 's|^\./||; s|_fuzz\.cpp$||')

run_target() {
  local t=$1 extra=()
  case $t in
    simclient_igc | simclient_acmi) extra=(../shared/data/flightlogs) ;;
  esac
  bash fuzz/run_fuzzer.sh "build-san/bin/fuzz_$t" "$seconds" "$runs/$t" \
    "fuzz/corpus/$t" "build-san/fuzz/seeds/$t" "${extra[@]}" > "$runs/$t.summary" 2> "$runs/$t.stderr"
}

jobs=$(nproc)
echo "fuzz: ${#targets[@]} targets, ${seconds} s each, ${jobs} at a time"
failed=0 running=0
for t in "${targets[@]}"; do
  if [ "$running" -ge "$jobs" ]; then
    wait -n || failed=1
    running=$((running - 1))
  fi
  run_target "$t" &
  running=$((running + 1))
done
while [ "$running" -gt 0 ]; do
  wait -n || failed=1
  running=$((running - 1))
done

for t in "${targets[@]}"; do cat "$runs/$t.summary"; done
if [ "$failed" -ne 0 ]; then
  echo "fuzz: crashes found; see build-san/fuzz/runs/<target>.stderr" >&2
  exit 1
fi

#!/usr/bin/env bash
# Runs one libFuzzer target for a while and prints one summary line; exits non-zero when it
# found a crash (sanitizer report, failed FUZZ_CHECK, uncaught exception, timeout, OOM).
#   run_fuzzer.sh <fuzzer> <seconds> <work-dir> [<seed-dir>...]
# Seed directories are only read (missing ones are skipped); new inputs go to
# <work-dir>/corpus, crash inputs to <work-dir>/artifacts/, libFuzzer's output to
# <work-dir>/log. Used by ctest (fuzz/CMakeLists.txt) and scripts/fuzz.sh.
set -uo pipefail

fuzzer=$1 seconds=$2 work=$3
shift 3
seeds=()
for d in "$@"; do
  if [ -d "$d" ]; then seeds+=("$d"); fi
done
mkdir -p "$work/corpus" "$work/artifacts"
log=$work/log

# UBSan reports abort by themselves (-fno-sanitize-recover=all); this adds their stack.
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1}
# -max_len: inputs up to 16 KiB (longer seeds are cut there); -timeout: an input running
# over 60 s is a hang; -rss_limit_mb: libFuzzer's default memory bound, stated.
"$fuzzer" -max_total_time="$seconds" -print_final_stats=1 -max_len=16384 -timeout=60 \
  -rss_limit_mb=2048 -artifact_prefix="$work/artifacts/" "$work/corpus" "${seeds[@]}" > "$log" 2>&1
rc=$?

# Figures from libFuzzer's final statistics and its last status line
# ("#N DONE cov: C ft: F corp: U/B ...").
stat() { sed -n "s/^stat::$1: *//p" "$log" | tail -n 1; }
status=$(grep -E '^#[0-9]+.*cov: ' "$log" | tail -n 1)
field() { sed -n "s/.* $1: \([^ ]*\).*/\1/p" <<< "$status"; }
crash=$(sed -n "s/.*Test unit written to \(.*\)$/\1/p" "$log" | tail -n 1)
printf '%s: %ss, %s execs, %s exec/s, cov %s, ft %s, corpus %s, crashes %s\n' \
  "$(basename "$fuzzer")" "$seconds" "$(stat number_of_executed_units)" "$(stat average_exec_per_sec)" \
  "$(field cov)" "$(field ft)" "$(field corp)" "${crash:-0}"
if [ $rc -ne 0 ]; then
  echo "--- last lines of $log (exit code $rc) ---" >&2
  tail -n 80 "$log" >&2
fi
exit $rc

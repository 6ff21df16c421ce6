#!/usr/bin/env bash
# README command 1: install, build, then the main job on the embedded defaults:
#   1. start `cloudsvc serve` (Unix socket + shared-memory ring, broken-cumulus weather),
#   2. replay the bundled synthetic demo flight (sim_client/demo_flight.csv) through
#      `sim_client replay`, writing the frames and a contact sheet to out/flight/,
#   3. stop the service (SIGTERM: it removes its socket and shared memory),
#   4. render the documented demo scenes (docs/img) to out/scenes/.
# Options: DEMO_SIZE=WxH (default 640x360), DEMO_FPS=poses per second of flight time (default 0.2).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh

size="${DEMO_SIZE:-640x360}"
fps="${DEMO_FPS:-0.2}"
mkdir -p out/flight out/scenes
sock="$(mktemp -u /tmp/cloudsvc-demo-XXXXXX.sock)"
shm="cloudsvc-demo-$$"
shm_max="${size}"

./build/bin/cloudsvc serve --listen "unix:${sock}" --shm "${shm}" --shm-max-size "${shm_max}" \
    --size "${size}" --weather broken-cumulus --time 2026-06-21T14:00:00Z > out/serve.log 2>&1 &
serve_pid=$!
cleanup() { kill -TERM "${serve_pid}" 2>/dev/null || true; wait "${serve_pid}" 2>/dev/null || true; }
trap cleanup EXIT
for _ in $(seq 1 300); do [ -S "${sock}" ] && break; sleep 0.1; done
[ -S "${sock}" ] || { echo "demo: cloudsvc serve did not start:"; cat out/serve.log; exit 1; }

./build/bin/sim_client replay sim_client/demo_flight.csv --connect "unix:${sock}" --out out/flight \
    --size "${size}" --fps "${fps}" --contact-sheet out/flight/contact-sheet.png

cleanup
trap - EXIT
echo "demo: service log in out/serve.log; frames and out/flight/contact-sheet.png written"

./build/bin/cloudsvc demo --out-dir out/scenes --size "${size}"

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
run_dir="$(mktemp -d /tmp/cloudsvc-demo-XXXXXX)"
sock="${run_dir}/s.sock"
ready="${run_dir}/ready"
shm="cloudsvc-demo-$$"
shm_max="${size}"

# --out-dir: the only directory a client may have the service write frames into.
./build/bin/cloudsvc serve --listen "unix:${sock}" --ready-file "${ready}" --shm "${shm}" --shm-max-size "${shm_max}" \
    --size "${size}" --out-dir out/flight --weather broken-cumulus --time 2026-06-21T14:00:00Z > out/serve.log 2>&1 &
serve_pid=$!
cleanup() { kill -TERM "${serve_pid}" 2>/dev/null || true; wait "${serve_pid}" 2>/dev/null || true; rm -rf "${run_dir}"; }
trap cleanup EXIT
# The service writes the ready file once it listens; wait for that (or for its exit).
for _ in $(seq 1 1200); do
  [ -f "${ready}" ] && break
  kill -0 "${serve_pid}" 2>/dev/null || break
  sleep 0.1
done
[ -f "${ready}" ] || { echo "demo: cloudsvc serve did not start:"; cat out/serve.log; exit 1; }

./build/bin/sim_client replay sim_client/demo_flight.csv --connect "unix:${sock}" --out out/flight \
    --size "${size}" --fps "${fps}" --contact-sheet out/flight/contact-sheet.png

cleanup
trap - EXIT
echo "demo: service log in out/serve.log; frames and out/flight/contact-sheet.png written"

./build/bin/cloudsvc demo --out-dir out/scenes --size "${size}"

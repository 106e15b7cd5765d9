#!/usr/bin/env bash
# Dashboard performance (docs/benchmarks/log.md, "Dashboard in headless Chromium"):
# `fleetlink demo` plus a fourth simulated robot publishing a 100k-point PointCloud2 at
# 10 Hz, its robot view open in headless Chromium. Prints frames/s, clouds shown/s, the
# age of the cloud on screen (p50/p99 over BENCH_SECONDS, default 60) and the JS heap
# after 1 and BENCH_MINUTES (default 10) minutes. Needs the release binary,
# web/node_modules and chromium (scripts/setup.d/55-web-packages.sh, 60-browser.sh).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
bin="${FLEETLINK_BIN:-$root/target/release/fleetlink}"
# shellcheck source=../tests/interop/lib.sh
. "$root/tests/interop/lib.sh"
interop_begin dashboard-bench
data="$tmp/demo-data"
robot_token="$(timeout 30 "$bin" admin --data-dir "$data" token robot robot4)"
: >"$tmp/hub.log"; : >"$tmp/agent.log"
"$bin" demo --listen 127.0.0.1:0 --data-dir "$data" >"$tmp/hub.log" 2>&1 &
pids+=($!)
addr="$(wait_for_line "$tmp/hub.log" '^  open http://([0-9.:]+)/ in a browser$' "demo start" "${pids[0]}")"
op_token="$(wait_for_line "$tmp/hub.log" '^  the operator token \([^)]*\): (.+)$' "operator token" "${pids[0]}")"
cat >"$tmp/agent.yaml" <<YAML
hub: ws://$addr/
name: robot4
token: $robot_token
local_rosbridge: null
sim:
  seed: 4
  odometry: { rate_hz: 20 }
  pose: { rate_hz: 10 }
  point_cloud: { rate_hz: 10, points: 100000 }
YAML
"$bin" agent --name robot4 --config "$tmp/agent.yaml" >"$tmp/agent.log" 2>&1 &
pids+=($!)
echo "hub http://$addr/, robot4 publishing 100k points at 10 Hz" >&2
node "$root/tests/interop/dashboard/bench.mjs" --url "http://$addr/" --token "$op_token" --robot robot4 \
    --seconds "${BENCH_SECONDS:-60}" --minutes "${BENCH_MINUTES:-10}" ${BENCH_SHOT:+--shot "$BENCH_SHOT"}

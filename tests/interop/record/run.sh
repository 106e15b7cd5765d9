#!/usr/bin/env bash
# MCAP recording and replay interop suite: the hub records the simulated robot's topics
# (its camera's H.264 video among them), a roslibpy publisher's strings and a Foxglove
# client's ROS 1 messages; Python's `mcap` reader with `mcap-ros2-support` and
# `mcap-ros1-support` reads the files, PyAV decodes the video; `fleetlink
# play` replays one to a second hub, where roslibpy receives it.
#
# Starts hub A with robot1 (simulated laser, odometry and camera video) and hub B (empty), each with
# its own data directory and tokens, then runs record_check.py, which drives the
# `fleetlink record` and `fleetlink play` commands and the peers. Every process started
# here is stopped on exit (trap), also on failure. Bounded: each step has a timeout; the
# suite takes well under 2 minutes.
#
# Env: FLEETLINK_BIN (default: target/release/fleetlink).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
bin="${FLEETLINK_BIN:-$root/target/release/fleetlink}"
py="$root/.venv/bin/python"
robot=robot1
scan_ranges=360
started=$SECONDS

[ -x "$bin" ] || { echo "FAIL: fleetlink binary not found at $bin (set FLEETLINK_BIN)" >&2; exit 1; }
"$py" -c 'import roslibpy, mcap, mcap_ros2, mcap_ros1, websockets' 2>/dev/null \
    || { echo "FAIL: Python peers missing; run scripts/setup.d/10-python-venv.sh" >&2; exit 1; }

# shellcheck source=../lib.sh
. "$here/../lib.sh"
interop_begin record

admin() { timeout 30 "$bin" admin "$@"; }
robot_token="$(admin --data-dir "$tmp/hub-data" token robot "$robot")"
op_token="$(admin --data-dir "$tmp/hub-data" token operator interop --group admin)"
denied_token="$(admin --data-dir "$tmp/hub-data" token operator nobody)"
op2_token="$(admin --data-dir "$tmp/hub2-data" token operator replay --group admin)"

: >"$tmp/hub.log"; : >"$tmp/agent.log"; : >"$tmp/hub2.log"
"$bin" hub --listen 127.0.0.1:0 --data-dir "$tmp/hub-data" >"$tmp/hub.log" 2>&1 &
pids+=($!)
hub_addr="$(wait_for_line "$tmp/hub.log" '^fleetlink hub listening on ([0-9.:]+)$' "hub start" "${pids[0]}")"
"$bin" hub --listen 127.0.0.1:0 --data-dir "$tmp/hub2-data" >"$tmp/hub2.log" 2>&1 &
pids+=($!)
hub2_addr="$(wait_for_line "$tmp/hub2.log" '^fleetlink hub listening on ([0-9.:]+)$' "hub B start" "${pids[1]}")"
echo "hub A: ws://$hub_addr/  hub B: ws://$hub2_addr/"

cat >"$tmp/agent.yaml" <<YAML
hub: ws://$hub_addr/
name: $robot
token: $robot_token
sim:
  laser_scan: { rate_hz: 10, ranges: $scan_ranges }
  odometry:   { rate_hz: 20 }
  image:      { rate_hz: 15, width: 320, height: 240 }
video:
  /camera/image/compressed: { topic: /camera/video }
YAML
"$bin" agent --name "$robot" --config "$tmp/agent.yaml" --no-local >"$tmp/agent.log" 2>&1 &
pids+=($!)

ready=""
for _ in $(seq 150); do
    robots="$(curl -fsS -m 2 -H "Authorization: Bearer $op_token" "http://$hub_addr/api/v1/robots" 2>/dev/null || true)"
    if grep -q "\"/$robot/scan\"" <<<"$robots" && grep -q '"online":true' <<<"$robots"; then
        ready=1; break
    fi
    sleep 0.1
done
[ -n "$ready" ] || { echo "FAIL: $robot not online with its topics within 15 s; last: ${robots:-none}" >&2; exit 1; }
echo "ready: $robot online"

rc=0
timeout --kill-after=5 120 "$py" "$here/record_check.py" --bin "$bin" \
    --hub "ws://$hub_addr" --hub2 "ws://$hub2_addr" --op-token "$op_token" \
    --op2-token "$op2_token" --denied-token "$denied_token" --robot "$robot" \
    --scan-ranges "$scan_ranges" --work "$tmp/work" || rc=$?

for pid in "${pids[@]}"; do
    kill -0 "$pid" 2>/dev/null || { echo "FAIL: server process $pid died" >&2; rc=1; }
done
echo "record interop: $((SECONDS - started)) s"
[ "$rc" -eq 0 ] || { echo "FAIL: record interop" >&2; exit 1; }
echo "PASS: record interop (mcap readers, fleetlink play to a second hub, roslibpy)"

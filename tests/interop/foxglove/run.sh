#!/usr/bin/env bash
# Foxglove WebSocket interop suite: @foxglove/ws-protocol's FoxgloveClient (npm, under
# Node) against a fleetlink hub with one simulated robot.
#
# Starts a hub and one agent (robot1: simulated laser, odometry, point cloud, a camera
# and its H.264 video; services /set_mode and /get_status; a local rosbridge listener
# where the robot's /cmd_vel is watched), waits until robot1 is online with its topics, then runs
# foxglove_client_check.mjs once per subprotocol (foxglove.websocket.v1 as Lichtblick
# offers it, foxglove.sdk.v1 as the current Foxglove app does), with client publishing
# and service calls in CDR on one run and JSON on the other, and a token without rights
# on each; then deflate_check.mjs (permessage-deflate, two compressing clients and one
# plain); then video_check.mjs (the camera's video read by FoxgloveClient, decoded by
# PyAV). Every process started here is stopped on exit (trap), also on failure.
# Bounded: each step has a timeout; the suite takes well under 2 minutes.
#
# Env: FLEETLINK_BIN (default: target/release/fleetlink).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
bin="${FLEETLINK_BIN:-$root/target/release/fleetlink}"
robot=robot1
scan_ranges=360
points=1000
started=$SECONDS

[ -x "$bin" ] || { echo "FAIL: fleetlink binary not found at $bin (set FLEETLINK_BIN)" >&2; exit 1; }
[ -d "$here/node_modules/@foxglove/ws-protocol" ] || { echo "FAIL: @foxglove/ws-protocol missing; run scripts/setup.d/20-node-packages.sh" >&2; exit 1; }

# shellcheck source=../lib.sh
. "$here/../lib.sh"
interop_begin foxglove

# --- credentials, minted in the hub's database before it starts: the robot, an admin
# operator, and an operator outside every group with no rules (may see and do nothing).
admin() { timeout 30 "$bin" admin --data-dir "$tmp/hub-data" "$@"; }
robot_token="$(admin token robot "$robot")"
op_token="$(admin token operator interop --group admin)"
denied_token="$(admin token operator nobody)"

# --- hub and agent (log files exist before the background start, so the reader never
# races them)
: >"$tmp/hub.log"; : >"$tmp/agent.log"
"$bin" hub --listen 127.0.0.1:0 --data-dir "$tmp/hub-data" >"$tmp/hub.log" 2>&1 &
pids+=($!)
hub_addr="$(wait_for_line "$tmp/hub.log" '^fleetlink hub listening on ([0-9.:]+)$' "hub start" "${pids[0]}")"
# Foxglove and Lichtblick take the token in the URL.
hub_url="ws://$hub_addr/?token=$op_token"
denied_url="ws://$hub_addr/?token=$denied_token"
echo "hub: ws://$hub_addr/ (tokens in the URL)"

cat >"$tmp/agent.yaml" <<YAML
hub: ws://$hub_addr/
name: $robot
token: $robot_token
local_rosbridge: { listen: 127.0.0.1:0 }
sim:
  laser_scan:  { rate_hz: 10, ranges: $scan_ranges }
  odometry:    { rate_hz: 20 }
  point_cloud: { rate_hz: 2, points: $points }
  image:       { rate_hz: 15, width: 320, height: 240 }
video:
  /camera/image/compressed: { topic: /camera/video }
YAML
"$bin" agent --name "$robot" --config "$tmp/agent.yaml" --local-listen 127.0.0.1:0 >"$tmp/agent.log" 2>&1 &
pids+=($!)
local_addr="$(wait_for_line "$tmp/agent.log" '^  local rosbridge: ws://([0-9.:]+)/$' "agent start" "${pids[1]}")"
local_url="ws://$local_addr/"
echo "agent $robot local rosbridge: $local_url"

# --- ready: robot1 online with its topics and services (bounded: 15 s)
ready=""
for _ in $(seq 150); do
    robots="$(curl -fsS -m 2 -H "Authorization: Bearer $op_token" "http://$hub_addr/api/v1/robots" 2>/dev/null || true)"
    if grep -q "\"/$robot/points\"" <<<"$robots" && grep -q '"online":true' <<<"$robots"; then
        ready=1; break
    fi
    sleep 0.1
done
[ -n "$ready" ] || { echo "FAIL: $robot not online with its topics within 15 s; last: ${robots:-none}" >&2; exit 1; }
echo "ready: $robot online"

failed=()
run_check() {
    local name=$1; shift
    echo "== $name"
    if ! timeout --kill-after=5 90 "$@"; then failed+=("$name"); fi
}
common=(--url "$hub_url" --denied-url "$denied_url" --local-url "$local_url" --robot "$robot"
        --scan-ranges "$scan_ranges" --points "$points")
run_check "foxglove.websocket.v1" node "$here/foxglove_client_check.mjs" "${common[@]}" \
    --subprotocol foxglove.websocket.v1 --publish-encoding cdr --call-encoding json \
    --param '/fleetlink_interop/max_speed=1.5'
run_check "foxglove.sdk.v1" node "$here/foxglove_client_check.mjs" "${common[@]}" \
    --subprotocol foxglove.sdk.v1 --publish-encoding json --call-encoding cdr \
    --param '/fleetlink_interop/mode="patrol"'

# The camera's video (issue 60): a Foxglove client reads its CompressedVideo frames from
# CDR, and FFmpeg's decoder (PyAV) decodes them all from the first.
echo "== foxglove video"
if ! { timeout --kill-after=5 60 node "$here/video_check.mjs" --url "$hub_url" \
            --topic "/$robot/camera/video" --seconds 4 --out "$tmp/foxglove-video.frames" \
        && timeout --kill-after=5 60 "$root/.venv/bin/python" "$root/tests/interop/video/video_peer.py" \
            decode "$tmp/foxglove-video.frames" --size 320x240 --min-frames 20; }; then
    failed+=("foxglove video")
fi

# Both processes must have survived everything the clients did.
# permessage-deflate (issue 56): FoxgloveClient over ws with perMessageDeflate.
run_check "foxglove deflate" node "$here/deflate_check.mjs" --url "$hub_url" \
    --api "http://$hub_addr" --token "$op_token" --robot "$robot" --points "$points"

for pid in "${pids[@]}"; do
    kill -0 "$pid" 2>/dev/null || failed+=("server process $pid died")
done

echo "foxglove interop: ${#failed[@]} failure(s) in 4 client runs, $((SECONDS - started)) s"
if [ ${#failed[@]} -ne 0 ]; then
    echo "FAIL: ${failed[*]}" >&2
    exit 1
fi
echo "PASS: foxglove interop (FoxgloveClient, both subprotocols)"

#!/usr/bin/env bash
# rosbridge interop suite: real roslibpy (PyPI) and roslib (npm, under Node) clients
# against a fleetlink hub and an agent's local rosbridge listener.
#
# Starts a hub and one agent (robot1, simulated laser/odometry/point cloud, local
# listener), waits until robot1 is online with its topics, then runs
#   roslibpy_check.py and roslib_check.mjs  x  (hub URL, agent's local URL),
#   foxglove_check.mjs, deflate_check.py and deflate_roslib_check.mjs (permessage-deflate,
#   hub and local), and actionlib_check.py (roslibpy 1.8's actionlib, on the hub)
# and exits non-zero if any of them failed. Every process started here is stopped on
# exit (trap), also on failure. Bounded: each step has a timeout, the whole suite
# stays under 5 minutes.
#
# Env: FLEETLINK_BIN (default: target/release/fleetlink), PYTHON (default: .venv/bin/python).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
bin="${FLEETLINK_BIN:-$root/target/release/fleetlink}"
python="${PYTHON:-$root/.venv/bin/python}"
python1="$root/.venv-roslibpy1/bin/python"
robot=robot1
scan_ranges=720
points=2000
started=$SECONDS

[ -x "$bin" ] || { echo "FAIL: fleetlink binary not found at $bin (set FLEETLINK_BIN)" >&2; exit 1; }
[ -x "$python" ] || { echo "FAIL: $python missing; run scripts/setup.d/10-python-venv.sh" >&2; exit 1; }
[ -x "$python1" ] || { echo "FAIL: $python1 missing; run scripts/setup.d/12-roslibpy-1.sh" >&2; exit 1; }
[ -d "$here/node_modules/roslib" ] || { echo "FAIL: roslib missing; run scripts/setup.d/20-node-packages.sh" >&2; exit 1; }

# shellcheck source=../lib.sh
. "$here/../lib.sh"
interop_begin rosbridge

# --- credentials, minted in the hub's database before it starts (fleetlink admin)
robot_token="$("$bin" admin --data-dir "$tmp/hub-data" token robot "$robot")"
op_token="$("$bin" admin --data-dir "$tmp/hub-data" token operator interop --group admin)"

# --- hub (log files exist before the background start, so the reader never races them)
: >"$tmp/hub.log"; : >"$tmp/agent.log"
"$bin" hub --listen 127.0.0.1:0 --data-dir "$tmp/hub-data" >"$tmp/hub.log" 2>&1 &
pids+=($!)
hub_addr="$(wait_for_line "$tmp/hub.log" '^fleetlink hub listening on ([0-9.:]+)$' "hub start" "${pids[0]}")"
# Clients authenticate the way browsers do: the token in the URL.
hub_url="ws://$hub_addr/?token=$op_token"
echo "hub: ws://$hub_addr/ (operator token in the URL)"

# --- agent
cat >"$tmp/agent.yaml" <<EOF
hub: ws://$hub_addr/
name: $robot
token: $robot_token
local_rosbridge: { listen: 127.0.0.1:0 }
sim:
  laser_scan:  { rate_hz: 10, ranges: $scan_ranges }
  odometry:    { rate_hz: 20 }
  point_cloud: { rate_hz: 2, points: $points }
  pose:        { rate_hz: 5 }
  image:       { rate_hz: 2 }
  markers:     { rate_hz: 2 }
topics:
  /markers: { mode: pull }
EOF
"$bin" agent --name "$robot" --config "$tmp/agent.yaml" --local-listen 127.0.0.1:0 >"$tmp/agent.log" 2>&1 &
pids+=($!)
local_addr="$(wait_for_line "$tmp/agent.log" '^  local rosbridge: ws://([0-9.:]+)/$' "agent start" "${pids[1]}")"
local_url="ws://$local_addr/"
echo "agent $robot local rosbridge: $local_url"

# --- ready: hub healthy, robot1 online with its sim topics (bounded: 15 s)
"$python" - "$hub_addr" "$robot" "$op_token" <<'EOF'
import json, sys, time, urllib.request
addr, robot, token = sys.argv[1], sys.argv[2], sys.argv[3]
want = {f"/{robot}/scan", f"/{robot}/odom", f"/{robot}/points"}
deadline, last = time.monotonic() + 15, None
while time.monotonic() < deadline:
    try:
        with urllib.request.urlopen(f"http://{addr}/healthz", timeout=2) as r:
            assert r.status == 200, r.status
        req = urllib.request.Request(f"http://{addr}/api/v1/robots",
                                     headers={"Authorization": f"Bearer {token}"})
        with urllib.request.urlopen(req, timeout=2) as r:
            robots = json.load(r)["robots"]
        me = [x for x in robots if x["name"] == robot]
        last = me
        if me and me[0]["online"] and want <= set(me[0]["topics"]):
            print(f"ready: /healthz ok, {robot} online with {sorted(me[0]['topics'])}")
            sys.exit(0)
    except Exception as e:  # not up yet
        last = repr(e)
    time.sleep(0.1)
print(f"FAIL: {robot} not online with {sorted(want)} within 15 s; last: {last}", file=sys.stderr)
sys.exit(1)
EOF

# --- the clients: each run is bounded (timeout), failures are collected, not fatal
failed=()
run_check() {
    local name=$1; shift
    echo "== $name"
    if ! timeout --kill-after=5 90 "$@"; then failed+=("$name"); fi
}
common=(--robot "$robot" --scan-ranges "$scan_ranges" --points "$points")
run_check "roslibpy hub" "$python" "$here/roslibpy_check.py" --url "$hub_url" --mode hub --peer-url "$local_url" "${common[@]}"
run_check "roslibpy local" "$python" "$here/roslibpy_check.py" --url "$local_url" --mode local --peer-url "$hub_url" "${common[@]}"
run_check "roslib hub" node "$here/roslib_check.mjs" --url "$hub_url" --mode hub --peer-url "$local_url" "${common[@]}"
run_check "roslib local" node "$here/roslib_check.mjs" --url "$local_url" --mode local --peer-url "$hub_url" "${common[@]}"
run_check "foxglove parsers" node "$here/foxglove_check.mjs" --url "$hub_url" --bin "$bin" --robot "$robot"
# permessage-deflate (issue 56): Python websockets and roslib over ws negotiate it; large
# messages arrive compressed, compressed publishes are read, a zip bomb gets 1009.
deflate_urls=(--url "$hub_url=/$robot/points" --url "$local_url=/points")
run_check "websockets deflate" "$python" "$here/deflate_check.py" "${deflate_urls[@]}" --points "$points"
run_check "roslib deflate" node "$here/deflate_roslib_check.mjs" "${deflate_urls[@]}" --points "$points"
# ROS 1 actions over topics, roslibpy 1.8's client and server on the hub (issue 56).
run_check "roslibpy 1.8 actionlib hub" "$python1" "$here/actionlib_check.py" --url "$hub_url"

# Both servers must have survived everything the clients did.
for pid in "${pids[@]}"; do
    kill -0 "$pid" 2>/dev/null || failed+=("server process $pid died")
done

echo "rosbridge interop: ${#failed[@]} failure(s) in 8 client runs, $((SECONDS - started)) s"
if [ ${#failed[@]} -ne 0 ]; then
    echo "FAIL: ${failed[*]}" >&2
    exit 1
fi
echo "PASS: rosbridge interop (roslibpy + roslib, hub + local listener)"

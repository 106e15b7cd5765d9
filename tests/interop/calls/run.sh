#!/usr/bin/env bash
# Services and actions interop suite: real roslibpy (PyPI) and roslib (npm, under Node)
# clients calling services and sending action goals through a fleetlink hub and an
# agent's local rosbridge listener.
#
# Starts a hub and one agent (robot1, simulator, local listener); the simulator offers
# /robot1/set_mode, /robot1/get_status and the action /robot1/navigate_to_pose. Waits
# until robot1 is online and /robot1/set_mode is listed by /rosapi/services (15 s), then
# runs calls_check.py (roslibpy + raw WebSocket clients) and calls_check.mjs (roslib),
# each under a timeout, and exits non-zero if any check failed. Every process started
# here is stopped on exit (trap), also on failure. The whole suite stays under 3 minutes.
#
# Env: FLEETLINK_BIN (default: target/release/fleetlink), PYTHON (default: .venv/bin/python).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
bin="${FLEETLINK_BIN:-$root/target/release/fleetlink}"
python="${PYTHON:-$root/.venv/bin/python}"
robot=robot1
op_name=interop
viewer_name=viewer
started=$SECONDS

[ -x "$bin" ] || { echo "FAIL: fleetlink binary not found at $bin (set FLEETLINK_BIN)" >&2; exit 1; }
[ -x "$python" ] || { echo "FAIL: $python missing; run scripts/setup.d/10-python-venv.sh" >&2; exit 1; }
# roslib is shared with the rosbridge suite (one node_modules, installed there).
[ -d "$here/../rosbridge/node_modules/roslib" ] || { echo "FAIL: roslib missing; run scripts/setup.d/20-node-packages.sh" >&2; exit 1; }

# shellcheck source=../lib.sh
. "$here/../lib.sh"
interop_begin calls

# --- credentials, minted in the hub's database before it starts (fleetlink admin):
# the robot, an admin operator, and a user outside admin with no rules (may call nothing).
admin() { timeout 30 "$bin" admin --data-dir "$tmp/hub-data" "$@"; }
robot_token="$(admin token robot "$robot")"
op_token="$(admin token operator "$op_name" --group admin)"
viewer_token="$(admin token operator "$viewer_name")"
# Robots may call only their own namespace by default; this fleet lets them call the
# cloud's services (what a deployment writes in its rules file).
admin rules import - >/dev/null <<'RULES'
rules:
  - subject: any_robot
    names: "/cloud/.*"
    ops: [call_service, send_action_goal]
RULES

# --- hub (log files exist before the background start, so the reader never races them)
: >"$tmp/hub.log"; : >"$tmp/agent.log"
"$bin" hub --listen 127.0.0.1:0 --data-dir "$tmp/hub-data" >"$tmp/hub.log" 2>&1 &
pids+=($!)
hub_addr="$(wait_for_line "$tmp/hub.log" '^fleetlink hub listening on ([0-9.:]+)$' "hub start" "${pids[0]}")"
# Clients authenticate the way browsers do: the token in the URL.
hub_url="ws://$hub_addr/?token=$op_token"
viewer_url="ws://$hub_addr/?token=$viewer_token"
echo "hub: ws://$hub_addr/ (tokens in the URL)"

# --- agent: the simulator (odometry only; its services and action come with it)
cat >"$tmp/agent.yaml" <<EOF
hub: ws://$hub_addr/
name: $robot
token: $robot_token
local_rosbridge: { listen: 127.0.0.1:0 }
sim:
  odometry: { rate_hz: 10 }
EOF
"$bin" agent --name "$robot" --config "$tmp/agent.yaml" --local-listen 127.0.0.1:0 >"$tmp/agent.log" 2>&1 &
pids+=($!)
local_addr="$(wait_for_line "$tmp/agent.log" '^  local rosbridge: ws://([0-9.:]+)/$' "agent start" "${pids[1]}")"
local_url="ws://$local_addr/"
echo "agent $robot local rosbridge: $local_url"

# --- ready: robot1 online, and its services listed by /rosapi/services (bounded: 15 s)
timeout 30 "$python" - "$hub_addr" "$robot" "$op_token" <<'EOF'
import json, sys, time, urllib.request
from websockets.sync.client import connect
addr, robot, token = sys.argv[1], sys.argv[2], sys.argv[3]
want = f"/{robot}/set_mode"
deadline, last = time.monotonic() + 15, None

def services():
    with connect(f"ws://{addr}/?token={token}", open_timeout=2, close_timeout=1) as ws:
        ws.send(json.dumps({"op": "call_service", "id": "ready", "service": "/rosapi/services", "args": {}}))
        end = time.monotonic() + 2
        while time.monotonic() < end:
            m = json.loads(ws.recv(timeout=max(0.01, end - time.monotonic())))
            if m.get("op") == "service_response" and m.get("id") == "ready":
                return m
    return "no service_response within 2 s"

while time.monotonic() < deadline:
    try:
        req = urllib.request.Request(f"http://{addr}/api/v1/robots",
                                     headers={"Authorization": f"Bearer {token}"})
        with urllib.request.urlopen(req, timeout=2) as r:
            me = [x for x in json.load(r)["robots"] if x["name"] == robot]
        if not (me and me[0]["online"]):
            last = f"{robot} not online: {me}"
        else:
            m = services()
            v = m.get("values") if isinstance(m, dict) else None
            names = v.get("services", []) if isinstance(v, dict) else []
            if want in names:
                print(f"ready: {robot} online, /rosapi/services lists {sorted(n for n in names if n.startswith(f'/{robot}/'))}")
                sys.exit(0)
            last = f"/rosapi/services without {want}: {str(m)[:400]}"
    except Exception as e:  # not up yet
        last = repr(e)
    time.sleep(0.2)
print(f"FAIL: {want} not listed within 15 s; last: {last}", file=sys.stderr)
sys.exit(1)
EOF

# --- the clients: each run is bounded (timeout), failures are collected, not fatal
failed=()
run_check() {
    local name=$1 limit=$2; shift 2
    echo "== $name"
    local rc=0
    timeout --kill-after=5 "$limit" "$@" || rc=$?
    if [ "$rc" -eq 124 ] || [ "$rc" -eq 137 ]; then
        echo "FAIL $name: killed after ${limit} s"
    fi
    if [ "$rc" -ne 0 ]; then failed+=("$name"); fi
}
common=(--hub-url "$hub_url" --local-url "$local_url" --robot "$robot" --viewer-url "$viewer_url"
        --api "$hub_addr" --op-token "$op_token" --op-name "$op_name" --viewer-name "$viewer_name")
run_check "roslibpy calls" 80 "$python" "$here/calls_check.py" "${common[@]}"
run_check "roslib calls" 40 node "$here/calls_check.mjs" "${common[@]}"

# Both servers must have survived everything the clients did.
for pid in "${pids[@]}"; do
    kill -0 "$pid" 2>/dev/null || failed+=("server process $pid died")
done

echo "calls interop: ${#failed[@]} failure(s), $((SECONDS - started)) s"
if [ ${#failed[@]} -ne 0 ]; then
    echo "FAIL: ${failed[*]}" >&2
    exit 1
fi
echo "PASS: calls interop (services and actions; roslibpy + roslib, hub + local listener)"

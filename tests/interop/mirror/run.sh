#!/usr/bin/env bash
# Mirror interop suite (issue 40, item 4): a robot's nodes offloaded to the cloud,
# unmodified. Real `fleetlink hub` and `fleetlink agent` processes; the ROS 2 nodes are
# Cyclone DDS participants (Python binding, ROS 2 names and CDR) in two graphs that cannot
# see each other: two network namespaces, each with DDS on its own loopback, joined by a
# veth pair with multicast off (the robot's radio link to the cloud).
#
#   robot namespace (10.203.0.1): the hub; robot1's agent (the simulated robot's
#     /scan, sensor_msgs/LaserScan at 10 Hz, and a ROS 2 bridge writing the hub's /map
#     into the robot's graph); a Cyclone reader of /map (nav_msgs/OccupancyGrid).
#   cloud namespace (10.203.0.2): `fleetlink agent --mirror robot1` with a credential of
#     its own (a robot token for robot1_mirror, and a rule letting it act under /robot1
#     only) and a ROS 2 bridge (`read: [".*"]`, `publish: [/map]`); two Cyclone nodes
#     reading /scan, the first publishing /map.
#
# Checks:
#   1. before any cloud node reads it, /robot1/scan is idle at the hub: the robot sends
#      none of it;
#   2. both cloud nodes receive the robot's /scan under its own name, 720 ranges each;
#   3. meanwhile the hub receives /scan at the simulator's rate (once, not once per
#      cloud node) and has one subscriber of it besides the robot's own link: the mirror;
#   4. the cloud node's /map reaches the robot's graph as /map, every field equal;
#   5. the cloud nodes gone, /robot1/scan is idle again within 20 s (the nodes' process
#      ends without a goodbye, so the mirror's DDS participant drops their readers when
#      their lease runs out, about 10 s).
#
# Needs root (network namespaces): fails otherwise, as CI runs it as root. Bounded: about
# 40 s; every process runs under `timeout` in this run's own namespaces, killed on exit.
#
# Env: FLEETLINK_BIN (default target/release/fleetlink), PYTHON (default .venv/bin/python
# with cyclonedds: scripts/setup.d/10-python-venv.sh, 35-ros2-peers.sh).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
bin="${FLEETLINK_BIN:-$root/target/release/fleetlink}"
python="${PYTHON:-$root/.venv/bin/python}"
export ROS_DOMAIN_ID=24 PYTHONDONTWRITEBYTECODE=1 NO_COLOR=1
unset ROS_DISTRO

[ -x "$bin" ] || { echo "FAIL: fleetlink binary not found at $bin (set FLEETLINK_BIN)" >&2; exit 1; }
[ -x "$python" ] || { echo "FAIL: $python missing; run scripts/setup.d/10-python-venv.sh" >&2; exit 1; }
"$python" -c 'import cyclonedds.domain' 2>/dev/null \
    || { echo "FAIL: $python lacks cyclonedds; run scripts/setup.d/35-ros2-peers.sh" >&2; exit 1; }
[ "$(id -u)" -eq 0 ] || { echo "FAIL: the mirror suite needs root for its network namespaces" >&2; exit 1; }
command -v ip >/dev/null || { echo "FAIL: \`ip\` (iproute2) missing; run scripts/setup.d/35-ros2-peers.sh" >&2; exit 1; }
bin="$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")"

# shellcheck source=../lib.sh
. "$here/../lib.sh"
interop_begin mirror

run_id="$$"
robot_ns="flmr-$run_id"
cloud_ns="flmc-$run_id"
mirror_cleanup() {
    local rc=$?
    if [ "$rc" -ne 0 ] && [ -f "$tmp/mirror.log" ]; then
        echo "--- last lines of the mirror's log" >&2; tail -n 30 "$tmp/mirror.log" >&2
    fi
    (exit "$rc")
    interop_cleanup
}
trap mirror_cleanup EXIT
interop_netns "$robot_ns"
interop_netns "$cloud_ns"
ip link add "flm${run_id}a" type veth peer name "flm${run_id}b"
ip link set "flm${run_id}a" netns "$robot_ns"
ip link set "flm${run_id}b" netns "$cloud_ns"
ip netns exec "$robot_ns" ip addr add 10.203.0.1/30 dev "flm${run_id}a"
ip netns exec "$cloud_ns" ip addr add 10.203.0.2/30 dev "flm${run_id}b"
ip netns exec "$robot_ns" ip link set "flm${run_id}a" up multicast off
ip netns exec "$cloud_ns" ip link set "flm${run_id}b" up multicast off

in_robot() { ip netns exec "$robot_ns" timeout --kill-after=5 "$@"; }
in_cloud() { ip netns exec "$cloud_ns" timeout --kill-after=5 "$@"; }
failed=()
fail() { echo "FAIL: $*"; failed+=("$*"); }
step() { echo "== $1"; }

# --- the hub, its credentials and the mirror's rule
admin() { in_robot 30 "$bin" admin --data-dir "$tmp/hub-data" "$@"; }
robot_token="$(admin token robot robot1)"
admin token robot robot1_mirror >"$tmp/mirror.token"
op_token="$(admin token operator interop --group admin)"
admin rules import - >/dev/null <<'RULES'
rules:
  - subject: {robot: robot1_mirror}
    names: "/robot1(/.*)?"
    ops: [publish, subscribe, call_service, send_action_goal]
RULES
in_robot 120 "$bin" hub --listen 0.0.0.0:0 --data-dir "$tmp/hub-data" >"$tmp/hub.log" 2>&1 &
pids+=($!)
port="$(wait_for_line "$tmp/hub.log" '^fleetlink hub listening on [0-9.]+:([0-9]+)$' "hub start" "${pids[-1]}")"
api="http://127.0.0.1:$port"
hub_topic() { in_robot 10 "$python" "$here/mirror_peer.py" hub-topic "$api" "$op_token" "$1"; }
# A field of the hub's entry for /robot1/scan: scan_field EXPR (`t` is the entry).
scan_field() {
    hub_topic /robot1/scan | in_robot 10 "$python" -c 'import json,sys; t=json.load(sys.stdin); print(eval(sys.argv[1]) if t else "absent")' "$1"
}

# --- robot1: the simulated robot's laser, and /map written into its graph
cat >"$tmp/robot.yaml" <<EOF
hub: ws://127.0.0.1:$port
name: robot1
token: $robot_token
local_rosbridge: null
sim: { laser_scan: {} }
ros2:
  subscribe: [/map]
EOF
in_robot 120 "$bin" agent --config "$tmp/robot.yaml" >"$tmp/agent.log" 2>&1 &
pids+=($!)
wait_for_line "$tmp/agent.log" '(connected to hub)' "robot1's agent connecting" "${pids[-1]}" >/dev/null

# --- the mirror in the cloud, from the command line and a short file
cat >"$tmp/mirror.yaml" <<EOF
local_rosbridge: null
ros2:
  read: [".*"]
  publish: [/map]
EOF
in_cloud 120 "$bin" agent --mirror robot1 --hub "ws://10.203.0.1:$port" \
    --token-file "$tmp/mirror.token" --config "$tmp/mirror.yaml" >"$tmp/mirror.log" 2>&1 &
pids+=($!)
wait_for_line "$tmp/mirror.log" '(connected to hub)' "the mirror connecting" "${pids[-1]}" >/dev/null
grep -q 'namespace=/robot1' "$tmp/mirror.log" || fail "the mirror's namespace is not /robot1: $(grep -m1 'connected to hub' "$tmp/mirror.log")"

step "1. nobody in the cloud reads /scan: the robot holds it back"
for _ in $(seq 50); do [ "$(scan_field 't["state"]')" = idle ] && break; sleep 0.1; done
sleep 1
state="$(scan_field '(t["state"], t["messages"])')"
[ "$state" = "('idle', 0)" ] && echo "ok: /robot1/scan at the hub: $state" \
    || fail "before any cloud node: /robot1/scan at the hub is $state, not idle with no messages"

step "2-4. two cloud nodes read /scan; one publishes /map"
in_robot 60 "$python" "$here/mirror_peer.py" robot-listen "$tmp/robot_got.json" 40 >"$tmp/robot-listen.log" 2>&1 &
pids+=($!)
listen_pid=${pids[-1]}
wait_for_line "$tmp/robot-listen.log" '^(ready)$' "the robot's /map reader" "$listen_pid" >/dev/null
in_cloud 60 "$python" "$here/mirror_peer.py" cloud-nodes "$tmp/cloud_got.json" 25 >"$tmp/cloud.log" 2>&1 &
pids+=($!)
cloud_pid=${pids[-1]}
wait_for_line "$tmp/cloud.log" '^(ready)$' "the cloud nodes" "$cloud_pid" >/dev/null
# The hub's count of /scan over two seconds while the cloud reads it.
for _ in $(seq 100); do [ "$(scan_field 't["state"]')" = flowing ] && break; sleep 0.1; done
m0="$(scan_field 't["messages"]')"; t0=$(date +%s.%N)
sleep 2
m1="$(scan_field 't["messages"]')"; t1=$(date +%s.%N)
# The listing is read until it shows the robot's link and the mirror (bounded, 5 s): in two
# full runs of the test command it once lacked one of them right after the rate was
# measured, while the scan flowed to the mirror (not understood yet, docs/testing.md).
for _ in $(seq 50); do
    subs="$(scan_field 'sorted(t["subscribers"])')"
    [ "$subs" = "['/robot1', '/robot1_mirror']" ] && break
    echo "note: /robot1/scan's subscribers at the hub: $subs; $(hub_topic /robot1/scan | head -c 600)"
    sleep 0.1
done
wait "$cloud_pid" || fail "the cloud nodes ended with an error: $(tail -n 5 "$tmp/cloud.log")"
touch "$tmp/robot_got.json.stop"
wait "$listen_pid" || fail "the robot's /map reader ended with an error: $(tail -n 5 "$tmp/robot-listen.log")"
check() { in_robot 10 "$python" - "$@"; }
check "$tmp/cloud_got.json" <<'PY' || fail "step 2: the cloud nodes did not both get the robot's /scan"
import json, sys
g = json.load(open(sys.argv[1]))
print(f"cloud nodes: scans {g['scans']}, ranges per scan {g['ranges']}, maps sent {g['maps_sent']}")
sys.exit(0 if min(g["scans"]) >= 20 and g["ranges"] == [[720], [720]] else 1)
PY
rate="$(in_robot 10 "$python" -c "print(round(($m1 - $m0) / ($t1 - $t0), 1))")"
echo "hub: /robot1/scan at $rate msg/s while two cloud nodes read it; subscribers $subs"
in_robot 10 "$python" -c "import sys; sys.exit(0 if 6 <= $rate <= 14 else 1)" \
    || fail "step 3: the hub received /scan at $rate msg/s, not the simulator's 10 once"
[ "$subs" = "['/robot1', '/robot1_mirror']" ] \
    || fail "step 3: /robot1/scan's subscribers at the hub are $subs, not the robot's link and the mirror"
check "$tmp/robot_got.json" <<'PY' || fail "step 4: the cloud node's /map did not reach the robot's graph whole"
import json, sys
g = json.load(open(sys.argv[1]))["maps"]
print(f"robot's graph: {len(g)} maps on /map")
ok = bool(g)
for m in g:
    n = (m["data"][0]) % 100
    want = [(i + n) % 100 for i in range(16 * 8)]
    ok &= (m["width"], m["height"], m["frame"], m["resolution"], m["origin_y"]) == (16, 8, "map", 0.05, -2.0)
    ok &= m["data"] == want
sys.exit(0 if ok else 1)
PY

step "5. the cloud nodes gone: the robot holds /scan back again"
idle=""
for _ in $(seq 200); do
    [ "$(scan_field 't["state"]')" = idle ] && { idle=1; break; }
    sleep 0.1
done
if [ -n "$idle" ]; then
    a="$(scan_field 't["messages"]')"; sleep 1; b="$(scan_field 't["messages"]')"
    [ "$a" = "$b" ] && echo "ok: /robot1/scan idle again, $b messages in all" \
        || fail "step 5: /robot1/scan is idle but still grew from $a to $b in a second"
else
    fail "step 5: /robot1/scan still $(scan_field 't["state"]') 20 s after the cloud nodes left"
fi
grep -q "INFO fleetlink_hub::agents: robot robot1 reconnected" "$tmp/hub.log" && fail "the mirror replaced robot1's own link"
grep -q "panicked" "$tmp/hub.log" "$tmp/agent.log" "$tmp/mirror.log" && fail "a fleetlink process panicked (see its log)"

if [ ${#failed[@]} -ne 0 ]; then
    echo "mirror suite: ${#failed[@]} check(s) failed" >&2
    exit 1
fi
echo "mirror suite: all checks passed"

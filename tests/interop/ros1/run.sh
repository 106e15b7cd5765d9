#!/usr/bin/env bash
# ROS 1 bridge interop suite: Debian's ROS 1 (roscore, rospy, rostopic, rosservice) on the
# robot side of a fleetlink agent, roslibpy clients on the hub side.
#
# Starts roscore (a free port), a hub, the robot's rospy node (ros_peer.py graph), the agent
# with a `ros1:` section, and a hub-side roslibpy process (hub_peer.py serve); then checks:
#   1. rospy LaserScan, PointCloud2 (100k points) and a custom type from a temporary
#      package (generated with genpy) arrive at a roslibpy subscriber with equal values;
#      rospy services (std_srvs/SetBool, AddTwoInts) answer roslibpy calls at the hub;
#   2. roslibpy's /<robot>/cmd_vel reaches the rospy subscriber; `rostopic echo -n 1` sees
#      a latched hub topic published before it started; `rosservice call` reaches a fleet
#      service advertised on the hub;
#   2a. a rospy subscriber waiting for /oneshot gets the hub's single message of it;
#   2b. rosapi's parameter services at the hub reach the robot's master for /<robot>/...
#      names (rosparam sets them on the robot, roslibpy reads, changes, searches and
#      deletes them at the hub; rosparam sees the change);
#   3. /chatter bridged both ways: every message is seen exactly once on each side (no
#      loop), counted on both sides;
#   4. a local subscriber asking for another type than the hub topic's is refused, the
#      agent's log names the topic and both types, so does its status topic at the hub
#      (/<robot>/fleetlink/diagnostics, ROS 1 part at WARN), and /cmd_vel keeps flowing;
#   5. roscore killed and restarted under the running agent: a publisher started afterwards
#      reaches the hub, and the agent's publication is registered again (`rostopic echo`);
#   6. that publisher restarted: the agent follows it (publisherUpdate) and data flows again;
#   7. a rospy camera (sensor_msgs/Image 640x480 rgb8, 15 Hz) offered as H.264 video: a
#      roslibpy viewer at the hub decodes every frame from the first with PyAV, and each
#      picture matches the scene its stamp names.
# Every step runs under `timeout`; every process started here is stopped on exit (trap).
# The whole suite stays under 3 minutes.
#
# Env: FLEETLINK_BIN (default: target/release/fleetlink), PYTHON (roslibpy; default
# .venv/bin/python). rospy runs with Debian's /usr/bin/python3.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
bin="${FLEETLINK_BIN:-$root/target/release/fleetlink}"
python="${PYTHON:-$root/.venv/bin/python}"
rospython=/usr/bin/python3
robot=robot1
started=$SECONDS

[ -x "$bin" ] || { echo "FAIL: fleetlink binary not found at $bin (set FLEETLINK_BIN)" >&2; exit 1; }
[ -x "$python" ] || { echo "FAIL: $python missing; run scripts/setup.d/10-python-venv.sh" >&2; exit 1; }
for tool in roscore rostopic rosservice; do
    command -v "$tool" >/dev/null || { echo "FAIL: $tool missing; run scripts/setup.d/50-ros1.sh" >&2; exit 1; }
done

# shellcheck source=../lib.sh
. "$here/../lib.sh"
interop_begin ros1

failed=()
fail() { echo "FAIL: $*"; failed+=("$*"); }

# --- the ROS environment: a private master port, logs and home in $tmp
free_port() { "$rospython" -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])'; }
master_port="$(free_port)"
export ROS_MASTER_URI="http://127.0.0.1:$master_port" ROS_HOSTNAME=127.0.0.1
export ROS_HOME="$tmp/ros" ROS_LOG_DIR="$tmp/ros/log"
mkdir -p "$ROS_LOG_DIR"

start_roscore() {
    : >"$tmp/roscore.log"
    roscore -p "$master_port" >"$tmp/roscore.log" 2>&1 &
    roscore_pid=$!
    pids+=("$roscore_pid")
    for _ in $(seq 100); do
        timeout 5 "$rospython" -c "import rosgraph,sys; sys.exit(0 if rosgraph.Master('/probe').is_online() else 1)" 2>/dev/null && return 0
        sleep 0.1
    done
    echo "FAIL: roscore did not come up" >&2; tail -n 20 "$tmp/roscore.log" >&2; return 1
}
start_roscore
echo "roscore: $ROS_MASTER_URI"

# --- a message package that exists only here: genpy classes for the rospy side. Neither
# the agent nor the hub has its definition; they learn it from the TCPROS header.
# AddTwoInts is generated as example_interfaces (the name the bundled registry knows it
# by): ROS 1 service connections carry no definitions, so service types must be known.
pkg="$tmp/src/fltest_msgs"; gen="$tmp/py"
mkdir -p "$pkg/msg" "$tmp/src/example_interfaces/srv"
printf 'float64 weight\nbool ok\n' >"$pkg/msg/Inner.msg"
printf '# A type only this suite knows.\nstring label\nint32[] values\ntime stamp\nInner inner\nInner[] more\n' >"$pkg/msg/Custom.msg"
printf 'int64 a\nint64 b\n---\nint64 sum\n' >"$tmp/src/example_interfaces/srv/AddTwoInts.srv"
timeout 30 "$rospython" /usr/lib/genpy/genmsg_py.py -p fltest_msgs -Ifltest_msgs:"$pkg/msg" -o "$gen/fltest_msgs/msg" "$pkg/msg/Inner.msg" "$pkg/msg/Custom.msg"
timeout 30 "$rospython" /usr/lib/genpy/genmsg_py.py --initpy -p fltest_msgs -o "$gen/fltest_msgs/msg"
timeout 30 "$rospython" /usr/lib/genpy/gensrv_py.py -p example_interfaces -o "$gen/example_interfaces/srv" "$tmp/src/example_interfaces/srv/AddTwoInts.srv"
timeout 30 "$rospython" /usr/lib/genpy/gensrv_py.py --initpy -p example_interfaces -o "$gen/example_interfaces/srv"
touch "$gen/fltest_msgs/__init__.py" "$gen/example_interfaces/__init__.py"
export PYTHONPATH="$gen${PYTHONPATH:+:$PYTHONPATH}"

# --- hub, with tokens; robots may call the cloud's services
admin() { timeout 30 "$bin" admin --data-dir "$tmp/hub-data" "$@"; }
robot_token="$(admin token robot "$robot")"
op_token="$(admin token operator interop --group admin)"
admin rules import - >/dev/null <<'RULES'
rules:
  - subject: any_robot
    names: "/cloud/.*"
    ops: [call_service, send_action_goal]
RULES
: >"$tmp/hub.log"; : >"$tmp/agent.log"
"$bin" hub --listen 127.0.0.1:0 --data-dir "$tmp/hub-data" >"$tmp/hub.log" 2>&1 &
pids+=($!)
hub_addr="$(wait_for_line "$tmp/hub.log" '^fleetlink hub listening on ([0-9.:]+)$' "hub start" "${pids[-1]}")"
hub_url="ws://$hub_addr/?token=$op_token"

# --- the robot's ROS node
"$rospython" "$here/ros_peer.py" graph "$tmp/ros_got.json" >"$tmp/graph.log" 2>&1 &
pids+=($!)
wait_for_line "$tmp/graph.log" '^(graph) ready$' "rospy graph node" "${pids[-1]}" >/dev/null

# --- the agent, bridging the graph
cat >"$tmp/agent.yaml" <<EOF
hub: ws://$hub_addr/
name: $robot
token: $robot_token
local_rosbridge: null
ros1:
  master_uri: $ROS_MASTER_URI
  publish:
    include: [/scan, /points, /custom, /chatter, /after_restart, /idle_points, /camera/image_raw]
  subscribe: [/cmd_vel, /announce, /chatter, /oneshot]
  services:
    expose: [/set_enabled, /add_two_ints]
    offer: ["/cloud/.*"]
video:
  /camera/image_raw: { topic: /camera/video, fps: 15, bitrate_kbps: 1500 }
EOF
"$bin" agent --config "$tmp/agent.yaml" >"$tmp/agent.log" 2>&1 &
pids+=($!)
agent_pid=${pids[-1]}

# --- the hub side: latched topic, fleet service, cmd_vel and chatter publishers
"$python" "$here/hub_peer.py" serve "$tmp/hub_got.json" --hub-url "$hub_url" --robot "$robot" >"$tmp/serve.log" 2>&1 &
pids+=($!)
wait_for_line "$tmp/serve.log" '^(serve) ready$' "hub serve" "${pids[-1]}" >/dev/null

step() { echo "== $1"; }

"$rospython" "$here/ros_peer.py" idle_cloud >"$tmp/idle_cloud.log" 2>&1 &
pids+=($!)
idle_cloud_pid=${pids[-1]}

step "1. robot -> hub: values and services"
timeout --kill-after=5 60 "$python" "$here/hub_peer.py" check-up --hub-url "$hub_url" --robot "$robot" || fail "check-up"

step "2. hub -> robot: cmd_vel, latched topic, fleet service"
got_cmd=""
for _ in $(seq 100); do
    got_cmd="$("$rospython" -c 'import json,sys; print(len(json.load(open(sys.argv[1]))["cmd_vel"]))' "$tmp/ros_got.json" 2>/dev/null || echo 0)"
    [ "${got_cmd:-0}" -gt 0 ] && break
    sleep 0.1
done
[ "${got_cmd:-0}" -gt 0 ] && echo "ok: rospy received /cmd_vel ($got_cmd messages)" || fail "/cmd_vel did not reach the rospy subscriber"
echo_out="$(timeout 20 rostopic echo -n 1 /announce 2>&1 || true)"
grep -q 'hello fleet' <<<"$echo_out" && echo "ok: rostopic echo -n 1 /announce saw the latched hub message" \
    || fail "rostopic echo /announce: $echo_out"
call_out="$(timeout 20 rosservice call /cloud/greet 2>&1 || true)"
grep -q 'hello from the fleet' <<<"$call_out" && echo "ok: rosservice call /cloud/greet reached the hub's service" \
    || fail "rosservice call /cloud/greet: $call_out"
info_out="$(timeout 20 rostopic info /announce 2>&1 || true)"
grep -q "fleetlink_$robot" <<<"$info_out" && echo "ok: rostopic info lists the agent as a publisher" \
    || fail "rostopic info /announce: $info_out"
node_out="$(timeout 20 rosnode info "/fleetlink_$robot" 2>&1 || true)"
grep -q '/cmd_vel' <<<"$node_out" && grep -q '/scan' <<<"$node_out" \
    && echo "ok: rosnode info shows the agent's publications and subscriptions" \
    || fail "rosnode info: $node_out"
hz_out="$(timeout 6 rostopic hz -w 5 /cmd_vel 2>&1 || true)"
grep -q 'average rate' <<<"$hz_out" && echo "ok: rostopic hz /cmd_vel: $(grep -m1 'average rate' <<<"$hz_out")" \
    || fail "rostopic hz /cmd_vel: $hz_out"

step "2a. a hub topic's first message reaches a rospy subscriber that was waiting for it"
"$rospython" "$here/ros_peer.py" oneshot >"$tmp/oneshot.log" 2>&1 &
pids+=($!)
oneshot_pid=${pids[-1]}
if wait_for_line "$tmp/oneshot.log" '^(oneshot) ready$' "the /oneshot subscriber" "$oneshot_pid" >/dev/null; then
    timeout --kill-after=5 30 "$python" "$here/hub_peer.py" publish-once --hub-url "$hub_url" --robot "$robot" || fail "publish-once (/oneshot)"
fi
if wait "$oneshot_pid"; then grep '^ok:' "$tmp/oneshot.log"; else cat "$tmp/oneshot.log"; fail "the first message of /oneshot"; fi

step "2b. parameters: the hub's rosapi reaches the robot's master"
timeout 20 rosparam set /max_speed 1.5 || fail "rosparam set /max_speed"
timeout 20 rosparam set /limits "{a: 1, b: [1, 2]}" || fail "rosparam set /limits"
timeout --kill-after=5 60 "$python" "$here/hub_peer.py" check-params --hub-url "$hub_url" --robot "$robot" \
    || fail "check-params"
speed="$(timeout 20 rosparam get /max_speed 2>&1 || true)"
[ "$speed" = "2.5" ] && echo "ok: rosparam get /max_speed on the robot sees the hub's set_param (2.5)" \
    || fail "rosparam get /max_speed after the hub's set_param: $speed"
if timeout 20 rosparam get /limits >/dev/null 2>&1; then fail "/limits still set on the robot after the hub's delete_param"
else echo "ok: /limits is deleted on the robot"; fi

step "3. /chatter both ways: no loop"
sleep 2 # both sides have been publishing for a while; the counters are written every 0.2 s
loop_report="$("$rospython" - "$tmp/ros_got.json" "$tmp/hub_got.json" <<'EOF'
import json, sys
ros = json.load(open(sys.argv[1]))["chatter"]
hub = json.load(open(sys.argv[2]))
problems = []
def dup(side, counts):
    return [f"{side} saw {k} {v} times" for k, v in counts.items() if v != 1]
problems += dup("rospy", ros) + dup("hub", hub)
robot_at_hub = sum(1 for k in hub if k.startswith("robot-"))
hub_at_robot = sum(1 for k in ros if k.startswith("hub-"))
if robot_at_hub < 5: problems.append(f"only {robot_at_hub} robot messages reached the hub")
if hub_at_robot < 5: problems.append(f"only {hub_at_robot} hub messages reached rospy")
print("; ".join(problems[:5]) if problems else f"ok: {robot_at_hub} robot->hub and {hub_at_robot} hub->robot chatter messages, each exactly once")
EOF
)"
case "$loop_report" in ok:*) echo "$loop_report" ;; *) fail "loop check: $loop_report" ;; esac

cmd_count() { "$rospython" -c 'import json,sys; print(len(json.load(open(sys.argv[1]))["cmd_vel"]))' "$tmp/ros_got.json" 2>/dev/null || echo 0; }

step "4. type mismatch on one topic"
before="$(cmd_count)"
timeout 20 "$rospython" "$here/ros_peer.py" wrongtype >"$tmp/wrongtype.log" 2>&1 || fail "wrongtype node: $(tail -n 3 "$tmp/wrongtype.log")"
mismatch="$(grep -m1 'type mismatch on /cmd_vel' "$tmp/agent.log" || true)"
if grep -q 'geometry_msgs/Twist' <<<"$mismatch" && grep -q 'std_msgs/String' <<<"$mismatch"; then
    echo "ok: the agent reported the mismatch naming both types"
else
    fail "no log line naming /cmd_vel and both types: '$mismatch'"
fi
grep -q unexpected "$tmp/wrongtype.log" && fail "the wrong-type subscriber received messages"
timeout --kill-after=5 40 "$python" "$here/hub_peer.py" check-status --hub-url "$hub_url" --robot "$robot" \
    || fail "check-status (the mismatch on the agent's status topic at the hub)"
after="$(cmd_count)"
[ "$after" -gt "$before" ] && echo "ok: /cmd_vel kept flowing ($before -> $after messages)" \
    || fail "/cmd_vel stopped during the mismatch ($before -> $after)"

step "4a. a topic nobody wants is not read from the graph"
# /idle_points (800 kB at 10 Hz) has had no viewer at the hub since the agent bridged it:
# after 10 s unwanted the agent closes its connection to the publisher (rospy's own bus
# info says so) and stops spending CPU on it; a viewer at the hub gets it again at once.
cpu_ticks() { awk '{print $14 + $15}' "/proc/$1/stat"; }
cpu_pct() { # pid seconds -> percent of one core over that window
    local a b; a="$(cpu_ticks "$1")"; sleep "$2"; b="$(cpu_ticks "$1")"
    echo "$(( (b - a) * 100 / ($(getconf CLK_TCK) * $2) ))"
}
connected() { timeout 20 "$rospython" "$here/ros_peer.py" connected /idle_cloud /idle_points "/fleetlink_$robot" 2>/dev/null || echo "?"; }
if wait_for_line "$tmp/agent.log" '.*(nobody wants /idle_points); no longer reading it.*' "the agent pausing /idle_points" "$agent_pid" >/dev/null; then
    echo "ok: the agent stopped reading /idle_points (nobody at the hub wants it)"
    c="$(connected)"
    [ "$c" = no ] && echo "ok: rospy's bus info shows no connection from the agent on /idle_points"         || fail "rospy's /idle_cloud still lists a connection to the agent on /idle_points ($c)"
    paused_agent="$(cpu_pct "$agent_pid" 5)"; paused_pub="$(cpu_pct "$idle_cloud_pid" 5)"
    timeout --kill-after=5 40 "$python" "$here/hub_peer.py" check-resume --hub-url "$hub_url" --robot "$robot"         || fail "check-resume (/idle_points wanted again)"
    c="$(connected)"
    [ "$c" = yes ] && echo "ok: rospy's bus info shows the agent connected again on /idle_points"         || fail "no connection from the agent on /idle_points after a viewer came ($c)"
    echo "figures: CPU with /idle_points unwatched and not read: agent ${paused_agent} %, publisher ${paused_pub} % (see docs/benchmarks/log.md, \"Reading only what is wanted\", for the comparison with reading it)"
else
    fail "the agent did not stop reading /idle_points: $(grep -m3 idle_points "$tmp/agent.log" || true)"
fi

step "5. roscore restart"
kill -TERM "$roscore_pid"; wait "$roscore_pid" 2>/dev/null || true
sleep 1
start_roscore
"$rospython" "$here/ros_peer.py" after >"$tmp/after.log" 2>&1 &
pids+=($!)
after_pid=${pids[-1]}
timeout --kill-after=5 40 "$python" "$here/hub_peer.py" check-after --hub-url "$hub_url" --robot "$robot" || fail "check-after"
echo_out="$(timeout 20 rostopic echo -n 1 /announce 2>&1 || true)"
grep -q 'hello fleet' <<<"$echo_out" && echo "ok: the agent's publication is registered with the new master" \
    || fail "rostopic echo /announce after the restart: $echo_out"

step "6. publisher restart"
kill -TERM "$after_pid"; wait "$after_pid" 2>/dev/null || true
"$rospython" "$here/ros_peer.py" after >"$tmp/after2.log" 2>&1 &
pids+=($!)
timeout --kill-after=5 40 "$python" "$here/hub_peer.py" check-after --hub-url "$hub_url" --robot "$robot" || fail "check-after (restarted publisher)"

step "7. a rospy camera's video decodes at the hub from the first frame"
# The camera outlives the watch and its decoding (which take longer on a loaded machine).
"$rospython" "$here/ros_peer.py" camera 40 >"$tmp/camera.log" 2>&1 &
pids+=($!)
camera_pid=${pids[-1]}
wait_for_line "$tmp/camera.log" '^(camera) ready$' "the rospy camera" "$camera_pid" >/dev/null
timeout --kill-after=5 40 "$python" "$root/tests/interop/video/video_peer.py" watch "$hub_url" \
    "/$robot/camera/video" 6 --min-frames 20 --scene || fail "the rospy camera's video (see above)"
kill -TERM "$camera_pid" 2>/dev/null || true
wait "$camera_pid" 2>/dev/null || true

kill -0 "$agent_pid" 2>/dev/null || fail "the agent died"
echo "ros1 interop: ${#failed[@]} failure(s), $((SECONDS - started)) s"
if [ ${#failed[@]} -ne 0 ]; then
    echo "FAIL: ${failed[*]}" >&2
    for f in graph serve roscore; do echo "--- $f log" >&2; tail -n 15 "$tmp/$f.log" >&2 || true; done
    exit 1
fi
echo "PASS: ros1 interop (rospy/rostopic/rosservice <-> agent <-> hub <-> roslibpy)"

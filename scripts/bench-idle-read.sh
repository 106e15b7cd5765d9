#!/usr/bin/env bash
# The robot-side CPU of a ROS 1 topic nobody watches: an 800 kB PointCloud2 at 10 Hz
# (rospy, tests/interop/ros1/ros_peer.py idle_cloud) bridged by the agent to a hub where
# nobody subscribes. For the first 10 s the agent still reads it (connected to the
# publisher, nothing sent up); then it stops reading (the bridge's pause after 10 s
# unwanted). CPU of the agent and of the publisher, from /proc, over a window of each
# phase; repeated ROUNDS times with fresh processes.
#
# Usage: scripts/bench-idle-read.sh [ROUNDS] (default 3). Needs Debian's ROS 1
# (scripts/setup.d/50-ros1.sh). Env: FLEETLINK_BIN (default target/release/fleetlink).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
bin="${FLEETLINK_BIN:-$root/target/release/fleetlink}"
rounds="${1:-3}"
peer="$root/tests/interop/ros1/ros_peer.py"
. "$root/tests/interop/lib.sh"
interop_begin idle-read

free_port() { python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])'; }
cpu_ticks() { awk '{print $14 + $15}' "/proc/$1/stat"; }
window=5
tck="$(getconf CLK_TCK)"
pct() { python3 -c "print(f'{($2 - $1) * 100 / ($tck * $window):.1f}')"; }

echo "| round | agent, read (%) | agent, not read (%) | publisher, read (%) | publisher, not read (%) |"
echo "|---|---|---|---|---|"
for round in $(seq "$rounds"); do
    port="$(free_port)"
    export ROS_MASTER_URI="http://127.0.0.1:$port" ROS_HOSTNAME=127.0.0.1 ROS_HOME="$tmp/ros$round" ROS_LOG_DIR="$tmp/ros$round/log"
    mkdir -p "$ROS_LOG_DIR"
    roscore -p "$port" >"$tmp/roscore$round.log" 2>&1 &
    pids+=($!)
    for _ in $(seq 100); do
        /usr/bin/python3 -c "import rosgraph,sys; sys.exit(0 if rosgraph.Master('/p').is_online() else 1)" 2>/dev/null && break
        sleep 0.1
    done
    data="$tmp/hub$round"
    token="$("$bin" admin --data-dir "$data" token robot robot1)"
    "$bin" hub --listen 127.0.0.1:0 --data-dir "$data" >"$tmp/hub.log" 2>&1 &
    pids+=($!)
    hub_addr="$(wait_for_line "$tmp/hub.log" '^fleetlink hub listening on ([0-9.:]+)$' "hub start" "${pids[-1]}")"
    /usr/bin/python3 "$peer" idle_cloud >"$tmp/cloud$round.log" 2>&1 &
    pids+=($!); pub=${pids[-1]}
    cat >"$tmp/agent.yaml" <<YAML
hub: ws://$hub_addr/
name: robot1
token: $token
local_rosbridge: null
ros1:
  master_uri: $ROS_MASTER_URI
  publish: { include: [/idle_points] }
YAML
    : >"$tmp/agent.log"
    "$bin" agent --config "$tmp/agent.yaml" >"$tmp/agent.log" 2>&1 &
    pids+=($!); agent=${pids[-1]}
    for _ in $(seq 300); do grep -q 'bridging /idle_points' "$tmp/agent.log" && break; sleep 0.05; done
    sleep 1.5 # connected and reading
    a0="$(cpu_ticks "$agent")"; p0="$(cpu_ticks "$pub")"; sleep "$window"
    a1="$(cpu_ticks "$agent")"; p1="$(cpu_ticks "$pub")"
    for _ in $(seq 300); do grep -q 'no longer reading it' "$tmp/agent.log" && break; sleep 0.05; done
    sleep 1
    a2="$(cpu_ticks "$agent")"; p2="$(cpu_ticks "$pub")"; sleep "$window"
    a3="$(cpu_ticks "$agent")"; p3="$(cpu_ticks "$pub")"
    echo "| $round | $(pct "$a0" "$a1") | $(pct "$a2" "$a3") | $(pct "$p0" "$p1") | $(pct "$p2" "$p3") |"
    for pid in "${pids[@]}"; do kill -TERM "$pid" 2>/dev/null || true; done
    for pid in "${pids[@]}"; do wait "$pid" 2>/dev/null || true; done
    pids=()
done

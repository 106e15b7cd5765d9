#!/usr/bin/env bash
# Robot-side cost of bridging a ROS 2 PointCloud2 stream (issue 11's benchmark): a Cyclone
# DDS node writes ~1 MB sensor_msgs/msg/PointCloud2 at 10 Hz on /points; the fleetlink
# agent (ros2: publish /points) carries it to a hub, where a rosbridge client measures
# latency from header.stamp. Side by side, in the same run and from the same DDS writer,
# a rosbridge-style bridge (decode, JSON with base64 data, WebSocket) feeds its own client.
# Reports each bridge's CPU (% of one core, from /proc/<pid>/stat over the measured
# window) and memory (VmRSS at the end, VmHWM), and latency p50/p99.
# The floor under any bridge of this stream, in the same window: what Cyclone DDS's own (C)
# threads spend receiving it in a plain subscriber on the robot, plus what writing the
# same bytes from memory into a loopback TCP connection costs (`fleetlink bench
# copy-floor`, its sender thread).
#
#   cargo build --release -p fleetlink && sudo scripts/bench-ros2.sh [SECONDS] [POINTS]
#
# Runs in a network namespace of its own (DDS multicast stays in it): needs root.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
bin="${FLEETLINK_BIN:-$root/target/release/fleetlink}"
python="${PYTHON:-$root/.venv/bin/python}"
seconds="${1:-30}"
npoints="${2:-65536}"
[ -x "$bin" ] || { echo "build first: cargo build --release -p fleetlink" >&2; exit 1; }
[ "$(id -u)" -eq 0 ] || { echo "needs root (network namespace): sudo $0" >&2; exit 1; }
"$python" -c 'import cyclonedds, cbor2, websockets' 2>/dev/null \
    || { echo "run scripts/setup.d/35-ros2-peers.sh first" >&2; exit 1; }

tmp="$(mktemp -d "${TMPDIR:-/tmp}/fleetlink-bench-ros2.XXXXXX")"
ns="flbench2-$$"
pids=()
cleanup() {
    # Everything started runs inside the namespace: stop all of it, then remove it.
    for sig in TERM KILL; do
        ip netns pids "$ns" 2>/dev/null | xargs -r kill -s "$sig" 2>/dev/null || true
        [ "$sig" = TERM ] && sleep 1
    done
    for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done
    wait 2>/dev/null || true
    ip netns del "$ns" 2>/dev/null || true
    rm -rf "$tmp"
}
trap cleanup EXIT
ip netns add "$ns"
ip netns exec "$ns" ip link set lo up
ip netns exec "$ns" ip link set lo multicast on
ip netns exec "$ns" ip route add 224.0.0.0/4 dev lo
in_ns() { ip netns exec "$ns" "$@"; }
export ROS_DOMAIN_ID=42 PYTHONPATH="$root/tests/interop/ros2"
peer() { in_ns "$python" "$root/tests/interop/ros2/bench_peer.py" "$@"; }
wait_line() { # file pattern
    for _ in $(seq 200); do grep -q "$2" "$1" 2>/dev/null && return 0; sleep 0.05; done
    echo "timed out waiting for '$2' in $1" >&2; cat "$1" >&2; exit 1
}

robot_token="$("$bin" admin --data-dir "$tmp/hub" token robot robot1)"
op_token="$("$bin" admin --data-dir "$tmp/hub" token operator bench --group admin)"
in_ns "$bin" hub --listen 127.0.0.1:18081 --data-dir "$tmp/hub" >"$tmp/hub.log" 2>&1 &
pids+=($!)
wait_line "$tmp/hub.log" "listening on"
cat >"$tmp/agent.yaml" <<EOF
hub: ws://127.0.0.1:18081/
name: robot1
token: $robot_token
local_rosbridge: { listen: "127.0.0.1:18083" }
ros2:
  publish: { include: [/points] }
EOF
in_ns "$bin" agent --config "$tmp/agent.yaml" >"$tmp/agent.log" 2>&1 &
pids+=($!)
peer rosbridge-style --port 18082 >"$tmp/style.log" 2>&1 &
pids+=($!)
wait_line "$tmp/style.log" "ready"
peer publish --seconds "$((seconds + 8))" --points "$npoints" >"$tmp/pub.log" 2>&1 &
pids+=($!)
pub_pid=$!
# The bridges' pids inside the namespace are ordinary pids: find them by command line.
sleep 3
in_this_ns() { ip netns pids "$ns" | xargs -r ps -o pid=,args= -p | awk -v want="$1" 'index($0, want) {print $1; exit}'; }
agent_pid="$(in_this_ns "agent --config $tmp/agent.yaml")"
style_pid="$(in_this_ns "bench_peer.py rosbridge-style")"
[ -n "$agent_pid" ] && [ -n "$style_pid" ] || { echo "bridge processes not found" >&2; exit 1; }
peer hub-sub --url "ws://127.0.0.1:18081/?token=$op_token" --seconds "$seconds" >"$tmp/hubsub.log" 2>&1 &
pids+=($!)
hubsub=$!
# The floor: a Cyclone subscriber on the robot, no bridge at all.
# It outlives the window by a few seconds: its Cyclone threads are counted at both ends.
peer dds-sub --seconds "$((seconds + 5))" >"$tmp/ddssub.log" 2>&1 &
pids+=($!)
ddssub=$!
if [ -n "${LOCAL_PROBE:-}" ]; then peer hub-sub --url "ws://127.0.0.1:18083/" --topic /points --seconds "$seconds" >"$tmp/localsub.log" 2>&1 & pids+=($!); fi
peer style-sub --url "ws://127.0.0.1:18082/" --seconds "$seconds" >"$tmp/stylesub.log" 2>&1 &
pids+=($!)
stylesub=$!
wait_line "$tmp/hubsub.log" "ready"
wait_line "$tmp/stylesub.log" "ready"
wait_line "$tmp/ddssub.log" "ready"
dds_pid="$(in_this_ns "bench_peer.py dds-sub")"
[ -n "$dds_pid" ] || { echo "the Cyclone subscriber's process was not found" >&2; exit 1; }
# Writing the stream from memory to a loopback TCP connection: the least a bridge pays to
# hand the bytes on (the CDR of the cloud plus its header is a little over the data).
in_ns "$bin" bench copy-floor --size "$((npoints * 16 + 128))" --rate 10 --seconds "$seconds" --json \
    >"$tmp/copyfloor.log" 2>&1 &
pids+=($!)
copyfloor=$!

ticks() { awk '{print $14 + $15}' "/proc/$1/stat"; }
# The threads Cyclone DDS names itself (recv, tev, dq.builtins, ...), not the Python
# interpreter's, which carry the process's own name; the comm field may hold spaces.
# (0 for a thread that has just ended.)
thread_ticks() { sed 's/.*) //' "$1/stat" 2>/dev/null | awk '{t = $12 + $13} END {print t + 0}' || :; }
cyclone_ticks() {
    local main t sum=0
    main="$(cat "/proc/$1/comm")"
    for t in /proc/"$1"/task/*; do
        [ "$(cat "$t/comm" 2>/dev/null)" = "$main" ] && continue
        sum=$((sum + $(thread_ticks "$t")))
    done
    echo "$sum"
}
# The agent's rustdds threads (named "RustDDS ..."): its DDS side, beside the uplink.
rustdds_ticks() {
    local t sum=0
    for t in /proc/"$1"/task/*; do
        case "$(cat "$t/comm" 2>/dev/null)" in RustDDS*) sum=$((sum + $(thread_ticks "$t"))) ;; esac
    done
    echo "$sum"
}
hz="$(getconf CLK_TCK)"
t0=$(date +%s.%N); a0=$(ticks "$agent_pid"); s0=$(ticks "$style_pid"); d0=$(cyclone_ticks "$dds_pid")
r0=$(rustdds_ticks "$agent_pid")
wait "$hubsub" "$stylesub" || true
t1=$(date +%s.%N); a1=$(ticks "$agent_pid"); s1=$(ticks "$style_pid"); d1=$(cyclone_ticks "$dds_pid")
r1=$(rustdds_ticks "$agent_pid")
wait "$copyfloor" "$ddssub" || true
write_cpu="$(sed -n 's/.*"sender_cpu_percent":\([0-9.]*\).*/\1/p' "$tmp/copyfloor.log" | awk '{printf "%.2f", $1}')"
mem() { awk '/^VmRSS|^VmHWM/ {printf "%s %.1f MB  ", $1, $2/1024}' "/proc/$1/status"; }
cpu() { awk -v a="$1" -v b="$2" -v t0="$t0" -v t1="$t1" -v hz="$hz" 'BEGIN {printf "%.2f", 100 * (b - a) / hz / (t1 - t0)}'; }

size=$((npoints * 16))
echo "ROS 2 bridging, PointCloud2 of $npoints points ($size data bytes) at 10 Hz, ${seconds} s measured"
echo "machine: $(nproc) cores, $(awk -F: '/model name/ {print $2; exit}' /proc/cpuinfo | sed 's/^ *//')"
printf '%-34s cpu %6s %% of one core  %s latency %s\n' "fleetlink agent (+ hub)" "$(cpu "$a0" "$a1")" "$(mem "$agent_pid")" "$(tail -n1 "$tmp/hubsub.log")"
printf '%-34s cpu %6s %% of one core\n' "  its rustdds threads" "$(cpu "$r0" "$r1")"
printf '%-34s cpu %6s %% of one core  %s latency %s\n' "rosbridge-style Python bridge" "$(cpu "$s0" "$s1")" "$(mem "$style_pid")" "$(tail -n1 "$tmp/stylesub.log")"
printf '%-34s latency %s\n' "DDS subscriber on the robot (floor)" "$(tail -n1 "$tmp/ddssub.log")"
dds_cpu="$(cpu "$d0" "$d1")"
printf '%-34s cpu %6s %% of one core\n' "  its Cyclone DDS threads (C)" "$dds_cpu"
printf '%-34s cpu %6s %% of one core\n' "writing the stream to loopback TCP" "${write_cpu:--}"
[ -n "$write_cpu" ] && printf '%-34s cpu %6s %% of one core (agent / floor: %sx)\n' "floor for any bridge (sum)" \
    "$(awk -v a="$dds_cpu" -v b="$write_cpu" 'BEGIN {printf "%.2f", a + b}')" \
    "$(awk -v x="$(cpu "$a0" "$a1")" -v a="$dds_cpu" -v b="$write_cpu" 'BEGIN {if (a + b > 0) printf "%.1f", x / (a + b); else print "inf"}')"
# The publisher's own time from stamp to the end of write() is inside every latency above.
wait "$pub_pid" 2>/dev/null || true
printf '%-34s %s\n' "publisher: stamp -> write() done" "$(grep '"sent"' "$tmp/pub.log" | tail -n1)"
[ -n "${LOCAL_PROBE:-}" ] && echo "agent's local listener: $(tail -n1 "$tmp/localsub.log")"
grep -E "WARN|ERROR" "$tmp/agent.log" | head -n 5 || true

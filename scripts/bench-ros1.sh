#!/usr/bin/env bash
# Robot-side cost of bridging a ROS 1 PointCloud2 stream (issue 10's benchmark): a rospy
# node publishes ~1 MB sensor_msgs/PointCloud2 at 10 Hz on /points; the fleetlink agent
# (ros1: publish /points) carries it to a hub, where a rosbridge client (cbor-raw) measures
# latency from header.stamp. Side by side, in the same run and from the same publisher,
# rosbridge_suite's own ROS 1 server (rosbridge_websocket, run from its source with
# Debian's rospy) feeds a roslibpy client, and a plain rospy subscriber on the robot gives
# the floor. Reports each bridge's CPU (% of one core, utime+stime from /proc/<pid>/stat
# over the measured window), memory (VmRSS at the end, VmHWM), the CPU ratio, and latency
# p50/p99 of each path. A plain TCP relay of a stream of the same size and rate
# (`fleetlink bench copy-floor`) runs in the same window: the CPU no bridge can go below.
#
#   sudo ROSBRIDGE_SRC=/path/to/rosbridge_suite scripts/bench-ros1.sh [SECONDS] [POINTS]
#
# ROSBRIDGE_SRC is a checkout of rosbridge_suite's ROS 1 code (the `ros1` branch), or any
# git repository of rosbridge_suite (its ROSBRIDGE_REV, default `ros1`, is extracted into
# the bench's temp directory). Get it with
#   git clone -b ros1 https://github.com/RobotWebTools/rosbridge_suite
# Env: FLEETLINK_BIN (default target/release/fleetlink), PYTHON (venv with roslibpy,
# websockets, cbor2; default .venv/bin/python), ROSBRIDGE_COMPRESSION (`none`, the
# default: roslibpy's JSON; or `cbor-raw`: a websockets client asking rosbridge for raw
# ROS 1 bytes, as the hub side does), THREADS=1 (the agent's CPU per thread),
# HUB_LINK=down (the agent points at a port where no hub listens: its cost without the
# uplink, i.e. the ROS 1 side alone).
#
# Runs in a network namespace of its own (fixed ports stay private): needs root.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
here="$root/tests/interop/ros1"
bin="${FLEETLINK_BIN:-$root/target/release/fleetlink}"
python="${PYTHON:-$root/.venv/bin/python}"
rospython=/usr/bin/python3
seconds="${1:-30}"
npoints="${2:-65536}"
rb_compression="${ROSBRIDGE_COMPRESSION:-none}"
[ -x "$bin" ] || { echo "build first: cargo build --release -p fleetlink (or set FLEETLINK_BIN)" >&2; exit 1; }
[ "$(id -u)" -eq 0 ] || { echo "needs root (network namespace): sudo $0" >&2; exit 1; }
case "$rb_compression" in none|cbor-raw) ;; *) echo "ROSBRIDGE_COMPRESSION: none or cbor-raw" >&2; exit 1 ;; esac
"$python" -c 'import roslibpy, cbor2, websockets' 2>/dev/null \
    || { echo "$python lacks roslibpy/cbor2/websockets: run scripts/setup.d/10-python-venv.sh" >&2; exit 1; }
command -v roscore >/dev/null && "$rospython" -c 'import rospy, sensor_msgs.msg' 2>/dev/null \
    || { echo "ROS 1 missing: run scripts/setup.d/50-ros1.sh" >&2; exit 1; }
# rosbridge_server's imports (autobahn/twisted serve, tornado and bson are imported by its
# package), and the package.xml files its message loader asks rospkg for.
"$rospython" -c 'import tornado, twisted, autobahn, bson, PIL; bson.BSON' 2>/dev/null \
    && [ -f /usr/share/sensor_msgs/package.xml ] && [ -f /usr/share/std_msgs/package.xml ] \
    || { echo "rosbridge_server's dependencies missing: run scripts/bench-setup-rosbridge-ros1.sh" >&2; exit 1; }

tmp="$(mktemp -d "${TMPDIR:-/tmp}/fleetlink-bench-ros1.XXXXXX")"
ns="flbench1-$$"
cleanup() {
    # Everything started runs inside the namespace: stop all of it, then remove it.
    for sig in TERM KILL; do
        ip netns pids "$ns" 2>/dev/null | xargs -r kill -s "$sig" 2>/dev/null || true
        [ "$sig" = TERM ] && sleep 1
    done
    wait 2>/dev/null || true
    ip netns del "$ns" 2>/dev/null || true
    rm -rf "$tmp"
}
trap cleanup EXIT

# --- rosbridge_suite's ROS 1 source: a checkout, or extracted from a repository.
src="${ROSBRIDGE_SRC:-}"
if [ -z "$src" ]; then
    echo "set ROSBRIDGE_SRC to rosbridge_suite's ROS 1 source, e.g.:" >&2
    echo "  git clone -b ros1 https://github.com/RobotWebTools/rosbridge_suite /opt/rosbridge_suite" >&2
    echo "  sudo ROSBRIDGE_SRC=/opt/rosbridge_suite $0 $*" >&2
    exit 1
fi
# The ROS 1 code is the catkin one (the ROS 2 port on the default branch has the same
# file names, built with ament).
ros1_tree() { grep -q '<buildtool_depend>catkin</buildtool_depend>' "$1/rosbridge_server/package.xml" 2>/dev/null \
    && [ -f "$1/rosbridge_server/scripts/rosbridge_websocket.py" ]; }
rev=""
if ! ros1_tree "$src"; then
    rev="${ROSBRIDGE_REV:-ros1}"
    git_dir="$(git -C "$src" rev-parse --git-dir 2>/dev/null || true)"
    [ -n "$git_dir" ] || { echo "$src is neither rosbridge_suite's ROS 1 source nor a git repository" >&2; exit 1; }
    case "$git_dir" in /*) ;; *) git_dir="$src/$git_dir" ;; esac
    git --git-dir="$git_dir" rev-parse -q --verify "$rev^{commit}" >/dev/null \
        || rev="origin/$rev"
    mkdir -p "$tmp/rosbridge_suite"
    git --git-dir="$git_dir" archive "$rev" rosbridge_library rosbridge_server rosbridge_msgs \
        | tar -x -C "$tmp/rosbridge_suite" \
        || { echo "no ROS 1 rosbridge at $rev in $src (ROSBRIDGE_REV)" >&2; exit 1; }
    src="$tmp/rosbridge_suite"
fi
ros1_tree "$src" \
    || { echo "not rosbridge_suite's ROS 1 (catkin) code: ${ROSBRIDGE_SRC}${rev:+ at $rev} (use the ros1 branch)" >&2; exit 1; }
rb_version="$(sed -n 's:.*<version>\(.*\)</version>.*:\1:p' "$src/rosbridge_server/package.xml" | head -n1)"
# It is not catkin-built: generate the message classes it imports with genpy —
# rosbridge_msgs from its own .msg files, and rosauth's Authentication service (not
# packaged by Debian; imported unconditionally, used only with ~authenticate).
rbpy="$tmp/rosbridge_py"
gen() { "$rospython" "/usr/lib/genpy/gen$1_py.py" "${@:2}"; }
gen msg -p rosbridge_msgs -Irosbridge_msgs:"$src/rosbridge_msgs/msg" -Istd_msgs:/usr/share/std_msgs/msg \
    -o "$rbpy/rosbridge_msgs/msg" "$src"/rosbridge_msgs/msg/*.msg
gen msg --initpy -p rosbridge_msgs -o "$rbpy/rosbridge_msgs/msg"
mkdir -p "$tmp/rosauth"
printf 'string mac\nstring client\nstring dest\nstring rand\ntime t\nstring level\ntime end\n---\nbool authenticated\n' \
    >"$tmp/rosauth/Authentication.srv"
gen srv -p rosauth -o "$rbpy/rosauth/srv" "$tmp/rosauth/Authentication.srv"
gen srv --initpy -p rosauth -o "$rbpy/rosauth/srv"
touch "$rbpy/rosbridge_msgs/__init__.py" "$rbpy/rosauth/__init__.py"

# --- the namespace and the ROS environment in it
ip netns add "$ns"
ip netns exec "$ns" ip link set lo up
in_ns() { ip netns exec "$ns" "$@"; }
export ROS_MASTER_URI=http://127.0.0.1:11311 ROS_HOSTNAME=127.0.0.1
export ROS_HOME="$tmp/ros" ROS_LOG_DIR="$tmp/ros/log"
mkdir -p "$ROS_LOG_DIR"
wait_line() { # file pattern
    for _ in $(seq 300); do grep -q "$2" "$1" 2>/dev/null && return 0; sleep 0.05; done
    echo "timed out waiting for '$2' in $1" >&2; tail -n 20 "$1" >&2; exit 1
}
robot() { in_ns "$rospython" "$here/bench_robot.py" "$@"; }
client() { in_ns "$python" "$here/bench_clients.py" "$@"; }

in_ns roscore -p 11311 >"$tmp/roscore.log" 2>&1 &
master_up() { in_ns timeout 5 "$rospython" -c "import rosgraph,sys; sys.exit(0 if rosgraph.Master('/probe').is_online() else 1)" 2>/dev/null; }
for _ in $(seq 100); do master_up && break; sleep 0.1; done
master_up || { echo "roscore did not come up" >&2; tail -n 20 "$tmp/roscore.log" >&2; exit 1; }

robot_token="$("$bin" admin --data-dir "$tmp/hub" token robot robot1)"
op_token="$("$bin" admin --data-dir "$tmp/hub" token operator bench --group admin)"
in_ns "$bin" hub --listen 127.0.0.1:18081 --data-dir "$tmp/hub" >"$tmp/hub.log" 2>&1 &
wait_line "$tmp/hub.log" "listening on"
hub_url=ws://127.0.0.1:18081/
[ "${HUB_LINK:-up}" = down ] && hub_url=ws://127.0.0.1:18089/
cat >"$tmp/agent.yaml" <<EOF
hub: $hub_url
name: robot1
token: $robot_token
local_rosbridge: null
ros1:
  publish: { include: [/points] }
EOF
in_ns "$bin" agent --config "$tmp/agent.yaml" >"$tmp/agent.log" 2>&1 &
in_ns env PYTHONPATH="$rbpy:$src/rosbridge_library/src:$src/rosbridge_server/src" \
    "$rospython" "$src/rosbridge_server/scripts/rosbridge_websocket.py" --address 127.0.0.1 --port 19090 \
    >"$tmp/rosbridge.log" 2>&1 &
wait_line "$tmp/rosbridge.log" "WebSocket server started"
# Runs until the clients are done (stopped below); the bound is only a safety net.
robot publish --seconds "$((seconds + 60))" --points "$npoints" >"$tmp/pub.log" 2>&1 &
wait_line "$tmp/pub.log" "ready"
# The bridges' pids inside the namespace are ordinary pids: find them by command line.
sleep 3
in_this_ns() { ip netns pids "$ns" | xargs -r ps -o pid=,args= -p | awk -v want="$1" 'index($0, want) {print $1; exit}'; }
agent_pid="$(in_this_ns "agent --config $tmp/agent.yaml")"
rb_pid="$(in_this_ns "rosbridge_websocket.py")"
hub_pid="$(in_this_ns "hub --listen 127.0.0.1:18081")"
pub_pid="$(in_this_ns "bench_robot.py publish")"
[ -n "$agent_pid" ] && [ -n "$rb_pid" ] && [ -n "$hub_pid" ] && [ -n "$pub_pid" ] || { echo "bridge processes not found" >&2; tail "$tmp"/*.log >&2; exit 1; }

client cbor-raw --url "ws://127.0.0.1:18081/?token=$op_token" --topic /robot1/points --seconds "$seconds" >"$tmp/hubsub.log" 2>&1 &
hubsub=$!
if [ "$rb_compression" = cbor-raw ]; then
    client cbor-raw --url ws://127.0.0.1:19090/ --topic /points --seconds "$seconds" >"$tmp/rbsub.log" 2>&1 &
    rb_client="websockets client, cbor-raw"
else
    client roslibpy --port 19090 --topic /points --seconds "$seconds" >"$tmp/rbsub.log" 2>&1 &
    rb_client="roslibpy client, JSON"
fi
rbsub=$!
robot sub --seconds "$seconds" >"$tmp/floor.log" 2>&1 &
floor=$!
wait_line "$tmp/hubsub.log" "ready"
wait_line "$tmp/rbsub.log" "ready"
wait_line "$tmp/floor.log" "ready"
# The floor under any bridge's CPU: a plain TCP relay moving a stream of the same size and
# rate between two loopback sockets, nothing else (its own 2 s warm-up, then the same span).
in_ns "$bin" bench copy-floor --size "$((npoints * 16 + 111))" --rate 10 --seconds "$seconds" --json \
    >"$tmp/copyfloor.log" 2>&1 &
copyfloor=$!

ticks() { awk '{print $14 + $15}' "/proc/$1/stat"; }
thread_ticks() { for t in /proc/"$1"/task/*; do printf '%s %s %s\n' "${t##*/}" "$(tr ' ' _ <"$t/comm")" "$(awk '{print $14 + $15}' "$t/stat")"; done 2>/dev/null; }
hz="$(getconf CLK_TCK)"
load0="$(cut -d' ' -f1-3 /proc/loadavg)"
t0=$(date +%s.%N); a0=$(ticks "$agent_pid"); r0=$(ticks "$rb_pid"); h0=$(ticks "$hub_pid")
thread_ticks "$agent_pid" >"$tmp/threads0"
wait "$hubsub" "$rbsub" "$floor" || true
t1=$(date +%s.%N); a1=$(ticks "$agent_pid"); r1=$(ticks "$rb_pid"); h1=$(ticks "$hub_pid")
thread_ticks "$agent_pid" >"$tmp/threads1"
load1="$(cut -d' ' -f1-3 /proc/loadavg)"
wait "$copyfloor" || true
copy_cpu="$(sed -n 's/.*"relay_cpu_percent":\([0-9.]*\).*/\1/p' "$tmp/copyfloor.log" | awk '{printf "%.2f", $1}')"
mem() { awk '/^VmRSS|^VmHWM/ {v[$1] = $2} END {printf "%7.1f MB %7.1f MB", v["VmRSS:"]/1024, v["VmHWM:"]/1024}' "/proc/$1/status"; }
pct() { awk -v a="$1" -v b="$2" -v t0="$t0" -v t1="$t1" -v hz="$hz" 'BEGIN {printf "%.2f", 100 * (b - a) / hz / (t1 - t0)}'; }
lat() { # log -> "p50 / p99 ms (n)" from the client's JSON line
    "$rospython" -c 'import json,sys
try: d = json.loads(open(sys.argv[1]).read().strip().splitlines()[-1])
except Exception: print("no result"); sys.exit()
print("%s / %s ms (n=%s)" % (d.get("p50_ms", "-"), d.get("p99_ms", "-"), d["n"]) if d.get("n") else "nothing received")' "$1"
}
agent_cpu="$(pct "$a0" "$a1")"; rb_cpu="$(pct "$r0" "$r1")"
ratio="$(awk -v a="$agent_cpu" -v r="$rb_cpu" 'BEGIN {if (a > 0) printf "%.1f", r / a; else print "inf"}')"
agent_rss_mb="$(awk '/^VmRSS/ {print $2 / 1024}' "/proc/$agent_pid/status")"
agent_hwm_mb="$(awk '/^VmHWM/ {print $2 / 1024}' "/proc/$agent_pid/status")"
met() { awk -v v="$1" -v op="$2" -v lim="$3" 'BEGIN {ok = (op == "<=") ? (v <= lim) : (v >= lim); print ok ? "met" : "NOT met"}'; }

echo
echo "ROS 1 bridging: sensor_msgs/PointCloud2, $npoints points ($((npoints * 16)) data bytes) at 10 Hz from rospy, $(awk -v a="$t0" -v b="$t1" 'BEGIN {printf "%.1f", b - a}') s measured"
echo "machine: $(nproc) cores, $(awk -F: '/model name/ {print $2; exit}' /proc/cpuinfo | sed 's/^ *//'); load average $load0 before, $load1 after"
printf '%-56s %9s  %10s %10s  %s\n' "" "CPU, %" "VmRSS" "VmHWM" "latency p50 / p99 from header.stamp"
agent_label="fleetlink agent (-> hub -> cbor-raw client)"
[ "${HUB_LINK:-up}" = down ] && agent_label="fleetlink agent, hub link DOWN (ROS 1 side only)"
printf '%-56s %9s  %s  %s\n' "$agent_label" "$agent_cpu" "$(mem "$agent_pid")" "$(lat "$tmp/hubsub.log")"
printf '%-56s %9s  %s  %s\n' "rosbridge_server $rb_version ($rb_client)" "$rb_cpu" "$(mem "$rb_pid")" "$(lat "$tmp/rbsub.log")"
printf '%-56s %9s  %21s  %s\n' "rospy subscriber on the robot (floor, no bridge)" "-" "" "$(lat "$tmp/floor.log")"
printf '%-56s %9s  %s\n' "hub (cloud side, not robot cost)" "$(pct "$h0" "$h1")" "$(mem "$hub_pid")"
printf '%-56s %9s\n' "plain TCP relay of the same stream (floor, copy-floor)" "${copy_cpu:--}"
echo "CPU is % of one core. rosbridge / agent CPU ratio: ${ratio}x"
[ -n "$copy_cpu" ] && echo "floor: rosbridge / plain relay: $(awk -v r="$rb_cpu" -v c="$copy_cpu" 'BEGIN {if (c > 0) printf "%.1f", r / c; else print "inf"}')x; 15x would need the agent at $(awk -v r="$rb_cpu" 'BEGIN {printf "%.2f", r / 15}') %"
echo "targets: agent CPU <= 1 %: $(met "$agent_cpu" "<=" 1); agent RSS <= 30 MB: $(met "$agent_hwm_mb" "<=" 30) (VmHWM; VmRSS $(met "$agent_rss_mb" "<=" 30)); ratio >= 15x: $(met "$ratio" ">=" 15)"
kill -TERM "$pub_pid" 2>/dev/null || true
wait_line "$tmp/pub.log" '"sent"'
echo "publisher, stamp -> publish() returned: $(grep '"sent"' "$tmp/pub.log" | tail -n1)"
if [ -n "${THREADS:-}" ]; then
    echo "agent threads, % of one core over the window:"
    join <(sort "$tmp/threads0") <(sort "$tmp/threads1") \
        | awk -v t0="$t0" -v t1="$t1" -v hz="$hz" '{printf "  %-24s %6.2f\n", $2, 100 * ($5 - $3) / hz / (t1 - t0)}' | sort -k2 -nr | head -n 12
fi
# The agent's own warnings, if any (without the log's colour codes).
sed 's/\x1b\[[0-9;]*m//g' "$tmp/agent.log" | grep -E "WARN|ERROR" | head -n 5 || true

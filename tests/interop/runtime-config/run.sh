#!/usr/bin/env bash
# Runtime configuration suite (issue 40, item 2): a running agent's ROS 2 bridge changed
# through the hub's API, checked by roslibpy at the hub, kept on the robot and by the hub.
# Real `fleetlink hub` and `fleetlink agent` processes; the robot's graph is a Cyclone DDS
# node (Python binding, ROS 2 names and CDR) writing std_msgs/String on /chatter_a,
# /chatter_b and /chatter_c at 10 Hz each; the agent starts with `ros2.publish:
# [/chatter_a, /chatter_b]` and a `topics:` section of its own (/chatter_a no_drop). All in
# a network namespace of its own (DDS discovery is multicast on its loopback).
#
# Checks:
#   1. before any change, roslibpy receives /robot1/chatter_a and _b at about 10 msg/s,
#      and /robot1/chatter_c not at all;
#   2. a change through the hub's API adds /chatter_c and removes /chatter_b (written
#      under `remove:`): roslibpy then receives a and c at about 10 msg/s and b not at
#      all; the agent did not reconnect;
#   3. a second change gives /chatter_c a rate limit of 2 Hz: c arrives at about 2 msg/s,
#      a still at about 10;
#   3b. the node's service /add_two_ints, not exposed at first (a roslibpy call of
#      /robot1/add_two_ints fails), is exposed by a third change: the call answers 42;
#   3c. roslibpy publishes /robot1/cmd at the hub: a Cyclone reader of /cmd gets none of
#      it until a change adds /cmd to `ros2.subscribe`, then gets it;
#   4. an invalid change (rate_limit_hz: 0) is refused with the error text the agent
#      gives for the same lines in its YAML file (`fleetlink agent --config`), and a
#      caller without the right to change the robot's configuration gets 403;
#   5. the agent restarted: it applies the changes it kept before it connects (said in
#      its log, which shows the configuration in force with each field's origin: c's rate
#      limit a kept change, a's no_drop the file's, merged per topic), and 2-3 hold at
#      roslibpy;
#   5b. the YAML edited (one more topic under `topics:`) and the agent restarted: it says
#      the file changed since the changes were made and applies those that still merge
#      (all of them here); `fleetlink agent --check` prints the same configuration; 2-3
#      hold;
#   6. then the hub restarted (same database, same port): it still keeps the changes
#      (GET shows who made them), the robot reconnects, and 2-3 hold;
#   7. the agent started again without its kept changes (their file deleted): the hub
#      applies what it keeps when the robot connects, and 2-3b hold.
#   8. ROS 1: Debian's roscore and two `rostopic pub -r 10` publishers (/ros1_a, /ros1_b)
#      beside a second robot's agent with `ros1.publish: [/ros1_a]`; a change through the
#      hub to `[/ros1_b]`: roslibpy then receives /robot2/ros1_b at about 10 msg/s and
#      /robot2/ros1_a not at all (its TCPROS connection closed, the master told).
#
# Needs root (network namespace): fails otherwise, as CI runs it as root. Bounded: about
# 90 s; every process runs under `timeout`, in this run's own namespace, killed on exit.
#
# Env: FLEETLINK_BIN (default target/release/fleetlink), PYTHON (default .venv/bin/python
# with roslibpy and cyclonedds: scripts/setup.d/10-python-venv.sh, 35-ros2-peers.sh).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
bin="${FLEETLINK_BIN:-$root/target/release/fleetlink}"
python="${PYTHON:-$root/.venv/bin/python}"
export ROS_DOMAIN_ID=25 PYTHONDONTWRITEBYTECODE=1 NO_COLOR=1
unset ROS_DISTRO

[ -x "$bin" ] || { echo "FAIL: fleetlink binary not found at $bin (set FLEETLINK_BIN)" >&2; exit 1; }
[ -x "$python" ] || { echo "FAIL: $python missing; run scripts/setup.d/10-python-venv.sh" >&2; exit 1; }
"$python" -c 'import roslibpy, cyclonedds.domain' 2>/dev/null \
    || { echo "FAIL: $python lacks roslibpy or cyclonedds; run scripts/setup.d/10-python-venv.sh and 35-ros2-peers.sh" >&2; exit 1; }
[ "$(id -u)" -eq 0 ] || { echo "FAIL: the runtime configuration suite needs root for its network namespace" >&2; exit 1; }
for tool in roscore rostopic; do
    command -v "$tool" >/dev/null || { echo "FAIL: $tool missing; run scripts/setup.d/50-ros1.sh" >&2; exit 1; }
done
command -v ip >/dev/null || { echo "FAIL: \`ip\` (iproute2) missing; run scripts/setup.d/40-netns-tools.sh" >&2; exit 1; }
bin="$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")"

# shellcheck source=../lib.sh
. "$here/../lib.sh"
interop_begin runtime-config

ns="flrc-$$"
interop_netns "$ns"

in_ns() { ip netns exec "$ns" timeout --kill-after=5 "$@"; }
failed=()
fail() { echo "FAIL: $*"; failed+=("$*"); }
step() { echo "== $1"; }
peer() { in_ns 60 "$python" "$here/runtime_peer.py" "$@"; }

# --- the hub and its credentials
admin() { in_ns 30 "$bin" admin --data-dir "$tmp/hub-data" "$@"; }
robot_token="$(admin token robot robot1)"
robot2_token="$(admin token robot robot2)"
op_token="$(admin token operator interop --group admin)"
viewer_token="$(admin token operator viewer)"
start_hub() {
    # A command, not a function, in the background: `$!` is then the process itself
    # (through `ip netns exec` and `timeout`, which pass a TERM on), so `stop` stops it.
    ip netns exec "$ns" timeout --kill-after=5 300 "$bin" hub --listen "127.0.0.1:$1" \
        --data-dir "$tmp/hub-data" >>"$tmp/hub.log" 2>&1 &
    pids+=($!)
    hub_pid=${pids[-1]}
}
start_hub 0
port="$(wait_for_line "$tmp/hub.log" '^fleetlink hub listening on [0-9.]+:([0-9]+)$' "hub start" "$hub_pid")"
api="http://127.0.0.1:$port/api/v1/robots/robot1/config"
ws="ws://127.0.0.1:$port/?token=$op_token"

# --- the robot's graph and its agent
# The graph lives as long as the suite (peer's 60 s bound is for one-shot checks: a graph
# stopped by it left every later step with nothing to count once the suite ran slower).
in_ns 900 "$python" "$here/runtime_peer.py" publish /chatter_a /chatter_b /chatter_c >"$tmp/graph.log" 2>&1 &
pids+=($!)
wait_for_line "$tmp/graph.log" '^(ready)$' "the Cyclone node" "${pids[-1]}" >/dev/null
# robot_yaml [MORE_TOPIC_LINES]: the agent's YAML.
robot_yaml() {
    cat >"$tmp/robot.yaml" <<EOF
hub: ws://127.0.0.1:$port
name: robot1
token: $robot_token
heartbeat_ms: 250
reconnect: { initial_ms: 100, max_ms: 500 }
local_rosbridge: null
runtime_file: $tmp/robot-state/runtime.json
ros2:
  publish: [/chatter_a, /chatter_b]
topics:
  /chatter_a: { no_drop: true }
${1:-}
EOF
}
robot_yaml
agent_runs=0
start_agent() {
    agent_runs=$((agent_runs + 1))
    ip netns exec "$ns" timeout --kill-after=5 300 "$bin" agent --config "$tmp/robot.yaml" \
        >"$tmp/agent-$agent_runs.log" 2>&1 &
    pids+=($!)
    agent_pid=${pids[-1]}
    ln -sf "agent-$agent_runs.log" "$tmp/agent.log"
    wait_for_line "$tmp/agent-$agent_runs.log" '(connected to hub)' "the agent connecting (run $agent_runs)" "$agent_pid" >/dev/null
}
stop() { kill -TERM "$1" 2>/dev/null; for _ in $(seq 100); do kill -0 "$1" 2>/dev/null || return 0; sleep 0.1; done; kill -KILL "$1"; }
start_agent

# Rates at roslibpy: rates A B C -> "a b c" in msg/s over 3 s.
rates() {
    peer count "$ws" 3 /robot1/chatter_a /robot1/chatter_b /robot1/chatter_c \
        | in_ns 70 "$python" -c 'import json,sys; r=json.load(sys.stdin); print(r["/robot1/chatter_a"], r["/robot1/chatter_b"], r["/robot1/chatter_c"])'
}
# within LO HI X: whether LO <= X <= HI.
within() { in_ns 10 "$python" -c "import sys; sys.exit(0 if $1 <= $3 <= $2 else 1)"; }
# expect WHAT "a b c" RANGE_A RANGE_B RANGE_C (each "LO HI")
expect() {
    local what=$1 got=$2 ok=1
    read -r a b c <<<"$got"
    within $3 "$a" || ok=0
    within $4 "$b" || ok=0
    within $5 "$c" || ok=0
    if [ "$ok" = 1 ]; then echo "ok: $what: a $a, b $b, c $c msg/s"; else fail "$what: a $a, b $b, c $c msg/s"; fi
}
put() { printf '%s' "$2" >"$tmp/change.body"; peer api PUT "$api" "$1" "$tmp/change.body"; }
# The answer's status line, and a field of its JSON: status_of OUT / field_of OUT EXPR (`a`).
status_of() { head -n1 <<<"$1"; }
field_of() { tail -n1 <<<"$1" | in_ns 70 "$python" -c 'import json,sys; a=json.load(sys.stdin); print(eval(sys.argv[1]))' "$2"; }

step "1. before any change: a and b flow, c is not bridged"
expect "before" "$(rates)" "7 13" "7 13" "0 0"

step "2. add /chatter_c and remove /chatter_b through the hub"
connects_before="$(grep -c 'connected to hub' "$tmp/agent-$agent_runs.log")"
out="$(put "$op_token" '{"ros2": {"publish": ["/chatter_c"]}, "remove": {"ros2": {"publish": ["/chatter_b"]}}}')"
[ "$(status_of "$out")" = 200 ] || fail "step 2: PUT answered $(status_of "$out"): $(tail -n1 <<<"$out")"
expect "after adding c and removing b" "$(rates)" "7 13" "0 0" "7 13"

step "3. a rate limit of 2 Hz on /chatter_c"
out="$(put "$op_token" '{"topics": {"/chatter_c": {"rate_limit_hz": 2}}}')"
[ "$(status_of "$out")" = 200 ] || fail "step 3: PUT answered $(status_of "$out"): $(tail -n1 <<<"$out")"
expect "c limited" "$(rates)" "7 13" "0 0" "1.3 2.7"
connects_after="$(grep -c 'connected to hub' "$tmp/agent-$agent_runs.log")"
[ "$connects_before" = "$connects_after" ] && echo "ok: the changes did not reconnect the agent" \
    || fail "the agent reconnected for a change ($connects_before -> $connects_after connections)"

step "3b. a service exposed while the agent runs"
got="$(peer call "$ws" /robot1/add_two_ints)"
case "$got" in failed:*) echo "ok: before: /robot1/add_two_ints $got" ;; *) fail "step 3b: /robot1/add_two_ints answered '$got' before it was exposed" ;; esac
out="$(put "$op_token" '{"ros2": {"services": {"expose": ["/add_two_ints"]}}}')"
[ "$(status_of "$out")" = 200 ] || fail "step 3b: PUT answered $(status_of "$out"): $(tail -n1 <<<"$out")"
got=""
for _ in $(seq 20); do
    got="$(peer call "$ws" /robot1/add_two_ints)"
    [ "$got" = 42 ] && break
    sleep 0.25
done
[ "$got" = 42 ] && echo "ok: after the change, /robot1/add_two_ints answers 2 + 40 = $got" \
    || fail "step 3b: /robot1/add_two_ints answered '$got' after it was exposed"
expect "the topics meanwhile" "$(rates)" "7 13" "0 0" "1.3 2.7"

step "3c. a hub topic written into the graph once a change subscribes it"
# count_down: how many of 3 s of roslibpy's /robot1/cmd (10 Hz) a Cyclone reader of /cmd got.
count_down() {
    peer listen /cmd 6 >"$tmp/listen.log" 2>&1 &
    local lp=$!
    wait_for_line "$tmp/listen.log" '^(ready)$' "the Cyclone reader of /cmd" "$lp" >/dev/null
    peer send "$ws" /robot1/cmd 3 >/dev/null 2>&1 || true
    wait "$lp" || true
    tail -n1 "$tmp/listen.log"
}
got="$(count_down)"
[ "$got" = 0 ] && echo "ok: before: the graph's /cmd got $got messages" \
    || fail "step 3c: the graph's /cmd got '$got' messages before ros2.subscribe had it"
out="$(put "$op_token" '{"ros2": {"subscribe": ["/cmd"]}}')"
[ "$(status_of "$out")" = 200 ] || fail "step 3c: PUT answered $(status_of "$out"): $(tail -n1 <<<"$out")"
got="$(count_down)"
within 15 40 "$got" && echo "ok: after the change: the graph's /cmd got $got of about 30 messages" \
    || fail "step 3c: the graph's /cmd got '$got' messages after the change"

step "4. an invalid change is refused with the YAML's text; a viewer may not change"
bad=$'topics:\n  /chatter_c: { rate_limit_hz: 0 }\n'
out="$(put "$op_token" "$bad")"
[ "$(status_of "$out")" = 400 ] || fail "step 4: the invalid change answered $(status_of "$out")"
api_error="$(field_of "$out" 'a["error"]')"
printf '%s' "$bad" >"$tmp/bad.yaml"
file_error="$( (in_ns 10 "$bin" agent --config "$tmp/bad.yaml" 2>&1 >/dev/null || true) | sed -n 's/^error: //p' | head -n1)"
# The same lines in a file and in a change: the same text after the file's name.
if [ -n "$file_error" ] && [ "${api_error#change}" = "${file_error#"$tmp/bad.yaml"}" ]; then
    echo "ok: refused as the YAML is: $api_error"
else
    fail "step 4: the API said '$api_error', the agent's YAML check '$file_error'"
fi
out="$(put "$viewer_token" '{"topics": {}}')"
[ "$(status_of "$out")" = 403 ] && echo "ok: a caller without the right gets 403" \
    || fail "step 4: a viewer's change answered $(status_of "$out")"

step "5. the agent restarted: it runs with the changes it kept"
stop "$agent_pid"
start_agent
grep -q 'the changes kept in .* are in force' "$tmp/agent-$agent_runs.log" \
    && echo "ok: $(grep -o 'the changes kept in .* are in force.*' "$tmp/agent-$agent_runs.log" | head -n1)" \
    || fail "step 5: the restarted agent did not apply the changes it kept"
# origin_says FILE WHAT PATTERN: the configuration shown in FILE has a line matching PATTERN.
origin_says() {
    if grep -qE "$3" "$1"; then echo "ok: $2: $(grep -E "$3" "$1" | head -n1 | sed 's/^ *//')"; else fail "$2: no line matching '$3' in $1"; fi
}
origin_says "$tmp/agent-$agent_runs.log" "step 5: c's rate limit, a kept change" '^ +rate_limit_hz: 2(\.0)?  # kept change, .* by user:interop'
origin_says "$tmp/agent-$agent_runs.log" "step 5: a's no_drop, the file's, next to it" '^ +no_drop: true  # file$'
expect "after the agent's restart" "$(rates)" "7 13" "0 0" "1.3 2.7"

step "5b. the YAML edited since the changes were made: what still merges applies"
stop "$agent_pid"
robot_yaml "  /chatter_b: { priority: 3 }"
start_agent
grep -q 'robot.yaml has changed since the changes kept in' "$tmp/agent-$agent_runs.log" \
    && echo "ok: $(grep -o 'robot.yaml has changed since.*' "$tmp/agent-$agent_runs.log" | head -n1)" \
    || fail "step 5b: the agent did not say its file changed since the kept changes"
grep -q 'set aside' "$tmp/agent-$agent_runs.log" && fail "step 5b: a kept change was set aside: $(grep 'set aside' "$tmp/agent-$agent_runs.log" | head -n1)"
in_ns 10 "$bin" agent --config "$tmp/robot.yaml" --check >"$tmp/check.out" 2>&1 || fail "step 5b: --check failed: $(tail -n3 "$tmp/check.out")"
origin_says "$tmp/check.out" "step 5b: --check: the kept rate limit" '^ +rate_limit_hz: 2(\.0)?  # kept change'
origin_says "$tmp/check.out" "step 5b: --check: the file's new topic" '^ +priority: 3(\.0)?  # file$'
origin_says "$tmp/check.out" "step 5b: --check: /chatter_b removed by a kept change" '^ +# - /chatter_b  \(removed by a kept change'
expect "after the file changed" "$(rates)" "7 13" "0 0" "1.3 2.7"

step "6. the hub restarted: it keeps the changes"
stop "$hub_pid"
start_hub "$port"
wait_for_line "$tmp/hub.log" '^fleetlink hub listening on [0-9.]+:([0-9]+)$' "hub restart" "$hub_pid" >/dev/null
for _ in $(seq 100); do
    [ "$(grep -c 'connected to hub' "$tmp/agent-$agent_runs.log")" -ge 2 ] && break
    sleep 0.1
done
out="$(peer api GET "$api" "$op_token")"
kept_by="$(field_of "$out" '(a.get("kept") or {}).get("by")')"
[ "$kept_by" = "user:interop" ] && echo "ok: the restarted hub keeps the changes made by $kept_by" \
    || fail "step 6: the restarted hub keeps changes by '$kept_by': $(tail -n1 <<<"$out")"
expect "after the hub's restart" "$(rates)" "7 13" "0 0" "1.3 2.7"

step "7. the agent without its kept changes: the hub applies them again"
stop "$agent_pid"
rm -f "$tmp/robot-state/runtime.json"
start_agent
if line="$(wait_for_line "$tmp/agent-$agent_runs.log" '(runtime configuration changed by the hub.*)' \
    "the hub applying its kept changes" "$agent_pid")"; then
    echo "ok: the agent's log: $line"
else
    fail "step 7: the hub did not apply its kept changes to the returning agent"
fi
expect "applied again by the hub" "$(rates)" "7 13" "0 0" "1.3 2.7"
# The service reaches the hub once the agent's bridge has found its server in the graph
# again: bounded wait for its advertisement.
for _ in $(seq 15); do
    got="$(peer call "$ws" /robot1/add_two_ints)"
    case "$got" in *"not advertised"*) sleep 1 ;; *) break ;; esac
done
[ "$got" = 42 ] && echo "ok: /robot1/add_two_ints exposed again: $got" \
    || fail "step 7: /robot1/add_two_ints answered '$got' once the hub applied its changes"
[ -f "$tmp/robot-state/runtime.json" ] && echo "ok: the robot keeps them again" \
    || fail "step 7: the hub's changes were not kept on the robot"
step "8. ROS 1: ros1.publish changed on a running agent"
export ROS_MASTER_URI="http://127.0.0.1:11411" ROS_HOSTNAME=127.0.0.1
export ROS_HOME="$tmp/ros" ROS_LOG_DIR="$tmp/ros/log"
mkdir -p "$ROS_LOG_DIR"
ip netns exec "$ns" timeout --kill-after=5 120 roscore -p 11411 >"$tmp/roscore.log" 2>&1 &
pids+=($!)
for _ in $(seq 100); do
    in_ns 5 /usr/bin/python3 -c "import rosgraph,sys; sys.exit(0 if rosgraph.Master('/probe').is_online() else 1)" 2>/dev/null && break
    sleep 0.1
done
for t in a b; do
    ip netns exec "$ns" timeout --kill-after=5 120 rostopic pub -r 10 "/ros1_$t" std_msgs/String "data: $t" \
        >"$tmp/pub_$t.log" 2>&1 &
    pids+=($!)
done
cat >"$tmp/robot2.yaml" <<EOF
hub: ws://127.0.0.1:$port
name: robot2
token: $robot2_token
local_rosbridge: null
runtime_file: $tmp/robot2-state/runtime.json
ros1:
  master_uri: $ROS_MASTER_URI
  host: 127.0.0.1
  publish: [/ros1_a]
EOF
ip netns exec "$ns" timeout --kill-after=5 120 "$bin" agent --config "$tmp/robot2.yaml" >"$tmp/agent2.log" 2>&1 &
pids+=($!)
wait_for_line "$tmp/agent2.log" '(connected to hub)' "robot2's agent connecting" "${pids[-1]}" >/dev/null
ros1_rates() {
    peer count "$ws" 3 /robot2/ros1_a /robot2/ros1_b \
        | in_ns 70 "$python" -c 'import json,sys; r=json.load(sys.stdin); print(r["/robot2/ros1_a"], r["/robot2/ros1_b"], 0)'
}
expect "ROS 1 before the change (a, b)" "$(ros1_rates)" "7 13" "0 0" "0 0"
api2="http://127.0.0.1:$port/api/v1/robots/robot2/config"
printf '%s' '{"ros1": {"publish": ["/ros1_b"]}, "remove": {"ros1": {"publish": ["/ros1_a"]}}}' >"$tmp/change2.body"
out="$(peer api PUT "$api2" "$op_token" "$tmp/change2.body")"
[ "$(status_of "$out")" = 200 ] || fail "step 8: PUT answered $(status_of "$out"): $(tail -n1 <<<"$out")"
expect "ROS 1 after the change (a, b)" "$(ros1_rates)" "0 0" "7 13" "0 0"

grep -q "panicked" "$tmp/hub.log" "$tmp"/agent-*.log "$tmp/agent2.log" && fail "a fleetlink process panicked (see its log)"

if [ ${#failed[@]} -ne 0 ]; then
    echo "runtime configuration suite: ${#failed[@]} check(s) failed" >&2
    exit 1
fi
echo "runtime configuration suite: all checks passed"

#!/usr/bin/env bash
# rosbridge client interop suite (issue 40 part 5): an agent bridges a robot that offers
# only a rosbridge server. The "robot's rosbridge server" is a second fleetlink hub (hub
# A; no other rosbridge server installs from the package registries here), with real
# roslibpy programs on it; the agent (`rosbridge: { url: ws://A }`, no simulator, no
# local listener) is connected to hub B, where roslibpy plays the operator.
#
# rosbridge_client_check.py, run twice:
#
#   before   on A: a /chatter publisher (std_msgs/msg/String) and a /set_flag provider
#            (std_srvs/srv/SetBool), a /cmd_vel subscriber; on B: /robot1/chatter carries
#            A's values, a call of /robot1/set_flag gets the provider's answer, and what
#            B publishes on /robot1/cmd_vel reaches A's /cmd_vel subscriber;
#   after    hub A is killed and started again on the same port (a robot's server that
#            restarted): the same three checks with new roslibpy programs and new values,
#            each within 15 s, so the bridge reconnected, subscribed and advertised again.
#
# Every wait is bounded; every process is stopped on exit. About 30 s.
#
# Env: FLEETLINK_BIN (default: target/release/fleetlink), PYTHON (default: .venv/bin/python).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
bin="${FLEETLINK_BIN:-$root/target/release/fleetlink}"
python="${PYTHON:-$root/.venv/bin/python}"
robot=robot1
started=$SECONDS

[ -x "$bin" ] || { echo "FAIL: fleetlink binary not found at $bin (set FLEETLINK_BIN)" >&2; exit 1; }
[ -x "$python" ] || { echo "FAIL: $python missing; run scripts/setup.d/10-python-venv.sh" >&2; exit 1; }

# shellcheck source=../lib.sh
. "$here/../lib.sh"
interop_begin rosbridge-client

# --- credentials: hub A (the robot's server) has one operator the bridge and the robot's
# programs use; hub B has the robot and an operator.
admin_a() { timeout 30 "$bin" admin --data-dir "$tmp/a-data" "$@"; }
admin_b() { timeout 30 "$bin" admin --data-dir "$tmp/b-data" "$@"; }
a_token="$(admin_a token operator robot_programs --group admin)"
robot_token="$(admin_b token robot "$robot")"
op_token="$(admin_b token operator interop --group admin)"

# --- hub A, "the robot's rosbridge server"; started again later on the same port.
: >"$tmp/hub-a.log"; : >"$tmp/hub.log"; : >"$tmp/agent.log"
start_a() {
    local listen=$1
    "$bin" hub --listen "$listen" --data-dir "$tmp/a-data" >>"$tmp/hub-a.log" 2>&1 &
    a_pid=$!
    pids+=("$a_pid")
}
start_a 127.0.0.1:0
a_addr="$(wait_for_line "$tmp/hub-a.log" '^fleetlink hub listening on ([0-9.:]+)$' "hub A start" "$a_pid")"
echo "hub A (the robot's rosbridge server): ws://$a_addr/"

# --- hub B, the fleet's hub (its log is the one shown on failure as hub.log).
"$bin" hub --listen 127.0.0.1:0 --data-dir "$tmp/b-data" >"$tmp/hub.log" 2>&1 &
b_pid=$!
pids+=("$b_pid")
b_addr="$(wait_for_line "$tmp/hub.log" '^fleetlink hub listening on ([0-9.:]+)$' "hub B start" "$b_pid")"
echo "hub B (the fleet's hub): ws://$b_addr/"

# --- the agent: only the rosbridge client.
cat >"$tmp/agent.yaml" <<YAML
hub: ws://$b_addr/
name: $robot
token: $robot_token
local_rosbridge: null
rosbridge:
  url: ws://$a_addr/
  token: $a_token
  publish: [/chatter]
  subscribe: [/cmd_vel]
  services: [/set_flag]
  discovery_ms: 500
  reconnect: { initial_ms: 200, max_ms: 2000 }
YAML
"$bin" agent --config "$tmp/agent.yaml" >"$tmp/agent.log" 2>&1 &
pids+=($!)
agent_pid=${pids[-1]}
wait_for_line "$tmp/agent.log" '^  rosbridge client of: (ws://.*)$' "agent start" "$agent_pid" >/dev/null
wait_for_line "$tmp/agent.log" '.*rosbridge: (connected) to .*' "agent connects to hub A" "$agent_pid" >/dev/null

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
check=("$python" "$here/rosbridge_client_check.py" --robot-server "ws://$a_addr/?token=$a_token"
       --hub "ws://$b_addr/?token=$op_token" --robot "$robot")
run_check "before the robot's server restarts" 60 "${check[@]}" --phase before

# --- the robot's server restarts: killed (no goodbye to its clients), then started again
# on the same port with the same data.
kill -KILL "$a_pid"
wait "$a_pid" 2>/dev/null || true
# Bounded: up to 10 attempts (the port may take a moment to be free), each waiting up to
# 5 s for the new "listening" line or the process's exit.
listening() { grep -c "^fleetlink hub listening on $a_addr\$" "$tmp/hub-a.log" || true; }
restarted=0
for _ in $(seq 10); do
    before="$(listening)"
    start_a "$a_addr"
    for _ in $(seq 100); do # 100 x 0.05 s
        [ "$(listening)" -gt "$before" ] && { restarted=1; break; }
        kill -0 "$a_pid" 2>/dev/null || break
        sleep 0.05
    done
    [ "$restarted" = 1 ] && break
    kill -KILL "$a_pid" 2>/dev/null || true
    wait "$a_pid" 2>/dev/null || true
done
[ "$restarted" = 1 ] || { echo "FAIL: hub A did not start again on $a_addr" >&2; exit 1; }
echo "hub A restarted on ws://$a_addr/"
run_check "after the robot's server restarted" 60 "${check[@]}" --phase after
if ! grep -q "rosbridge: link to ws://$a_addr/ lost" "$tmp/agent.log"; then
    echo "FAIL: the agent never noticed that hub A went away"
    failed+=("link loss noticed")
fi
if ! grep -q "rosbridge: connected to ws://$a_addr/ again" "$tmp/agent.log"; then
    echo "FAIL: the agent did not log its reconnect"
    failed+=("reconnect logged")
fi

kill -0 "$b_pid" 2>/dev/null || failed+=("hub B died")
kill -0 "$agent_pid" 2>/dev/null || failed+=("the agent died")
kill -0 "$a_pid" 2>/dev/null || failed+=("hub A (restarted) died")

echo "rosbridge client interop: ${#failed[@]} failure(s), $((SECONDS - started)) s"
if [ ${#failed[@]} -ne 0 ]; then
    echo "--- last lines of hub A's log" >&2; tail -n 20 "$tmp/hub-a.log" >&2
    echo "FAIL: ${failed[*]}" >&2
    exit 1
fi
echo "PASS: rosbridge client interop (topics both ways, a service call, reconnect after the server restarted)"

#!/usr/bin/env bash
# Failover interop suite (issue 38 item 4): an agent whose config lists two hubs moves to
# the second when the first is killed, loses no no_drop message on the way, and stays
# there when the first comes back.
#
# Starts hub A and hub B (two `fleetlink hub` processes on 127.0.0.1:0, each with its own
# data dir; robots from 127.0.0.0/8 need no token, since a robot token lives in one hub's
# database) and one agent listing A then B, with the simulator (odometry) and a no_drop
# topic /counter. failover_check.py subscribes on B to /robot1/counter and /robot1/odom
# before the robot is there, and publishes an incrementing counter on /counter (20 Hz)
# through the agent's local listener. Then:
#
#   1. hub A is frozen (SIGSTOP) for 0.5 s, so the counter values the agent sends it
#      meanwhile are never confirmed, then killed (kill -9): robot1 must be online at B
#      within 3 s of the kill (B's REST API, polled every 20 ms; the agent's "connected
#      to hub" log line gives its own figure);
#   2. B's subscriber gets the topics without doing anything;
#   3. hub A restarts on its old port: robot1 must stay on B for 4 s (A never lists it
#      online, the agent logs no new connection);
#   4. failover_check.py audits what B got: from its first /counter message on, every
#      value once, in order, none missing; every value published since A froze (those
#      A never confirmed included), exactly once.
#
# Prints PASS/FAIL lines with the figures. Every wait is bounded; every process started
# here is stopped on exit (trap), also on failure. The suite takes about 20 s.
#
# Env: FLEETLINK_BIN (default: target/release/fleetlink), PYTHON (default: .venv/bin/python).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
bin="${FLEETLINK_BIN:-$root/target/release/fleetlink}"
python="${PYTHON:-$root/.venv/bin/python}"
robot=robot1
started=$SECONDS
failover_limit_ms=3000
stay_s=4

[ -x "$bin" ] || { echo "FAIL: fleetlink binary not found at $bin (set FLEETLINK_BIN)" >&2; exit 1; }
[ -x "$python" ] || { echo "FAIL: $python missing; run scripts/setup.d/10-python-venv.sh" >&2; exit 1; }

# shellcheck source=../lib.sh
. "$here/../lib.sh"
interop_begin failover

# --- two hubs, each with its own database and an admin operator token
declare -A addr token pid
start_hub() { # NAME LISTEN LOG
    "$bin" hub --listen "$2" --data-dir "$tmp/hub-$1" --robot-network "127.0.0.0/8=$robot" >"$3" 2>&1 &
    pids+=($!)
    pid[$1]=$!
    addr[$1]="$(wait_for_line "$3" '^fleetlink hub listening on ([0-9.:]+)$' "hub $1 start" "${pid[$1]}")"
}
for h in a b; do
    token[$h]="$(timeout 30 "$bin" admin --data-dir "$tmp/hub-$h" token operator interop --group admin)"
    : >"$tmp/hub-$h.log"
    start_hub "$h" 127.0.0.1:0 "$tmp/hub-$h.log"
    echo "hub ${h^^}: ws://${addr[$h]}/ (pid ${pid[$h]})"
done
# lib.sh shows the tail of $tmp/hub.log on failure: hub A's.
ln -s "$tmp/hub-a.log" "$tmp/hub.log"

# --- the agent: A first, then B
: >"$tmp/agent.log"
cat >"$tmp/agent.yaml" <<EOF
hub: [ws://${addr[a]}/, ws://${addr[b]}/]
name: $robot
local_rosbridge: { listen: 127.0.0.1:0 }
topics:
  /counter: { no_drop: true, queue: 1000 }
sim:
  odometry: { rate_hz: 10 }
EOF
"$bin" agent --config "$tmp/agent.yaml" >"$tmp/agent.log" 2>&1 &
pids+=($!)
agent_pid=$!
local_addr="$(wait_for_line "$tmp/agent.log" '^  local rosbridge: ws://([0-9.:]+)/$' "agent start" "$agent_pid")"

# Polls hub NAME's GET /api/v1/robots until robot1's `online` is WANT (true/false), at
# most SECONDS; prints the milliseconds since T0_NS (ns since the epoch) when it was.
robot_online() { # NAME WANT SECONDS T0_NS
    "$python" - "${addr[$1]}" "${token[$1]}" "$robot" "$2" "$3" "$4" <<'PY'
import json, sys, time, urllib.request
addr, token, robot, want, limit, t0 = sys.argv[1:7]
want, deadline, last = want == "true", time.monotonic() + float(limit), None
while time.monotonic() < deadline:
    try:
        req = urllib.request.Request(f"http://{addr}/api/v1/robots",
                                     headers={"Authorization": f"Bearer {token}"})
        with urllib.request.urlopen(req, timeout=1) as r:
            me = [x for x in json.load(r)["robots"] if x["name"] == robot]
        now = time.time_ns()
        if bool(me and me[0]["online"]) == want:
            print((now - int(t0)) // 1_000_000)
            sys.exit(0)
        last = me
    except Exception as e:  # not up (yet)
        last = repr(e)
    time.sleep(0.02)
print(f"{robot} online={not want} at {addr} for {limit} s; last: {last}", file=sys.stderr)
sys.exit(1)
PY
}

failed=()
fail() { # NAME MESSAGE
    echo "FAIL: $2"
    failed+=("$1")
}

robot_online a true 15 "$(date +%s%N)" >/dev/null || { echo "FAIL: $robot never came online at hub A" >&2; exit 1; }
echo "$robot online at hub A; local rosbridge ws://$local_addr/"

# --- the clients: B's subscriber (before the robot is there) and the counter publisher
: >"$tmp/check.out"
"$python" "$here/failover_check.py" --hub-url "ws://${addr[b]}/?token=${token[b]}" \
    --local-url "ws://$local_addr/" --robot "$robot" --hz 20 --log "$tmp/check.log" \
    --stop "$tmp/stop" --down-at "$tmp/down_at" >"$tmp/check.out" 2>&1 &
pids+=($!)
check_pid=$!
wait_for_line "$tmp/check.out" '^(ready)$' "clients connected" "$check_pid" >/dev/null
# Two seconds of the counter flowing through hub A (40 values), so some are in flight
# when it dies.
for _ in $(seq 100); do
    [ "$(grep -c '^pub ' "$tmp/check.log" || true)" -ge 40 ] && break
    sleep 0.05
done
b_before="$(grep -c '^rx ' "$tmp/check.log" || true)"

# --- 1. hub A stops answering, then dies
date +%s%N >"$tmp/down_at"
kill -STOP "${pid[a]}"
sleep 0.5 # the agent sends A ~10 counter values that A never confirms
# (Reaped at once with stderr aside, so bash does not report "Killed".)
{ kill -KILL "${pid[a]}"; killed_at="$(date +%s%N)"; wait "${pid[a]}"; } 2>/dev/null || true
echo "hub A frozen (SIGSTOP) for 0.5 s, then killed (kill -9), after $(grep -c '^pub ' "$tmp/check.log") counter values"
if ms="$(robot_online b true 10 "$killed_at")"; then
    # The agent's own account: its log line's timestamp (RFC 3339, UTC).
    log_ms="$("$python" - "$tmp/agent.log" "ws://${addr[b]}/" "$killed_at" <<'PY'
import datetime, re, sys
path, url, t0 = sys.argv[1], sys.argv[2], int(sys.argv[3])
for line in open(path, encoding="utf-8", errors="replace"):
    line = re.sub(r"\x1b\[[0-9;]*m", "", line)
    m = re.match(r"^(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d)(?:\.(\d+))?Z\s", line)
    if m and f"connected to hub {url}" in line:
        t = datetime.datetime.fromisoformat(m.group(1)).replace(tzinfo=datetime.timezone.utc)
        ns = int(t.timestamp()) * 1_000_000_000 + int((m.group(2) or "0")[:9].ljust(9, "0"))
        print(f"{(ns - t0) / 1e6:.0f} ms")
        break
else:
    print("no such line")
PY
)"
    if [ "$ms" -le "$failover_limit_ms" ]; then
        echo "PASS: $robot online at hub B ${ms} ms after hub A was killed (limit ${failover_limit_ms} ms; by the agent's log: ${log_ms})"
    else
        fail "failover" "$robot online at hub B only ${ms} ms after hub A was killed (limit ${failover_limit_ms} ms)"
    fi
else
    fail "failover" "$robot not online at hub B within 10 s of hub A's kill"
fi
grep -E "hub link down|connected to hub" "$tmp/agent.log" | sed -E 's/\x1b\[[0-9;]*m//g; s/^/    agent: /'

# --- 2. B's subscriber gets the topic by itself
for _ in $(seq 100); do
    [ "$(grep -c '^rx ' "$tmp/check.log" || true)" -gt "$b_before" ] && break
    sleep 0.05
done
b_after="$(grep -c '^rx ' "$tmp/check.log" || true)"
if [ "$b_before" -eq 0 ] && [ "$b_after" -gt 0 ]; then
    echo "PASS: B's subscriber, subscribed before the robot was there, receives /$robot/counter ($b_after so far)"
else
    fail "subscriber" "B's subscriber got $b_before /counter messages before the failover and $b_after after"
fi

# --- 3. hub A back on its old port: robot1 stays on B
: >"$tmp/hub-a2.log"
start_hub a "${addr[a]}" "$tmp/hub-a2.log"
echo "hub A restarted on ${addr[a]} (pid ${pid[a]})"
if robot_online a true "$stay_s" "$(date +%s%N)" >/dev/null 2>&1; then
    fail "sticky" "$robot went back to hub A after it restarted"
elif ! robot_online b true 1 "$(date +%s%N)" >/dev/null; then
    fail "sticky" "$robot is not online at hub B any more"
else
    moves="$(grep -c "connected to hub ws://${addr[a]}/" "$tmp/agent.log" || true)"
    if [ "$moves" -eq 1 ]; then
        echo "PASS: $robot stayed on hub B for ${stay_s} s after hub A came back (agent connected to A once, at start)"
    else
        fail "sticky" "the agent connected to hub A $moves times"
    fi
fi

# --- 4. the audit of what B received
touch "$tmp/stop"
rc=0
for _ in $(seq 400); do kill -0 "$check_pid" 2>/dev/null || break; sleep 0.05; done
kill -KILL "$check_pid" 2>/dev/null && echo "FAIL: failover_check.py still running 20 s after --stop"
wait "$check_pid" || rc=$?
grep -E '^(PASS|FAIL|    )' "$tmp/check.out" || true
[ "$rc" -eq 0 ] || failed+=("no_drop audit (failover_check.py exit $rc)")

for p in "${pid[a]}" "${pid[b]}" "$agent_pid"; do
    kill -0 "$p" 2>/dev/null || failed+=("process $p died")
done

echo "failover interop: ${#failed[@]} failure(s), $((SECONDS - started)) s"
if [ ${#failed[@]} -ne 0 ]; then
    echo "FAIL: ${failed[*]}" >&2
    exit 1
fi
echo "PASS: failover interop (kill -9 of hub A: robot on hub B, no_drop counter whole, stays on B)"

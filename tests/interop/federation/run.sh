#!/usr/bin/env bash
# Federation interop suite (issue 38 item 3): three hubs as separate processes on
# loopback, joined by Zenoh over mutual TLS (each hub's certificate from the fleet's CA,
# made by `fleetlink admin cert federation`; each listens on its own tls/ endpoint; B
# connects to A, C to A and B), one simulated robot whose agent lists hub A then hub B.
#
# federation_check.py, with roslibpy clients on hubs B and C and the hubs' REST API:
#
#   1. a subscriber on C receives the robot's /robot1/odom (published at A);
#   2. while nobody subscribes to it on B, no message of it reaches B's Zenoh session
#      (B's /api/v1/federation counts what it hears, per topic and in total), A sends
#      each message once (its counter of sent messages against C's received ones), and a
#      topic nobody subscribes to anywhere (/robot1/scan) stays on the robot (idle at A);
#   3. B lists the whole fleet: /rosapi/topics has the robot's topics, /api/v1/robots
#      has robot1 online at hub-a, /rosapi/services its services;
#   4. an operator on B calls the robot's services (set_mode, get_status) and sends its
#      navigate_to_pose action a goal (feedback, then SUCCEEDED) and a second goal that it
#      cancels after the first feedback (CANCELED);
#   5. no loops: a topic published on each of the three hubs and subscribed on each is
#      received by each subscriber exactly once per message (triangle);
#   6. keyframe asks cross hubs: a viewer on C of the robot's video (its simulated camera,
#      keyframes 60 s apart), throttled so that it loses frames, decodes every frame it is
#      given from the first (tests/interop/video/video_peer.py, PyAV), at least 3 in 5 s,
#      which only keyframes C asked of A, and A of the robot, can give (keyframe_asks).
#
# Then the failover part, with tests/interop/failover/failover_check.py subscribing on C:
# hub A is frozen 0.5 s (SIGSTOP) and killed (kill -9); the agent moves to B, C's
# subscribers resume by themselves, and the no_drop /robot1/counter arrives at C with
# every value once, in order, none missing (also the values A never confirmed, which the
# agent resends through B while C may have heard some of them from A already).
#
# Every wait is bounded; every process is stopped on exit. About 50 s.
#
# Env: FLEETLINK_BIN (default: target/release/fleetlink), PYTHON (default: .venv/bin/python).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
bin="${FLEETLINK_BIN:-$root/target/release/fleetlink}"
python="${PYTHON:-$root/.venv/bin/python}"
robot=robot1

[ -x "$bin" ] || { echo "FAIL: fleetlink binary not found at $bin (set FLEETLINK_BIN)" >&2; exit 1; }
[ -x "$python" ] || { echo "FAIL: $python missing; run scripts/setup.d/10-python-venv.sh" >&2; exit 1; }
# PyAV and numpy for the video viewer of check 6 (video_peer.py).
"$python" -c 'import av, numpy, roslibpy' 2>/dev/null \
    || { echo "FAIL: $python lacks av, numpy or roslibpy; run scripts/setup-test-env.sh" >&2; exit 1; }
if ! "$bin" hub --help | grep -q -- '--federate'; then
    echo "FAIL: $bin has no --federate (built without the federation feature)" >&2
    exit 1
fi

# shellcheck source=../lib.sh
. "$here/../lib.sh"
interop_begin federation

# Three free loopback ports for the Zenoh endpoints (bound and released; a port taken
# meanwhile makes the hub fail at start, which the start wait reports).
read -r za zb zc < <("$python" - <<'PY'
import socket
socks = [socket.socket() for _ in range(3)]
for s in socks:
    s.bind(("127.0.0.1", 0))
print(*[s.getsockname()[1] for s in socks])
PY
)
declare -A addr token pid zport=([a]=$za [b]=$zb [c]=$zc) connect
connect[a]=""
connect[b]="--zenoh-connect tls/127.0.0.1:$za"
connect[c]="--zenoh-connect tls/127.0.0.1:$za --zenoh-connect tls/127.0.0.1:$zb"
certs="$tmp/certs/federation-interop"
for h in a b c; do
    "$bin" admin cert --dir "$tmp/certs" federation --fleet interop --hub "hub-$h" --ip 127.0.0.1 >/dev/null
done

start_hub() { # NAME LISTEN
    local log="$tmp/hub-$1.log"
    # shellcheck disable=SC2086 # connect[] holds several words on purpose
    RUST_LOG="${HUB_RUST_LOG:-info,zenoh=warn}" "$bin" hub --listen "$2" --data-dir "$tmp/hub-$1" \
        --robot-network "127.0.0.0/8=$robot" \
        --federate zenoh --fleet interop --zenoh-ca "$certs/ca.pem" \
        --zenoh-cert "$certs/hub-$1.pem" --zenoh-key "$certs/hub-$1.key" \
        --zenoh-listen "tls/127.0.0.1:${zport[$1]}" ${connect[$1]} >>"$log" 2>&1 &
    pids+=($!)
    pid[$1]=$!
    addr[$1]="$(wait_for_line "$log" '^fleetlink hub listening on ([0-9.:]+)$' "hub $1 start" "${pid[$1]}")"
}
for h in a b c; do
    token[$h]="$(timeout 30 "$bin" admin --data-dir "$tmp/hub-$h" token operator interop --group admin)"
    : >"$tmp/hub-$h.log"
    start_hub "$h" 127.0.0.1:0
    echo "hub ${h^^}: ws://${addr[$h]}/ zenoh tls/127.0.0.1:${zport[$h]} (pid ${pid[$h]})"
done
ln -s "$tmp/hub-a.log" "$tmp/hub.log"

: >"$tmp/agent.log"
cat >"$tmp/agent.yaml" <<YAML
hub: [ws://${addr[a]}/, ws://${addr[b]}/]
name: $robot
local_rosbridge: { listen: 127.0.0.1:0 }
topics:
  /counter: { no_drop: true, queue: 1000 }
sim:
  odometry: { rate_hz: 10 }
  laser_scan: { rate_hz: 5 }
  image: { rate_hz: 15 }
video:
  /camera/image/compressed: { topic: /camera/video, fps: 15, keyframe_s: 60 }
YAML
"$bin" agent --config "$tmp/agent.yaml" >"$tmp/agent.log" 2>&1 &
pids+=($!)
agent_pid=$!
local_addr="$(wait_for_line "$tmp/agent.log" '^  local rosbridge: ws://([0-9.:]+)/$' "agent start" "$agent_pid")"
echo "agent $robot: local rosbridge ws://$local_addr/"

failed=()
rc=0
timeout 120 "$python" "$here/federation_check.py" --robot "$robot" \
    --hub "a=${addr[a]},${token[a]}" --hub "b=${addr[b]},${token[b]}" --hub "c=${addr[c]},${token[c]}" \
    || rc=$?
[ "$rc" -eq 0 ] || failed+=("federation_check.py (exit $rc)")

# No link between the hubs dropped while the checks ran: each hub admitted each of the two
# others once. A link that breaks and comes back admits its hub again, and what was in
# flight on it is lost (a race in Zenoh's TLS link did this every few runs; vendor/README.md).
for h in a b c; do
    n="$(grep -c 'federation: hub .* admitted: its certificate' "$tmp/hub-$h.log" || true)"
    if [ "$n" -eq 2 ]; then
        echo "PASS links_held: hub ${h^^} admitted each of the other two hubs once (no link dropped)"
    else
        echo "FAIL links_held: hub ${h^^} admitted hubs $n times (want 2: a link dropped and was made again):"
        grep -E 'admitted: its certificate|Closing transport|TX task failed|RX task failed' "$tmp/hub-$h.log" | sed 's/^/    /' | head -n 20
        failed+=("links_held (hub ${h^^})")
    fi
done

if [ -n "${FEDERATION_ONLY_CHECK:-}" ]; then
    [ ${#failed[@]} -eq 0 ] || { echo "FAIL: ${failed[*]}"; exit 1; }
    exit 0
fi

# --- failover across federated hubs: subscribers on C, the robot moves from A to B
: >"$tmp/check.out"
"$python" "$here/../failover/failover_check.py" --hub-url "ws://${addr[c]}/?token=${token[c]}" \
    --local-url "ws://$local_addr/" --robot "$robot" --hz 20 --log "$tmp/check.log" \
    --stop "$tmp/stop" --down-at "$tmp/down_at" >"$tmp/check.out" 2>&1 &
pids+=($!)
check_pid=$!
wait_for_line "$tmp/check.out" '^(ready)$' "clients connected" "$check_pid" >/dev/null
counted() { grep -c "^rx " "$tmp/check.log" || true; }
for _ in $(seq 200); do
    [ "$(counted)" -ge 20 ] && break
    sleep 0.05
done
c_before="$(counted)"
if [ "$c_before" -lt 20 ]; then
    failed+=("counter")
    echo "FAIL: C's subscriber got $c_before /$robot/counter values through hub A in 10 s (want 20)"
fi
date +%s%N >"$tmp/down_at"
kill -STOP "${pid[a]}"
sleep 0.5
{ kill -KILL "${pid[a]}"; wait "${pid[a]}"; } 2>/dev/null || true
echo "hub A frozen (SIGSTOP) for 0.5 s, then killed (kill -9), after $c_before counter values at C"
resumed=""
for _ in $(seq 300); do # 15 s: Zenoh notices A gone, the agent reconnects to B
    now="$(counted)"
    if [ "$now" -gt "$((c_before + 40))" ]; then resumed=$now; break; fi
    sleep 0.05
done
if [ -n "$resumed" ]; then
    echo "PASS: C's subscriber resumed by itself after the robot moved to hub B ($resumed counter values so far)"
else
    failed+=("resume")
    echo "FAIL: C's subscriber did not resume within 15 s of hub A's kill ($(counted) counter values)"
fi
grep -E "hub link down|connected to hub" "$tmp/agent.log" | sed -E 's/\x1b\[[0-9;]*m//g; s/^/    agent: /'

touch "$tmp/stop"
rc=0
for _ in $(seq 400); do kill -0 "$check_pid" 2>/dev/null || break; sleep 0.05; done
kill -KILL "$check_pid" 2>/dev/null && echo "FAIL: failover_check.py still running 20 s after --stop"
wait "$check_pid" || rc=$?
grep -E '^(PASS|FAIL|    )' "$tmp/check.out" || true
[ "$rc" -eq 0 ] || failed+=("no_drop audit at C (failover_check.py exit $rc)")
# (failover_check.py's lines speak of "B", the hub it subscribes on: here that is hub C.)
# What C's federation heard twice: counter values it got from A, then again from B after
# the move (the agent resends what A never confirmed), delivered once.
"$python" - "${addr[c]}" "${token[c]}" <<'PY' || true
import json, sys, urllib.request
addr, token = sys.argv[1:3]
req = urllib.request.Request(f"http://{addr}/api/v1/federation", headers={"Authorization": f"Bearer {token}"})
c = json.load(urllib.request.urlopen(req, timeout=5))["counters"]
print(f"    hub C's federation: {c['received']} messages received, {c['duplicates']} no-drop duplicates dropped")
PY

if [ ${#failed[@]} -ne 0 ]; then
    echo "FAIL: federation: ${failed[*]}"
    exit 1
fi
echo "PASS: federation suite"

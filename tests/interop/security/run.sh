#!/usr/bin/env bash
# Security interop suite: every seam attacked as a stranger would, each attack meeting the
# refusal it must (docs/security.md, "Attacks and the answers they meet", lists them with
# the check that covers each).
#
# Two hubs on loopback federated over mutual TLS (certificates from `fleetlink admin cert
# federation`, fleet "sec"), one simulated robot on hub A with a black box, the same
# operators on both hubs with different rules (alice may call /robot1/set_mode on B, not on
# A), a rule on A that denies hub B publishing /robot1/joint_cmd.
#
# The attackers (security_check.py): eclipse-zenoh sessions on hub A's federation port
# (plain TCP, TLS without a certificate, a certificate of another CA, a certificate of the
# fleet's CA naming another fleet, an admitted hub calling hub-only services), roslibpy
# clients (anonymous, rights-less, alice on each hub), the REST API, a forged agent HELLO,
# and @foxglove/ws-protocol's FoxgloveClient reading a hidden parameter by another
# spelling (tests/interop/foxglove/foxglove_param_attack.mjs). Also here: a hub with
# --federate but no certificates refuses to start, and a hub given only --zenoh-connect
# listens on no federation port.
#
# Every wait is bounded; every process is stopped on exit. About 40 s.
#
# Env: FLEETLINK_BIN (default: target/release/fleetlink), PYTHON (default: .venv/bin/python).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
bin="${FLEETLINK_BIN:-$root/target/release/fleetlink}"
python="${PYTHON:-$root/.venv/bin/python}"

[ -x "$bin" ] || { echo "FAIL: fleetlink binary not found at $bin (set FLEETLINK_BIN)" >&2; exit 1; }
[ -x "$python" ] || { echo "FAIL: $python missing; run scripts/setup.d/10-python-venv.sh" >&2; exit 1; }
"$python" -c 'import zenoh' 2>/dev/null \
    || { echo "FAIL: the Python venv has no eclipse-zenoh; run scripts/setup.d/10-python-venv.sh" >&2; exit 1; }
command -v openssl >/dev/null || { echo "FAIL: openssl is needed for the stranger's certificates" >&2; exit 1; }

# shellcheck source=../lib.sh
. "$here/../lib.sh"
interop_begin security
failed=()

# --- certificates: the fleet's (fleetlink admin cert), a stranger CA's, and one of the
# fleet's CA that names another fleet (both made with openssl, as an attacker would)
pki="$tmp/pki"
certs="$pki/federation-sec"
for h in a b rogue; do
    "$bin" admin cert --dir "$pki" federation --fleet sec --hub "hub-$h" --ip 127.0.0.1 >/dev/null
done
printf 'subjectAltName=IP:127.0.0.1\nextendedKeyUsage=serverAuth,clientAuth\n' >"$tmp/ext.cnf"
leaf() { # NAME CN CA_CERT CA_KEY
    openssl req -newkey ec -pkeyopt ec_paramgen_curve:P-256 -nodes -keyout "$tmp/$1.key" \
        -out "$tmp/$1.csr" -subj "/CN=$2" 2>/dev/null
    openssl x509 -req -in "$tmp/$1.csr" -CA "$3" -CAkey "$4" -CAcreateserial -days 2 \
        -extfile "$tmp/ext.cnf" -out "$tmp/$1.pem" 2>/dev/null
}
openssl req -x509 -newkey ec -pkeyopt ec_paramgen_curve:P-256 -nodes -days 2 \
    -keyout "$tmp/stranger-ca.key" -out "$tmp/stranger-ca.pem" -subj "/CN=stranger CA" 2>/dev/null
leaf stranger "hub-x@sec" "$tmp/stranger-ca.pem" "$tmp/stranger-ca.key"
leaf otherfleet "hub-y@globex" "$certs/ca.pem" "$certs/ca.key"

# --- a hub that would federate without certificates refuses to start, saying how
if "$bin" hub --listen 127.0.0.1:0 --data-dir "$tmp/hub-nocert" --federate zenoh --fleet sec \
    --zenoh-listen tcp/127.0.0.1:0 >"$tmp/nocert.log" 2>&1; then
    failed+=("no-certificates start")
    echo "FAIL: a hub with --federate zenoh and no certificates started"
elif grep -q "prove who they are" "$tmp/nocert.log" && grep -q "fleetlink admin cert federation" "$tmp/nocert.log"; then
    echo "PASS: --federate zenoh without certificates refuses to start: $(grep -o 'hubs must prove[^:]*' "$tmp/nocert.log")"
else
    failed+=("no-certificates message")
    echo "FAIL: the refusal to start does not say how to set up certificates:"; tail -3 "$tmp/nocert.log"
fi

# --- hubs A and B, the same operators on both with different rules
read -r za < <("$python" -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])')
declare -A addr token alice nobody pid
rules_common='
  - subject: {user: alice}
    names: "/recordings"
    ops: [admin]
  - subject: {user: alice}
    names: "/rosapi/.*"
    ops: [call_service]
  - subject: {user: alice}
    names: "/robot1/.*"
    ops: [subscribe, call_service, send_action_goal, publish]
  - subject: {user: alice}
    names: "/robot1/(odom|secret_param)"
    ops: [subscribe, call_service, publish]
    effect: deny'
cat >"$tmp/rules-a.yaml" <<YAML
rules:$rules_common
  - subject: {user: alice}
    names: "/robot1/set_mode"
    ops: [call_service]
    effect: deny
  - subject: {hub: hub-b}
    names: "/robot1/joint_cmd"
    ops: [publish]
    effect: deny
YAML
printf 'rules:%s\n' "$rules_common" >"$tmp/rules-b.yaml"
for h in a b; do
    d="$tmp/hub-$h"
    token[$h]="$(timeout 30 "$bin" admin --data-dir "$d" token operator root --group admin)"
    alice[$h]="$(timeout 30 "$bin" admin --data-dir "$d" token operator alice)"
    nobody[$h]="$(timeout 30 "$bin" admin --data-dir "$d" token operator nobody)"
    timeout 30 "$bin" admin --data-dir "$d" rules import "$tmp/rules-$h.yaml" >/dev/null
done
robot_token="$(timeout 30 "$bin" admin --data-dir "$tmp/hub-a" token robot robot1)"
robot2_token="$(timeout 30 "$bin" admin --data-dir "$tmp/hub-a" token robot robot2)"
start_hub() { # NAME ZENOH-FLAGS...
    local h=$1; shift
    local log="$tmp/hub-$h.log"
    : >"$log"
    RUST_LOG=info,zenoh=warn "$bin" hub --listen 127.0.0.1:0 --data-dir "$tmp/hub-$h" \
        --federate zenoh --fleet sec --zenoh-ca "$certs/ca.pem" \
        --zenoh-cert "$certs/hub-$h.pem" --zenoh-key "$certs/hub-$h.key" "$@" >>"$log" 2>&1 &
    pids+=($!)
    pid[$h]=$!
    addr[$h]="$(wait_for_line "$log" '^fleetlink hub listening on ([0-9.:]+)$' "hub $h start" "${pid[$h]}")"
}
start_hub a --zenoh-listen "tls/127.0.0.1:$za"
start_hub b --zenoh-connect "tls/127.0.0.1:$za"
ln -s "$tmp/hub-a.log" "$tmp/hub.log"
echo "hub A: ws://${addr[a]}/ zenoh tls/127.0.0.1:$za; hub B: ws://${addr[b]}/ (connects only)"
wait_for_line "$tmp/hub-b.log" 'federation: hub (hub-a) \(.*admitted' "hub B admits hub A" "${pid[b]}" >/dev/null

# --- a hub given only --zenoh-connect listens on no federation port
listening="$(ss -Hltnp | grep -c "pid=${pid[b]}," || true)"
if [ "$listening" -eq 1 ]; then
    echo "PASS: hub B (only --zenoh-connect) listens on its HTTP port alone, on no Zenoh port"
else
    failed+=("connect-only listener")
    echo "FAIL: hub B (only --zenoh-connect) listens on $listening ports:"; ss -Hltnp | grep "pid=${pid[b]},"
fi

# --- the robot, with a black box of its odometry and scans
cat >"$tmp/agent.yaml" <<YAML
hub: ws://${addr[a]}/
name: robot1
token: $robot_token
runtime_file: $tmp/agent-state/runtime.json
local_rosbridge: { listen: 127.0.0.1:0 }
blackbox: { dir: $tmp/blackbox, topics: [/odom, /scan], compression: none }
sim:
  odometry: { rate_hz: 20 }
  laser_scan: { rate_hz: 5 }
YAML
: >"$tmp/agent.log"
RUST_LOG=info "$bin" agent --config "$tmp/agent.yaml" >"$tmp/agent.log" 2>&1 &
pids+=($!)
agent_pid=$!
local_addr="$(wait_for_line "$tmp/agent.log" '^  local rosbridge: ws://([0-9.:]+)/$' "agent start" "$agent_pid")"
echo "agent robot1 on hub A: local rosbridge ws://$local_addr/"

rc=0
timeout 240 "$python" "$here/security_check.py" \
    --hub "a=${addr[a]},${token[a]},${alice[a]},${nobody[a]}" \
    --hub "b=${addr[b]},${token[b]},${alice[b]},${nobody[b]}" \
    --zenoh "tls/127.0.0.1:$za" --certs "$certs" --tmp "$tmp" \
    --local "$local_addr" --robot2-token "$robot2_token" \
    --hub-log "$tmp/hub-a.log" --runtime-file "$tmp/agent-state/runtime.json" \
    --bin "$bin" || rc=$?
[ "$rc" -eq 0 ] || failed+=("security_check.py (exit $rc)")

if [ ${#failed[@]} -ne 0 ]; then
    echo "FAIL: security: ${failed[*]}"
    exit 1
fi
echo "PASS: security suite"

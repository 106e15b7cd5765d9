#!/usr/bin/env bash
# Site hubs interop suite (issue 40, item 1): real `fleetlink hub` processes chained with
# --upstream, real agents, roslibpy on both sides, the WAN between them a veth pair that
# is cut.
#
# Two network namespaces joined by a veth pair, the "WAN": cloud (10.202.0.1) runs the
# cloud hub; site (10.202.0.2) runs the site hub "site7" (--upstream to the cloud hub, a
# robot token minted there) and robot3's agent (simulator: odometry, set_mode, get_status,
# navigate_to_pose; a no_drop topic /counter fed through its local rosbridge listener).
# site_check.py runs in the cloud namespace as a roslibpy client of the cloud hub and
# starts its site-side peer (site_check.py --role local, in the site namespace):
#
#   1. robot3's service and action goal (feedback, result, and a cancel) across both hops;
#   2. /site7/robot3/odom and the no_drop /site7/robot3/counter received upstream;
#   3. the WAN cut for 10 s (ip link set down): the site's own roslibpy client keeps
#      receiving odometry from the site hub every second, and keeps publishing;
#   4. the WAN back: the cloud's subscriber gets odometry again without doing anything,
#      and every /counter value once, in order, none missing, those sent during the cut
#      included (they waited in the site's durable outbox).
#
# Then a triangle of three hubs (on the cloud namespace's loopback, fixed ports: the
# namespace is this run's own), each the site of the next, each bridging /chat both ways
# with it (--upstream-config with remap and subscribe): ten messages published on one hub
# reach each of the others at most twice (once by each way round) and never come back.
#
# Needs root and `ip netns`; otherwise prints SKIP. Every process runs in this run's own
# namespaces and is killed with them on exit. Bounded: about 40 s.
#
# Env: FLEETLINK_BIN (default target/release/fleetlink), PYTHON (default .venv/bin/python).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
bin="${FLEETLINK_BIN:-$root/target/release/fleetlink}"
python="${PYTHON:-$root/.venv/bin/python}"

if [ "$(id -u)" -ne 0 ]; then
    echo "SKIP: site hubs suite needs root (network namespaces)"; exit 0
fi
if ! command -v ip >/dev/null || ! ip netns list >/dev/null 2>&1; then
    echo "SKIP: site hubs suite needs \`ip netns\` (iproute2)"; exit 0
fi
[ -x "$bin" ] || { echo "FAIL: fleetlink binary not found at $bin (set FLEETLINK_BIN)" >&2; exit 1; }
[ -x "$python" ] || { echo "FAIL: $python missing; run scripts/setup.d/10-python-venv.sh" >&2; exit 1; }
bin="$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")"
export NO_COLOR=1 PYTHONDONTWRITEBYTECODE=1

run_id="$$-$(od -An -N2 -tx2 /dev/urandom | tr -d ' ')"
cloud_ns="flc-$run_id"
site_ns="fls-$run_id"
cloud_ip=10.202.0.1
site_ip=10.202.0.2
tmp="$(mktemp -d "${TMPDIR:-/tmp}/fleetlink-interop-site.XXXXXX")"
# The agent's state (its default runtime_file) in this run's directory, never the user's.
export XDG_STATE_HOME="$tmp/state"
unset STATE_DIRECTORY
made=()

cleanup() {
    local rc=$?
    trap - EXIT INT TERM
    for ns in "${made[@]}"; do
        for pid in $(ip netns pids "$ns" 2>/dev/null); do kill -TERM "$pid" 2>/dev/null || true; done
    done
    sleep 0.5
    for ns in "${made[@]}"; do
        for pid in $(ip netns pids "$ns" 2>/dev/null); do kill -KILL "$pid" 2>/dev/null || true; done
        ip netns del "$ns" 2>/dev/null || true
    done
    if [ "$rc" -ne 0 ]; then
        for f in cloud site robot tri-a tri-b tri-c; do
            [ -f "$tmp/$f.log" ] && { echo "--- last lines of $f log"; tail -n 20 "$tmp/$f.log"; } >&2
        done
    fi
    rm -rf "$tmp"
    exit "$rc"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

ip netns add "$cloud_ns" && made+=("$cloud_ns")
ip netns add "$site_ns" && made+=("$site_ns")
ip link add vc netns "$cloud_ns" type veth peer name vs netns "$site_ns"
ip -n "$cloud_ns" addr add "$cloud_ip/30" dev vc
ip -n "$site_ns" addr add "$site_ip/30" dev vs
for ns in "$cloud_ns" "$site_ns"; do ip -n "$ns" link set lo up; done
ip -n "$cloud_ns" link set vc up
ip -n "$site_ns" link set vs up
in_cloud() { ip netns exec "$cloud_ns" "$@"; }
in_site() { ip netns exec "$site_ns" "$@"; }

# Waits (bounded, 10 s) for a line matching $2 in log $1; prints its first group.
wait_line() {
    for _ in $(seq 200); do
        local m
        m="$(sed -nE "s#$2#\\1#p" "$1" | head -n1)"
        [ -n "$m" ] && { echo "$m"; return 0; }
        sleep 0.05
    done
    echo "FAIL: $3: no line matching '$2' in $1 within 10 s" >&2
    return 1
}

# --- the cloud hub, and the site's credential there
op_token="$("$bin" admin --data-dir "$tmp/cloud" token operator interop --group admin)"
site_token="$("$bin" admin --data-dir "$tmp/site" token operator local --group admin)"
"$bin" admin --data-dir "$tmp/cloud" token robot site7 >"$tmp/site7.token"
in_cloud "$bin" hub --listen "$cloud_ip:0" --data-dir "$tmp/cloud" >"$tmp/cloud.log" 2>&1 &
cloud_addr="$(wait_line "$tmp/cloud.log" '^fleetlink hub listening on ([0-9.:]+)$' "cloud hub start")"
echo "cloud hub: ws://$cloud_addr/ (namespace $cloud_ns)"

# --- the site hub: robots of its network need no token; upstream as site7
in_site "$bin" hub --listen "$site_ip:0" --data-dir "$tmp/site" --robot-network 10.202.0.0/30 \
    --robot-network 127.0.0.0/8 \
    --upstream "ws://$cloud_addr/" --name site7 --upstream-token-file "$tmp/site7.token" \
    >"$tmp/site.log" 2>&1 &
site_addr="$(wait_line "$tmp/site.log" '^fleetlink hub listening on ([0-9.:]+)$' "site hub start")"
echo "site hub:  ws://$site_addr/ (namespace $site_ns), upstream as site7"

# --- robot3 on the site hub
cat >"$tmp/robot.yaml" <<EOF
hub: ws://$site_addr/
name: robot3
heartbeat_ms: 500
local_rosbridge: { listen: 127.0.0.1:0 }
topics:
  /counter: { no_drop: true, queue: 2000 }
sim:
  odometry: { rate_hz: 10 }
  laser_scan: null
  point_cloud: null
  image: null
EOF
in_site "$bin" agent --config "$tmp/robot.yaml" >"$tmp/robot.log" 2>&1 &
local_addr="$(wait_line "$tmp/robot.log" '^  local rosbridge: ws://([0-9.:]+)/$' "agent start")"

rc=0
timeout --kill-after=5 90 ip netns exec "$cloud_ns" "$python" "$here/site_check.py" \
    --cloud "$cloud_addr" --token "$op_token" --site "$site_addr" --site-token "$site_token" \
    --local "$local_addr" \
    --site-ns "$site_ns" --wan-dev vs --python "$python" || rc=$?
[ "$rc" -eq 0 ] || { echo "FAIL: site hubs: the two-hop chain (exit $rc)" >&2; exit 1; }

# --- a triangle of hubs: a -> b -> c -> a, /chat bridged both ways at every link
declare -A port=([a]=18101 [b]=18102 [c]=18103) next=([a]=b [b]=c [c]=a)
for h in a b c; do
    "$bin" admin --data-dir "$tmp/tri-$h" token operator interop --group admin >"$tmp/tri-$h.op"
    printf 'rules:\n  - subject: any_robot\n    names: "/chat"\n    ops: [publish, subscribe]\n' |
        "$bin" admin --data-dir "$tmp/tri-$h" rules import - >/dev/null
done
for h in a b c; do
    n="${next[$h]}"
    "$bin" admin --data-dir "$tmp/tri-$n" token robot "site$h" >"$tmp/tri-$h.up"
    cat >"$tmp/tri-$h.yaml" <<EOF
hub: ws://127.0.0.1:${port[$n]}/
name: site$h
heartbeat_ms: 500
remap: { /chat: /chat }
subscribe:
  - { hub: /chat, local: /chat }
EOF
done
for h in a b c; do
    in_cloud "$bin" hub --listen "127.0.0.1:${port[$h]}" --data-dir "$tmp/tri-$h" \
        --upstream-config "$tmp/tri-$h.yaml" --upstream-token-file "$tmp/tri-$h.up" \
        >"$tmp/tri-$h.log" 2>&1 &
done
for h in a b c; do
    wait_line "$tmp/tri-$h.log" '^fleetlink hub listening on ([0-9.:]+)$' "triangle hub $h" >/dev/null
done
timeout --kill-after=5 60 ip netns exec "$cloud_ns" "$python" "$here/site_check.py" --role triangle \
    --hubs "127.0.0.1:${port[a]},127.0.0.1:${port[b]},127.0.0.1:${port[c]}" \
    --tokens "$(cat "$tmp/tri-a.op"),$(cat "$tmp/tri-b.op"),$(cat "$tmp/tri-c.op")" || rc=$?
[ "$rc" -eq 0 ] || { echo "FAIL: site hubs: the triangle (exit $rc)" >&2; exit 1; }
echo "PASS: site hubs interop (two hops with a 10 s WAN cut, and a triangle of hubs)"

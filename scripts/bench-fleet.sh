#!/usr/bin/env bash
# The fleet-size curve (issue 38): one hub on this machine, `fleetlink bench fleet` beside
# it, for each fleet size N: the fleet connected and idle, then loaded (TOPICS topics per
# robot at RATE Hz, one subscriber on every robot's pose topic and one on every topic).
# Each size gets a fresh hub (its memory per connection is measured from a clean start).
#
#   cargo build --release -p fleetlink && scripts/bench-fleet.sh [SIZES] [SECONDS]
#
#   SIZES    robots per run, default "100 300 1000 3000 10000"
#   SECONDS  measured seconds of each loaded run, default 10
#
# Env: FLEETLINK_BIN (default target/release/fleetlink); TOPICS (10), RATE (10), SIZE (64);
# LOADED_MAX (default 1000): sizes above it are measured idle only, with a loaded run at
# LOADED_RATE_BIG Hz (default 1) instead, since N x TOPICS x RATE is more than two cores
# can generate and relay beyond about 100k msg/s; HEARTBEAT_MS (default: the hub's 1000);
# IDLE_S (default 5): seconds the connected fleet is measured idle before the load;
# PROBE_MS (default 200, as the agent's link estimator probes while data waits: robots ping
# this often while they publish, at their heartbeat when idle; 0: heartbeat pings only).
# Pose subscribers: one per robot up to 1,000 (the first 1,000 robots' beyond that: two
# connections per robot would pass the open-files limit of 20,000 at 10,000 robots).
# SERVER=floor runs each size against `fleetlink bench fleet-floor` instead of a hub: the
# least a relay does for this traffic, the floor under the hub's figure (same machine,
# same generator; run both back to back and compare).
# Results: one JSON line per run in $OUT (default target/bench-fleet.jsonl) and a table on
# stdout. The hub trusts robots from 127.0.0.0/8 (--robot-network); subscribers use an
# admin operator token minted in its data directory.
set -euo pipefail
sizes="${1:-100 300 1000 3000 10000}"
seconds="${2:-10}"
root="$(cd "$(dirname "$0")/.." && pwd)"
bin="${FLEETLINK_BIN:-$root/target/release/fleetlink}"
topics="${TOPICS:-10}" rate="${RATE:-10}" size="${SIZE:-64}"
loaded_max="${LOADED_MAX:-1000}" big_rate="${LOADED_RATE_BIG:-1}"
out="${OUT:-$root/target/bench-fleet.jsonl}"
[ -x "$bin" ] || { echo "build first: cargo build --release -p fleetlink" >&2; exit 1; }
mkdir -p "$(dirname "$out")"
: >"$out"

tmp="$(mktemp -d "${TMPDIR:-/tmp}/fleetlink-bench-fleet.XXXXXX")"
hub_pid=
cleanup() {
    [ -n "$hub_pid" ] && kill "$hub_pid" 2>/dev/null && wait "$hub_pid" 2>/dev/null
    rm -rf "$tmp"
}
trap cleanup EXIT

start_hub() {
    rm -rf "$tmp/hub-data"
    if [ "${SERVER:-hub}" = floor ]; then
        token=floor
        : >"$tmp/hub.log"
        "$bin" bench fleet-floor --listen 127.0.0.1:0 >"$tmp/hub.log" 2>&1 &
        hub_pid=$!
        for _ in $(seq 100); do
            addr="$(sed -nE 's/^listening on ([0-9.:]+)$/\1/p' "$tmp/hub.log")"
            [ -n "$addr" ] && return 0
            sleep 0.1
        done
        echo "the floor did not start:" >&2
        cat "$tmp/hub.log" >&2
        exit 1
    fi
    token="$("$bin" admin --data-dir "$tmp/hub-data" token operator bench --group admin)"
    local hb=()
    [ -n "${HEARTBEAT_MS:-}" ] && hb=(--heartbeat-ms "$HEARTBEAT_MS")
    : >"$tmp/hub.log"
    "$bin" hub --listen 127.0.0.1:0 --data-dir "$tmp/hub-data" --robot-network 127.0.0.0/8 \
        "${hb[@]}" >"$tmp/hub.log" 2>&1 &
    hub_pid=$!
    for _ in $(seq 100); do
        addr="$(sed -nE 's/^fleetlink hub listening on ([0-9.:]+)$/\1/p' "$tmp/hub.log")"
        [ -n "$addr" ] && return 0
        sleep 0.1
    done
    echo "the hub did not start:" >&2
    cat "$tmp/hub.log" >&2
    exit 1
}

stop_hub() {
    kill "$hub_pid" 2>/dev/null || true
    wait "$hub_pid" 2>/dev/null || true
    hub_pid=
}

run() { # robots rate subscribers wildcard(0|1)
    local wild=()
    [ "$4" = 1 ] && wild=(--wildcard)
    FLEETLINK_SUBSCRIBER_TOKEN="$token" "$bin" bench fleet --hub "$addr" --hub-pid "$hub_pid" \
        --robots "$1" --topics "$topics" --rate "$2" --size "$size" --subscribers "$3" \
        --probe-ms "${PROBE_MS:-200}" \
        "${wild[@]}" --duration "$seconds" --idle "${IDLE_S:-5}" --json 2>"$tmp/bench.err" | tee -a "$out" ||
        { tail -5 "$tmp/bench.err" >&2; return 1; }
}

for n in $sizes; do
    if [ "$n" -le "$loaded_max" ]; then r="$rate"; else r="$big_rate"; fi
    subs=$((n < 1000 ? n : 1000))
    echo "== $n robots: idle, then $topics topics at $r Hz with $subs pose subscribers + 1 wildcard" >&2
    start_hub
    run "$n" "$r" "$subs" 1 >/dev/null
    stop_hub
done

# The table: one row per run.
python3 - "$out" <<'PY'
import json, sys
rows = [json.loads(l) for l in open(sys.argv[1]) if l.strip()]
print("| robots | connect s | hub MB idle | kB/conn | hub CPU % idle | rate Hz | in msg/s | delivered msg/s | drops | p50 ms | p99 ms | p999 ms | hub CPU % loaded | bench CPU % loaded |")
print("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
for r in rows:
    h = r["hub"][0] if r["hub"] else {}
    lat = r.get("latency_us") or {}
    ms = lambda k: f'{lat[k] / 1000:.1f}' if k in lat else "-"
    mb = lambda k: f'{h[k] / 1024:.0f}' if h.get(k) is not None else "-"
    print(f'| {r["robots"]} | {r["connect_s"]} | {mb("rss_idle_kb")} | {h.get("kb_per_connection", "-")} '
          f'| {h.get("cpu_idle_pct", "-")} | {r["rate"]:g} | {r["sent_per_s"]:.0f} | {r["delivered_per_s"]:.0f} '
          f'| {r["drops"]} | {ms("p50")} | {ms("p99")} | {ms("p999")} | {h.get("cpu_loaded_pct", "-")} '
          f'| {r.get("bench_cpu_loaded_pct", "-")} |')
PY

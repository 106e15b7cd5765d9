#!/usr/bin/env bash
# What a Zenoh hop between federated hubs costs (issues 38, 55): three hubs on this
# machine, joined by Zenoh on loopback, and `fleetlink bench fleet` beside them. For each
# fleet size N, three runs in turn (A B C A B C ..., REPEAT rounds):
#
#   one        robots and subscribers all on hub A (the other two hubs federated over
#              TLS but idle): every message stays on one hub;
#   three-tls  robot i on hub i mod 3, its pose subscriber on the next hub, the wildcard
#              subscriber on hub A: every pose message crosses one Zenoh hop, and the
#              wildcard's share of the other hubs' topics crosses to A. The hubs' links
#              are mutual TLS (certificates from `fleetlink admin cert federation`), as
#              a hub runs by default;
#   three-tcp  the same over plain TCP (--zenoh-insecure-tcp): what authentication costs.
#
# Latency is end to end (robot stamp to subscriber receipt, one clock); the Zenoh hop's
# cost is the difference between the runs. Hub CPU is summed over the three processes
# (from /proc) and divided by the messages delivered. At the defaults, 30 robots send
# 3,000 msg/s.
#
#   cargo build --release -p fleetlink && scripts/bench-federation.sh [SIZES] [SECONDS]
#
#   SIZES    robots per run, default "30 300"
#   SECONDS  measured seconds per run, default 10
#
# Env: FLEETLINK_BIN (default target/release/fleetlink); TOPICS (10), RATE (10),
# SIZE (64), REPEAT (2), OUT (default target/bench-federation.jsonl).
# The hubs share one data directory (SQLite in WAL mode is safe across processes), so one
# operator token works on all three; robots from 127.0.0.0/8 need none.
set -euo pipefail
sizes="${1:-30 300}"
seconds="${2:-10}"
root="$(cd "$(dirname "$0")/.." && pwd)"
bin="${FLEETLINK_BIN:-$root/target/release/fleetlink}"
topics="${TOPICS:-10}" rate="${RATE:-10}" size="${SIZE:-64}" repeat="${REPEAT:-2}"
out="${OUT:-$root/target/bench-federation.jsonl}"
[ -x "$bin" ] || { echo "build first: cargo build --release -p fleetlink" >&2; exit 1; }
"$bin" hub --help | grep -q -- --federate || { echo "$bin has no --federate" >&2; exit 1; }
mkdir -p "$(dirname "$out")"
: >"$out"

tmp="$(mktemp -d "${TMPDIR:-/tmp}/fleetlink-bench-federation.XXXXXX")"
pids=()
cleanup() {
    for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done
    for p in "${pids[@]}"; do wait "$p" 2>/dev/null || true; done
    rm -rf "$tmp"
}
trap cleanup EXIT

free_port() { python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])'; }
declare -A addr pid
pki="$tmp/pki/federation-bench"
for h in a b c; do
    "$bin" admin cert --dir "$tmp/pki" federation --fleet bench --hub "bench-$h" --ip 127.0.0.1 >/dev/null
done
start_hubs() { # tls|tcp
    local link=$1
    for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done
    for p in "${pids[@]}"; do wait "$p" 2>/dev/null || true; done
    pids=()
    rm -rf "$tmp/data"
    token="$("$bin" admin --data-dir "$tmp/data" token operator bench --group admin)"
    local za zb zc
    za="$(free_port)" zb="$(free_port)" zc="$(free_port)"
    declare -A listen=([a]=$za [b]=$zb [c]=$zc)
    declare -A connect=([a]="" [b]="--zenoh-connect $link/127.0.0.1:$za"
        [c]="--zenoh-connect $link/127.0.0.1:$za --zenoh-connect $link/127.0.0.1:$zb")
    for h in a b c; do
        : >"$tmp/hub-$h.log"
        local trust=(--zenoh-insecure-tcp --hub-name "bench-$h")
        [ "$link" = tls ] && trust=(--zenoh-ca "$pki/ca.pem" --zenoh-cert "$pki/bench-$h.pem" --zenoh-key "$pki/bench-$h.key")
        # shellcheck disable=SC2086 # several words on purpose
        "$bin" hub --listen 127.0.0.1:0 --data-dir "$tmp/data" --robot-network 127.0.0.0/8 \
            --federate zenoh --fleet bench "${trust[@]}" \
            --zenoh-listen "$link/127.0.0.1:${listen[$h]}" ${connect[$h]} >"$tmp/hub-$h.log" 2>&1 &
        pids+=($!)
        pid[$h]=$!
        addr[$h]=""
        for _ in $(seq 100); do
            addr[$h]="$(sed -nE 's/^fleetlink hub listening on ([0-9.:]+)$/\1/p' "$tmp/hub-$h.log")"
            [ -n "${addr[$h]}" ] && break
            sleep 0.1
        done
        [ -n "${addr[$h]}" ] || { echo "hub $h did not start:" >&2; cat "$tmp/hub-$h.log" >&2; exit 1; }
    done
    sleep 1 # the hubs find each other
}

run() { # label robots hub-args...
    local label=$1 n=$2
    shift 2
    local subs=$((n < 1000 ? n : 1000))
    FLEETLINK_SUBSCRIBER_TOKEN="$token" "$bin" bench fleet "$@" \
        --hub-pid "${pid[a]}" --hub-pid "${pid[b]}" --hub-pid "${pid[c]}" \
        --robots "$n" --topics "$topics" --rate "$rate" --size "$size" --subscribers "$subs" \
        --wildcard --duration "$seconds" --json 2>"$tmp/bench.err" |
        python3 -c 'import json,sys; r=json.load(sys.stdin); r["layout"]=sys.argv[1]; print(json.dumps(r))' "$label" |
        tee -a "$out" >/dev/null || { tail -5 "$tmp/bench.err" >&2; return 1; }
}

for n in $sizes; do
    for i in $(seq "$repeat"); do
        echo "== $n robots, round $i: one hub, then three over TLS, then three over plain TCP" >&2
        start_hubs tls
        run one "$n" --hub "ws://${addr[a]}/"
        for link in tls tcp; do
            start_hubs "$link"
            run "three-$link" "$n" --hub "ws://${addr[a]}/" --hub "ws://${addr[b]}/" --hub "ws://${addr[c]}/"
        done
    done
done

python3 - "$out" <<'PY'
import json, statistics, sys
rows = [json.loads(l) for l in open(sys.argv[1]) if l.strip()]
print("| robots | layout | in msg/s | delivered msg/s | drops | p50 ms | p99 ms | hubs' CPU % (sum) | hub CPU µs per delivered msg | bench CPU % |")
print("|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|")
for r in rows:
    lat = r.get("latency_us") or {}
    cpu = sum(h.get("cpu_loaded_pct") or 0 for h in r["hub"])
    per = cpu / 100 * 1e6 / r["delivered_per_s"] if r["delivered_per_s"] else float("nan")
    print(f'| {r["robots"]} | {r["layout"]} | {r["sent_per_s"]:.0f} | {r["delivered_per_s"]:.0f} | {r["drops"]} '
          f'| {lat.get("p50", 0) / 1000:.2f} | {lat.get("p99", 0) / 1000:.2f} | {cpu:.0f} | {per:.1f} '
          f'| {r.get("bench_cpu_loaded_pct", "-")} |')
# Medians per size and layout, and the hop: three minus one.
by = {}
for r in rows:
    by.setdefault((r["robots"], r["layout"]), []).append(r)
med = lambda rs, f: statistics.median(f(r) for r in rs)
p50 = lambda r: (r.get("latency_us") or {}).get("p50", 0) / 1000
for n in sorted({k[0] for k in by}):
    one = by.get((n, "one"), [])
    if not one:
        continue
    for link in ("tls", "tcp"):
        three = by.get((n, f"three-{link}"), [])
        if three:
            print(f"{n} robots: median p50 one hub {med(one, p50):.2f} ms, three hubs over {link} "
                  f"{med(three, p50):.2f} ms: the Zenoh hop adds {med(three, p50) - med(one, p50):.2f} ms at p50")
PY

#!/usr/bin/env bash
# Server CPU per delivered message (issue 13's benchmark): one publisher and one subscriber
# exchange 64-byte messages at a fixed rate through the fleetlink hub (rosbridge JSON,
# rosbridge CBOR, native fleetlink.v1), nats-server and mosquitto, all driven by the same
# generator (`fleetlink bench delivery`). Each server's CPU comes from /proc over the
# measured window, so a generator that saturates first does not bend the figure. Servers
# run on core 0 and the generator on core 1 (taskset) when there are two cores or more.
# Rounds alternate the systems; the table gives the median of the rounds. The floor rows
# are `fleetlink bench ws-floor`, a bare WebSocket relay with the hub's shape and none of
# its work (no parsing, checks or routing), driven as rosbridge JSON: on the hub's own
# WebSocket layer (the hub's JSON figure minus this one is what the hub's own work costs
# per message) and on tokio-tungstenite (what that library would cost instead).
#
#   cargo build --release -p fleetlink && scripts/bench-delivery.sh [ROUNDS] [RATES] [SECONDS]
#   e.g. scripts/bench-delivery.sh 3 "100000 300000" 5
#
# BASELINE_BIN=PATH also starts a hub from another build (e.g. the commit before a change)
# and runs the rosbridge JSON and CBOR paths against it in the same rounds, alternating
# with this build's hub: before/after in one run ("baseline" rows).
#
# nats-server and mosquitto come from Debian (installed here when missing; needs root).
set -euo pipefail
. "$(dirname "$0")/bench-lib.sh"
rounds="${1:-3}"
rates="${2:-100000 300000}"
seconds="${3:-5}"
bench_init delivery

missing=()
command -v nats-server >/dev/null || missing+=(nats-server)
command -v mosquitto >/dev/null || missing+=(mosquitto)
if [ ${#missing[@]} -ne 0 ]; then
    [ "$(id -u)" -eq 0 ] || { echo "install ${missing[*]} (Debian packages) or run as root" >&2; exit 1; }
    apt-get -o DPkg::Lock::Timeout=600 update
    DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=600 install -y --no-install-recommends "${missing[@]}"
fi

server_cpu=() gen_cpu=()
if [ "$(nproc)" -ge 2 ]; then server_cpu=(taskset -c 0); gen_cpu=(taskset -c 1); fi

token="$("$bin" admin --data-dir "$tmp/hub" token operator bench --group admin)"
hub_port="$(free_port)"
"${server_cpu[@]}" "$bin" hub --listen "127.0.0.1:$hub_port" --data-dir "$tmp/hub" >"$tmp/hub.log" 2>&1 &
hub_pid=$!; pids+=($hub_pid)
nats_port="$(free_port)"
"${server_cpu[@]}" nats-server -a 127.0.0.1 -p "$nats_port" >"$tmp/nats.log" 2>&1 &
nats_pid=$!; pids+=($nats_pid)
mqtt_port="$(free_port)"
"${server_cpu[@]}" mosquitto -p "$mqtt_port" >"$tmp/mosquitto.log" 2>&1 &
mqtt_pid=$!; pids+=($mqtt_pid)
floor_port="$(free_port)"
"${server_cpu[@]}" "$bin" bench ws-floor --listen "127.0.0.1:$floor_port" >"$tmp/floor.log" 2>&1 &
floor_pid=$!; pids+=($floor_pid)
tung_port="$(free_port)"
"${server_cpu[@]}" "$bin" bench ws-floor --websocket tungstenite --listen "127.0.0.1:$tung_port" \
    >"$tmp/floor-tungstenite.log" 2>&1 &
tung_pid=$!; pids+=($tung_pid)
base_pid=""
if [ -n "${BASELINE_BIN:-}" ]; then
    base_port="$(free_port)"
    "$BASELINE_BIN" admin --data-dir "$tmp/base" token operator bench --group admin >"$tmp/base.token"
    "${server_cpu[@]}" "$BASELINE_BIN" hub --listen "127.0.0.1:$base_port" --data-dir "$tmp/base" \
        >"$tmp/base.log" 2>&1 &
    base_pid=$!; pids+=($base_pid)
    wait_port "$base_port"
fi
wait_port "$hub_port"; wait_port "$nats_port"; wait_port "$mqtt_port"; wait_port "$floor_port"
wait_port "$tung_port"

run() { # protocol server pid rate [token]
    "${gen_cpu[@]}" "$bin" bench delivery --protocol "$1" --server "$2" --token "${5:-$token}" \
        --server-pid "$3" --rate "$4" --duration "$seconds" --warmup 2 --json
}
for round in $(seq "$rounds"); do
    for rate in $rates; do
        run rosbridge-json "ws://127.0.0.1:$hub_port" "$hub_pid" "$rate"
        run rosbridge-cbor "ws://127.0.0.1:$hub_port" "$hub_pid" "$rate"
        if [ -n "$base_pid" ]; then
            run rosbridge-json "ws://127.0.0.1:$base_port" "$base_pid" "$rate" "$(cat "$tmp/base.token")" |
                sed 's/"protocol":"RosbridgeJson"/"protocol":"BaselineJson"/'
            run rosbridge-cbor "ws://127.0.0.1:$base_port" "$base_pid" "$rate" "$(cat "$tmp/base.token")" |
                sed 's/"protocol":"RosbridgeCbor"/"protocol":"BaselineCbor"/'
        fi
        run native "ws://127.0.0.1:$hub_port" "$hub_pid" "$rate"
        run rosbridge-json "ws://127.0.0.1:$floor_port" "$floor_pid" "$rate" |
            sed 's/"protocol":"RosbridgeJson"/"protocol":"WsFloor"/'
        run rosbridge-json "ws://127.0.0.1:$tung_port" "$tung_pid" "$rate" |
            sed 's/"protocol":"RosbridgeJson"/"protocol":"WsFloorTungstenite"/'
        run nats "127.0.0.1:$nats_port" "$nats_pid" "$rate"
        run mqtt "127.0.0.1:$mqtt_port" "$mqtt_pid" "$rate"
    done
    echo "round $round of $rounds done" >&2
done >"$tmp/results.jsonl"

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
echo "versions: $("$bin" --version), $(nats-server --version), mosquitto $(dpkg-query -W -f='${Version}' mosquitto 2>/dev/null || echo '?')"
python3 - "$tmp/results.jsonl" <<'EOF'
import json, statistics, sys
rows = [json.loads(l) for l in open(sys.argv[1]) if l.strip()]
names = {"RosbridgeJson": "fleetlink rosbridge JSON", "RosbridgeCbor": "fleetlink rosbridge CBOR",
         "BaselineJson": "baseline build, JSON", "BaselineCbor": "baseline build, CBOR",
         "Native": "fleetlink native", "WsFloor": "floor: bare WebSocket relay",
         "WsFloorTungstenite": "floor on tokio-tungstenite",
         "Nats": "nats-server", "Mqtt": "mosquitto (MQTT QoS 0)"}
print(f"{'system':28} {'rate':>8} {'delivered/s':>12} {'server CPU':>11} {'µs/delivery (median, min-max)':>32}")
for rate in sorted({r["rate"] for r in rows}):
    for proto in names:
        rs = [r for r in rows if r["rate"] == rate and r["protocol"] == proto]
        if not rs:
            continue
        us = [r["server_cpu_us_per_delivery"] for r in rs]
        print(f"{names[proto]:28} {rate:>8} {statistics.median(r['delivered_per_sec'] for r in rs):>12.0f} "
              f"{statistics.median(r['server_cpu_percent'] for r in rs):>10.1f}% "
              f"{statistics.median(us):>14.2f} ({min(us):.2f}-{max(us):.2f})")
EOF

#!/usr/bin/env bash
# Hub memory per idle rosbridge connection: N clients connect, each advertises a topic
# and publishes one 64-byte message, then stays connected without sending or reading
# anything more. Prints the hub's resident memory before and after, and the difference per
# connection.
#
#   cargo build --release -p fleetlink && scripts/bench-idle-memory.sh [N]
set -euo pipefail
. "$(dirname "$0")/bench-lib.sh"
bench_init idle-memory
n="${1:-400}"
token="$("$bin" admin --data-dir "$tmp/hub" token operator bench --group admin)"
port="$(free_port)"
"$bin" hub --listen "127.0.0.1:$port" --data-dir "$tmp/hub" \
    --max-connections $((n + 100)) --max-connections-per-ip $((n + 100)) >"$tmp/hub.log" 2>&1 &
hub=$!; pids+=($hub)
wait_port "$port"
sleep 1
rss() { awk '/VmRSS/ {print $2}' "/proc/$hub/status"; }
before="$(rss)"
# A bare WebSocket client per connection: the handshake, two masked text frames.
python3 - "$port" "$n" "$token" >"$tmp/clients.log" 2>&1 <<'PY' &
import asyncio, base64, json, os, struct, sys
port, n, token = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
def frame(text):
    b, key = text.encode(), os.urandom(4)
    head = bytes([0x81, 0x80 | len(b)]) if len(b) < 126 else bytes([0x81, 0x80 | 126]) + struct.pack(">H", len(b))
    return head + key + bytes(c ^ key[i % 4] for i, c in enumerate(b))
async def client(i, keep):
    r, w = await asyncio.open_connection("127.0.0.1", port)
    key = base64.b64encode(os.urandom(16)).decode()
    w.write((f"GET /?token={token} HTTP/1.1\r\nHost: hub\r\nUpgrade: websocket\r\n"
             f"Connection: Upgrade\r\nSec-WebSocket-Key: {key}\r\nSec-WebSocket-Version: 13\r\n\r\n").encode())
    await w.drain()
    await r.readuntil(b"\r\n\r\n")
    topic = f"/idle/t{i}"
    w.write(frame(json.dumps({"op": "advertise", "topic": topic, "type": "std_msgs/String"})))
    w.write(frame(json.dumps({"op": "publish", "topic": topic, "msg": {"data": "x" * 64}})))
    await w.drain()
    keep.append((r, w))
async def main():
    keep = []
    for i in range(0, n, 50):
        await asyncio.gather(*(client(j, keep) for j in range(i, min(n, i + 50))))
    await asyncio.sleep(3)
    print("connected", len(keep), flush=True)
    await asyncio.sleep(3600)
asyncio.run(main())
PY
pids+=($!)
for _ in $(seq 600); do grep -q connected "$tmp/clients.log" && break; sleep 0.1; done
grep -q connected "$tmp/clients.log" || { cat "$tmp/clients.log" >&2; exit 1; }
after="$(rss)"
echo "hub RSS: $before kB idle, $after kB with $n idle rosbridge connections: $(( (after - before) / n )) kB per connection"

#!/usr/bin/env python3
"""Viewers with and without permessage-deflate, for scripts/bench-deflate.sh.

  bytes: two rosbridge viewers at once on the same topics, one that negotiated
         permessage-deflate and one that did not; bytes each read from its socket
         (WebSocket frames as they arrived) over the window.
  cpu:   N viewers of one topic; the hub's CPU (utime + stime from /proc) over the
         window, and the messages the viewers got.

Prints one JSON line. Python `websockets` offers permessage-deflate by default, as
browsers do; `compression=None` turns it off.
"""
import argparse
import asyncio
import json
import os
import time

from websockets.asyncio.client import connect
from websockets.protocol import Protocol

_receive_data = Protocol.receive_data


def _counting_receive_data(self, data):
    self.bench_bytes = getattr(self, "bench_bytes", 0) + len(data)
    return _receive_data(self, data)


Protocol.receive_data = _counting_receive_data


def cpu_seconds(pid):
    with open(f"/proc/{pid}/stat") as f:
        fields = f.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


class Viewer:
    def __init__(self, ws):
        self.ws, self.messages = ws, 0

    async def run(self):
        try:
            async for _ in self.ws:
                self.messages += 1
        except Exception:
            pass


async def open_viewer(url, deflate, subs):
    ws = await connect(url, compression="deflate" if deflate else None, max_size=None,
                       max_queue=None)
    negotiated = "permessage-deflate" in ws.response.headers.get("Sec-WebSocket-Extensions", "")
    assert negotiated == deflate, f"deflate negotiated: {negotiated}, wanted {deflate}"
    for s in subs:
        await ws.send(json.dumps({"op": "subscribe", **s}))
    v = Viewer(ws)
    v.task = asyncio.create_task(v.run())
    return v


async def window(viewers, seconds, warmup, pid=None):
    await asyncio.sleep(warmup)
    b0 = [v.ws.protocol.bench_bytes for v in viewers]
    m0 = [v.messages for v in viewers]
    c0, t0 = (cpu_seconds(pid) if pid else 0), time.monotonic()
    await asyncio.sleep(seconds)
    c1, t1 = (cpu_seconds(pid) if pid else 0), time.monotonic()
    b = [v.ws.protocol.bench_bytes - x for v, x in zip(viewers, b0)]
    m = [v.messages - x for v, x in zip(viewers, m0)]
    for v in viewers:
        await v.ws.close()
    return b, m, c1 - c0, t1 - t0


async def main():
    p = argparse.ArgumentParser()
    p.add_argument("mode", choices=["bytes", "cpu"])
    p.add_argument("--url", required=True)
    p.add_argument("--subs", required=True, help="JSON list of subscribe operations (without op)")
    p.add_argument("--viewers", type=int, default=1)
    p.add_argument("--deflate", type=int, default=1)
    p.add_argument("--hub-pid", type=int)
    p.add_argument("--seconds", type=float, default=10)
    p.add_argument("--warmup", type=float, default=2)
    a = p.parse_args()
    subs = json.loads(a.subs)
    if a.mode == "bytes":
        vs = [await open_viewer(a.url, True, subs), await open_viewer(a.url, False, subs)]
        b, m, _, t = await window(vs, a.seconds, a.warmup)
        print(json.dumps({"mode": "bytes", "deflate_bytes_per_s": b[0] / t, "plain_bytes_per_s": b[1] / t,
                          "deflate_messages": m[0], "plain_messages": m[1], "seconds": t}))
    else:
        vs = [await open_viewer(a.url, bool(a.deflate), subs) for _ in range(a.viewers)]
        b, m, cpu, t = await window(vs, a.seconds, a.warmup, a.hub_pid)
        delivered = sum(m)
        print(json.dumps({"mode": "cpu", "viewers": a.viewers, "deflate": bool(a.deflate),
                          "hub_cpu_percent": 100 * cpu / t, "delivered": delivered,
                          "bytes_per_s": sum(b) / t,
                          "hub_cpu_us_per_delivery": 1e6 * cpu / delivered if delivered else None}))


asyncio.run(main())

#!/usr/bin/env python3
"""permessage-deflate with Python `websockets` (issue 56), a rosbridge client as scripts
write them: `websockets` offers the extension by default.

Against the hub and against the agent's local listener (--url, several times):
  - the handshake's answer carries permessage-deflate with server_no_context_takeover;
  - a subscription to the robot's point cloud (JSON) arrives compressed (RSV1, counted
    where websockets inflates frames) and whole (its point count);
  - a large message this client publishes goes out compressed (websockets compresses
    what it sends) and comes back to a second subscriber as it was sent;
and, on the first URL only, a compressed message inflating past the hub's message size
limit (a zip bomb of a few KB) closes that connection with 1009 while another one keeps
being served. Exits 0 when every check passed, 1 naming the failed check.
"""
import argparse
import asyncio
import json
import sys

from websockets.asyncio.client import connect
from websockets.exceptions import ConnectionClosed
from websockets.extensions import permessage_deflate

TIMEOUT = 15

compressed_in = 0
_decode = permessage_deflate.PerMessageDeflate.decode


def _counting_decode(self, frame, *, max_size=None):
    global compressed_in
    if frame.rsv1:
        compressed_in += 1
    return _decode(self, frame, max_size=max_size)


permessage_deflate.PerMessageDeflate.decode = _counting_decode


class CheckFailed(Exception):
    pass


def check(cond, what):
    if not cond:
        raise CheckFailed(what)


def ok(what):
    print(f"  ok: {what}", flush=True)


async def first(ws, pred):
    async def loop():
        while True:
            m = json.loads(await ws.recv())
            if pred(m):
                return m
    return await asyncio.wait_for(loop(), TIMEOUT)


async def check_url(url, cloud_topic, points):
    async with connect(url, max_size=64 << 20) as ws:
        answer = ws.response.headers.get("Sec-WebSocket-Extensions", "")
        check("permessage-deflate" in answer and "server_no_context_takeover" in answer,
              f"{url}: answer '{answer}' lacks permessage-deflate; server_no_context_takeover")
        ok(f"negotiated: {answer}")
        before = compressed_in
        await ws.send(json.dumps({"op": "subscribe", "topic": cloud_topic}))
        m = await first(ws, lambda m: m.get("op") == "publish" and m.get("topic") == cloud_topic)
        c = m["msg"]
        check(c["width"] * c["height"] == points, f"cloud has {c['width'] * c['height']} points, want {points}")
        check(compressed_in > before, "the point cloud did not arrive compressed (no RSV1 frame)")
        ok(f"{cloud_topic}: {points} points, arrived compressed")
        # Publish a large message compressed; a second client receives it.
        topic = "/deflate_interop/text"
        async with connect(url, max_size=64 << 20) as sub:
            await sub.send(json.dumps({"op": "subscribe", "topic": topic, "type": "std_msgs/msg/String"}))
            await ws.send(json.dumps({"op": "advertise", "topic": topic, "type": "std_msgs/msg/String"}))
            text = "".join(f"line {i} of a long report; " for i in range(20000))
            got = None
            for _ in range(50):
                await ws.send(json.dumps({"op": "publish", "topic": topic, "msg": {"data": text}}))
                try:
                    got = await asyncio.wait_for(
                        first(sub, lambda m: m.get("op") == "publish" and m.get("topic") == topic), 0.3)
                    break
                except asyncio.TimeoutError:
                    continue
            check(got is not None, f"{topic}: nothing arrived")
            check(got["msg"]["data"] == text, f"{topic}: the text arrived changed ({len(got['msg']['data'])} chars)")
            ok(f"a compressed publish of {len(text)} chars arrived whole")


async def check_bomb(url, cloud_topic, limit):
    async with connect(url, max_size=64 << 20) as other:
        await other.send(json.dumps({"op": "subscribe", "topic": cloud_topic}))
        await first(other, lambda m: m.get("topic") == cloud_topic)
        async with connect(url, max_size=64 << 20) as ws:
            # Zeros compress about a thousand to one: a few KB on the wire.
            await ws.send(json.dumps({"op": "publish", "topic": "/bomb", "msg": {"data": "0" * (limit + 1024)}}))
            try:
                await asyncio.wait_for(ws.recv(), TIMEOUT)
                raise CheckFailed("the hub answered a message over its limit instead of closing")
            except ConnectionClosed as e:
                code = e.rcvd.code if e.rcvd else None
                check(code == 1009, f"closed with {code}, want 1009")
        ok(f"a compressed message inflating past {limit} bytes: closed with 1009")
        # The other connection is still served.
        await first(other, lambda m: m.get("topic") == cloud_topic)
        ok("another client on the same hub still receives")


async def main():
    p = argparse.ArgumentParser()
    p.add_argument("--url", action="append", required=True, help="a rosbridge URL and its cloud topic: URL=TOPIC")
    p.add_argument("--points", type=int, default=2000)
    p.add_argument("--limit", type=int, default=16 << 20, help="the server's message size limit")
    a = p.parse_args()
    targets = [u.rsplit("=", 1) for u in a.url]
    for url, topic in targets:
        await check_url(url, topic, a.points)
    await check_bomb(targets[0][0], targets[0][1], a.limit)


try:
    asyncio.run(main())
except CheckFailed as e:
    print(f"FAIL: {e}", file=sys.stderr)
    sys.exit(1)

"""The ROS 2 bridging benchmark's peers (scripts/bench-ros2.sh runs them).

  publish        a Cyclone DDS node writing sensor_msgs/msg/PointCloud2 on /points at
                 --hz, --points points of 16 bytes (x, y, z, intensity), header.stamp =
                 the wall clock at write
  hub-sub        a rosbridge client of the fleetlink hub subscribed with
                 compression "cbor-raw" (the CDR as the robot wrote it): latency = arrival
                 - header.stamp
  rosbridge-style  the comparison bridge: a Cyclone reader that does what rosbridge's
                 server does with a message (decode it into an object, turn it into JSON
                 with uint8[] as base64, send it as a publish op over a WebSocket)
  style-sub      a client of that bridge measuring latency the same way
  dds-sub        a Cyclone subscriber on the robot: the latency floor (no bridge)

Latency figures are printed as one JSON line: {"n", "p50_ms", "p99_ms", "max_ms"}.
"""
import argparse
import asyncio
import base64
import json
import struct
import sys
import threading
import time

import ros2_types as T
from ros2_dds import Node, now


def points(n):
    fields = [T.PointField(name=f, offset=4 * i, datatype=7, count=1) for i, f in enumerate("xyz")]
    fields.append(T.PointField(name="intensity", offset=12, datatype=7, count=1))
    data = bytes(range(256)) * (n * 16 // 256) + bytes(n * 16 % 256)
    return fields, data


def publish(args):
    node = Node()
    w = node.writer("rt/points", T.PointCloud2)
    fields, data = points(args.points)
    period = 1.0 / args.hz
    end = time.time() + args.seconds
    nxt = time.time()
    sent = 0
    wrote = []
    print("publish ready", flush=True)
    while time.time() < end:
        msg = T.PointCloud2(
            header=T.Header(stamp=now(), frame_id="lidar"),
            height=1, width=args.points, fields=fields, is_bigendian=False,
            point_step=16, row_step=16 * args.points, data=data, is_dense=True)
        w.write(msg)
        # How long building and serializing took after the stamp: part of every latency
        # below, not the bridges' doing.
        wrote.append(time.time() - (msg.header.stamp.sec + msg.header.stamp.nanosec / 1e9))
        sent += 1
        nxt += period
        time.sleep(max(0.0, nxt - time.time()))
    print(json.dumps({"sent": sent, "write": summary(wrote[5:])}), flush=True)


def summary(lat):
    lat.sort()
    if not lat:
        return {"n": 0}
    pick = lambda q: round(lat[min(len(lat) - 1, int(q * len(lat)))] * 1000, 2)
    return {"n": len(lat), "p50_ms": pick(0.5), "p99_ms": pick(0.99), "max_ms": round(lat[-1] * 1000, 2)}


def stamp_of_cdr(cdr):
    sec, nsec = struct.unpack_from("<iI", cdr, 4)
    return sec + nsec / 1e9


async def hub_sub(args):
    import cbor2
    import websockets
    lat = []
    async with websockets.connect(args.url, max_size=None) as ws:
        await ws.send(json.dumps({"op": "subscribe", "topic": args.topic, "compression": "cbor-raw"}))
        print("hub-sub ready", flush=True)
        end = time.time() + args.seconds
        while time.time() < end:
            try:
                frame = await asyncio.wait_for(ws.recv(), timeout=max(0.1, end - time.time()))
            except asyncio.TimeoutError:
                break
            t = time.time()
            if isinstance(frame, bytes):
                m = cbor2.loads(frame)
                if m.get("op") == "publish":
                    lat.append(t - stamp_of_cdr(m["msg"]["bytes"]))
    print(json.dumps(summary(lat[args.skip:])), flush=True)


def rosbridge_style(args):
    """Decode → object → JSON (uint8[] as base64, as rosbridge does) → every client."""
    import websockets.sync.server as wss
    clients = set()
    lock = threading.Lock()

    def to_obj(v):
        if isinstance(v, (bytes, bytearray)):
            return base64.b64encode(v).decode()
        if hasattr(v, "__dataclass_fields__"):
            return {k: to_obj(getattr(v, k)) for k in v.__dataclass_fields__}
        if isinstance(v, list):
            if v and isinstance(v[0], int) and all(0 <= x < 256 for x in v[:8]):
                return base64.b64encode(bytes(v)).decode()
            return [to_obj(x) for x in v]
        return v

    def on_sample(s):
        text = json.dumps({"op": "publish", "topic": "/points", "msg": to_obj(s)})
        with lock:
            targets = list(clients)
        for c in targets:
            try:
                c.send(text)
            except Exception:
                pass

    node = Node()
    node.reader("rt/points", T.PointCloud2, on_sample)

    def handler(ws):
        with lock:
            clients.add(ws)
        try:
            for _ in ws:
                pass
        finally:
            with lock:
                clients.discard(ws)

    with wss.serve(handler, "127.0.0.1", args.port, max_size=None) as server:
        print("rosbridge-style ready", flush=True)
        server.serve_forever()


async def style_sub(args):
    import websockets
    lat = []
    async with websockets.connect(args.url, max_size=None) as ws:
        print("style-sub ready", flush=True)
        end = time.time() + args.seconds
        while time.time() < end:
            try:
                frame = await asyncio.wait_for(ws.recv(), timeout=max(0.1, end - time.time()))
            except asyncio.TimeoutError:
                break
            t = time.time()
            st = json.loads(frame)["msg"]["header"]["stamp"]
            lat.append(t - (st["sec"] + st["nanosec"] / 1e9))
    print(json.dumps(summary(lat[args.skip:])), flush=True)


def dds_sub(args):
    """The floor: a Cyclone reader on the robot, latency the same way."""
    lat = []
    node = Node()
    node.reader("rt/points", T.PointCloud2,
                lambda s: lat.append(time.time() - (s.header.stamp.sec + s.header.stamp.nanosec / 1e9)))
    print("dds-sub ready", flush=True)
    time.sleep(args.seconds)
    print(json.dumps(summary(list(lat)[args.skip:])), flush=True)


def main():
    p = argparse.ArgumentParser()
    sub = p.add_subparsers(dest="mode", required=True)
    a = sub.add_parser("publish")
    a.add_argument("--points", type=int, default=65536)
    a.add_argument("--hz", type=float, default=10)
    a.add_argument("--seconds", type=float, default=30)
    for name in ("hub-sub", "style-sub"):
        a = sub.add_parser(name)
        a.add_argument("--url", required=True)
        a.add_argument("--topic", default="/robot1/points")
        a.add_argument("--seconds", type=float, default=30)
        a.add_argument("--skip", type=int, default=5, help="first messages left out (warm-up)")
    a = sub.add_parser("dds-sub")
    a.add_argument("--seconds", type=float, default=30)
    a.add_argument("--skip", type=int, default=5)
    a = sub.add_parser("rosbridge-style")
    a.add_argument("--port", type=int, required=True)
    args = p.parse_args()
    if args.mode == "publish":
        publish(args)
    elif args.mode == "hub-sub":
        asyncio.run(hub_sub(args))
    elif args.mode == "style-sub":
        asyncio.run(style_sub(args))
    elif args.mode == "dds-sub":
        dds_sub(args)
    else:
        rosbridge_style(args)


if __name__ == "__main__":
    sys.exit(main())

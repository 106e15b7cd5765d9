"""The WebSocket clients of the ROS 1 bridging benchmark (scripts/bench-ros1.sh runs them
with the project's venv: roslibpy, websockets, cbor2). Both stand for the hub side.

  cbor-raw   a rosbridge v2 client (websockets + cbor2) subscribed with compression
             "cbor-raw": the ROS 1 serialization as the robot published it. Used on the
             fleetlink hub, and on rosbridge_server when the bench compares that mode.
  roslibpy   a roslibpy subscriber (JSON, roslibpy's only encoding for data: uint8[] as
             base64), the ordinary way a Python client reads rosbridge.

Each measures latency as arrival (after decoding the frame) - header.stamp, and prints it
as one JSON line: {"n", "p50_ms", "p99_ms", "max_ms"}.
"""
import argparse
import asyncio
import json
import struct
import sys
import threading
import time


def summary(lat):
    lat = sorted(lat)
    if not lat:
        return {"n": 0}
    pick = lambda q: round(lat[min(len(lat) - 1, int(q * len(lat)))] * 1000, 2)
    return {"n": len(lat), "p50_ms": pick(0.5), "p99_ms": pick(0.99), "max_ms": round(lat[-1] * 1000, 2)}


def stamp_of_ros1(raw):
    # std_msgs/Header first: uint32 seq, then time stamp as uint32 secs, uint32 nsecs.
    sec, nsec = struct.unpack_from("<II", raw, 4)
    return sec + nsec / 1e9


async def cbor_raw(args):
    import cbor2
    import websockets

    lat = []
    async with websockets.connect(args.url, max_size=None) as ws:
        await ws.send(json.dumps({"op": "subscribe", "topic": args.topic, "compression": "cbor-raw"}))
        print("cbor-raw ready", flush=True)
        end = time.time() + args.seconds
        while time.time() < end:
            try:
                frame = await asyncio.wait_for(ws.recv(), timeout=max(0.1, end - time.time()))
            except asyncio.TimeoutError:
                break
            if isinstance(frame, bytes):
                m = cbor2.loads(frame)
                if m.get("op") == "publish":
                    lat.append(time.time() - stamp_of_ros1(m["msg"]["bytes"]))
    print(json.dumps(summary(lat[args.skip:])), flush=True)


def roslibpy_sub(args):
    import roslibpy

    lat = []
    lock = threading.Lock()

    def on_msg(m):
        t = time.time()
        st = m["header"]["stamp"]
        with lock:
            lat.append(t - (st["secs"] + st["nsecs"] / 1e9))

    ros = roslibpy.Ros(host=args.host, port=args.port)
    ros.run(timeout=10)
    topic = roslibpy.Topic(ros, args.topic, "sensor_msgs/PointCloud2")
    topic.subscribe(on_msg)
    print("roslibpy ready", flush=True)
    time.sleep(args.seconds)
    topic.unsubscribe()
    with lock:
        got = list(lat)
    print(json.dumps(summary(got[args.skip:])), flush=True)
    ros.terminate()


def main():
    p = argparse.ArgumentParser()
    sub = p.add_subparsers(dest="mode", required=True)
    a = sub.add_parser("cbor-raw")
    a.add_argument("--url", required=True)
    b = sub.add_parser("roslibpy")
    b.add_argument("--host", default="127.0.0.1")
    b.add_argument("--port", type=int, required=True)
    for x in (a, b):
        x.add_argument("--topic", required=True)
        x.add_argument("--seconds", type=float, default=30)
        x.add_argument("--skip", type=int, default=5, help="first messages left out (warm-up)")
    args = p.parse_args()
    if args.mode == "cbor-raw":
        asyncio.run(cbor_raw(args))
    else:
        roslibpy_sub(args)


if __name__ == "__main__":
    sys.exit(main())

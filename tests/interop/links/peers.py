#!/usr/bin/env python3
"""Peers of the bad-links suite, each run as its own process inside a network namespace.

  pub     roslibpy publisher on the agent's local rosbridge listener: /probe/fast and/or
          /probe/reliable (std_msgs/msg/String, data "<seq> <send time ns>"), each on its
          own connection (two programs on the robot, so one cannot hold up the other's
          socket). Logs every publish as "<topic> <seq> <send ns>" to --log.
  direct  roslibpy publisher connected straight to the hub, no agent in between: what a
          robot without fleetlink runs (a rosbridge client talking to a rosbridge
          server). Publishes /probe/direct like /probe/fast and logs it the same way.
          Keeps roslibpy's defaults on purpose: its factory reconnects by itself (first
          retry after 1 s, growing) and its topics re-advertise after a reconnect; no
          reconnect logic of ours, so the suite measures what a user of it gets.
  sub     roslibpy subscriber at the hub (token in an Authorization header) on
          /<robot>/probe/fast, /<robot>/probe/reliable and /probe/direct; logs every
          message as "<topic> <recv ns> <seq> <send ns>" to --log (topic without its
          prefix). Reconnects by itself.
  points  plain WebSocket subscriber at the hub on /<robot>/points with compression
          cbor-raw (roslibpy cannot take binary frames); logs "points <recv ns> <bytes>"
          where bytes is the raw ROS serialization's length. Reconnects by itself.
  sensors plain WebSocket publisher on the agent's local rosbridge listener speaking
          rosbridge v2 CBOR (binary `advertise` and `publish` ops), as a robot's lidar and
          camera drivers would: /cloud (sensor_msgs/msg/PointCloud2, an organized 16 x 900
          lidar cloud, x/y/z/intensity float32 little-endian, 230 kB) and
          /camera/compressed (sensor_msgs/msg/CompressedImage, "jpeg": a JFIF header, ~60 kB
          of noise, which entropy-coded image data is, and the end marker) at --hz each, each
          on its own connection. Logs every publish as "<cloud|jpeg> <seq> <stamp ns>
          <sha256 of data> <bytes of data> <bytes of data after zstd level 1, or ->", and
          any `status` the agent sends as "# status ...".
  sensorsub
          roslibpy subscriber at the hub on /<robot>/cloud and /<robot>/camera/compressed;
          logs every message as "<cloud|jpeg> <recv ns> <stamp ns> <sha256 of the
          base64-decoded data> <bytes>". The stamp identifies a message in both logs.
  twist   roslibpy publisher on the agent's local rosbridge listener: --topic
          (geometry_msgs/msg/Twist, a motion command's type) at --hz, the sequence number
          in linear.x. Logs every publish as "twist <seq> <send ns>".
  watch   roslibpy subscriber at the hub on each --topic SHORT=NAME=TYPE; logs every
          message as "<short> <recv ns> <id>", the id being linear.x as an integer (the
          twist peer's sequence number) for a Twist, else header.stamp in ns, else "-".
  loris   slowloris: N TCP connections that send a request line and then one header
          line a second, never finishing; logs "closed <seconds after open>" per
          connection the server closes, "open <n>" at the end for the rest.
  caller  roslibpy client calling --service every --period s, each call asynchronous
          (its own callback, so one that hangs does not hold up the next) and with its
          own deadline (rosbridge `timeout`: --timeout s). Logs "call <n> <send ns>",
          then "ok <n> <recv ns> <values as JSON>" or "err <n> <recv ns> <text>"; a
          call with no answer --timeout + 2 s after it was sent is logged "timeout <n>
          <ns>" (an answer after that is still logged). Connects to the hub (token) or
          to the agent's local listener (no token).
  provider
          roslibpy client at the hub advertising --service (std_srvs/srv/SetBool): a fleet
          service robots call. Answers at once, success true, message "echo <data>";
          logs "served <recv ns>" per call.

Both namespaces share one clock, so receive time - send time is the one-way latency.
Every process ends on SIGTERM (or its own --duration / --count) and flushes its log line
by line, so a record survives a kill of the process under test.
"""

import argparse
import base64
import hashlib
import json
import math
import random
import selectors
import signal
import socket
import struct
import sys
import threading
import time
import urllib.parse

import cbor2
import roslibpy
from roslibpy.comm.comm_autobahn import AutobahnRosBridgeClientFactory
from websockets.sync.client import connect as ws_connect

try:  # the reference zstd library (pulled in by rosbags; Python 3.14 has it built in)
    from backports import zstd
except ImportError:
    try:
        from compression import zstd
    except ImportError:
        zstd = None

STRING = "std_msgs/msg/String"
CONNECT_TIMEOUT = 10.0

stop = threading.Event()


def on_term(_sig, _frame):
    stop.set()


def open_log(path):
    return open(path, "a", buffering=1, encoding="ascii")  # line-buffered


class LockedLog:
    """One log written by two publishing threads, a line at a time."""

    def __init__(self, f):
        self.f, self.lock = f, threading.Lock()

    def write(self, line):
        with self.lock:
            self.f.write(line)


def ros_connect(url):
    u = urllib.parse.urlparse(url)
    token = urllib.parse.parse_qs(u.query).get("token", [None])[0]
    headers = {"Authorization": f"Bearer {token}"} if token else None
    ros = roslibpy.Ros(host=u.hostname, port=u.port, headers=headers)
    ros.run(timeout=CONNECT_TIMEOUT)
    return ros


class FastResubscribeTopic(roslibpy.Topic):
    """roslibpy re-sends a subscription one second after a reconnect; a hub restart
    test wants it at once (the reconnect itself is already waited for by send_on_ready;
    the short delay only lets the factory drop the dead protocol first)."""

    def _reconnect_topic(self, _proto):
        self.ros.call_later(0.05, lambda: self.ros.send_on_ready(self._connect_message))


def run_pub(a):
    log = LockedLog(open_log(a.log))
    plan = []  # (topic name, rate)
    if a.fast_hz > 0:
        plan.append(("/probe/fast", a.fast_hz))
    if a.reliable_hz > 0:
        plan.append(("/probe/reliable", a.reliable_hz))
    threads = []
    for name, hz in plan:
        ros = ros_connect(a.url)  # one connection per topic, as two robot programs
        topic = roslibpy.Topic(ros, name, STRING)
        topic.advertise()
        t = threading.Thread(target=publish_loop, args=(topic, name, hz, a, log), daemon=True)
        threads.append((t, ros))
    print("pub: connected", flush=True)
    for t, _ in threads:
        t.start()
    for t, _ in threads:
        t.join()
    time.sleep(0.5)  # let the reactor write what publish() queued before closing
    for _, ros in threads:
        ros.close()


def run_direct(a):
    log = LockedLog(open_log(a.log))
    ros = ros_connect(a.url)
    topic = roslibpy.Topic(ros, "/probe/direct", STRING)
    topic.advertise()
    print("direct: connected", flush=True)
    publish_loop(topic, "/probe/direct", a.hz, a, log)
    time.sleep(0.5)  # as run_pub: what publish() queued leaves before the close
    ros.close()


def publish_loop(topic, name, hz, a, log):
    period = 1.0 / hz
    seq = a.start_seq
    deadline = time.monotonic() + a.duration if a.duration > 0 else None
    next_at = time.monotonic()
    sent = 0
    while not stop.is_set():
        if a.count and sent >= a.count:
            break
        if deadline and time.monotonic() >= deadline:
            break
        now_ns = time.time_ns()
        topic.publish(roslibpy.Message({"data": f"{seq} {now_ns}"}))
        log.write(f"{name} {seq} {now_ns}\n")
        seq += 1
        sent += 1
        next_at += period
        delay = next_at - time.monotonic()
        if delay > 0:
            stop.wait(delay)
        else:
            next_at = time.monotonic()  # fell behind (a stalled reactor): no burst to catch up


def run_sub(a):
    # Reconnect fast after a hub restart: first retry after 0.1 s, never more than 0.3 s.
    AutobahnRosBridgeClientFactory.set_initial_delay(0.1)
    AutobahnRosBridgeClientFactory.set_max_delay(0.3)
    log = open_log(a.log)
    ros = ros_connect(a.url)
    lock = threading.Lock()

    def handler(short):
        def on_msg(m):
            recv = time.time_ns()
            seq, sent = m["data"].split()
            with lock:
                log.write(f"{short} {recv} {seq} {sent}\n")
        return on_msg

    # /probe/direct comes from a client of the hub itself (peers.py direct), so its name
    # has no robot prefix.
    names = {"fast": f"/{a.robot}/probe/fast", "reliable": f"/{a.robot}/probe/reliable",
             "direct": "/probe/direct"}
    for short, name in names.items():
        t = FastResubscribeTopic(ros, name, STRING)
        t.subscribe(handler(short))
    ros.factory.on("ready", lambda _p: log.write(f"ready {time.time_ns()}\n"))
    print("sub: subscribed", flush=True)
    stop.wait()
    ros.close()


def run_points(a):
    log = open_log(a.log)
    u = urllib.parse.urlparse(a.url)
    token = urllib.parse.parse_qs(u.query).get("token", [None])[0]
    url = f"ws://{u.hostname}:{u.port}/"
    headers = {"Authorization": f"Bearer {token}"} if token else None
    sub = {"op": "subscribe", "id": "links-points", "topic": f"/{a.robot}/points",
           "type": "sensor_msgs/msg/PointCloud2", "compression": "cbor-raw", "throttle_rate": 0}
    announced = False
    while not stop.is_set():
        try:
            with ws_connect(url, additional_headers=headers, open_timeout=CONNECT_TIMEOUT,
                            close_timeout=1, max_size=256 << 20) as ws:
                ws.send(json.dumps(sub))
                if not announced:
                    print("points: subscribed", flush=True)
                    announced = True
                while not stop.is_set():
                    try:
                        frame = ws.recv(timeout=0.2)
                    except TimeoutError:
                        continue
                    recv = time.time_ns()
                    if isinstance(frame, str):
                        continue  # status messages
                    m = cbor2.loads(frame)
                    if m.get("op") == "publish":
                        log.write(f"points {recv} {len(m['msg']['bytes'])}\n")
        except Exception as e:  # connection lost or refused: retry, bounded by --duration/TERM
            log.write(f"# {type(e).__name__}: {e}\n".encode("ascii", "replace").decode())
            stop.wait(0.2)


class Lidar:
    """A 16-ring lidar (+-15 deg, 900 columns) 0.4 m above the floor of a walled yard
    (walls 2.5 m high, 9-18 m away). The cloud is organized as lidar drivers publish it:
    one row per ring, one column per firing, and a ray that saw only sky (above the
    walls) stays in it as a NaN point. Ranges carry 1 cm of noise, fresh in every sweep;
    intensity is the sensor's 8-bit reflectivity (an integer in a float32, as drivers
    report it)."""

    RINGS, COLUMNS, HEIGHT, WALL_H = 16, 900, 0.4, 2.5
    X, Y = (-12.0, 18.0), (-9.0, 11.0)
    POINT = struct.Struct("<ffff")  # x, y, z, intensity

    def __init__(self):
        self.rays = []  # row by row: (unit vector x, y, z, range or None, reflectivity)
        for r in range(self.RINGS):
            el = math.radians(-15 + 30 * r / (self.RINGS - 1))
            se, ce = math.sin(el), math.cos(el)
            for c in range(self.COLUMNS):
                az = math.tau * c / self.COLUMNS
                ca, sa = math.cos(az), math.sin(az)
                wall = min(d for d in (self.X[1] / ca if ca > 1e-9 else None,
                                       self.X[0] / ca if ca < -1e-9 else None,
                                       self.Y[1] / sa if sa > 1e-9 else None,
                                       self.Y[0] / sa if sa < -1e-9 else None) if d is not None)
                if se < 0 and self.HEIGHT / -se * ce < wall:
                    rng, refl = self.HEIGHT / -se, 30.0      # the floor
                elif 0 <= self.HEIGHT + wall * se / ce <= self.WALL_H:
                    rng, refl = wall / ce, 100.0             # a wall
                else:
                    rng, refl = None, 0.0                    # sky: no return
                self.rays.append((ce * ca, ce * sa, se, rng, refl))

    def sweep(self, seq):
        gauss = random.Random(seq).gauss
        nan, pack = float("nan"), self.POINT.pack
        out = []
        for x, y, z, rng, refl in self.rays:
            if rng is None:
                out.append(pack(nan, nan, nan, 0.0))
            else:
                r = rng + gauss(0, 0.01)
                out.append(pack(r * x, r * y, r * z, float(round(refl / (1 + 0.05 * r)))))
        return b"".join(out)

    def message(self, seq, stamp_ns):
        def field(name, offset):
            return {"name": name, "offset": offset, "datatype": 7, "count": 1}  # 7: FLOAT32
        step = self.POINT.size
        # The type's fields in order, uint8[] as a byte string: the normal form
        # (crates/msg/src/cbor_check.rs).
        return {"header": header(stamp_ns, "lidar"), "height": self.RINGS, "width": self.COLUMNS,
                "fields": [field("x", 0), field("y", 4), field("z", 8), field("intensity", 12)],
                "is_bigendian": False, "point_step": step, "row_step": self.COLUMNS * step,
                "data": self.sweep(seq), "is_dense": False}


# SOI, then an APP0 JFIF segment (version 1.1, 72 dpi, no thumbnail).
JFIF = bytes.fromhex("ffd8ffe000104a46494600010101004800480000")


def jpeg_message(seq, stamp_ns):
    """A camera frame: what follows a JPEG's header is entropy-coded data, statistically
    noise; the size varies from frame to frame, as a camera's does."""
    rnd = random.Random(seq)
    return {"header": header(stamp_ns, "camera"), "format": "jpeg",
            "data": JFIF + rnd.randbytes(60_000 + rnd.randint(-1500, 1500)) + b"\xff\xd9"}


def header(stamp_ns, frame_id):
    return {"stamp": {"sec": stamp_ns // 1_000_000_000, "nanosec": stamp_ns % 1_000_000_000},
            "frame_id": frame_id}


def blob_line(short, seq, stamp_ns, data):
    zlen = len(zstd.compress(data, level=1)) if zstd is not None else "-"
    return f"{short} {seq} {stamp_ns} {hashlib.sha256(data).hexdigest()} {len(data)} {zlen}\n"


def run_sensors(a):
    log = LockedLog(open_log(a.log))
    lidar = Lidar()
    plan = [("cloud", "/cloud", "sensor_msgs/msg/PointCloud2", lidar.message),
            ("jpeg", "/camera/compressed", "sensor_msgs/msg/CompressedImage", jpeg_message)]
    conns = []
    for short, name, ros_type, make in plan:  # one connection per driver
        ws = ws_connect(a.url, open_timeout=CONNECT_TIMEOUT, close_timeout=1, max_size=64 << 20)
        ws.send(cbor2.dumps({"op": "set_level", "level": "warning"}))
        ws.send(cbor2.dumps({"op": "advertise", "topic": name, "type": ros_type}))
        conns.append((ws, short, name, make))
    print("sensors: connected", flush=True)
    threads = [threading.Thread(target=sensor_loop, args=(c, a.hz, log), daemon=True) for c in conns]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for ws, *_ in conns:
        ws.close()


def sensor_loop(conn, hz, log):
    ws, short, name, make = conn
    period, seq, next_at = 1.0 / hz, 0, time.monotonic()
    while not stop.is_set():
        seq += 1
        stamp = time.time_ns()
        msg = make(seq, stamp)
        ws.send(cbor2.dumps({"op": "publish", "topic": name, "msg": msg}))
        log.write(blob_line(short, seq, stamp, msg["data"]))
        while True:  # what the agent answered: a refused publish says why here
            try:
                reply = ws.recv(timeout=0)
            except TimeoutError:
                break
            text = reply if isinstance(reply, str) else json.dumps(cbor2.loads(reply), default=repr)
            log.write(f"# status {one_line(text)}\n")
            print(f"sensors: {name}: {one_line(text)}", flush=True)
        next_at += period
        delay = next_at - time.monotonic()
        if delay > 0:
            stop.wait(delay)
        else:
            next_at = time.monotonic()  # fell behind: no burst to catch up


def run_sensorsub(a):
    log = LockedLog(open_log(a.log))
    ros = ros_connect(a.url)
    show_status(ros, log)

    def handler(short):
        def on_msg(m):
            recv = time.time_ns()
            st = m["header"]["stamp"]
            data = m["data"]
            data = base64.b64decode(data) if isinstance(data, str) else bytes(data)
            log.write(f"{short} {recv} {st['sec'] * 1_000_000_000 + st['nanosec']} "
                      f"{hashlib.sha256(data).hexdigest()} {len(data)}\n")
        return on_msg

    for short, name, ros_type in (("cloud", f"/{a.robot}/cloud", "sensor_msgs/msg/PointCloud2"),
                                  ("jpeg", f"/{a.robot}/camera/compressed", "sensor_msgs/msg/CompressedImage")):
        roslibpy.Topic(ros, name, ros_type).subscribe(handler(short))
    print("sensorsub: subscribed", flush=True)
    stop.wait()
    ros.close()


def run_twist(a):
    log = open_log(a.log)
    ros = ros_connect(a.url)
    topic = roslibpy.Topic(ros, a.topic, "geometry_msgs/msg/Twist")
    topic.advertise()
    print("twist: connected", flush=True)
    zero = {"x": 0.0, "y": 0.0, "z": 0.0}
    period, seq, next_at = 1.0 / a.hz, 0, time.monotonic()
    while not stop.is_set():
        seq += 1
        now_ns = time.time_ns()
        topic.publish(roslibpy.Message({"linear": {"x": float(seq), "y": 0.0, "z": 0.0}, "angular": zero}))
        log.write(f"twist {seq} {now_ns}\n")
        next_at += period
        delay = next_at - time.monotonic()
        if delay > 0:
            stop.wait(delay)
        else:
            next_at = time.monotonic()  # fell behind: no burst to catch up
    time.sleep(0.5)  # as run_pub: what publish() queued leaves before the close
    ros.close()


def run_watch(a):
    log = LockedLog(open_log(a.log))
    ros = ros_connect(a.url)
    show_status(ros, log)

    def handler(short):
        def on_msg(m):
            recv = time.time_ns()
            if "linear" in m:
                ident = str(int(m["linear"]["x"]))
            elif "header" in m:
                st = m["header"]["stamp"]
                ident = str(st["sec"] * 1_000_000_000 + st["nanosec"])
            else:
                ident = "-"
            log.write(f"{short} {recv} {ident}\n")
        return on_msg

    for spec in a.topic:
        short, name, ros_type = spec.split("=", 2)
        roslibpy.Topic(ros, name, ros_type).subscribe(handler(short))
    print("watch: subscribed", flush=True)
    stop.wait()
    ros.close()


def run_loris(a):
    log = open_log(a.log)
    sel = selectors.DefaultSelector()
    opened = {}
    for i in range(a.conns):
        s = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
        s.settimeout(5)
        try:
            s.connect((a.host, a.port))
        except OSError as e:
            log.write(f"refused {e}\n")
            s.close()
            continue
        s.setblocking(False)
        s.send(f"GET /?loris={i} HTTP/1.1\r\nHost: {a.host}\r\n".encode())
        opened[s] = time.monotonic()
        sel.register(s, selectors.EVENT_READ)
    print(f"loris: {len(opened)} connections open", flush=True)
    deadline = time.monotonic() + a.duration
    next_trickle = time.monotonic() + 1
    while opened and not stop.is_set() and time.monotonic() < deadline:
        for key, _ in sel.select(timeout=0.1):
            s = key.fileobj
            try:
                data = s.recv(4096)
            except OSError:
                data = b""
            if not data:  # closed (or reset) by the server
                log.write(f"closed {time.monotonic() - opened.pop(s):.3f}\n")
                sel.unregister(s)
                s.close()
            # a response (408/400) before the close is fine; the close is what counts
        if time.monotonic() >= next_trickle:
            next_trickle += 1
            for s in list(opened):
                try:
                    s.send(b"X-Trickle: 1\r\n")
                except OSError:
                    pass  # the read side reports the close
    log.write(f"open {len(opened)}\n")
    for s in opened:
        s.close()


CALL_GRACE_S = 2.0  # past the call's own deadline: the peer stops waiting for it


def one_line(v):
    """A service_response's values as one ASCII line (the log is ASCII)."""
    text = v if isinstance(v, str) else json.dumps(v, separators=(",", ":"), sort_keys=True)
    return " ".join(text.split()).encode("ascii", "replace").decode()


def show_status(ros, log):
    """roslibpy has no handler for `status` ops (it logs a traceback and drops them):
    log them instead, so an error the server sent explains a call that then fails."""
    proto = ros.factory._proto
    if proto is not None:
        proto._message_handlers["status"] = lambda m: log.write(f"# status {one_line(dict(m))}\n")


def run_caller(a):
    log = LockedLog(open_log(a.log))
    ros = ros_connect(a.url)
    show_status(ros, log)
    args = json.loads(a.args)
    pending = {}  # call number -> monotonic time after which it is given up
    lock = threading.Lock()

    def answered(n, ok):
        def on(values):
            recv = time.time_ns()
            with lock:
                pending.pop(n, None)
            if ok:
                log.write(f"ok {n} {recv} {one_line(dict(values))}\n")
            else:
                log.write(f"err {n} {recv} {one_line(values)}\n")
        return on

    print("caller: connected", flush=True)
    n = 0
    next_at = time.monotonic()
    while not stop.is_set():
        now = time.monotonic()
        if now >= next_at:
            n += 1
            msg = roslibpy.Message({"op": "call_service", "id": f"links-call:{n}", "service": a.service,
                                    "args": args, "timeout": a.timeout})
            with lock:
                pending[n] = now + a.timeout + CALL_GRACE_S
            log.write(f"call {n} {time.time_ns()}\n")  # before the answer can be logged
            ros.call_async_service(msg, answered(n, True), answered(n, False))
            next_at += a.period
            if next_at <= now:
                next_at = now + a.period  # fell behind: no burst to catch up
        with lock:
            expired = [k for k, t in pending.items() if t <= now]
            for k in expired:
                del pending[k]
        for k in expired:
            log.write(f"timeout {k} {time.time_ns()}\n")
        stop.wait(max(0.0, min(0.02, next_at - time.monotonic())))
    ros.close()


def run_provider(a):
    log = open_log(a.log)
    ros = ros_connect(a.url)
    show_status(ros, LockedLog(log))

    def serve(req, resp):
        resp["success"] = True
        resp["message"] = f"echo {bool(req.get('data'))}"
        log.write(f"served {time.time_ns()}\n")
        return True

    roslibpy.Service(ros, a.service, "std_srvs/srv/SetBool").advertise(serve)
    print("provider: advertised", flush=True)
    stop.wait()
    ros.close()


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sp = ap.add_subparsers(dest="cmd", required=True)
    p = sp.add_parser("pub")
    p.add_argument("--url", required=True)
    p.add_argument("--fast-hz", type=float, default=50)
    p.add_argument("--reliable-hz", type=float, default=50)
    p.add_argument("--start-seq", type=int, default=1)
    p.add_argument("--count", type=int, default=0, help="per topic; 0 = until stopped")
    p.add_argument("--duration", type=float, default=0, help="seconds; 0 = until stopped")
    p.add_argument("--log", required=True)
    p = sp.add_parser("direct")
    p.add_argument("--url", required=True, help="hub URL with ?token=")
    p.add_argument("--hz", type=float, default=50)
    p.add_argument("--log", required=True)
    p.set_defaults(start_seq=1, count=0, duration=0)
    p = sp.add_parser("sensors")
    p.add_argument("--url", required=True, help="the agent's local listener")
    p.add_argument("--hz", type=float, default=5)
    p.add_argument("--log", required=True)
    for name in ("sub", "points", "sensorsub"):
        p = sp.add_parser(name)
        p.add_argument("--url", required=True, help="hub URL with ?token=")
        p.add_argument("--robot", default="robot1")
        p.add_argument("--log", required=True)
    p = sp.add_parser("twist")
    p.add_argument("--url", required=True, help="the agent's local listener")
    p.add_argument("--topic", default="/cmd_vel_echo")
    p.add_argument("--hz", type=float, default=20)
    p.add_argument("--log", required=True)
    p = sp.add_parser("watch")
    p.add_argument("--url", required=True, help="hub URL with ?token=")
    p.add_argument("--topic", action="append", required=True, help="SHORT=NAME=TYPE, repeatable")
    p.add_argument("--log", required=True)
    p = sp.add_parser("loris")
    p.add_argument("--host", required=True)
    p.add_argument("--port", type=int, required=True)
    p.add_argument("--conns", type=int, default=500)
    p.add_argument("--duration", type=float, default=30)
    p.add_argument("--log", required=True)
    p = sp.add_parser("caller")
    p.add_argument("--url", required=True, help="hub URL with ?token=, or the agent's local listener")
    p.add_argument("--service", required=True)
    p.add_argument("--args", default="{}", help="the request, JSON")
    p.add_argument("--period", type=float, default=0.5)
    p.add_argument("--timeout", type=float, default=10.0, help="each call's deadline, seconds")
    p.add_argument("--log", required=True)
    p = sp.add_parser("provider")
    p.add_argument("--url", required=True, help="hub URL with ?token=")
    p.add_argument("--service", required=True)
    p.add_argument("--log", required=True)
    a = ap.parse_args()
    signal.signal(signal.SIGTERM, on_term)
    signal.signal(signal.SIGINT, on_term)
    {"pub": run_pub, "direct": run_direct, "sub": run_sub, "points": run_points, "loris": run_loris,
     "caller": run_caller, "provider": run_provider, "sensors": run_sensors,
     "sensorsub": run_sensorsub, "twist": run_twist, "watch": run_watch}[a.cmd](a)
    return 0


if __name__ == "__main__":
    sys.exit(main())

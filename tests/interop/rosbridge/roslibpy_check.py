#!/usr/bin/env python3
"""rosbridge interop check with roslibpy (PyPI) against a fleetlink hub or agent.

Modes:
  hub    --url is the hub; topics are /<robot>/scan ... ; the publish path sends
         geometry_msgs/msg/Twist on /<robot>/cmd_vel at the hub and checks that a second
         roslibpy client on the agent's local listener (--peer-url) receives it on /cmd_vel.
  local  --url is the agent's local rosbridge listener; topics are /scan ... ; the publish
         path sends on a local topic and checks that a roslibpy client on the hub
         (--peer-url) receives it under /<robot>/<topic>.

roslibpy cannot subscribe with compression='cbor' (Topic only accepts 'none'/'png' and its
protocol raises NotImplementedError on binary frames), so the point cloud is checked twice:
through roslibpy uncompressed (base64 `data`), and with compression 'cbor' through a plain
WebSocket client decoding with the independent `cbor2` library.

Exits 0 when every check passed, 1 with a message naming the failed check otherwise.
Every wait is bounded by a timeout.
"""

import argparse
import base64
import json
import math
import random
import struct
import sys
import threading
import time
import urllib.parse
import urllib.request

import cbor2
import roslibpy
from websockets.sync.client import connect as ws_connect

TIMEOUT = 10.0  # seconds, for any single wait
PUBLISH_ATTEMPTS = 100  # publish path: bounded retries until the route is live
PUBLISH_INTERVAL = 0.1  # seconds between retries (each retry waits on an event)


class CheckFailed(Exception):
    pass


def check(cond, what):
    if not cond:
        raise CheckFailed(what)


def ok(what):
    print(f"  ok: {what}", flush=True)


class Inbox:
    """Collects callback values; wait() blocks on a condition, bounded by a timeout."""

    def __init__(self):
        self.items = []
        self.cond = threading.Condition()

    def put(self, item):
        with self.cond:
            self.items.append(item)
            self.cond.notify_all()

    def wait(self, n, timeout, what, pred=lambda _: True):
        deadline = time.monotonic() + timeout
        with self.cond:
            while True:
                matching = [i for i in self.items if pred(i)]
                if len(matching) >= n:
                    return matching
                left = deadline - time.monotonic()
                if left <= 0:
                    raise CheckFailed(
                        f"{what}: got {len(matching)} of {n} within {timeout}s")
                self.cond.wait(left)


def connect(url):
    u = urllib.parse.urlparse(url)
    # roslibpy builds the URL from host and port; a token in the URL's query goes in an
    # Authorization header instead (both are accepted by the hub).
    token = urllib.parse.parse_qs(u.query).get("token", [None])[0]
    headers = {"Authorization": f"Bearer {token}"} if token else None
    ros = roslibpy.Ros(host=u.hostname, port=u.port, is_secure=u.scheme == "wss", headers=headers)
    try:
        ros.run(timeout=TIMEOUT)
    except Exception as e:  # roslibpy raises RosTimeoutError
        raise CheckFailed(f"connect {url}: {e}") from e
    check(ros.is_connected, f"connect {url}: not connected")
    return ros


def call(ros, service, args=None, stype=""):
    svc = roslibpy.Service(ros, service, stype)
    try:
        return svc.call(roslibpy.ServiceRequest(args or {}), timeout=TIMEOUT)
    except Exception as e:
        raise CheckFailed(f"call {service}: {type(e).__name__}: {e}") from e


def check_stamp(stamp, what):
    check(isinstance(stamp, dict) and "sec" in stamp and "nanosec" in stamp,
          f"{what}: header.stamp {stamp!r} lacks sec/nanosec")
    check(0 <= stamp["nanosec"] < 1_000_000_000, f"{what}: nanosec {stamp['nanosec']}")
    t = stamp["sec"] + stamp["nanosec"] * 1e-9
    check(abs(t - time.time()) < 60, f"{what}: stamp {t} is not near now {time.time()}")
    return t


def check_topics(ros, ns):
    want = {f"{ns}/scan": "sensor_msgs/msg/LaserScan",
            f"{ns}/odom": "nav_msgs/msg/Odometry",
            f"{ns}/points": "sensor_msgs/msg/PointCloud2"}
    try:
        names = ros.get_topics()
    except Exception as e:
        raise CheckFailed(f"ros.get_topics(): {type(e).__name__}: {e}") from e
    for t in want:
        check(t in names, f"ros.get_topics() lacks {t}: {names}")
    ok(f"ros.get_topics() lists {sorted(want)}")
    res = call(ros, "/rosapi/topics", stype="rosapi/Topics")
    topics, types = res["topics"], res["types"]
    check(len(topics) == len(types), f"/rosapi/topics: {len(topics)} topics, {len(types)} types")
    by_name = dict(zip(topics, types))
    for t, ty in want.items():
        check(by_name.get(t) == ty, f"/rosapi/topics: type of {t} is {by_name.get(t)!r}, want {ty}")
    ok("/rosapi/topics types: " + ", ".join(f"{t}={ty}" for t, ty in want.items()))
    try:
        ty = ros.get_topic_type(f"{ns}/odom")
    except Exception as e:
        raise CheckFailed(f"ros.get_topic_type(): {type(e).__name__}: {e}") from e
    check(ty == "nav_msgs/msg/Odometry", f"/rosapi/topic_type {ns}/odom = {ty!r}")
    ok(f"/rosapi/topic_type {ns}/odom = {ty}")
    # Definitions travel with topics: the full text is listed for viewers that decode
    # custom types (rosbag2/MCAP concatenated form), dependencies headed as the fields
    # spell them (what @foxglove/rosmsg matches).
    res = call(ros, "/rosapi/topics_and_raw_types", stype="rosapi/TopicsAndRawTypes")
    defs = dict(zip(res["topics"], res["typedefs_full_text"]))
    scan = defs.get(f"{ns}/scan", "")
    check("float32[] ranges" in scan and "\nMSG: std_msgs/Header\n" in scan,
          f"/rosapi/topics_and_raw_types: definition of {ns}/scan is {scan[:200]!r}")
    ok(f"/rosapi/topics_and_raw_types: {ns}/scan carries its full definition ({len(scan)} chars)")


def check_graph(ros, mode, robot):
    try:
        services = ros.get_services()
        nodes = ros.get_nodes()
    except Exception as e:
        raise CheckFailed(f"ros.get_services()/get_nodes(): {type(e).__name__}: {e}") from e
    for s in ("/rosapi/topics", "/rosapi/get_time", "/rosapi/topic_type"):
        check(s in services, f"/rosapi/services lacks {s}: {services}")
    check(isinstance(nodes, list) and nodes and all(isinstance(n, str) and n.startswith("/") for n in nodes),
          f"/rosapi/nodes: {nodes!r}")
    if mode == "hub":
        check(f"/{robot}" in nodes, f"/rosapi/nodes at the hub lacks the robot /{robot}: {nodes}")
    ok(f"/rosapi/services lists the rosapi services; /rosapi/nodes = {nodes}")


def check_get_time(ros):
    try:
        t = ros.get_time()  # reads time.secs / time.nsecs
    except Exception as e:
        raise CheckFailed(f"ros.get_time(): {type(e).__name__}: {e}") from e
    check(abs(t["secs"] + t["nsecs"] * 1e-9 - time.time()) < 60,
          f"/rosapi/get_time {dict(t)} not near now")
    raw = call(ros, "/rosapi/get_time", stype="rosapi/GetTime")["time"]
    check(raw.get("sec") == raw.get("secs") or abs(raw["sec"] - raw["secs"]) <= 1,
          f"/rosapi/get_time ROS 2 and ROS 1 fields disagree: {raw}")
    ok(f"/rosapi/get_time = {t['secs']}.{t['nsecs']:09d}")


def check_scan(ros, ns, ranges):
    inbox = Inbox()
    topic = roslibpy.Topic(ros, f"{ns}/scan", "sensor_msgs/msg/LaserScan")
    topic.subscribe(inbox.put)
    msgs = inbox.wait(3, TIMEOUT, f"LaserScan on {ns}/scan")[:3]
    topic.unsubscribe()
    stamps = []
    for m in msgs:
        r = m["ranges"]
        check(len(r) == ranges, f"scan: {len(r)} ranges, want {ranges}")
        amin, amax, inc = m["angle_min"], m["angle_max"], m["angle_increment"]
        check(inc > 0 and amin < amax, f"scan: angles min {amin} max {amax} inc {inc}")
        check(abs(amin + inc * (len(r) - 1) - amax) < 1e-3,
              f"scan: angle_min + inc*(n-1) = {amin + inc * (len(r) - 1)} != angle_max {amax}")
        lo, hi = m["range_min"], m["range_max"]
        check(0 <= lo < hi, f"scan: range_min {lo} range_max {hi}")
        bad = [x for x in r if not (isinstance(x, (int, float)) and lo <= x <= hi)]
        check(not bad, f"scan: {len(bad)} ranges outside [{lo}, {hi}], e.g. {bad[:3]}")
        check(m["header"]["frame_id"].endswith("laser"), f"scan: frame_id {m['header']['frame_id']!r}")
        stamps.append(check_stamp(m["header"]["stamp"], "scan"))
    check(stamps == sorted(stamps) and len(set(stamps)) == 3, f"scan: stamps not increasing: {stamps}")
    ok(f"3 LaserScans on {ns}/scan: {ranges} ranges, consistent angles, increasing stamps")


def check_odom(ros, ns):
    inbox = Inbox()
    topic = roslibpy.Topic(ros, f"{ns}/odom", "nav_msgs/msg/Odometry")
    topic.subscribe(inbox.put)
    m = inbox.wait(1, TIMEOUT, f"Odometry on {ns}/odom")[0]
    topic.unsubscribe()
    check(m["child_frame_id"].endswith("base_link"), f"odom: child_frame_id {m['child_frame_id']!r}")
    check(len(m["pose"]["covariance"]) == 36, "odom: pose.covariance length")
    q = m["pose"]["pose"]["orientation"]
    norm = math.sqrt(sum(q[k] ** 2 for k in "xyzw"))
    check(abs(norm - 1) < 1e-3, f"odom: orientation not a unit quaternion ({norm})")
    check_stamp(m["header"]["stamp"], "odom")
    ok(f"Odometry on {ns}/odom: unit quaternion, 6x6 covariances")


def check_points_json(ros, ns, points):
    inbox = Inbox()
    topic = roslibpy.Topic(ros, f"{ns}/points", "sensor_msgs/msg/PointCloud2")
    topic.subscribe(inbox.put)
    m = inbox.wait(1, TIMEOUT, f"PointCloud2 on {ns}/points")[0]
    topic.unsubscribe()
    check(isinstance(m["data"], str), f"points (json): data is {type(m['data']).__name__}, want base64 str")
    data = base64.b64decode(m["data"], validate=True)
    check(m["width"] == points, f"points (json): width {m['width']}, want {points}")
    check(len(data) == m["width"] * m["height"] * m["point_step"] == m["row_step"] * m["height"],
          f"points (json): {len(data)} bytes for width {m['width']} x point_step {m['point_step']}")
    ok(f"PointCloud2 on {ns}/points (json): {len(data)} bytes = {m['width']} x {m['point_step']}")


def check_points_cbor(url, ns, points):
    """compression 'cbor' with a plain WebSocket client; roslibpy has no CBOR support."""
    topic = f"{ns}/points"
    with ws_connect(url, open_timeout=TIMEOUT, close_timeout=2, max_size=64 << 20) as ws:
        ws.send(json.dumps({"op": "subscribe", "id": "cbor-points", "topic": topic,
                            "type": "sensor_msgs/msg/PointCloud2", "compression": "cbor"}))
        deadline = time.monotonic() + TIMEOUT
        for _ in range(1000):  # bounded: frames before the first publish (status, ...)
            left = deadline - time.monotonic()
            if left <= 0:
                break
            try:
                frame = ws.recv(timeout=left)
            except TimeoutError:
                break
            if isinstance(frame, str):
                raise CheckFailed(f"points (cbor): text frame instead of CBOR: {frame[:200]}")
            m = cbor2.loads(frame)
            check(m.get("op") == "publish" and m.get("topic") == topic,
                  f"points (cbor): unexpected frame {str(m)[:200]}")
            msg = m["msg"]
            data = msg["data"]
            # rosbridge sends uint8[] as a CBOR byte string (docs/protocol.md §2.2).
            form = "byte string"
            check(isinstance(data, bytes),
                  f"points (cbor): data is {type(data).__name__}, want a CBOR byte string")
            check(msg["width"] == points, f"points (cbor): width {msg['width']}, want {points}")
            check(len(data) == msg["width"] * msg["height"] * msg["point_step"],
                  f"points (cbor): {len(data)} bytes for width {msg['width']} x point_step {msg['point_step']}")
            check_stamp(msg["header"]["stamp"], "points (cbor)")
            ok(f"PointCloud2 on {topic} (compression cbor): binary frame, data {len(data)} bytes as {form}")
            return
    raise CheckFailed(f"points (cbor): no CBOR publish on {topic} within {TIMEOUT}s")


def check_params(ros, mode):
    """roslibpy's Param: set, get (a tree read by its prefix), delete."""
    base = f"/interop_py_{mode}"
    roslibpy.Param(ros, f"{base}/speed").set(1.25, timeout=TIMEOUT)
    roslibpy.Param(ros, f"{base}/names").set(["a", "b"], timeout=TIMEOUT)
    got = roslibpy.Param(ros, f"{base}/speed").get(timeout=TIMEOUT)
    check(got == 1.25, f"param {base}/speed read back as {got!r}")
    tree = roslibpy.Param(ros, base).get(timeout=TIMEOUT)
    check(tree == {"speed": 1.25, "names": ["a", "b"]}, f"param tree {base} = {tree!r}")
    names = ros.get_params()
    check(f"{base}/speed" in names, f"get_param_names lacks {base}/speed: {names!r}")
    roslibpy.Param(ros, base).delete(timeout=TIMEOUT)
    gone = roslibpy.Param(ros, f"{base}/speed").get(timeout=TIMEOUT)
    check(gone in (None, ""), f"deleted param still reads {gone!r}")
    ok(f"roslibpy Param set/get/delete on {base} (tree read by prefix)")


def check_invalid_op(ros):
    """An unknown op gets a status error with our id, and the connection keeps working."""
    statuses = Inbox()
    # roslibpy registers no handler for 'status' (it logs and drops them); install one on
    # the live protocol object to see the server's answer.
    proto = ros.factory._proto
    check(proto is not None, "invalid op: roslibpy has no live protocol object")
    proto._message_handlers["status"] = statuses.put
    ros.send_on_ready(roslibpy.Message({"op": "no_such_op", "id": "bad-op-1"}))
    st = statuses.wait(1, TIMEOUT, "status reply to op 'no_such_op'",
                       pred=lambda s: s.get("id") == "bad-op-1")[0]
    check(st.get("level") == "error", f"invalid op: status level {st.get('level')!r}: {dict(st)}")
    check("no_such_op" in st.get("msg", ""), f"invalid op: status msg does not name the op: {dict(st)}")
    ok(f"invalid op answered: {json.dumps(dict(st))}")
    check_get_time(ros)
    ok("connection still serves requests after the error")


def check_pull(ros, url, robot):
    """A pull topic (the agent's /markers, `mode: pull`): a roslibpy subscriber gets nothing
    by itself; each `pull` op brings exactly one message; the REST pull answers with one."""
    topic = f"/{robot}/markers"
    got = Inbox()
    sub = roslibpy.Topic(ros, topic, "visualization_msgs/msg/MarkerArray")
    sub.subscribe(got.put)
    time.sleep(1.5)  # markers are published at 2 Hz on the robot
    check(not got.items, f"pull topic {topic}: {len(got.items)} messages without a pull")
    ok(f"pull topic {topic}: nothing without a pull (1.5 s)")
    for n in (1, 2):
        ros.send_on_ready(roslibpy.Message({"op": "pull", "topic": topic, "id": f"pull-{n}"}))
        got.wait(n, TIMEOUT, f"message {n} pulled from {topic}")
        time.sleep(0.8)
        check(len(got.items) == n, f"pull {n} of {topic}: {len(got.items)} messages, want {n}")
    check(isinstance(got.items[-1].get("markers"), list), f"pulled {topic}: {str(got.items[-1])[:200]}")
    ok(f"pull op: exactly one {topic} message per pull ({len(got.items[-1]['markers'])} markers)")
    sub.unsubscribe()
    u = urllib.parse.urlparse(url)
    token = urllib.parse.parse_qs(u.query)["token"][0]
    req = urllib.request.Request(f"http://{u.hostname}:{u.port}/api/v1/robots/{robot}/topics/markers/pull",
                                 method="POST", headers={"Authorization": f"Bearer {token}"})
    with urllib.request.urlopen(req, timeout=TIMEOUT) as r:
        v = json.load(r)
    check(v.get("topic") == topic and isinstance(v.get("msg", {}).get("markers"), list),
          f"REST pull: {str(v)[:200]}")
    ok(f"REST pull: {topic} answered with {len(v['msg']['markers'])} markers")


def publish_until_received(pub_topic, msg, inbox, what, pred):
    """Publishes until the subscriber side has it; bounded in count and time."""
    for _ in range(PUBLISH_ATTEMPTS):
        pub_topic.publish(roslibpy.Message(msg))
        try:
            return inbox.wait(1, PUBLISH_INTERVAL, what, pred)[0]
        except CheckFailed:
            continue
    raise CheckFailed(f"{what}: nothing after {PUBLISH_ATTEMPTS} publishes "
                      f"({PUBLISH_ATTEMPTS * PUBLISH_INTERVAL:.0f}s)")


def check_publish_hub(ros, local_url, robot):
    """Operator publishes /<robot>/cmd_vel at the hub; the robot's local /cmd_vel gets it."""
    local = connect(local_url)
    try:
        inbox = Inbox()
        sub = roslibpy.Topic(local, "/cmd_vel", "geometry_msgs/msg/Twist")
        sub.subscribe(inbox.put)
        nonce = random.randint(1, 1_000_000) / 1024.0  # exactly representable
        twist = {"linear": {"x": 0.5, "y": -0.25, "z": 0.0},
                 "angular": {"x": 0.0, "y": 0.0, "z": nonce}}
        pub = roslibpy.Topic(ros, f"/{robot}/cmd_vel", "geometry_msgs/msg/Twist")
        pub.advertise()
        got = publish_until_received(pub, twist, inbox, "Twist at the robot's local /cmd_vel",
                                     lambda m: m["angular"]["z"] == nonce)
        check(dict(got) == twist, f"cmd_vel: robot got {dict(got)}, sent {twist}")
        pub.unadvertise()
        sub.unsubscribe()
        ok(f"Twist published on /{robot}/cmd_vel at the hub reached local /cmd_vel unchanged")
    finally:
        local.close()


def check_publish_local(ros, hub_url, robot):
    """A local program publishes /interop_py/chatter; the hub sees /<robot>/interop_py/chatter."""
    hub = connect(hub_url)
    try:
        inbox = Inbox()
        text = f"hello from roslibpy {random.randint(0, 1 << 30)}"
        sub = roslibpy.Topic(hub, f"/{robot}/interop_py/chatter", "std_msgs/msg/String")
        sub.subscribe(inbox.put)
        pub = roslibpy.Topic(ros, "/interop_py/chatter", "std_msgs/msg/String")
        pub.advertise()
        got = publish_until_received(pub, {"data": text}, inbox,
                                     f"String at the hub on /{robot}/interop_py/chatter",
                                     lambda m: m.get("data") == text)
        check(dict(got) == {"data": text}, f"chatter: hub got {dict(got)}")
        pub.unadvertise()
        sub.unsubscribe()
        ok(f"String published locally on /interop_py/chatter reached the hub as /{robot}/interop_py/chatter")
    finally:
        hub.close()


ZERO_TIME = {"sec": 0, "nanosec": 0}

# RFC 8746 typed arrays rosbridge's CBOR uses for numeric arrays: tag -> struct format.
TYPED_ARRAYS = {69: "H", 70: "I", 71: "Q", 72: "b", 77: "h", 78: "i", 79: "q", 85: "f", 86: "d"}


def plain(v):
    """A CBOR message with its typed arrays as lists of numbers."""
    if isinstance(v, cbor2.CBORTag) and v.tag in TYPED_ARRAYS:
        fmt = TYPED_ARRAYS[v.tag]
        return list(struct.unpack(f"<{len(v.value) // struct.calcsize(fmt)}{fmt}", v.value))
    if isinstance(v, dict):
        return {k: plain(x) for k, x in v.items()}
    if isinstance(v, list):
        return [plain(x) for x in v]
    return v


def partial_cases(prefix, nonce):
    """(topic, type, partial message, predicate on what a subscriber gets, what) per case."""
    return [
        (f"{prefix}/goal_id", "actionlib_msgs/GoalID", {"id": nonce},
         lambda m: m == {"stamp": {"secs": 0, "nsecs": 0}, "id": nonce},
         "GoalID with only its id: zero stamp, named as ROS 1 names it (a type only ROS 1 has)"),
        (f"{prefix}/markers", "visualization_msgs/msg/MarkerArray",
         {"markers": [{"ns": nonce, "id": 3, "pose": {"position": {"x": 1.5}}}]},
         lambda m: len(m["markers"]) == 1 and m["markers"][0]["ns"] == nonce
         and m["markers"][0]["header"] == {"stamp": ZERO_TIME, "frame_id": ""}
         and m["markers"][0]["pose"]["position"] == {"x": 1.5, "y": 0.0, "z": 0.0}
         and m["markers"][0]["points"] == [] and m["markers"][0]["text"] == ""
         and m["markers"][0]["lifetime"] == ZERO_TIME,
         "MarkerArray whose marker has 3 of its fields: the rest defaults"),
        (f"{prefix}/pose_cov", "geometry_msgs/msg/PoseWithCovarianceStamped",
         {"header": {"frame_id": nonce}},
         lambda m: m["header"] == {"stamp": ZERO_TIME, "frame_id": nonce}
         and m["pose"]["covariance"] == [0.0] * 36
         and m["pose"]["pose"]["orientation"]["w"] == 1.0,
         "PoseWithCovarianceStamped with only a frame: 36 zeros of covariance"),
    ]


def check_partial_messages(ros, url):
    """Partial messages reach JSON and CBOR subscribers with the type's defaults filled."""
    nonce = f"partial-{random.randint(0, 1 << 30)}"
    for topic, typ, msg, pred, what in partial_cases("/interop_py", nonce):
        inbox = Inbox()
        sub = roslibpy.Topic(ros, topic, typ)
        sub.subscribe(inbox.put)
        with ws_connect(url, open_timeout=TIMEOUT, close_timeout=2) as ws:
            ws.send(json.dumps({"op": "subscribe", "topic": topic, "type": typ,
                                "compression": "cbor"}))
            pub = roslibpy.Topic(ros, topic, typ)
            pub.advertise()
            got = publish_until_received(pub, msg, inbox, f"{what} (JSON)",
                                         lambda m: pred(dict(m)))
            check(pred(dict(got)), f"{what} (JSON): got {dict(got)}")
            frame = None
            deadline = time.monotonic() + TIMEOUT
            while time.monotonic() < deadline:
                f = ws.recv(timeout=max(0.01, deadline - time.monotonic()))
                if isinstance(f, bytes):
                    frame = cbor2.loads(f)
                    break
            check(frame is not None and frame.get("op") == "publish",
                  f"{what} (CBOR): no binary publish within {TIMEOUT}s")
            check(pred(plain(frame["msg"])), f"{what} (CBOR): got {frame['msg']}")
            pub.unadvertise()
        sub.unsubscribe()
        ok(f"{what}, on JSON and CBOR subscribers of {topic}")


def check_unknown_field(url):
    """A field the type does not have is refused, as rosbridge refuses it, naming it."""
    topic = "/interop_py/unknown_field"
    with ws_connect(url, open_timeout=TIMEOUT, close_timeout=2) as ws:
        ws.send(json.dumps({"op": "advertise", "topic": topic, "type": "geometry_msgs/msg/Twist"}))
        ws.send(json.dumps({"op": "publish", "id": "p1", "topic": topic,
                            "msg": {"linear": {"x": 1.0}, "bogus": 3}}))
        deadline = time.monotonic() + TIMEOUT
        while time.monotonic() < deadline:
            f = ws.recv(timeout=max(0.01, deadline - time.monotonic()))
            m = json.loads(f) if isinstance(f, str) else {}
            if m.get("op") == "status" and m.get("level") == "error":
                check("no field 'bogus'" in m.get("msg", ""),
                      f"unknown field: status does not name it: {m}")
                ok(f"a publish with a field its type lacks is refused: {m['msg']}")
                return
    raise CheckFailed(f"unknown field: no error status within {TIMEOUT}s")


def check_provider_answers(ros):
    """A provider whose callback returns False or nothing answers its callers, as with rosbridge."""
    for ret in (False, None):
        name = f"/interop_py/answers_{str(ret).lower()}"
        message = f"answered by a callback returning {ret}"
        server = roslibpy.Service(ros, name, "std_srvs/srv/Trigger")

        def handler(request, response, ret=ret, message=message):
            response["success"] = True
            response["message"] = message
            return ret

        server.advertise(handler)
        try:
            got = None
            for _ in range(PUBLISH_ATTEMPTS):  # until the advertisement is in place
                try:
                    got = call(ros, name, {}, "std_srvs/srv/Trigger")
                    break
                except CheckFailed as e:
                    if "not advertised" not in str(e):
                        raise
                    time.sleep(PUBLISH_INTERVAL)
            check(got == {"success": True, "message": message},
                  f"provider returning {ret}: the caller got {got}")
            ok(f"a provider whose callback returns {ret} answers its caller: {got}")
        finally:
            server.unadvertise()


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--url", required=True, help="rosbridge URL to test, ws://HOST:PORT/")
    ap.add_argument("--mode", choices=["hub", "local"], required=True)
    ap.add_argument("--robot", default="robot1")
    ap.add_argument("--peer-url", required=True,
                    help="the other side: the agent's local listener in hub mode, the hub in local mode")
    ap.add_argument("--scan-ranges", type=int, default=720)
    ap.add_argument("--points", type=int, default=2000)
    a = ap.parse_args()
    ns = f"/{a.robot}" if a.mode == "hub" else ""
    print(f"roslibpy {roslibpy.__version__} -> {a.url} ({a.mode} mode)", flush=True)
    ros = None
    try:
        ros = connect(a.url)
        ok(f"connected to {a.url}")
        check_topics(ros, ns)
        check_get_time(ros)
        check_graph(ros, a.mode, a.robot)
        check_scan(ros, ns, a.scan_ranges)
        check_odom(ros, ns)
        check_points_json(ros, ns, a.points)
        check_points_cbor(a.url, ns, a.points)
        check_params(ros, a.mode)
        check_invalid_op(ros)
        check_partial_messages(ros, a.url)
        check_unknown_field(a.url)
        check_provider_answers(ros)
        if a.mode == "hub":
            check_pull(ros, a.url, a.robot)
            check_publish_hub(ros, a.peer_url, a.robot)
        else:
            check_publish_local(ros, a.peer_url, a.robot)
    except CheckFailed as e:
        print(f"FAIL roslibpy ({a.mode}): {e}", file=sys.stderr, flush=True)
        return 1
    except Exception as e:  # a reply of the wrong shape (KeyError, TypeError, ...)
        print(f"FAIL roslibpy ({a.mode}): {type(e).__name__}: {e}", file=sys.stderr, flush=True)
        return 1
    finally:
        if ros is not None:
            try:
                ros.terminate()
            except Exception:
                pass
    print(f"PASS roslibpy ({a.mode})", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())

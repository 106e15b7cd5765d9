"""The robot's side of the ros2 interop suite: ROS 2 nodes as plain Cyclone DDS
participants (its Python binding; ROS 2 topic and type names, CDR), run with the repo's
.venv python. ROS_DOMAIN_ID selects the domain (default 0).

Modes:
  msg-package DIR   writes the suite's custom type, DIR/fltest_msgs/msg/Battery.msg.
  graph OUT --msg-path DIR --chatter-stop FILE
                    the robot's graph. First serializes every value it will send (and a
                    sample of every service and action type) with rosbags as well and
                    exits 1 unless the bytes equal Cyclone's ("crosscheck ..." lines).
                    Then: publishes /robot_description (std_msgs/msg/String,
                    transient_local) once; at 5 Hz /scan (LaserScan), /battery
                    (fltest_msgs/msg/Battery, its .msg read from DIR), /points
                    (PointCloud2, 100k points, once a second) and, until FILE exists,
                    /chatter ("robot-N", from a participant of its own); subscribes
                    /cmd_vel and /chatter; serves /add_two_ints
                    (example_interfaces/srv/AddTwoInts, 20 ms per request) and the action /fibonacci
                    (example_interfaces/action/Fibonacci, 0.1 s per step). Prints
                    "graph ready"; writes what it received to OUT (JSON) every 0.2 s.
  announce [--wait S]
                    a participant started late: a transient_local reader of /announce
                    must get the hub's latched "hello fleet", written before the reader
                    existed. Exit 0 when it did.
  node-info --node NAME [--gid 16|24] [--wait S]
                    reads ros_discovery_info as `ros2 node list` does, with GIDs of 16
                    (Iron and newer) or 24 bytes (Humble and older): the agent's node NAME
                    is listed under its participant, with its rt/cmd_vel writer among the
                    node's writers. Exit 0 when so.
  announce-node --node NAME [--gid 16|24]
                    a node of another distribution: keeps its participant's sample on
                    ros_discovery_info with GIDs of that size, naming node NAME, until
                    stopped. Prints "announce-node ready: ...".
  first-message [--wait S]
                    a volatile reader of /oneshot, started before the hub publishes it
                    once: prints "first-message ready" when the agent is discovered,
                    exit 0 when the single message arrived.
  call-greet [--wait S]
                    calls /cloud/greet (std_srvs/srv/Trigger) as a ROS 2 client; exit 0
                    when the fleet's answer came.
  call-fib [--wait S]
                    a ROS 2 action client of the fleet action /cloud/fib (served at the
                    hub, offered to the robot by the agent): order 5 succeeds with
                    feedback and status updates, order 40 is cancelled.
  late              a participant started after the agent: publishes /late_topic
                    ("late-N", std_msgs/msg/String) at 5 Hz until stopped.
  delivery-check    the peers' own plumbing: a reader takes /chatter written at 1 kHz both
                    by a participant in this process and by another process, at once,
                    for 2 s. Exit 0 when every write returned and the reader saw both.
                    (Cyclone listeners deadlocked exactly there; see ros2_dds.Node.)
  selftest          checks all of the above against Cyclone peers of its own (no
                    fleetlink): run it by hand inside a network namespace when changing
                    this file. See selftest().
Every wait is bounded; failures print "FAIL: ...".
"""
import argparse
import base64
import dataclasses
import itertools
import json
import os
import random
import signal
import struct
import subprocess
import sys
import tempfile
import threading
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import expected as E  # noqa: E402
from cyclonedds.core import DDSException  # noqa: E402
import ros2_types as T  # noqa: E402
from ros2_dds import (FibonacciClient, FibonacciServer, Node, ParameterServer, ServiceClient, ServiceServer,  # noqa: E402
                      topic_name, wait_until)


def log(line):
    print(line, flush=True)


# ---------------------------------------------------------------- values as DDS samples

def time_msg(d):
    return T.Time(sec=d["sec"], nanosec=d["nanosec"])


def header_msg(d):
    return T.Header(stamp=time_msg(d["stamp"]), frame_id=d["frame_id"])


def scan_msg():
    d = E.scan()
    return T.LaserScan(header=header_msg(d.pop("header")), **d)


def cloud_msg():
    d = E.cloud(E.cloud_data())
    return T.PointCloud2(header=header_msg(d.pop("header")), fields=[T.PointField(**f) for f in d.pop("fields")], **d)


def battery_msg(n):
    d = E.battery(n)
    return T.Battery(stamp=time_msg(d.pop("stamp")), **d)


def to_json(obj):
    """An IDL sample in rosbridge JSON form (uint8[] as base64), service header left out;
    the self-test compares it with the same functions the hub's peer uses."""
    from cyclonedds.idl._main import get_extended_type_hints
    from cyclonedds.idl.types import sequence

    hints = get_extended_type_hints(type(obj))
    out = {}
    for f in dataclasses.fields(obj):
        if f.name in T.SERVICE_HEADER:
            continue
        v, h = getattr(obj, f.name), hints[f.name]
        if isinstance(h, sequence) and getattr(h.subtype, "__metadata__", (None,))[0] == "uint8":
            out[f.name] = base64.b64encode(bytes(v)).decode()
        elif dataclasses.is_dataclass(v):
            out[f.name] = to_json(v)
        elif isinstance(v, list):
            out[f.name] = [to_json(x) if dataclasses.is_dataclass(x) else x for x in v]
        else:
            out[f.name] = v
    return out


def write_json(path, value):
    with open(path + ".tmp", "w") as f:
        json.dump(value, f)
    os.replace(path + ".tmp", path)


# ---------------------------------------------------------------- the custom type

def battery_msg_path(msg_path):
    return os.path.join(msg_path, "fltest_msgs", "msg", "Battery.msg")


def msg_package(msg_path):
    os.makedirs(os.path.dirname(battery_msg_path(msg_path)), exist_ok=True)
    with open(battery_msg_path(msg_path), "w") as f:
        f.write(T.BATTERY_MSG)


# ---------------------------------------------------------------- rosbags cross-check

def representative_samples():
    """One sample of every type the graph sends or receives besides its topic values."""
    t = T.Time(sec=1700000000, nanosec=42)
    info = T.GoalInfo(goal_id=T.UUID(uuid=bytes(range(16))), stamp=t)
    return [
        T.String(data=E.robot_description()),
        T.Twist(linear=T.Vector3(**E.TWIST["linear"]), angular=T.Vector3(**E.TWIST["angular"])),
        T.AddTwoIntsRequest(guid=2**63 + 5, seq=7, a=-2**40, b=3),
        T.AddTwoIntsResponse(guid=2**63 + 5, seq=7, sum=-2**40 + 3),
        T.TriggerRequest(guid=1, seq=1, structure_needs_at_least_one_member=0),
        T.TriggerResponse(guid=1, seq=1, success=True, message=E.GREETING),
        T.FibonacciSendGoalRequest(guid=9, seq=1, goal_id=info.goal_id, goal=T.FibonacciGoal(order=5)),
        T.FibonacciSendGoalResponse(guid=9, seq=1, accepted=True, stamp=t),
        T.FibonacciGetResultRequest(guid=9, seq=2, goal_id=info.goal_id),
        T.FibonacciGetResultResponse(guid=9, seq=2, status=T.SUCCEEDED, result=T.FibonacciResult(sequence=E.fibonacci(5))),
        T.FibonacciFeedbackMessage(goal_id=info.goal_id, feedback=T.FibonacciFeedback(sequence=[0, 1, 1])),
        T.CancelGoalRequest(guid=9, seq=3, goal_info=info),
        T.CancelGoalResponse(guid=9, seq=3, return_code=0, goals_canceling=[info, info]),
        T.GoalStatusArray(status_list=[T.GoalStatus(goal_info=info, status=T.EXECUTING)]),
        T.GetParametersRequest(guid=4, seq=1, names=["max_speed", "waypoints"]),
        T.GetParametersResponse(guid=4, seq=1, values=[T.parameter_value(t, v) for t, v in E.PARAMETERS.values()] + [
            T.parameter_value(5, [0, 7, 255]), T.parameter_value(6, [True, False]),
            T.parameter_value(8, [0.5, -1e300]), T.parameter_value(9, ["a", ""]), T.parameter_value(0)]),
        T.SetParametersRequest(guid=4, seq=2, parameters=[
            T.Parameter(name="max_speed", value=T.parameter_value(3, 2.0))]),
        T.SetParametersResponse(guid=4, seq=2, results=[
            T.SetParametersResult(successful=False, reason="read-only"),
            T.SetParametersResult(successful=True, reason="")]),
        T.ListParametersRequest(guid=4, seq=3, prefixes=["a"], depth=0),
        T.ListParametersResponse(guid=4, seq=3, result=T.ListParametersResult(names=["x", "a.b"], prefixes=["a"])),
    ]


class CrossCheck:
    """Serializes samples with rosbags as well; remembers the types checked."""

    def __init__(self, msg_path):
        with open(battery_msg_path(msg_path)) as f:
            self.store = T.typestore(f.read())
        self.types = set()
        self.failures = []

    def __call__(self, obj):
        problem = T.crosscheck(self.store, obj)
        if problem:
            self.failures.append(problem)
            log(f"FAIL: crosscheck {problem}")
        self.types.add(T.ros_name(type(obj)))
        return problem is None


# ---------------------------------------------------------------- graph

def graph(args):
    check = CrossCheck(args.msg_path)
    scan, cloud = scan_msg(), cloud_msg()
    for sample in [scan, cloud, battery_msg(1), T.String(data="robot-1")] + representative_samples():
        check(sample)
    if check.failures:
        return 1
    log(f"crosscheck ok: Cyclone's CDR equals rosbags' for {len(check.types)} types: {', '.join(sorted(check.types))}")

    node = Node()
    got = {"cmd_vel": 0, "cmd_vel_values": [], "chatter": {}, "chatter_sent": 0, "add_two_ints": 0, "goals": []}
    lock = threading.Lock()

    # Latched, before anything else (and, in the suite, before the agent starts).
    description = node.writer(topic_name("/robot_description"), T.String, qos=T.LATCHED_QOS)
    description.write(T.String(data=E.robot_description()))

    def on_cmd(m):
        v = [m.linear.x, m.linear.y, m.linear.z, m.angular.x, m.angular.y, m.angular.z]
        with lock:
            got["cmd_vel"] += 1
            if v not in got["cmd_vel_values"]:
                got["cmd_vel_values"].append(v)

    def on_chatter(m):
        with lock:
            got["chatter"][m.data] = got["chatter"].get(m.data, 0) + 1

    def on_add(req, reply):
        # A server slower than a burst of calls: 20 ms each, on the node's one dispatch
        # thread, while its request reader keeps the last 10 (rmw's default). The agent
        # must keep no more than that unanswered, or 40 calls at once lose 30.
        time.sleep(0.02)
        with lock:
            got["add_two_ints"] += 1
        reply(sum=req.a + req.b)

    node.reader(topic_name("/cmd_vel"), T.Twist, on_cmd)
    node.reader(topic_name("/chatter"), T.String, on_chatter)
    ServiceServer(node, "/add_two_ints", T.AddTwoIntsRequest, T.AddTwoIntsResponse, on_add)
    fib = FibonacciServer(node, "/fibonacci", step=0.1)
    # A node's parameters, served as rclcpp serves them (step 6c reads and changes them).
    params = ParameterServer(node, E.PARAMETER_NODE, {n: T.parameter_value(t, v) for n, (t, v) in E.PARAMETERS.items()},
                             read_only=["serial"])
    scan_w = node.writer(topic_name("/scan"), T.LaserScan)
    cloud_w = node.writer(topic_name("/points"), T.PointCloud2)
    battery_w = node.writer(topic_name("/battery"), T.Battery)
    # /chatter's writer is another participant: what the graph's reader sees of it is
    # then exactly what any other node sees (once each), and a second copy is a loop.
    chat_w = Node().writer(topic_name("/chatter"), T.String)
    log("graph ready")

    def write(writer, sample, what):
        """A reliable writer blocks while its history is full of unacknowledged samples
        (up to the QoS's max_blocking_time, then fails): a slow reader costs this one
        sample, not the graph."""
        try:
            writer.write(sample)
            return True
        except DDSException as e:
            with lock:
                got["write_errors"] = got.get("write_errors", 0) + 1
            log(f"{what}: write failed: {e}")
            return False

    n = 0
    while True:
        n += 1
        write(scan_w, scan, "/scan")
        b = battery_msg(n)
        if n <= 50 and not check(b):  # every battery value differs: check the first 50
            return 1
        write(battery_w, b, "/battery")
        if n % 5 == 1:  # 1.2 MB once a second
            write(cloud_w, cloud, "/points")
        if not os.path.exists(args.chatter_stop):
            # Numbered by successful writes: a failed one is sent again, under its number.
            with lock:
                k = got["chatter_sent"] + 1
            if write(chat_w, T.String(data=f"robot-{k}"), "/chatter"):
                with lock:
                    got["chatter_sent"] = k
        with lock:
            got["goals"] = fib.report()
            got["params"] = params.values()
            snapshot = json.dumps(got)
        with open(args.out + ".tmp", "w") as f:
            f.write(snapshot)
        os.replace(args.out + ".tmp", args.out)
        time.sleep(0.2)


# ---------------------------------------------------------------- late joiners

def announce(args):
    """A reader created now, transient_local: it can only get the hub's single latched
    message from the history of the agent's writer."""
    node = Node()
    created = time.time_ns()
    box = []
    node.reader(topic_name("/announce"), T.String, box.append, qos=T.LATCHED_QOS)
    if not wait_until(lambda: box, args.wait):
        log(f"FAIL: /announce: no sample within {args.wait:.0f} s for a transient_local reader "
            "(is the agent's writer reliable + transient_local, and did it get the hub's latched message?)")
        return 1
    m = box[0]
    age = (created - m.sample_info.source_timestamp) / 1e9
    if m.data != E.ANNOUNCE:
        log(f"FAIL: /announce: {m.data!r}, want {E.ANNOUNCE!r}")
        return 1
    if age <= 0:
        log(f"FAIL: /announce: the sample was written {-age:.2f} s after this reader was created: "
            "not the writer's history (a re-publish?)")
        return 1
    log(f"ok: a late transient_local reader got /announce {E.ANNOUNCE!r}, written {age:.2f} s before it existed")
    return 0


def node_info(args):
    """`ros2 node list`'s source: the agent's sample on ros_discovery_info, read with
    GIDs of --gid bytes, must name node --node and list the agent's writer of
    rt/cmd_vel among the node's writers (that writer's GUID as Cyclone's own discovery
    knows it) under the agent's participant GID."""
    from cyclonedds.builtin import BuiltinDataReader, BuiltinTopicDcpsPublication
    from rosbags.typesys import Stores, get_typestore

    _, _, Info = T.discovery_types(args.gid)
    store = get_typestore(Stores.ROS2_HUMBLE if args.gid == 24 else Stores.ROS2_JAZZY)
    node = Node()
    infos = []
    # ros_discovery_info has no key: every participant's sample is one instance, so a
    # reader of depth 1 keeps only whichever arrived last between two takes (the Humble
    # node's sample can displace the agent's). Room for many, as rmw keeps.
    node.reader("ros_discovery_info", Info, infos.append, qos=T.qos(transient_local=True, depth=64))
    publications = BuiltinDataReader(node.dp, BuiltinTopicDcpsPublication)
    cmd_writers = {}

    def agent_sample():
        """The agent's newest sample naming the node: (info, entry), or None."""
        for s in publications.take(N=100):
            if s.topic_name == "rt/cmd_vel":
                cmd_writers[s.key.bytes] = s.participant_key.bytes
        for info in reversed(list(infos)):
            for n in info.node_entities_info_seq:
                if n.node_name == args.node.lstrip("/") and n.node_namespace == "/":
                    return info, n
        return None

    def lists_cmd_writer():
        got = agent_sample()
        return got is not None and any(T.gid_bytes(g)[:16] in cmd_writers for g in got[1].writer_gid_seq)

    if not wait_until(agent_sample, args.wait):
        seen = [f"{n.node_namespace}/{n.node_name}" for i in infos for n in i.node_entities_info_seq]
        log(f"FAIL: no node {args.node} on ros_discovery_info within {args.wait:.0f} s ({args.gid}-byte GIDs); "
            f"nodes seen: {seen}")
        return 1
    # The node's sample is rewritten as its endpoints appear: judge the newest one once
    # it lists the rt/cmd_vel writer (or after 5 s, the newest there is).
    wait_until(lists_cmd_writer, 5)
    info, entry = agent_sample()
    problem = T.crosscheck(store, info)
    if problem:
        log(f"FAIL: the agent's sample re-serialized differs from rosbags' ({args.gid}-byte GIDs): {problem}")
        return 1
    gid = T.gid_bytes(info.gid)
    writers = [T.gid_bytes(g) for g in entry.writer_gid_seq]
    readers = [T.gid_bytes(g) for g in entry.reader_gid_seq]
    if any(g[16:] != bytes(args.gid - 16) for g in [gid] + writers + readers):
        log(f"FAIL: a {args.gid}-byte GID is not a GUID padded with zeros: {gid.hex()}")
        return 1
    mine = [w for w in writers if w[:16] in cmd_writers]
    if not mine:
        log(f"FAIL: the node's {len(writers)} writers do not include a writer of rt/cmd_vel "
            f"(Cyclone knows {len(cmd_writers)}: {[k.hex() for k in cmd_writers]})")
        return 1
    if cmd_writers[mine[0][:16]] != gid[:16]:
        log(f"FAIL: the node's rt/cmd_vel writer belongs to participant {cmd_writers[mine[0][:16]].hex()}, "
            f"but the sample's GID is {gid[:16].hex()}")
        return 1
    log(f"ok: ros_discovery_info ({args.gid}-byte GIDs, equal to rosbags' layout) lists node {args.node} "
        f"with {len(readers)} readers and {len(writers)} writers, among them its rt/cmd_vel writer")
    return 0


def announce_node(args):
    """A node of another distribution: writes this participant's ParticipantEntitiesInfo
    on ros_discovery_info with --gid-byte GIDs (transient local, as rmw does) naming
    node --node, then stays until stopped. An agent without ros2.distro or ROS_DISTRO
    must take the GID size from it."""
    Gid, NodeInfo, Info = T.discovery_types(args.gid)
    node = Node()

    def gid(raw16):
        return Gid(data=list(raw16) + [0] * (args.gid - 16))

    ns, _, name = args.node.rpartition("/")
    sample = Info(gid=gid(node.dp.guid.bytes), node_entities_info_seq=[
        NodeInfo(node_namespace=ns or "/", node_name=name, reader_gid_seq=[], writer_gid_seq=[])])
    # Kept in a variable: a collected writer is deleted, and its kept sample with it.
    writer = node.writer("ros_discovery_info", Info, qos=T.qos(transient_local=True, depth=1))
    writer.write(sample)
    log(f"announce-node ready: {args.node} with {args.gid}-byte GIDs")
    signal.pause()


def first_message(args):
    """A node waiting for a topic that the hub publishes once, later: its volatile reader
    must get that one message, although the agent makes its writer only when the message
    comes (and a volatile reader gets nothing written before it is matched)."""
    from cyclonedds.builtin import BuiltinDataReader, BuiltinTopicDcpsPublication

    node = Node()
    got = []
    node.reader(topic_name("/oneshot"), T.String, got.append)
    publications = BuiltinDataReader(node.dp, BuiltinTopicDcpsPublication)
    seen = set()

    def agent_known():
        seen.update(s.topic_name for s in publications.take(N=100))
        return "rt/cmd_vel" in seen

    # Discovery between this participant and the agent has happened both ways once the
    # agent's writers are known here.
    if not wait_until(agent_known, args.wait):
        log(f"FAIL: the agent's rt/cmd_vel writer was not discovered within {args.wait:.0f} s")
        return 1
    log("first-message ready")
    if not wait_until(lambda: got, args.wait):
        log(f"FAIL: /oneshot: the hub's single message did not arrive within {args.wait:.0f} s")
        return 1
    if [m.data for m in got] != [E.ONESHOT]:
        log(f"FAIL: /oneshot: got {[m.data for m in got]}, want [{E.ONESHOT!r}]")
        return 1
    log(f"ok: a reader waiting for /oneshot got the hub's single message {E.ONESHOT!r}")
    return 0


def call_greet(args):
    node = Node()
    client = ServiceClient(node, "/cloud/greet", T.TriggerRequest, T.TriggerResponse)
    deadline = time.monotonic() + args.wait
    if not client.wait_ready(args.wait):
        log(f"FAIL: /cloud/greet: no server matched within {args.wait:.0f} s (a reader of rq/cloud/greetRequest "
            "and a writer of rr/cloud/greetReply, types std_srvs::srv::dds_::Trigger_Request_/_Response_)")
        return 1
    attempts = 0
    while time.monotonic() < deadline:
        attempts += 1
        resp = client.call(min(3.0, max(0.5, deadline - time.monotonic())), structure_needs_at_least_one_member=0)
        if resp is None:
            continue  # the route behind the agent may still be settling; retry (bounded)
        if resp.success is True and resp.message == E.GREETING:
            log(f"ok: /cloud/greet answered {{success: true, message: {resp.message!r}}} (attempt {attempts})")
            return 0
        log(f"FAIL: /cloud/greet answered success={resp.success!r} message={resp.message!r}, "
            f"want true, {E.GREETING!r}")
        return 1
    log(f"FAIL: /cloud/greet: servers matched but no reply with our header within {args.wait:.0f} s "
        f"({attempts} requests)")
    return 1


def call_fib(args):
    """A local ROS 2 action client of the fleet action /cloud/fib (served at the hub):
    order 5 succeeds with feedback and status updates; a long goal is cancelled."""
    node = Node()
    client = FibonacciClient(node, "/cloud/fib")
    if not client.wait_ready(args.wait):
        log(f"FAIL: /cloud/fib: the agent's action services were not matched within {args.wait:.0f} s")
        return 1
    bad = 0
    uuid = bytes(random.getrandbits(8) for _ in range(16))
    sent = client.send.call(5.0, goal_id=T.UUID(uuid=list(uuid)), goal=T.FibonacciGoal(order=5))
    if sent is None or not sent.accepted:
        log(f"FAIL: /cloud/fib send_goal: {sent!r}, want accepted")
        return 1
    res = client.result.call(20.0, goal_id=T.UUID(uuid=list(uuid)))
    want = [0, 1, 1, 2, 3, 5]
    if res is None or res.status != T.SUCCEEDED or list(res.result.sequence) != want:
        log(f"FAIL: /cloud/fib order 5 result: {res!r}, want status {T.SUCCEEDED} {want}")
        bad += 1
    else:
        log(f"ok: /cloud/fib order 5 through the agent: status SUCCEEDED, {want}")
    wait_until(lambda: T.SUCCEEDED in client.statuses.get(uuid, []), 3)
    fbs = client.feedbacks.get(uuid, [])
    if fbs and all(f == want[:len(f)] for f in fbs):
        log(f"ok: /cloud/fib feedback: {len(fbs)} message(s), each a prefix of the result; status topic {client.statuses.get(uuid)}")
    else:
        log(f"FAIL: /cloud/fib feedback {fbs!r}, want prefixes of {want}")
        bad += 1
    if T.SUCCEEDED not in client.statuses.get(uuid, []):
        log(f"FAIL: /cloud/fib status topic never said SUCCEEDED: {client.statuses.get(uuid)}")
        bad += 1
    long_id = bytes(random.getrandbits(8) for _ in range(16))
    sent = client.send.call(5.0, goal_id=T.UUID(uuid=list(long_id)), goal=T.FibonacciGoal(order=40))
    if sent is None or not sent.accepted:
        log(f"FAIL: /cloud/fib order 40 send_goal: {sent!r}")
        return 1
    wait_until(lambda: client.feedbacks.get(long_id), 5)
    cancel = client.cancel.call(5.0, goal_info=T.GoalInfo(goal_id=T.UUID(uuid=list(long_id)), stamp=T.Time(sec=0, nanosec=0)))
    if cancel is None or cancel.return_code != 0 or len(cancel.goals_canceling) != 1:
        log(f"FAIL: /cloud/fib cancel_goal answered {cancel!r}, want return_code 0 and the goal listed")
        bad += 1
    res = client.result.call(10.0, goal_id=T.UUID(uuid=list(long_id)))
    if res is None or res.status != T.CANCELED:
        log(f"FAIL: /cloud/fib cancelled goal's result: {res!r}, want status {T.CANCELED}")
        bad += 1
    else:
        log(f"ok: /cloud/fib order 40 cancelled: status CANCELED, partial {list(res.result.sequence)[:6]}...")
    return 1 if bad else 0


def late(args):
    w = Node().writer(topic_name("/late_topic"), T.String)
    log("late ready")
    n = 0
    while True:
        n += 1
        w.write(T.String(data=f"late-{n}"))
        time.sleep(0.2)


def idle_cloud(args):
    """A lidar driver nobody at the hub watches: /idle_points, a 160 kB PointCloud2 at
    10 Hz. Prints `matched N` whenever the number of readers matched to its writer
    changes: the agent's reader goes when the agent stops reading the topic, and comes
    back when a viewer at the hub wants it."""
    n = 10_000
    w = Node().writer(topic_name("/idle_points"), T.PointCloud2)
    fields = [T.PointField(name=f, offset=4 * i, datatype=7, count=1) for i, f in enumerate(["x", "y", "z", "intensity"])]
    data = list(b"".join(struct.pack("<ffff", (i % 100) * 0.05, (i // 100) * 0.05, 1.0, 7.0) for i in range(n)))
    log("idle_cloud ready")
    matched = -1
    while True:
        now = time.time()
        stamp = T.Time(sec=int(now), nanosec=int((now % 1) * 1e9))
        w.write(T.PointCloud2(header=T.Header(stamp=stamp, frame_id="lidar"), height=1, width=n, fields=fields,
                              is_bigendian=False, point_step=16, row_step=16 * n, data=data, is_dense=True))
        m = len(w.get_matched_subscriptions())
        if m != matched:
            matched = m
            log(f"matched {m}")
        time.sleep(0.1)


# ---------------------------------------------------------------- self-test

class SelfTest:
    def __init__(self):
        self.failures = []

    def check(self, ok, what):
        log(("ok: " if ok else "FAIL: ") + what)
        if not ok:
            self.failures.append(what)
        return ok


def selftest(args):
    """Plays the agent's part with Cyclone peers of its own: reads the graph's topics
    (values checked with the hub peer's comparisons), publishes /cmd_vel, /chatter and a
    latched /announce, serves /cloud/greet, calls /add_two_ints from two clients at once,
    runs the Fibonacci action to success and to a cancel, and checks the late joiners
    (announce, call-greet, late) as subprocesses. Run inside a network namespace with
    multicast on lo, like run.sh does."""
    st = SelfTest()
    tmp = tempfile.mkdtemp(prefix="fleetlink-ros2-selftest.")
    msgs = os.path.join(tmp, "msgs")
    msg_package(msgs)
    out, stop = os.path.join(tmp, "graph.json"), os.path.join(tmp, "chatter.stop")
    me = [sys.executable, os.path.abspath(__file__)]
    procs = []

    def start(*argv):
        p = subprocess.Popen(me + list(argv), stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        procs.append(p)
        return p

    def first_line(p, want, timeout):
        """Waits (bounded) for a line equal to `want`; echoes the child's output."""
        box = []

        def pump():
            for line in p.stdout:
                print("    | " + line.rstrip(), flush=True)
                if line.strip() == want:
                    box.append(True)

        threading.Thread(target=pump, daemon=True).start()
        return wait_until(lambda: box or p.poll() is not None, timeout) and bool(box)

    try:
        # A crosscheck that must fail: the right name, one field a different width.
        from cyclonedds.idl import IdlStruct
        from cyclonedds.idl.types import uint16

        @dataclasses.dataclass
        class WrongBattery(IdlStruct, typename=T.dds_name("fltest_msgs/msg/Battery")):
            label: str
            voltage: T.float32
            cells: uint16
            balance_mv: T.array[T.int16, 3]
            temps: T.sequence[T.float64]
            stamp: T.Time

        problem = T.crosscheck(CrossCheck(msgs).store, WrongBattery(**{f.name: getattr(battery_msg(3), f.name) for f in dataclasses.fields(T.Battery)}))
        st.check(problem is not None and "cells" in problem, f"crosscheck catches a wrong field type: {problem}")

        # The loop check must notice a loop: robot-2 back from the other side.
        looped = {"robot-1": 1, "robot-2": 2, **{f"hub-{k}": 1 for k in range(1, 8)}}
        found = E.chatter_problems(looped, "robot", 2, "hub", 7, "robot")
        st.check(found == ["robot saw robot-2 2 times"], f"the loop check notices a loop: {found}")

        graph_p = start("graph", out, "--msg-path", msgs, "--chatter-stop", stop)
        if not st.check(first_line(graph_p, "graph ready", 30), "graph started"):
            return 1

        node = Node()
        got = {}
        lock = threading.Lock()

        def keep(name):
            def put(m):
                with lock:
                    got.setdefault(name, []).append(m)
            return put

        def first(name, timeout):
            wait_until(lambda: got.get(name), timeout)
            with lock:
                return (got.get(name) or [None])[0]

        for name, cls in (("/scan", T.LaserScan), ("/points", T.PointCloud2), ("/battery", T.Battery),
                          ("/late_topic", T.String)):
            node.reader(topic_name(name), cls, keep(name))
        time.sleep(1.0)  # so that /robot_description's reader below is surely late
        node.reader(topic_name("/robot_description"), T.String, keep("/robot_description"), qos=T.LATCHED_QOS)

        m = first("/scan", 10)
        st.check(m is not None and not E.check_scan(to_json(m)), f"/scan equal: {E.check_scan(to_json(m)) if m else 'none'}")
        m = first("/points", 10)
        st.check(m is not None and not E.check_cloud(to_json(m)), f"/points equal: {E.check_cloud(to_json(m)) if m else 'none'}")
        m = first("/battery", 10)
        st.check(m is not None and not E.check_battery(to_json(m)),
                 f"/battery equal: {E.check_battery(to_json(m)) if m else 'none'}")
        m = first("/robot_description", 10)
        st.check(m is not None and m.data == E.robot_description(), "a late transient_local reader got /robot_description")

        # Hub -> robot: /cmd_vel, /chatter ("hub-N"), the latched /announce.
        cmd_w = node.writer(topic_name("/cmd_vel"), T.Twist)
        chat_w = node.writer(topic_name("/chatter"), T.String)
        ann_w = node.writer(topic_name("/announce"), T.String, qos=T.LATCHED_QOS)
        ann_w.write(T.String(data=E.ANNOUNCE))
        ServiceServer(node, "/cloud/greet", T.TriggerRequest, T.TriggerResponse,
                      lambda req, reply: reply(success=True, message=E.GREETING))
        sent = {"hub": 0}
        running = threading.Event()
        running.set()

        def hub_publisher():
            while running.is_set():
                cmd_w.write(T.Twist(linear=T.Vector3(**E.TWIST["linear"]), angular=T.Vector3(**E.TWIST["angular"])))
                if not os.path.exists(stop):
                    sent["hub"] += 1
                    chat_w.write(T.String(data=f"hub-{sent['hub']}"))
                time.sleep(0.2)

        threading.Thread(target=hub_publisher, daemon=True).start()
        time.sleep(1.0)
        r = subprocess.run(me + ["announce", "--wait", "10"], capture_output=True, text=True, timeout=30)
        st.check(r.returncode == 0, f"announce mode: {r.stdout.strip()} {r.stderr.strip()[-300:]}")
        r = subprocess.run(me + ["call-greet", "--wait", "10"], capture_output=True, text=True, timeout=30)
        st.check(r.returncode == 0, f"call-greet mode: {r.stdout.strip()} {r.stderr.strip()[-300:]}")

        # Two clients calling /add_two_ints at once: each must get its own sums.
        clients = [ServiceClient(node, "/add_two_ints", T.AddTwoIntsRequest, T.AddTwoIntsResponse) for _ in range(2)]
        st.check(all(c.wait_ready(10) for c in clients), "/add_two_ints clients matched the server")
        results = []

        def caller(c, k):
            for i in range(10):
                a, b = k * 1_000_000 + i, -(2**40) + i
                resp = c.call(5, a=a, b=b)
                results.append(resp is not None and resp.sum == a + b)

        threads = [threading.Thread(target=caller, args=(c, k)) for k, c in enumerate(clients) for _ in range(2)]
        for t in threads:
            t.start()
        for t in threads:
            t.join(30)
        st.check(len(results) == 40 and all(results), f"/add_two_ints: {results.count(True)} of 40 concurrent calls right")

        # The action: order 5 to success, then order 50 cancelled after its first feedback.
        fc = FibonacciClient(node, "/fibonacci")
        st.check(fc.wait_ready(10), "/fibonacci: the three services matched")
        uuid = os.urandom(16)
        resp = fc.send.call(5, goal_id=T.UUID(uuid=uuid), goal=T.FibonacciGoal(order=5))
        st.check(resp is not None and resp.accepted, f"goal 5 accepted: {resp}")
        res = fc.result.call(10, goal_id=T.UUID(uuid=uuid))
        st.check(res is not None and res.status == T.SUCCEEDED and list(res.result.sequence) == E.fibonacci(5),
                 f"goal 5: status {res and res.status}, result {res and list(res.result.sequence)}")
        wait_until(lambda: fc.statuses.get(uuid, [None])[-1] == T.SUCCEEDED, 3)
        with fc.lock:
            fbs, sts = fc.feedbacks.get(uuid, []), fc.statuses.get(uuid, [])
        st.check(len(fbs) == 4 and fbs[-1] == E.fibonacci(5), f"goal 5: feedback {fbs}")
        st.check(sts and sts[-1] == T.SUCCEEDED, f"goal 5: statuses on the status topic {sts}")
        uuid2 = os.urandom(16)
        resp = fc.send.call(5, goal_id=T.UUID(uuid=uuid2), goal=T.FibonacciGoal(order=50))
        st.check(resp is not None and resp.accepted, "goal 50 accepted")
        wait_until(lambda: fc.feedbacks.get(uuid2), 5)
        c = fc.cancel.call(5, goal_info=T.GoalInfo(goal_id=T.UUID(uuid=uuid2), stamp=T.Time(sec=0, nanosec=0)))
        st.check(c is not None and c.return_code == 0 and [bytes(g.goal_id.uuid) for g in c.goals_canceling] == [uuid2],
                 f"cancel goal 50: {c}")
        res = fc.result.call(10, goal_id=T.UUID(uuid=uuid2))
        seq = list(res.result.sequence) if res else None
        st.check(res is not None and res.status == T.CANCELED and seq == E.fibonacci(50)[:len(seq)] and len(seq) < 51,
                 f"goal 50: status {res and res.status}, {len(seq or [])} numbers")
        wait_until(lambda: fc.statuses.get(uuid2, [None])[-1] == T.CANCELED, 3)
        st.check(fc.statuses.get(uuid2, [None])[-1] == T.CANCELED, f"goal 50: statuses {fc.statuses.get(uuid2)}")
        c = fc.cancel.call(5, goal_info=T.GoalInfo(goal_id=T.UUID(uuid=uuid2), stamp=T.Time(sec=0, nanosec=0)))
        st.check(c is not None and c.return_code == 3, f"cancelling a finished goal: return_code {c and c.return_code}")

        # A participant started late.
        start("late")
        m = first("/late_topic", 10)
        st.check(m is not None and m.data.startswith("late-"), f"/late_topic from a late participant: {m}")

        # /chatter: stop both sides, let it settle, count.
        open(stop, "w").close()
        time.sleep(1.5)
        with open(out) as f:
            g = json.load(f)
        problems = E.chatter_problems(g["chatter"], "robot", g["chatter_sent"], "hub", sent["hub"], "graph")
        st.check(not problems, f"chatter at the graph: {problems or 'each message once'} "
                 f"({g['chatter_sent']} robot, {sent['hub']} hub sent)")
        st.check(g["cmd_vel"] > 0 and g["cmd_vel_values"] == [list(E.TWIST["linear"].values()) + list(E.TWIST["angular"].values())],
                 f"graph's /cmd_vel: {g['cmd_vel']} messages, values {g['cmd_vel_values']}")
        st.check(g["add_two_ints"] == 40, f"graph served {g['add_two_ints']} /add_two_ints calls")
        st.check([(x["order"], x["status"]) for x in g["goals"]] == [(5, T.SUCCEEDED), (50, T.CANCELED)],
                 f"graph's goals: {g['goals']}")
    finally:
        for p in procs:
            p.terminate()
        for p in procs:
            try:
                p.wait(5)
            except subprocess.TimeoutExpired:
                p.kill()
    log(f"selftest: {len(st.failures)} failure(s)")
    return 1 if st.failures else 0


def delivery_check(args):
    """Writes from this process and from a child process to one reader here, at once."""
    if args.path == "child":  # the other process: writes until killed
        w = Node().writer(topic_name("/chatter"), T.String)
        for i in itertools.count(1):
            w.write(T.String(data=f"remote-{i}"))
            time.sleep(0.001)
    node = Node()
    seen = {"local": 0, "remote": 0}
    lock = threading.Lock()

    def on_chatter(m):
        with lock:
            seen[m.data.split("-")[0]] += 1

    node.reader(topic_name("/chatter"), T.String, on_chatter)
    w = Node().writer(topic_name("/chatter"), T.String)
    child = subprocess.Popen([sys.executable, os.path.abspath(__file__), "delivery-check", "child"])
    try:
        if not wait_until(lambda: seen["remote"] > 0, 20):
            log("FAIL: delivery-check: nothing from the other process within 20 s")
            return 1
        writes, end = 0, time.monotonic() + 2
        while time.monotonic() < end:  # a deadlock stops here; run.sh's timeout ends it
            writes += 1
            w.write(T.String(data=f"local-{writes}"))
            time.sleep(0.001)
        with lock:
            got = dict(seen)
        ok = got["local"] > 0 and got["remote"] > 0
        log(f"{'ok' if ok else 'FAIL'}: delivery-check: {writes} local writes returned; the reader took "
            f"{got['local']} local and {got['remote']} remote samples meanwhile")
        return 0 if ok else 1
    finally:
        child.kill()


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("mode", choices=["msg-package", "graph", "announce", "node-info", "announce-node", "first-message", "call-greet", "call-fib", "late", "delivery-check", "selftest", "idle-cloud"])
    p.add_argument("path", nargs="?", help="msg-package: DIR; graph: OUT; delivery-check: (child, internal)")
    p.add_argument("--msg-path")
    p.add_argument("--chatter-stop")
    p.add_argument("--wait", type=float, default=20.0)
    p.add_argument("--gid", type=int, choices=[16, 24], default=16, help="node-info: GID bytes")
    p.add_argument("--node", help="node-info: the agent's node name")
    args = p.parse_args()
    if args.mode == "msg-package":
        msg_package(args.path)
        return 0
    if args.mode == "graph":
        if not (args.path and args.msg_path and args.chatter_stop):
            p.error("graph needs OUT, --msg-path and --chatter-stop")
        args.out = args.path
        return graph(args)
    if args.mode in ("node-info", "announce-node") and not args.node:
        p.error(f"{args.mode} needs --node")
    return {"announce": announce, "node-info": node_info, "announce-node": announce_node, "first-message": first_message, "call-greet": call_greet, "call-fib": call_fib, "late": late, "idle-cloud": idle_cloud,
            "delivery-check": delivery_check, "selftest": selftest}[args.mode](args)


if __name__ == "__main__":
    rc = main()
    sys.stdout.flush()
    # Cyclone's threads may hold a process at exit; the result is known, leave now.
    os._exit(rc or 0)

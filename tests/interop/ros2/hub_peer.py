"""The hub's side of the ros2 interop suite: roslibpy clients of the fleetlink hub (run
with the repo's .venv python). Hub names are the robot's ROS names under /<robot>; types
are ROS 2 names (sensor_msgs/msg/LaserScan), values rosbridge JSON.

Modes (all take --hub-url URL --robot NAME):
  serve OUT --chatter-stop FILE
                stays running: advertises the fleet service /cloud/greet
                (std_srvs/srv/Trigger), publishes a latched /<robot>/announce
                (std_msgs/msg/String) once, /<robot>/cmd_vel (geometry_msgs/msg/Twist) at
                5 Hz and, until FILE exists, /<robot>/chatter ("hub-N"); a second client
                counts what it sees on /<robot>/chatter. Writes the counts to OUT (JSON)
                every 0.2 s. Prints "serve ready".
  check-up      /<robot>/scan, /<robot>/points (100k points) and /<robot>/battery (a type
                only the robot's --msg-path knows) arrive with the values ros2_peer.py
                sent.
  check-latched /<robot>/robot_description (transient_local on the robot, published before
                the agent started) arrives, and a client subscribing after that still
                gets it (latched at the hub).
  check-calls   /<robot>/add_two_ints answers, also many calls in flight at once, each
                with its own sum.
  check-action [--action NAME]
                the action /<robot>/fibonacci (or NAME): order 5 gives feedback and SUCCEEDED with
                [0, 1, 1, 2, 3, 5]; order 50 cancelled after its first feedback ends
                CANCELED.
  check-late    /<robot>/late_topic (a participant started after the agent) arrives.
  check-gone    /<robot>/late_topic leaves the hub's topic list and has no publisher there
                (rosapi topics, publishers) once its only writer's participant is gone
                (killed: DDS notices when its lease ends).
  check-fastdds --peer-log FILE [--pad N]
                Fast DDS (fastdds_peer, ROS 2's default middleware's DDS) both ways:
                /<robot>/fdds_up (std_msgs/msg/String, "fastdds N", odd N padded with
                --pad bytes) arrives in order and whole;
                then /<robot>/fdds_down ("from the hub N") is published at 10 Hz until
                FILE has the peer's "down: from the hub" line (15 s at most); the Fast
                DDS server /<robot>/fdds_add_two_ints answers three calls.
  check-params  the parameters of the robot's node /nav_node (ros2_peer.py) through the
                hub's rosapi as <node>:<parameter>: listed, read with roslibpy's Param,
                changed (keeping the parameter's type), refusals with the node's reason,
                deleted; clear errors for a missing node and a name without a node.
  publish-once  publishes /<robot>/oneshot (std_msgs/msg/String) once.
  serve-fib     stays running: serves the fleet action /cloud/fib (Fibonacci) in plain
                rosbridge ops, one step per 0.1 s with feedback, cancel honoured. Prints
                "serve-fib ready".
Exit status 0 when every check passed; each check prints "ok: ..." or "FAIL: ...".
"""
import argparse
import json
import os
import queue
import sys
import threading
import time
import urllib.parse

import roslibpy
from roslibpy.core import GoalStatus

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import expected as E  # noqa: E402

WAIT = 20.0

failures = []


def check(ok, what):
    print(("ok: " if ok else "FAIL: ") + what, flush=True)
    if not ok:
        failures.append(what)
    return ok


def connect(url):
    u = urllib.parse.urlparse(url)
    # roslibpy builds the URL from host and port: the token goes in a header instead.
    token = urllib.parse.parse_qs(u.query).get("token", [None])[0]
    headers = {"Authorization": f"Bearer {token}"} if token else None
    ros = roslibpy.Ros(host=u.hostname, port=u.port, headers=headers)
    ros.run(timeout=10)
    # roslibpy has no handler for 'status' ops; print them: they explain failed checks.
    proto = ros.factory._proto
    if proto is not None:
        proto._message_handlers["status"] = lambda m: print(f"    status op from the hub: {dict(m)}", flush=True)
    return ros


def first(ros, name, ty, wait=WAIT, want=lambda m: True):
    """The first message on `name` (None after `wait` seconds)."""
    q = queue.Queue()
    t = roslibpy.Topic(ros, name, ty)
    t.subscribe(lambda m: want(m) and q.put(m))
    try:
        return q.get(timeout=wait)
    except queue.Empty:
        return None
    finally:
        t.unsubscribe()


def short(v, n=200):
    s = json.dumps(v, default=str) if not isinstance(v, str) else v
    return s if len(s) <= n else s[:n] + "..."


# ---------------------------------------------------------------- checks

def check_up(args):
    ros = connect(args.hub_url)
    r = f"/{args.robot}"
    wanted = (("scan", "sensor_msgs/msg/LaserScan", E.check_scan),
              ("points", "sensor_msgs/msg/PointCloud2", E.check_cloud),
              ("battery", "fltest_msgs/msg/Battery", E.check_battery))
    # All three subscribed at once, one shared deadline.
    boxes, topics = {}, []
    for name, ty, _ in wanted:
        q = boxes[name] = queue.Queue()
        t = roslibpy.Topic(ros, f"{r}/{name}", ty)
        t.subscribe(q.put)
        topics.append(t)
    deadline = time.monotonic() + WAIT
    for name, ty, compare in wanted:
        try:
            m = boxes[name].get(timeout=max(0.1, deadline - time.monotonic()))
        except queue.Empty:
            m = None
        if check(m is not None, f"{r}/{name} ({ty}) arrives"):
            problems = compare(dict(m))
            check(not problems, f"{r}/{name} values equal what the robot sent"
                  + (f": {'; '.join(problems[:4])}" if problems else ""))
    for t in topics:
        t.unsubscribe()


def check_latched(args):
    name = f"/{args.robot}/robot_description"
    want = E.robot_description()
    m = first(connect(args.hub_url), name, "std_msgs/msg/String")
    if not check(m is not None, f"{name} (transient_local on the robot, published before the agent started) "
                 "arrives at the hub"):
        return
    check(m["data"] == want, f"{name}: {len(m['data'])} characters, want the robot's {len(want)}")
    # This client connects and subscribes only now: it gets the message from the hub's
    # latch, or not at all (the robot published it once).
    late = first(connect(args.hub_url), name, "std_msgs/msg/String", wait=5)
    check(late is not None and late["data"] == want,
          f"a subscriber started after {name} arrived gets it (latched at the hub)")


def check_calls(args):
    ros = connect(args.hub_url)
    name = f"/{args.robot}/add_two_ints"
    svc = roslibpy.Service(ros, name, "example_interfaces/srv/AddTwoInts")
    # First a single call, retried while the route settles (bounded).
    deadline, last = time.monotonic() + WAIT, None
    while True:
        try:
            res = dict(svc.call(roslibpy.ServiceRequest({"a": 2, "b": 40}), timeout=5))
            break
        except Exception as e:
            last = f"{type(e).__name__}: {e}"
            if time.monotonic() > deadline:
                res = {"error": last}
                break
            time.sleep(0.3)
    if not check(res == {"sum": 42}, f"{name} answered {res}, want {{'sum': 42}}"):
        return
    # Then 40 calls in flight at once over two connections. They are issued from this one
    # thread (roslibpy's id counter is not thread-safe) and answered asynchronously.
    conns = [ros, connect(args.hub_url)]
    svcs = [roslibpy.Service(c, name, "example_interfaces/srv/AddTwoInts") for c in conns]
    done = queue.Queue()
    t0 = time.monotonic()
    for k in range(40):
        a, b = 2**40 + 1000 * k, -7 * k  # int64 values beyond 32 bits
        svcs[k % 2].call(roslibpy.ServiceRequest({"a": a, "b": b}),
                         lambda r, a=a, b=b: done.put((a + b, dict(r))),
                         lambda e, a=a, b=b: done.put((a + b, {"error": str(e)})))
    got = []
    try:
        for _ in range(40):
            got.append(done.get(timeout=max(0.1, t0 + WAIT - time.monotonic())))
    except queue.Empty:
        pass
    wrong = [(want, r) for want, r in got if r != {"sum": want}]
    check(len(got) == 40 and not wrong, f"{name}: {len(got) - len(wrong)} of 40 concurrent calls answered with "
          f"their own sum in {time.monotonic() - t0:.2f} s" + (f"; wrong: {short(wrong[:3])}" if wrong else ""))


class Goal:
    """One goal's feedback and outcome, collected from roslibpy's callbacks."""

    def __init__(self, client, order):
        self.feedback, self.outcome = [], queue.Queue()
        self.id = client.send_goal(roslibpy.Goal({"order": order}),
                                   lambda r: self.outcome.put(("resultback", dict(r))),
                                   lambda f: self.feedback.append(dict(f)),
                                   lambda e: self.outcome.put(("errback", dict(e) if hasattr(e, "keys") else e)))

    def wait(self, timeout):
        try:
            return self.outcome.get(timeout=timeout)
        except queue.Empty:
            return None, None


def status_of(res):
    s = res.get("status") if isinstance(res, dict) else None
    return s.value if isinstance(s, GoalStatus) else s


def check_action(args):
    ros = connect(args.hub_url)
    name = f"/{args.robot}/{args.action}"
    client = roslibpy.ActionClient(ros, name, "example_interfaces/action/Fibonacci")
    # 1. order 5 to success; resent while the action is not yet known at the hub (bounded).
    deadline, attempts = time.monotonic() + WAIT, 0
    while True:
        attempts += 1
        goal = Goal(client, 5)
        kind, res = goal.wait(10)
        if kind == "resultback" or time.monotonic() > deadline:
            break
        if attempts == 1:
            print(f"    goal 5: {kind} {short(res)}; sending it again until {WAIT:.0f} s have passed", flush=True)
        time.sleep(0.5)
    want = E.fibonacci(5)
    values = res.get("values") if isinstance(res, dict) else None
    check(kind == "resultback" and status_of(res) == GoalStatus.SUCCEEDED.value and values == {"sequence": want},
          f"{name} order 5: {kind} status {status_of(res)} values {short(values)}, want SUCCEEDED (4) {want}")
    fbs = [f.get("sequence") for f in goal.feedback]
    check(len(fbs) >= 1 and all(isinstance(s, list) and s == want[:len(s)] for s in fbs),
          f"{name} order 5: {len(fbs)} feedback message(s), each a prefix of the result: {short(fbs)}")
    # 2. order 50 (5 s on the robot), cancelled after its first feedback.
    goal = Goal(client, 50)
    if not check(wait_for(lambda: goal.feedback, 10), f"{name} order 50: first feedback"):
        return
    t0 = time.monotonic()
    client.cancel_goal(goal.id)
    kind, res = goal.wait(10)
    seq = (res.get("values") or {}).get("sequence") if isinstance(res, dict) else None
    check(status_of(res) == GoalStatus.CANCELED.value,
          f"{name} order 50 cancelled: {kind} status {status_of(res)} after {time.monotonic() - t0:.2f} s, "
          f"want CANCELED (5); values {short(res.get('values') if isinstance(res, dict) else res)}")
    full = E.fibonacci(50)
    check(seq is None or (isinstance(seq, list) and seq == full[:len(seq)] and len(seq) < len(full)),
          f"{name} order 50 cancelled: partial result of {len(seq or [])} numbers, a prefix of the full one")


def wait_for(cond, timeout):
    deadline = time.monotonic() + timeout
    while not cond():
        if time.monotonic() > deadline:
            return False
        time.sleep(0.05)
    return True


def check_fastdds(args):
    ros = connect(args.hub_url)
    r = f"/{args.robot}"
    got = queue.Queue()
    up = roslibpy.Topic(ros, f"{r}/fdds_up", "std_msgs/msg/String")
    up.subscribe(lambda m: got.put(m.get("data")))
    texts = []
    deadline = time.monotonic() + WAIT
    while len(texts) < 5 and time.monotonic() < deadline:
        try:
            texts.append(got.get(timeout=max(0.1, deadline - time.monotonic())))
        except queue.Empty:
            break
    up.unsubscribe()
    numbers = [int(t.split()[1]) for t in texts if isinstance(t, str) and t.startswith("fastdds ")]
    shown = [short(t, 40) for t in texts]
    if check(len(texts) >= 5, f"{r}/fdds_up from the Fast DDS writer arrives: {shown}"):
        check(len(numbers) == len(texts) and numbers == sorted(numbers)
              and numbers[-1] - numbers[0] == len(numbers) - 1,
              f"its values are the writer's, in order, none missing: {shown}")
        # Odd ones carry --pad bytes more: samples of that size arrive whole.
        want = [len(f"fastdds {n}") + (1 + args.pad if n % 2 and args.pad else 0) for n in numbers]
        got_len = [len(t) for t in texts]
        check(got_len == want, f"the large ones ({args.pad} bytes more) arrive whole: lengths {got_len}, want {want}")
    down = roslibpy.Topic(ros, f"{r}/fdds_down", "std_msgs/msg/String")
    down.advertise()
    reached = False
    deadline = time.monotonic() + 15
    i = 0
    while time.monotonic() < deadline and not reached:
        down.publish(roslibpy.Message({"data": f"from the hub {i}"}))
        i += 1
        time.sleep(0.1)
        with open(args.peer_log) as f:
            reached = any(line.startswith("down: from the hub") for line in f)
    with open(args.peer_log) as f:
        lines = [line.strip() for line in f if line.startswith("down:")]
    check(reached and all(line.startswith("down: from the hub ") for line in lines),
          f"{r}/fdds_down reaches the Fast DDS reader as std_msgs/msg/String "
          f"({i} published): {lines[:5]}")
    down.unadvertise()
    # The Fast DDS server of /fdds_add_two_ints, called at the hub (retried while the
    # agent discovers and exposes it).
    name = f"{r}/fdds_add_two_ints"
    svc = roslibpy.Service(ros, name, "example_interfaces/srv/AddTwoInts")
    answers, deadline = [], time.monotonic() + WAIT
    for a, b in ((20, 22), (-5, 3), (1 << 40, 7)):
        while True:
            try:
                answers.append(dict(svc.call(roslibpy.ServiceRequest({"a": a, "b": b}), timeout=5)))
                break
            except Exception as e:
                if time.monotonic() > deadline:
                    answers.append({"error": f"{type(e).__name__}: {e}"})
                    break
                time.sleep(0.3)
    check(answers == [{"sum": 42}, {"sum": -2}, {"sum": (1 << 40) + 7}],
          f"{name} (a Fast DDS server) answers each call with its own sum: {answers}")


def check_late(args):
    name = f"/{args.robot}/late_topic"
    m = first(connect(args.hub_url), name, "std_msgs/msg/String")
    check(m is not None and str(m.get("data", "")).startswith("late-"),
          f"{name} (a participant started after the agent) arrives at the hub: {m and dict(m)}")


def check_resume(args):
    """A viewer at the hub opens /<robot>/idle_points, which the agent stopped reading:
    a fresh message arrives within a few seconds (the agent makes its reader again and
    the next 10 Hz message comes up). The hub may hand the viewer the topic's last message
    at once (its latest-message cache), however old: what counts is the first one
    published after the subscribe."""
    ros = connect(args.hub_url)
    t0 = time.time()

    def stamp_of(m):
        st = m["header"]["stamp"]
        return st.get("sec", st.get("secs", 0)) + st.get("nanosec", st.get("nsecs", 0)) / 1e9

    # Fresh: published after the subscribe (half a second of slack for the two clocks' reads).
    m = first(ros, f"/{args.robot}/idle_points", "sensor_msgs/msg/PointCloud2", wait=10,
              want=lambda m: stamp_of(m) >= t0 - 0.5)
    took = time.time() - t0
    check(m is not None and m["width"] == 10_000,
          f"/{args.robot}/idle_points: a message published after the subscribe arrived {took:.2f} s "
          f"after it (within 10 s: the agent reads the topic afresh)")


def check_gone(args):
    name = f"/{args.robot}/late_topic"
    ros = connect(args.hub_url)
    topics = roslibpy.Service(ros, "/rosapi/topics", "rosapi/Topics")
    publishers = roslibpy.Service(ros, "/rosapi/publishers", "rosapi/Publishers")
    seen = {}

    def gone():
        try:
            seen["listed"] = name in topics.call(roslibpy.ServiceRequest({}), timeout=5).get("topics", [])
            seen["publishers"] = publishers.call(roslibpy.ServiceRequest({"topic": name}), timeout=5).get("publishers")
        except Exception as e:
            seen["error"] = str(e)
            return False
        return not seen["listed"] and not seen["publishers"]

    t0 = time.monotonic()
    # A killed participant says nothing: DDS forgets it when its lease (Cyclone: 10 s)
    # ends, the agent unadvertises the topic at its next look, the uplink tells the hub.
    ok = wait_for(gone, 25)
    check(ok, f"{name} left the hub's topics and publishers {time.monotonic() - t0:.1f} s after its "
              f"writer's participant was killed ({seen})")


# ---------------------------------------------------------------- serve

def rosapi(ros, call, **fields):
    """One rosapi call through the hub: (True, answer) or (False, the error text)."""
    svc = roslibpy.Service(ros, f"/rosapi/{call}", "rosapi_msgs/srv/X")
    try:
        return True, dict(svc.call(roslibpy.ServiceRequest(fields), timeout=15))
    except Exception as e:
        return False, str(e)


def check_params(args):
    """A node's parameters on the robot (ros2_peer.py's ParameterServer) through the
    hub's rosapi, as Foxglove and roslibpy use it: names as <node>:<parameter> under the
    robot's namespace."""
    ros = connect(args.hub_url)
    node = f"/{args.robot}{E.PARAMETER_NODE}"
    want = sorted(f"{node}:{n}" for n in E.PARAMETERS)
    # The agent finds the node in DDS discovery: retried while it does (bounded).
    deadline, names = time.monotonic() + WAIT, []
    while time.monotonic() < deadline:
        ok, res = rosapi(ros, "get_param_names")
        names = sorted(n for n in res.get("names", []) if n.startswith(node + ":")) if ok else []
        if names == want:
            break
        time.sleep(0.3)
    check(names == want, f"get_param_names lists the node's parameters: {short(names)}, want {want}")
    for n, (_, v) in E.PARAMETERS.items():
        try:
            got = roslibpy.Param(ros, f"{node}:{n}").get(timeout=15)
        except Exception as e:
            got = f"error: {e}"
        check(got == v, f"roslibpy Param {node}:{n} reads {got!r}, want {v!r}")
    ok, res = rosapi(ros, "has_param", name=f"{node}:max_speed")
    check(ok and res.get("exists") is True, f"has_param {node}:max_speed: {res}")
    ok, res = rosapi(ros, "has_param", name=f"{node}:nope")
    check(ok and res.get("exists") is False, f"has_param {node}:nope: {res}")
    ok, res = rosapi(ros, "get_param", name=f"{node}:nope", default_value="7")
    check(ok and res.get("value") == "7", f"get_param of a missing parameter gives the default: {res}")

    # 2 to a double parameter stays a double (the node refuses a change of type).
    try:
        roslibpy.Param(ros, f"{node}:max_speed").set(2, timeout=15)
        got = roslibpy.Param(ros, f"{node}:max_speed").get(timeout=15)
    except Exception as e:
        got = f"error: {e}"
    check(got == 2.0 and isinstance(got, float), f"set {node}:max_speed to 2, then it reads {got!r}, want 2.0")
    ok, res = rosapi(ros, "set_param", name=f"{node}:waypoints", value="[4, 5]")
    check(ok, f"set {node}:waypoints to [4, 5]: {res}")
    for name, value, why in ((f"{node}:serial", '"SN-1"', "read-only"),
                             (f"{node}:max_speed", '"fast"', "has type")):
        ok, res = rosapi(ros, "set_param", name=name, value=value)
        check(not ok and why in res, f"set {name} to {value} is refused with the node's reason: {short(res)}")
    ok, res = rosapi(ros, "delete_param", name=f"{node}:robot_name")
    check(ok, f"delete_param {node}:robot_name: {res}")
    ok, res = rosapi(ros, "has_param", name=f"{node}:robot_name")
    check(ok and res.get("exists") is False, f"{node}:robot_name is gone after delete_param: {res}")
    ok, res = rosapi(ros, "get_param", name=f"/{args.robot}/ghost_node:x")
    check(not ok and "ghost_node" in res, f"get_param of a node that is not there names it: {short(res)}")
    ok, res = rosapi(ros, "get_param", name=f"/{args.robot}/max_speed")
    check(not ok and "<node>:<parameter>" in res, f"a name without a node says how to name one: {short(res)}")


def publish_once(args):
    """Publishes /<robot>/oneshot once (a topic new to the hub), as a one-off command
    would be. The rosapi call after it returns once the hub has handled the publish (a
    connection's operations are handled in order)."""
    ros = connect(args.hub_url)
    roslibpy.Topic(ros, f"/{args.robot}/oneshot", "std_msgs/msg/String").publish(
        roslibpy.Message({"data": E.ONESHOT}))
    ok, res = rosapi(ros, "topics")
    check(ok, f"/{args.robot}/oneshot published once (the hub answered the call after it: {short(res, 80)})")


def serve_fib(args):
    """A fleet action server at the hub: /cloud/fib (example_interfaces/action/Fibonacci),
    spoken in plain rosbridge ops (roslibpy has no action server). One step per 0.1 s with
    feedback; a cancel ends the goal with its partial sequence and status 5."""
    import websockets.sync.client as wsc
    with wsc.connect(args.hub_url, max_size=None) as ws:
        ws.send(json.dumps({"op": "advertise_action", "action": "/cloud/fib",
                            "type": "example_interfaces/action/Fibonacci"}))
        print("serve-fib ready", flush=True)
        goals = {}  # id -> {"seq": [...], "order": n, "next": t}
        while True:
            try:
                m = json.loads(ws.recv(timeout=0.02))
            except TimeoutError:
                m = None
            if m and m.get("op") == "send_action_goal":
                goals[m["id"]] = {"seq": [0, 1], "order": int(m.get("args", {}).get("order", 0)),
                                  "next": time.time() + 0.1}
            elif m and m.get("op") == "cancel_action_goal" and m.get("id") in goals:
                g = goals.pop(m["id"])
                ws.send(json.dumps({"op": "action_result", "id": m["id"], "action": "/cloud/fib",
                                    "values": {"sequence": g["seq"]}, "status": 5, "result": True}))
            for gid, g in list(goals.items()):
                if time.time() < g["next"]:
                    continue
                g["next"] += 0.1
                if len(g["seq"]) <= g["order"]:
                    g["seq"].append((g["seq"][-1] + g["seq"][-2]) & 0x7FFFFFFF)
                    ws.send(json.dumps({"op": "action_feedback", "id": gid, "action": "/cloud/fib",
                                        "values": {"sequence": g["seq"]}}))
                else:
                    goals.pop(gid)
                    ws.send(json.dumps({"op": "action_result", "id": gid, "action": "/cloud/fib",
                                        "values": {"sequence": g["seq"]}, "status": 4, "result": True}))


def serve(args):
    r = f"/{args.robot}"
    ros = connect(args.hub_url)
    watcher = connect(args.hub_url)
    counts = {}
    lock = threading.Lock()

    def on_chatter(m):
        with lock:
            counts[m["data"]] = counts.get(m["data"], 0) + 1

    roslibpy.Topic(watcher, f"{r}/chatter", "std_msgs/msg/String").subscribe(on_chatter)
    greet = roslibpy.Service(ros, "/cloud/greet", "std_srvs/srv/Trigger")
    greet.advertise(lambda req, res: res.update(success=True, message=E.GREETING) or True)
    announce = roslibpy.Topic(ros, f"{r}/announce", "std_msgs/msg/String", latch=True)
    announce.publish(roslibpy.Message({"data": E.ANNOUNCE}))
    cmd = roslibpy.Topic(ros, f"{r}/cmd_vel", "geometry_msgs/msg/Twist")
    chatter = roslibpy.Topic(ros, f"{r}/chatter", "std_msgs/msg/String")
    time.sleep(1.0)  # the watcher's subscription is in place before hub-1
    print("serve ready", flush=True)
    n = sent = 0
    while True:
        n += 1
        cmd.publish(roslibpy.Message(E.TWIST_PARTIAL))
        if not os.path.exists(args.chatter_stop):
            sent = n
            chatter.publish(roslibpy.Message({"data": f"hub-{n}"}))
        with lock:
            text = json.dumps({"chatter": counts, "chatter_sent": sent})
        with open(args.out + ".tmp", "w") as f:
            f.write(text)
        os.replace(args.out + ".tmp", args.out)
        time.sleep(0.2)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("mode", choices=["serve", "check-up", "check-latched", "check-calls", "check-action", "check-late", "check-gone", "serve-fib", "check-fastdds", "check-params", "publish-once", "check-resume"])
    p.add_argument("out", nargs="?")
    p.add_argument("--hub-url", required=True)
    p.add_argument("--robot", required=True)
    p.add_argument("--chatter-stop")
    p.add_argument("--peer-log")
    p.add_argument("--pad", type=int, default=0, help="check-fastdds: the padding of odd messages")
    p.add_argument("--action", default="fibonacci", help="check-action: the robot's action (default fibonacci)")
    args = p.parse_args()
    if args.mode == "serve" and not (args.out and args.chatter_stop):
        p.error("serve needs OUT and --chatter-stop")
    if args.mode == "check-fastdds" and not args.peer_log:
        p.error("check-fastdds needs --peer-log")
    {"serve": serve, "check-up": check_up, "check-latched": check_latched, "check-calls": check_calls,
     "check-action": check_action, "check-late": check_late, "check-gone": check_gone,
     "serve-fib": serve_fib, "check-fastdds": check_fastdds,
     "check-params": check_params, "publish-once": publish_once, "check-resume": check_resume}[args.mode](args)
    print(f"{args.mode}: {len(failures)} failure(s)", flush=True)
    os._exit(1 if failures else 0)


if __name__ == "__main__":
    main()

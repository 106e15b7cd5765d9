"""The hub's side of the ros1 interop suite: roslibpy clients on the hub (run with the
project venv's python).

Modes (all take --hub-url URL --robot NAME):
  serve OUT     stays running: advertises the fleet service /cloud/greet
                (std_srvs/Trigger), publishes a latched /<robot>/announce once, publishes
                /<robot>/cmd_vel and /<robot>/chatter ("hub-N") at 5 Hz, and counts what a
                second client receives on /<robot>/chatter; writes the counts to OUT.
  check-up      /<robot>/scan, /<robot>/points and /<robot>/custom arrive with exactly the
                values ros_peer.py published (the custom type decoded by the hub from the
                definition it learned); /<robot>/set_enabled and /<robot>/add_two_ints
                answer calls.
  check-after   /<robot>/after_restart (a publisher started after roscore restarted)
                arrives.
  check-params  rosapi's parameter services at the hub reach the robot's ROS master for
                names under /<robot>/ (run.sh set /max_speed and /limits with rosparam):
                get, set, has, search, delete, a default for a missing one; a hub
                parameter outside any robot stays the hub's own.
  publish-once  publishes /<robot>/oneshot once.
  check-status  the agent's status topic /<robot>/fleetlink/diagnostics
                (diagnostic_msgs/DiagnosticArray) shows its ROS 1 part at WARN with the
                /cmd_vel type mismatch named, both types in it.
Exit status 0 when every check passed; each failure is printed as "FAIL: ...".
"""
import argparse
import base64
import json
import math
import os
import queue
import struct
import sys
import threading
import time
import urllib.parse

import roslibpy

WAIT = 20.0
POINTS = 100_000


def connect(url):
    u = urllib.parse.urlparse(url)
    token = urllib.parse.parse_qs(u.query).get("token", [None])[0]
    headers = {"Authorization": f"Bearer {token}"} if token else None
    ros = roslibpy.Ros(host=u.hostname, port=u.port, headers=headers)
    ros.run(timeout=10)
    return ros


def first(ros, name, ty, wait=WAIT, want=lambda m: True):
    q = queue.Queue()
    t = roslibpy.Topic(ros, name, ty)
    t.subscribe(lambda m: want(m) and q.put(m))
    try:
        return q.get(timeout=wait)
    except queue.Empty:
        return None
    finally:
        t.unsubscribe()


failures = []


def check(ok, what):
    print(("ok: " if ok else "FAIL: ") + what, flush=True)
    if not ok:
        failures.append(what)


def close_enough(a, b):
    return len(a) == len(b) and all(math.isclose(x, y, rel_tol=1e-6, abs_tol=1e-6) for x, y in zip(a, b))


def check_up(args):
    ros = connect(args.hub_url)
    r = f"/{args.robot}"
    scan = first(ros, f"{r}/scan", "sensor_msgs/LaserScan")
    check(scan is not None, f"{r}/scan arrives")
    if scan:
        check(scan["header"]["frame_id"] == "laser", f"scan frame_id {scan['header']['frame_id']!r}")
        check(scan["header"]["stamp"] == {"secs": 1700000000, "nsecs": 250}
              or scan["header"]["stamp"] == {"sec": 1700000000, "nanosec": 250},
              f"scan stamp {scan['header']['stamp']}")
        check(close_enough(scan["ranges"], [1.0 + 0.25 * (i % 40) for i in range(360)]), "scan ranges equal")
        check(close_enough(scan["intensities"], [float(i % 7) for i in range(360)]), "scan intensities equal")
        check(math.isclose(scan["angle_min"], -1.5) and math.isclose(scan["range_max"], 30.0), "scan limits equal")
    cloud = first(ros, f"{r}/points", "sensor_msgs/PointCloud2")
    check(cloud is not None, f"{r}/points arrives")
    if cloud:
        expect = b"".join(struct.pack("<fff", i * 0.5, -i * 0.25, 2.0) for i in range(POINTS))
        data = cloud["data"]
        got = base64.b64decode(data) if isinstance(data, str) else bytes(data)
        check(cloud["width"] == POINTS and cloud["point_step"] == 12, f"cloud width {cloud['width']}")
        check([f["name"] for f in cloud["fields"]] == ["x", "y", "z"], "cloud fields")
        check(got == expect, f"cloud data equal ({len(got)} bytes)")
    custom = first(ros, f"{r}/custom", "fltest_msgs/Custom")
    check(custom is not None, f"{r}/custom arrives (custom type)")
    if custom:
        n = int(custom["label"].split("-")[1])
        check(custom["values"] == [n, -n, 7], f"custom values {custom['values']}")
        check(custom["inner"] == {"weight": 0.5, "ok": True}, f"custom inner {custom['inner']}")
        check(custom["more"] == [{"weight": 1.5, "ok": False}, {"weight": 2.5, "ok": True}], "custom more")
        check(custom["stamp"] in ({"secs": 12, "nsecs": 34}, {"sec": 12, "nanosec": 34}), f"custom stamp {custom['stamp']}")
    deadline = time.time() + WAIT
    while True:
        try:
            res = roslibpy.Service(ros, f"{r}/set_enabled", "std_srvs/SetBool").call(
                roslibpy.ServiceRequest({"data": True}), timeout=5)
            break
        except Exception as e:
            if time.time() > deadline:
                res = {"error": str(e)}
                break
            time.sleep(0.3)
    check(dict(res) == {"success": True, "message": "enabled=True"}, f"{r}/set_enabled answered {dict(res)}")
    try:
        res = dict(roslibpy.Service(ros, f"{r}/add_two_ints", "example_interfaces/AddTwoInts").call(
            roslibpy.ServiceRequest({"a": 2, "b": 40}), timeout=5))
    except Exception as e:
        res = {"error": str(e)}
    check(res == {"sum": 42}, f"{r}/add_two_ints answered {res}")


def check_after(args):
    ros = connect(args.hub_url)
    m = first(ros, f"/{args.robot}/after_restart", "std_msgs/String", wait=25)
    check(m is not None and m["data"].startswith("after-"), f"/after_restart arrived at the hub: {m}")


def check_status(args):
    ros = connect(args.hub_url)

    def ros1_part(m):
        return next((s for s in m.get("status", []) if s.get("name") == "fleetlink agent: ros1"), None)

    def mismatch_named(m):
        part = ros1_part(m)
        problems = [kv["value"] for kv in (part or {}).get("values", []) if kv.get("key") == "problem"]
        return any("/cmd_vel" in p and "geometry_msgs/Twist" in p and "std_msgs/String" in p for p in problems)

    # Latched, republished every 5 s: the first message may predate the mismatch.
    m = first(ros, f"/{args.robot}/fleetlink/diagnostics", "diagnostic_msgs/DiagnosticArray", wait=15,
              want=mismatch_named)
    part = ros1_part(m) if m else None
    check(part is not None, f"the status topic names the /cmd_vel mismatch with both types: {part}")
    if part:
        counters = {kv["key"]: kv["value"] for kv in part["values"] if kv["key"] != "problem"}
        check(part["level"] == 1, f"the ROS 1 part is at WARN (1): level {part['level']}, message {part['message']!r}")
        check(int(counters.get("type_mismatches", 0)) >= 1 and int(counters.get("messages_up", 0)) > 0,
              f"its counters: {counters}")
        names = [s["name"] for s in m["status"]]
        check("fleetlink agent: uplink" in names, f"the uplink has a part too: {names}")


def serve(args):
    r = f"/{args.robot}"
    ros = connect(args.hub_url)
    watcher = connect(args.hub_url)
    counts = {}
    lock = threading.Lock()

    def on_chatter(m):
        with lock:
            counts[m["data"]] = counts.get(m["data"], 0) + 1

    roslibpy.Topic(watcher, f"{r}/chatter", "std_msgs/String").subscribe(on_chatter)
    greet = roslibpy.Service(ros, "/cloud/greet", "std_srvs/Trigger")
    greet.advertise(lambda req, res: res.update(success=True, message="hello from the fleet") or True)
    announce = roslibpy.Topic(ros, f"{r}/announce", "std_msgs/String", latch=True)
    announce.publish(roslibpy.Message({"data": "hello fleet"}))
    cmd = roslibpy.Topic(ros, f"{r}/cmd_vel", "geometry_msgs/Twist")
    chatter = roslibpy.Topic(ros, f"{r}/chatter", "std_msgs/String")
    print("serve ready", flush=True)
    n = 0
    while True:
        n += 1
        # Partial, as clients write it: the hub fills the zeros in before the robot gets it.
        cmd.publish(roslibpy.Message({"linear": {"x": 0.5}, "angular": {"z": 0.25}}))
        chatter.publish(roslibpy.Message({"data": f"hub-{n}"}))
        with lock:
            text = json.dumps(counts)
        with open(args.out + ".tmp", "w") as f:
            f.write(text)
        os.replace(args.out + ".tmp", args.out)
        time.sleep(0.2)


def rosapi(ros, call, **args):
    """One rosapi parameter call; its values, or the error text of a refused call."""
    srv = roslibpy.Service(ros, f"/rosapi/{call}", f"rosapi/{call.title().replace('_', '')}")
    try:
        return srv.call(roslibpy.ServiceRequest(args), timeout=WAIT)
    except Exception as e:  # roslibpy raises on result: false, with the values as text
        return {"error": str(e)}


def check_params(args):
    ros = connect(args.hub_url)
    r = args.robot
    got = rosapi(ros, "get_param", name=f"/{r}/max_speed")
    check(json.loads(got.get("value", "null")) == 1.5, f"get_param /{r}/max_speed from the robot's master: {got}")
    got = rosapi(ros, "get_param", name=f"/{r}/limits")
    check(json.loads(got.get("value", "null")) == {"a": 1, "b": [1, 2]}, f"get_param /{r}/limits (a tree): {got}")
    got = rosapi(ros, "set_param", name=f"/{r}/max_speed", value="2.5")
    check("error" not in got, f"set_param /{r}/max_speed 2.5: {got}")
    got = rosapi(ros, "get_param", name=f"/{r}/max_speed")
    check(json.loads(got.get("value", "null")) == 2.5, f"the robot's /max_speed reads back 2.5: {got}")
    got = rosapi(ros, "has_param", name=f"/{r}/limits/a")
    check(got.get("exists") is True, f"has_param /{r}/limits/a: {got}")
    got = rosapi(ros, "search_param", name=f"/{r}/max_speed")
    check(got.get("global_name") == f"/{r}/max_speed", f"search_param gives the hub's name: {got}")
    got = rosapi(ros, "delete_param", name=f"/{r}/limits")
    check("error" not in got, f"delete_param /{r}/limits: {got}")
    got = rosapi(ros, "has_param", name=f"/{r}/limits")
    check(got.get("exists") is False, f"/{r}/limits is gone: {got}")
    got = rosapi(ros, "delete_param", name=f"/{r}/limits")
    check("error" in got and "not set" in got["error"] and r in got["error"],
          f"deleting it again is an error naming the robot: {got}")
    got = rosapi(ros, "get_param", name=f"/{r}/missing", default="7")
    check(got.get("value") == "7", f"a missing robot parameter gives the caller's default: {got}")
    # Outside any robot's namespace: the hub's own store, as before.
    rosapi(ros, "set_param", name="/fleet/limit", value="3")
    got = rosapi(ros, "get_param", name="/fleet/limit")
    check(got.get("value") == "3", f"a hub parameter stays the hub's: {got}")
    # The listing has both: the robot's master's names in its namespace, and the hub's.
    names = rosapi(ros, "get_param_names").get("names", [])
    check(f"/{r}/max_speed" in names and "/fleet/limit" in names
          and f"/{r}/limits/a" not in names,
          f"get_param_names lists the robot's names (/{r}/max_speed, not the deleted "
          f"/{r}/limits/a) and the hub's (/fleet/limit): {names}")
    check(f"/{r}/run_id" in names,
          f"the robot master's own parameters are listed too: {names}")
    ros.close()


def publish_once(args):
    """Publishes /<robot>/oneshot (std_msgs/String, a topic new to the hub) once, as a
    one-off command would be. The rosapi call after it returns once the hub has handled
    the publish (a connection's operations are handled in order)."""
    ros = connect(args.hub_url)
    roslibpy.Topic(ros, f"/{args.robot}/oneshot", "std_msgs/String").publish(roslibpy.Message({"data": "only once"}))
    got = rosapi(ros, "topics")
    check("error" not in got, f"/{args.robot}/oneshot published once (then rosapi topics answered)")


def check_resume(args):
    """A viewer at the hub opens /<robot>/idle_points, which the agent stopped reading:
    a fresh message arrives within a few seconds (the agent connects to the publisher
    again and the next 10 Hz message comes up)."""
    ros = connect(args.hub_url)
    t0 = time.time()
    m = first(ros, f"/{args.robot}/idle_points", "sensor_msgs/PointCloud2", wait=10)
    took = time.time() - t0
    check(m is not None and m["width"] == 50_000, f"/{args.robot}/idle_points arrived {took:.2f} s after the subscribe")
    if m is not None:
        stamp = m["header"]["stamp"]
        age = t0 - (stamp.get("secs", stamp.get("sec", 0)) + stamp.get("nsecs", stamp.get("nanosec", 0)) / 1e9)
        # Fresh, not a message kept from before reading stopped.
        check(age < 3.0, f"the first message was published {age:.2f} s before the subscribe (< 3 s: read afresh)")
    print(f"resume: {took:.2f} s", flush=True)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("mode")
    p.add_argument("out", nargs="?")
    p.add_argument("--hub-url", required=True)
    p.add_argument("--robot", required=True)
    args = p.parse_args()
    {"serve": serve, "check-up": check_up, "check-after": check_after, "check-status": check_status,
     "check-params": check_params, "publish-once": publish_once, "check-resume": check_resume}[args.mode](args)
    print(f"{args.mode}: {len(failures)} failure(s)", flush=True)
    os._exit(1 if failures else 0)


if __name__ == "__main__":
    main()

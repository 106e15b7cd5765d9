#!/usr/bin/env python3
"""Three federated hubs seen by their clients: roslibpy on hubs B and C, and the hubs'
REST API (an admin operator's token per hub). The robot (--robot, with the simulator's
odometry, laser scan, services and navigate_to_pose action) is connected to hub A.

Checks, in order (see run.sh for the story):

  subscribe_remote  a subscriber on C receives /<robot>/odom, published at A
  no_data_to_b      while nobody subscribes on B, B's Zenoh session hears none of it
                    (B's /api/v1/federation: the topic's received count and the total);
                    A sends each message once (A's sent count against C's received);
                    /<robot>/scan, wanted nowhere, is idle at A (not sent by the robot)
  listings          B's /rosapi/topics and /rosapi/services list the robot's topics and
                    services; B's /api/v1/robots has the robot online at hub-a
  calls             from B: set_mode then get_status reflects it; a navigate_to_pose goal
                    gets feedback then SUCCEEDED; a second goal cancelled after its first
                    feedback ends CANCELED
  triangle          /fleet/chat published on each hub and subscribed on each: every
                    subscriber gets every other hub's message exactly once (no loops)
  keyframe_asks     a viewer on C of /<robot>/camera/video (the simulated camera's, its
                    own keyframes 60 s apart), throttled to 200 ms with a queue of one so
                    it loses frames, decodes every frame from the first (video_peer.py
                    watch, PyAV), at least 3 in 5 s: keyframes C asked A for, and A its
                    robot (C's keyframe_asks_out and A's keyframe_asks_acted went up)

Prints `PASS <check>: figures` or `FAIL <check>: why`; exits 1 if any failed. Every wait
is bounded.
"""

import argparse
import json
import math
import os
import subprocess
import sys
import threading
import time
import urllib.request

import roslibpy
from roslibpy.core import GoalStatus

ODOM = "nav_msgs/msg/Odometry"
STRING = "std_msgs/msg/String"
NAV_TYPE = "fleetlink_sim/action/NavigateTo"
WAIT = 15.0
VIDEO_PEER = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "video", "video_peer.py")


class CheckFailed(Exception):
    pass


def check(cond, why):
    if not cond:
        raise CheckFailed(why)


def wait_until(what, fn, timeout=WAIT, every=0.05):
    deadline = time.monotonic() + timeout
    last = None
    while time.monotonic() < deadline:
        last = fn()
        if last:
            return last
        time.sleep(every)
    raise CheckFailed(f"{what}: not within {timeout:.0f} s (last: {str(last)[:300]})")


class Hub:
    def __init__(self, name, addr, token):
        self.name, self.addr, self.token = name, addr, token
        host, port = addr.rsplit(":", 1)
        self.ros = roslibpy.Ros(host=host, port=int(port),
                                headers={"Authorization": f"Bearer {token}"})
        self.ros.run(timeout=10)

    def api(self, path):
        req = urllib.request.Request(f"http://{self.addr}{path}",
                                     headers={"Authorization": f"Bearer {self.token}"})
        with urllib.request.urlopen(req, timeout=5) as r:
            return json.load(r)

    def federation(self):
        return self.api("/api/v1/federation")

    def imported(self, topic):
        for t in self.federation().get("imported", []):
            if t["topic"] == topic:
                return t
        return None

    def exported(self, topic):
        for t in self.federation().get("exported", []):
            if t["topic"] == topic:
                return t
        return None

    def call(self, name, type_, args=None):
        svc = roslibpy.Service(self.ros, name, type_)
        return svc.call(roslibpy.ServiceRequest(args or {}), timeout=10)


class Inbox:
    def __init__(self):
        self.items, self.cv = [], threading.Condition()

    def put(self, x):
        with self.cv:
            self.items.append(x)
            self.cv.notify_all()

    def wait(self, n, timeout, what):
        with self.cv:
            if not self.cv.wait_for(lambda: len(self.items) >= n, timeout):
                raise CheckFailed(f"{what}: {len(self.items)} of {n} within {timeout:.0f} s")
            return list(self.items)


def subscribe_remote(ctx):
    topic = f"/{ctx.robot}/odom"
    got = Inbox()
    t0 = time.monotonic()
    sub = roslibpy.Topic(ctx.c.ros, topic, ODOM)
    sub.subscribe(lambda m: got.put(time.monotonic()))
    ctx.keep.append(sub)
    first = got.wait(1, WAIT, f"{topic} at hub C")[0] - t0
    got.wait(20, 10, f"20 messages of {topic} at hub C")
    return f"{topic} published at A reaches a subscriber on C ({first * 1000:.0f} ms after subscribing; 20 messages)"


def no_data_to_b(ctx):
    odom, scan = f"/{ctx.robot}/odom", f"/{ctx.robot}/scan"
    # B knows the topic (listings) but has no Zenoh subscriber and hears nothing of it.
    wait_until(f"{odom} in B's catalog", lambda: ctx.b.imported(odom))
    time.sleep(1.0)  # C's subscription has had time to make A send
    fb = ctx.b.federation()
    imp = next(t for t in fb["imported"] if t["topic"] == odom)
    check(not imp["subscribed"] and imp["received"] == 0,
          f"B heard {odom} while nobody subscribes there: {imp}")
    check(fb["counters"]["received"] == 0,
          f"B's Zenoh session received {fb['counters']['received']} messages with no subscriber on B")
    # A sends each message once: what C received matches what A sent (within the few in
    # flight between the two reads).
    fa, fc = ctx.a.federation(), ctx.c.federation()
    sent = next(t for t in fa["exported"] if t["topic"] == odom)
    recv = next(t for t in fc["imported"] if t["topic"] == odom)
    check(sent["wanted_remotely"], f"A does not see C's subscriber of {odom}: {sent}")
    check(sent["sent"] > 0 and abs(sent["sent"] - recv["received"]) <= 3,
          f"A sent {sent['sent']} messages of {odom}, C received {recv['received']}")
    # The scan nobody wants anywhere stays on the robot.
    topics = {t["name"]: t for t in ctx.a.api("/api/v1/topics")["topics"]}
    check(scan in topics, f"{scan} not listed at A: {sorted(topics)}")
    check(topics[scan].get("state") == "idle",
          f"{scan} (no subscriber on any hub) is {topics[scan].get('state')!r} at A, want idle")
    ex = ctx.a.exported(scan)
    check(ex is not None and ex["sent"] == 0 and not ex["wanted_remotely"],
          f"A sent {scan} to Zenoh though nobody wants it: {ex}")
    # A subscriber on B makes it flow there too, and leaving stops it.
    got = Inbox()
    sub = roslibpy.Topic(ctx.b.ros, odom, ODOM)
    sub.subscribe(lambda m: got.put(1))
    got.wait(5, WAIT, f"{odom} at B once subscribed")
    sub.unsubscribe()
    wait_until(f"B's Zenoh subscriber of {odom} gone", lambda: not ctx.b.imported(odom)["subscribed"])
    time.sleep(0.5)
    before = ctx.b.imported(odom)["received"]
    time.sleep(1.0)
    after = ctx.b.imported(odom)["received"]
    check(after == before, f"B still hears {odom} after its last subscriber left ({before} -> {after})")
    return (f"no message of {odom} reached B while nobody subscribed there (0 received); "
            f"A sent {sent['sent']}, C received {recv['received']}; {scan} idle at A, 0 sent; "
            f"B received {before} while subscribed, none after")


def listings(ctx):
    odom = f"/{ctx.robot}/odom"

    def topics():
        r = ctx.b.call("/rosapi/topics", "rosapi/Topics")
        return odom in r["topics"] and r

    r = wait_until(f"{odom} in B's /rosapi/topics", topics)
    i = r["topics"].index(odom)
    check(r["types"][i] in (ODOM, "nav_msgs/Odometry"), f"{odom} has type {r['types'][i]} at B")

    def services():
        s = ctx.b.call("/rosapi/services", "rosapi/Services")["services"]
        return f"/{ctx.robot}/get_status" in s and s

    svcs = wait_until("the robot's services in B's /rosapi/services", services)
    robots = ctx.b.api("/api/v1/robots")["robots"]
    me = [r for r in robots if r["name"] == ctx.robot]
    check(me and me[0]["online"] and me[0].get("hub") == "hub-a",
          f"B's /api/v1/robots: {me or robots}")
    check(odom in me[0]["topics"], f"B lists the robot without {odom}: {me[0]}")
    return (f"B lists {len(r['topics'])} topics (with {odom} as {r['types'][i]}), "
            f"{len(svcs)} services, and {ctx.robot} online at hub-a")


def calls(ctx):
    r = ctx.robot
    t0 = time.monotonic()
    ctx.b.call(f"/{r}/set_mode", "std_srvs/srv/SetBool", {"data": True})
    first = time.monotonic() - t0
    st = ctx.b.call(f"/{r}/get_status", "std_srvs/srv/Trigger")
    check(st.get("success") is True, f"get_status through B: {st}")
    status = json.loads(st["message"])
    rtts = []
    for _ in range(20):
        t = time.monotonic()
        ctx.b.call(f"/{r}/get_status", "std_srvs/srv/Trigger")
        rtts.append((time.monotonic() - t) * 1000)
    rtts.sort()
    # navigate_to_pose: feedback then SUCCEEDED.
    name = f"/{r}/navigate_to_pose"
    ac = roslibpy.ActionClient(ctx.b.ros, name, NAV_TYPE)

    def goal(dist):
        st = json.loads(ctx.b.call(f"/{r}/get_status", "std_srvs/srv/Trigger")["message"])
        x, y = st["x"], st["y"]
        d = math.hypot(x, y)
        ux, uy = (-x / d, -y / d) if d > 1.5 else (1.0, 0.0)
        gx, gy = round(x + dist * ux, 3), round(y + dist * uy, 3)
        fb, out = Inbox(), Inbox()
        gid = ac.send_goal(roslibpy.Goal({"x": gx, "y": gy}),
                           lambda res: out.put(("result", dict(res))),
                           lambda f: fb.put(dict(f)),
                           lambda e: out.put(("error", e)))
        return gid, fb, out

    _, fb, out = goal(0.5)
    kind, res = out.wait(1, 15, f"result of {name}")[0]
    st_v = res.get("status")
    st_v = st_v.value if isinstance(st_v, GoalStatus) else st_v
    check(kind == "result" and st_v == GoalStatus.SUCCEEDED.value,
          f"{name} from B: {kind} {res}")
    nfb = len(fb.items)
    check(nfb >= 1, f"{name} from B: no feedback before the result")
    gid, fb, out = goal(5.0)
    fb.wait(1, 10, f"first feedback of the second {name} goal")
    ac.cancel_goal(gid)
    kind, res = out.wait(1, 10, f"result of the cancelled {name} goal")[0]
    st_v = res.get("status") if isinstance(res, dict) else None
    st_v = st_v.value if isinstance(st_v, GoalStatus) else st_v
    check(st_v == GoalStatus.CANCELED.value, f"cancelled {name} from B: {kind} {res}")
    return (f"set_mode/get_status from B (mode {status.get('mode')!r}; first call {first * 1000:.0f} ms, "
            f"then p50 {rtts[len(rtts) // 2]:.1f} ms, max {rtts[-1]:.1f} ms over 20); "
            f"{name}: {nfb} feedback then SUCCEEDED, and a goal cancelled after feedback: CANCELED")


def triangle(ctx):
    topic = "/fleet/chat"
    hubs = {"a": ctx.a, "b": ctx.b, "c": ctx.c}
    inbox = {h: Inbox() for h in hubs}
    for h, hub in hubs.items():
        s = roslibpy.Topic(hub.ros, topic, STRING)
        s.subscribe(lambda m, h=h: inbox[h].put(m["data"]))
        ctx.keep.append(s)
    pubs = {h: roslibpy.Topic(hub.ros, topic, STRING) for h, hub in hubs.items()}
    for p in pubs.values():
        p.advertise()
    # Every hub's subscriber must see the others' publishers (catalog and interest):
    # probe until a message from each hub reaches each other hub.
    def probed():
        for h, p in pubs.items():
            p.publish(roslibpy.Message({"data": f"probe {h}"}))
        return all(any(m == f"probe {o}" for m in inbox[h].items) for h in hubs for o in hubs if o != h)

    wait_until("probes across the triangle", probed, timeout=WAIT, every=0.3)
    time.sleep(0.5)
    for b in inbox.values():
        with b.cv:
            b.items.clear()
    n = 20
    for i in range(n):
        for h, p in pubs.items():
            p.publish(roslibpy.Message({"data": f"{h} {i}"}))
        time.sleep(0.01)
    time.sleep(1.5)
    report = []
    for h in hubs:
        got = [m for m in inbox[h].items if not m.startswith("probe")]
        for o in hubs:
            mine = [m for m in got if m.startswith(f"{o} ")]
            # A rosbridge client gets its own publishes too (as with rosbridge): once.
            want = [f"{o} {i}" for i in range(n)]
            if sorted(mine, key=lambda m: int(m.split()[1])) != want:
                counters = {k: hub.federation()["counters"] for k, hub in hubs.items()}
                missing = sorted(set(want) - set(mine))
                raise CheckFailed(f"subscriber on {h} got {len(mine)} messages from {o} (want each of "
                                  f"{n} once; missing {missing}); the hubs' federation counters: {counters}")
        report.append(f"{h}: {len(got)}")
    return f"{topic} on 3 hubs, {n} messages each: every subscriber got each message exactly once ({', '.join(report)})"


def keyframe_asks(ctx):
    topic = f"/{ctx.robot}/camera/video"
    wait_until(f"{topic} in C's catalog", lambda: ctx.c.imported(topic))
    c0, a0 = ctx.c.federation()["counters"], ctx.a.federation()["counters"]
    # The viewer takes one frame in 200 ms and loses the rest, so it is given keyframes
    # only; with the stream's own 60 s apart, every one past the first was asked for.
    try:
        r = subprocess.run([sys.executable, VIDEO_PEER, "watch", f"ws://{ctx.c.addr}/?token={ctx.c.token}",
                            topic, "5", "--size", "320x240", "--min-frames", "3",
                            "--throttle", "200", "--queue", "1"],
                           capture_output=True, text=True, timeout=20)
    except subprocess.TimeoutExpired as e:
        raise CheckFailed(f"the viewer on C did not end within 20 s: {e.stdout!r}")
    lines = [ln for ln in r.stdout.splitlines() if ln.strip() and "subscribed to" not in ln]
    check(r.returncode == 0,
          f"the throttled viewer on C (exit {r.returncode}): {' | '.join(lines)} {r.stderr.strip()[-500:]}")

    def counted():
        c, a = ctx.c.federation()["counters"], ctx.a.federation()["counters"]
        return (c["keyframe_asks_out"] - c0["keyframe_asks_out"],
                a["keyframe_asks_in"] - a0["keyframe_asks_in"],
                a["keyframe_asks_acted"] - a0["keyframe_asks_acted"])

    # What A counts may lag C's count by the asks' way through Zenoh: a bounded wait.
    deadline = time.monotonic() + 3
    out, heard, acted = counted()
    while not (out > 0 and acted > 0) and time.monotonic() < deadline:
        time.sleep(0.1)
        out, heard, acted = counted()
    check(out > 0 and acted > 0, f"{' | '.join(lines)}; but C's keyframe_asks_out went up by {out} and "
          f"A's keyframe_asks_acted by {acted} (keyframe_asks_in by {heard}): want both above 0")
    return f"{' | '.join(lines)}; C asked {out} times, A heard {heard} asks and acted on {acted}"


class Ctx:
    pass


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--robot", required=True)
    ap.add_argument("--hub", action="append", required=True, help="NAME=ADDR,TOKEN")
    a = ap.parse_args()
    ctx = Ctx()
    ctx.robot, ctx.keep = a.robot, []
    for spec in a.hub:
        name, rest = spec.split("=", 1)
        addr, token = rest.split(",", 1)
        setattr(ctx, name, Hub(name, addr, token))
    # The robot must be online at A before anything else.
    wait_until(f"{a.robot} online at A",
               lambda: any(r["name"] == a.robot and r["online"] for r in ctx.a.api("/api/v1/robots")["robots"]))
    failed = 0
    for check_fn in (subscribe_remote, no_data_to_b, listings, calls, triangle, keyframe_asks):
        try:
            print(f"PASS {check_fn.__name__}: {check_fn(ctx)}", flush=True)
        except CheckFailed as e:
            failed += 1
            print(f"FAIL {check_fn.__name__}: {e}", flush=True)
        except Exception as e:  # noqa: BLE001 - report and go on to the next check
            failed += 1
            print(f"FAIL {check_fn.__name__}: {type(e).__name__}: {e}", flush=True)
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""The roslibpy clients of the site hubs suite (run.sh), in three roles.

--role chain (the default), in the cloud namespace, a client of the cloud hub:
  1. calls /site7/robot3/set_mode and get_status, and sends /site7/robot3/navigate_to_pose
     a short goal (feedback, then SUCCEEDED) and a long one it cancels (CANCELED), all
     across both hops;
  2. subscribes /site7/robot3/odom and the no_drop /site7/robot3/counter, and starts its
     site-side peer (--role local, with `ip netns exec` in the site namespace), which
     publishes /counter at 20 Hz through robot3's local listener and counts the
     /robot3/odom the site hub sends it, a line a second on its stdout;
  3. takes the WAN down (the site end of the veth) for 10 s: the peer must keep getting
     odometry from the site hub in every second of it, and publishing;
  4. brings it back: odometry must reach the cloud again within 5 s; the peer stops
     publishing; the cloud must get every /counter value from its first one on, once,
     in order, none missing (those published during the cut included).

--role local: the site-side peer above (runs until its stdin closes).

--role triangle: three hubs (--hubs), each the site of the next, /chat bridged both ways
  at each link. Publishes ten messages on the first; a subscriber on each hub counts what
  it gets until 2 s pass without anything: the first hub's subscriber gets each once, the
  others each at least once and at most twice (once by each way round); nothing more
  comes, however long one waits.

Prints PASS/FAIL lines with the figures; exits 1 if any check failed. Every wait is
bounded.
"""

import argparse
import json
import subprocess
import sys
import threading
import time

import roslibpy

STRING = "std_msgs/msg/String"
ODOM = "nav_msgs/msg/Odometry"
NAV = "fleetlink_sim/action/NavigateTo"
TIMEOUT = 10.0
failed = 0


def result(ok, what):
    global failed
    print(f"{'PASS' if ok else 'FAIL'}: {what}", flush=True)
    failed += 0 if ok else 1


def connect(addr, token=None):
    headers = {"Authorization": f"Bearer {token}"} if token else None
    host, port = addr.rsplit(":", 1)
    ros = roslibpy.Ros(host=host, port=int(port), headers=headers)
    ros.run(timeout=TIMEOUT)
    return ros


class Box:
    """Values a roslibpy callback thread hands over, waited for with a bound."""

    def __init__(self):
        self.cv = threading.Condition()
        self.items = []

    def put(self, v):
        with self.cv:
            self.items.append(v)
            self.cv.notify_all()

    def wait(self, n, seconds, what):
        with self.cv:
            if not self.cv.wait_for(lambda: len(self.items) >= n, seconds):
                raise TimeoutError(f"{what}: {len(self.items)} of {n} within {seconds} s")
            return list(self.items)


def close(ros):
    try:
        ros.close(timeout=3)
    except Exception:  # already gone: nothing to close
        pass


def call(ros, name, args, seconds=TIMEOUT):
    svc = roslibpy.Service(ros, name, "")
    return svc.call(roslibpy.ServiceRequest(args), timeout=seconds)


def call_until_ok(ros, name, args, seconds):
    deadline = time.monotonic() + seconds
    while True:
        try:
            return call(ros, name, args, 2.0)
        except Exception as e:  # not reachable yet (the robot's services still on the way)
            if time.monotonic() > deadline:
                raise TimeoutError(f"{name}: {e}") from e
            time.sleep(0.2)


def goal(ac, x, y):
    fb, out = Box(), Box()
    gid = ac.send_goal(roslibpy.Goal({"x": x, "y": y}), lambda r: out.put(dict(r)),
                       lambda f: fb.put(dict(f)), lambda e: out.put({"error": str(e)}))
    return gid, fb, out


def status_of(res):
    s = res.get("status")
    return getattr(s, "value", s)


def towards_origin(x, y, dist):
    n = max((x * x + y * y) ** 0.5, 1e-6)
    return round(x - dist * x / n, 3), round(y - dist * y / n, 3)


def check_calls(ros):
    r = call_until_ok(ros, "/site7/robot3/set_mode", {"data": False}, 20)
    result(r.get("success") is True and "idle" in r.get("message", ""),
           f"set_mode across both hops: {dict(r)}")
    st = json.loads(call(ros, "/site7/robot3/get_status", {})["message"])
    ac = roslibpy.ActionClient(ros, "/site7/robot3/navigate_to_pose", NAV)
    gx, gy = towards_origin(st["x"], st["y"], 0.6)
    _, fb, out = goal(ac, gx, gy)
    res = out.wait(1, 15, "the short goal's result")[0]
    fbs = list(fb.items)
    result(status_of(res) == 4 and res.get("values", {}).get("reached") is True and fbs,
           f"navigate_to_pose across both hops: {len(fbs)} feedbacks, status {status_of(res)}")
    st = json.loads(call(ros, "/site7/robot3/get_status", {})["message"])
    gx, gy = towards_origin(st["x"], st["y"], 5.0)
    gid, fb, out = goal(ac, gx, gy)
    fb.wait(1, 10, "the long goal's first feedback")
    ac.cancel_goal(gid)
    res = out.wait(1, 10, "the cancelled goal's result")[0]
    result(status_of(res) == 5, f"the long goal cancelled across both hops: status {status_of(res)}")


def chain(a):
    ros = connect(a.cloud, a.token)
    check_calls(ros)
    got, odom = [], []
    lock = threading.Lock()

    def on_counter(m):
        with lock:
            got.append(int(m["data"]))

    def on_odom(_m):
        with lock:
            odom.append(time.monotonic())

    roslibpy.Topic(ros, "/site7/robot3/counter", STRING).subscribe(on_counter)
    roslibpy.Topic(ros, "/site7/robot3/odom", ODOM).subscribe(on_odom)
    peer = subprocess.Popen(
        ["ip", "netns", "exec", a.site_ns, a.python, __file__, "--role", "local",
         "--site", a.site, "--site-token", a.site_token, "--local", a.local],
        stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)
    lines = []
    reader = threading.Thread(target=lambda: [lines.append(json.loads(l)) for l in peer.stdout],
                              daemon=True)
    reader.start()
    deadline = time.monotonic() + 15
    while time.monotonic() < deadline and not (got and odom):
        time.sleep(0.1)
    result(bool(got) and bool(odom),
           f"upstream before the cut: {len(got)} /counter and {len(odom)} odometry messages")
    time.sleep(2)
    wan = ["ip", "-n", a.site_ns, "link", "set", a.wan_dev]
    subprocess.run(wan + ["down"], check=True)
    cut_at = time.monotonic()
    with lock:
        at_cut = len(got)
    time.sleep(10)
    with lock:
        during = len(got) - at_cut
    subprocess.run(wan + ["up"], check=True)
    back_at = time.monotonic()
    seconds = [l for l in lines if cut_at + 0.5 <= l["at"] <= back_at]
    result(len(seconds) >= 8 and all(l["odom"] > 0 for l in seconds),
           f"the site served its own client through the cut: odometry per second "
           f"{[l['odom'] for l in seconds]}, /counter published {seconds[-1]['sent'] if seconds else 0}")
    deadline = back_at + 15
    resumed = None
    while time.monotonic() < deadline:
        with lock:
            if odom and odom[-1] > back_at:
                resumed = odom[-1] - back_at
                break
        time.sleep(0.05)
    result(resumed is not None and resumed < 5,
           f"odometry upstream again {resumed if resumed is None else round(resumed, 2)} s after the WAN returned")
    time.sleep(2)
    peer.stdin.close()
    peer.wait(timeout=10)
    reader.join(timeout=5)
    last = max((l["sent"] for l in lines), default=0)
    deadline = time.monotonic() + 20
    while time.monotonic() < deadline:
        with lock:
            if got and got[-1] >= last:
                break
        time.sleep(0.1)
    time.sleep(1)
    with lock:
        seq = list(got)
    first = seq[0] if seq else None
    want = list(range(first, last + 1)) if seq else []
    missing = sorted(set(want) - set(seq))
    dups = len(seq) - len(set(seq))
    result(seq == want and last > 0,
           f"no_drop /counter upstream: {first}..{last}, {len(seq)} received, {dups} twice, "
           f"{len(missing)} missing {missing[:10]}, {during} arrived during the cut")
    close(ros)


def local(a):
    """The site's own client: publishes /counter through the robot, counts odometry."""
    site, robot = connect(a.site, a.site_token), connect(a.local)
    odom = [0]
    lock = threading.Lock()

    def on_odom(_m):
        with lock:
            odom[0] += 1

    roslibpy.Topic(site, "/robot3/odom", ODOM).subscribe(on_odom)
    counter = roslibpy.Topic(robot, "/counter", STRING)
    counter.advertise()
    stop = threading.Event()
    threading.Thread(target=lambda: (sys.stdin.read(), stop.set()), daemon=True).start()
    n, next_report = 0, time.monotonic() + 1
    while not stop.is_set():
        n += 1
        counter.publish(roslibpy.Message({"data": str(n)}))
        stop.wait(0.05)
        if time.monotonic() >= next_report:
            with lock:
                count, odom[0] = odom[0], 0
            print(json.dumps({"at": time.monotonic(), "odom": count, "sent": n}), flush=True)
            next_report += 1
    print(json.dumps({"at": time.monotonic(), "odom": 0, "sent": n}), flush=True)
    time.sleep(0.5)  # the last publishes on their way before the socket closes
    close(robot)
    close(site)


def triangle(a):
    hubs, tokens = a.hubs.split(","), a.tokens.split(",")
    subs, got = [], [[] for _ in hubs]
    for i, (h, t) in enumerate(zip(hubs, tokens)):
        ros = connect(h, t)
        roslibpy.Topic(ros, "/chat", STRING).subscribe(lambda m, i=i: got[i].append(m["data"]))
        subs.append(ros)
    talker = connect(hubs[0], tokens[0])
    chat = roslibpy.Topic(talker, "/chat", STRING)
    chat.advertise()
    # The bridges are up once a probe from the first hub reaches the last one.
    deadline = time.monotonic() + 20
    while not any(m == "probe" for m in got[2]):
        if time.monotonic() > deadline:
            result(False, "a probe on the first hub never reached the third")
            return
        chat.publish(roslibpy.Message({"data": "probe"}))
        time.sleep(0.3)
    time.sleep(2)
    for g in got:
        g.clear()
    for i in range(10):
        chat.publish(roslibpy.Message({"data": f"m{i}"}))
    quiet_since, sizes = time.monotonic(), [0, 0, 0]
    deadline = time.monotonic() + 20
    while time.monotonic() - quiet_since < 2 and time.monotonic() < deadline:
        now = [len(g) for g in got]
        if now != sizes:
            sizes, quiet_since = now, time.monotonic()
        time.sleep(0.05)
    want = [f"m{i}" for i in range(10)]
    counts = [{m: g.count(m) for m in want} for g in got]
    extra = [sorted(set(g) - set(want)) for g in got]
    result(all(c == 1 for c in counts[0].values()) and not extra[0],
           f"the first hub: each message once, none back from the far side: {counts[0]}")
    for i in (1, 2):
        result(all(1 <= c <= 2 for c in counts[i].values()) and not extra[i],
               f"hub {i + 1}: each message once or twice (once by each way round): {counts[i]}")
    time.sleep(2)
    result([len(g) for g in got] == sizes,
           f"nothing more in 2 s more: {sizes} messages, then {[len(g) for g in got]}")
    for r in subs + [talker]:
        close(r)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--role", default="chain", choices=["chain", "local", "triangle"])
    p.add_argument("--cloud")
    p.add_argument("--token")
    p.add_argument("--site")
    p.add_argument("--site-token")
    p.add_argument("--local")
    p.add_argument("--site-ns")
    p.add_argument("--wan-dev")
    p.add_argument("--python", default=sys.executable)
    p.add_argument("--hubs")
    p.add_argument("--tokens")
    a = p.parse_args()
    try:
        {"chain": chain, "local": local, "triangle": triangle}[a.role](a)
    except TimeoutError as e:
        result(False, str(e))
    if a.role != "local":
        print(f"site hubs ({a.role}): {failed} failure(s)", flush=True)
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()

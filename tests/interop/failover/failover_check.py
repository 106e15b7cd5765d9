#!/usr/bin/env python3
"""The clients of the failover suite (run.sh): a roslibpy publisher on the agent's local
rosbridge listener and a roslibpy subscriber on hub B, then the audit of what B got.

  publisher   /counter (std_msgs/msg/String, data "<n> <send time ns>"), n = 1, 2, 3, ...
              at --hz, on the agent's local listener (--local-url). The agent's config
              makes /counter a no_drop topic. Every publish is logged "pub <n> <ns>".
  subscriber  on hub B (--hub-url, an operator token in the URL), subscribed before the
              robot is there to /<robot>/counter and to the simulator's /<robot>/odom;
              logs "rx <n> <recv ns>" and "odom <recv ns>".

Prints "ready" once both are connected and publishing has begun, then runs until the file
--stop appears (or --max-seconds pass). Then it stops publishing, waits (bounded) until B
has every counter value from the first it received onward, and checks, with the time
hub A stopped answering read from --down-at (ns since the epoch, written by run.sh, which
froze hub A then and killed it soon after):

  - what B received is n0, n0+1, n0+2, ...: no value twice, none missing, in order;
  - every value published since hub A stopped answering arrived at B exactly once, and
    so did those among them the agent had sent to A (A never confirmed them);
  - the subscriber got /<robot>/counter and /<robot>/odom on B without doing anything.

Prints a PASS or FAIL line per check with its figures; exits 1 if any failed. Every wait
is bounded.
"""

import argparse
import os
import sys
import threading
import time
import urllib.parse

import roslibpy

STRING = "std_msgs/msg/String"
ODOM = "nav_msgs/msg/Odometry"
CONNECT_TIMEOUT = 10.0
DRAIN_S = 10.0  # after publishing stops, for the rest of the counter to reach B


class Record:
    """What the publisher sent and the subscriber got, shared by their threads."""

    def __init__(self, log_path):
        self.lock = threading.Lock()
        self.log = open(log_path, "a", buffering=1, encoding="ascii")
        self.sent = []  # (n, send ns)
        self.got = []  # (n, recv ns), in arrival order
        self.odom = 0

    def note(self, line):
        with self.lock:
            self.log.write(line + "\n")


def ros_connect(url):
    u = urllib.parse.urlparse(url)
    token = urllib.parse.parse_qs(u.query).get("token", [None])[0]
    headers = {"Authorization": f"Bearer {token}"} if token else None
    ros = roslibpy.Ros(host=u.hostname, port=u.port, headers=headers)
    ros.run(timeout=CONNECT_TIMEOUT)
    return ros


def subscribe(url, robot, rec):
    ros = ros_connect(url)

    def on_counter(m):
        recv = time.time_ns()
        n = int(m["data"].split()[0])
        with rec.lock:
            rec.got.append((n, recv))
        rec.note(f"rx {n} {recv}")

    def on_odom(_m):
        with rec.lock:
            rec.odom += 1

    roslibpy.Topic(ros, f"/{robot}/counter", STRING).subscribe(on_counter)
    roslibpy.Topic(ros, f"/{robot}/odom", ODOM).subscribe(on_odom)
    return ros


def publish(ros, hz, rec, stop):
    topic = roslibpy.Topic(ros, "/counter", STRING)
    topic.advertise()
    period, n, next_at = 1.0 / hz, 1, time.monotonic()
    while not stop.is_set():
        now = time.time_ns()
        topic.publish(roslibpy.Message({"data": f"{n} {now}"}))
        with rec.lock:
            rec.sent.append((n, now))
        rec.note(f"pub {n} {now}")
        n += 1
        next_at += period
        delay = next_at - time.monotonic()
        if delay > 0:
            stop.wait(delay)
        else:
            next_at = time.monotonic()  # fell behind: no burst to catch up


def wait_for(path, seconds):
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        if os.path.exists(path):
            return True
        time.sleep(0.05)
    return False


def audit(rec, down_at):
    """The checks; returns the number that failed."""
    with rec.lock:
        sent, got, odom = list(rec.sent), list(rec.got), rec.odom
    failed = 0

    def result(ok, what):
        nonlocal failed
        print(f"{'PASS' if ok else 'FAIL'}: {what}", flush=True)
        failed += 0 if ok else 1

    if not got:
        result(False, "hub B's subscriber received no /counter message at all")
        return failed + 1
    seqs = [n for n, _ in got]
    first, last = seqs[0], sent[-1][0]
    want = list(range(first, last + 1))
    dups = len(seqs) - len(set(seqs))
    missing = sorted(set(want) - set(seqs))
    in_order = seqs == want
    result(
        in_order,
        f"B received /counter {first}..{seqs[-1]} ({len(seqs)} messages) of {last} published: "
        f"{dups} duplicates, {len(missing)} missing {missing[:10]}, "
        f"{'in order' if in_order else 'NOT in order'}",
    )
    after = [n for n, t in sent if t >= down_at]
    counts = {}
    for n in seqs:
        counts[n] = counts.get(n, 0) + 1
    not_once = [n for n in after if counts.get(n, 0) != 1]
    result(
        bool(after) and not not_once,
        f"every value published since hub A stopped answering ({len(after)}, from "
        f"{after[:1]}) reached B exactly once; not exactly once: {not_once[:10]}",
    )
    before = [n for n, t in sent if t < down_at]
    print(
        f"    {len(before)} values published before hub A stopped answering (A delivered "
        f"them); B's first is {first}; first /counter on B "
        f"{(got[0][1] - down_at) / 1e9:.2f} s after A stopped answering",
        flush=True,
    )
    result(odom > 0, f"B's subscriber got {odom} /odom messages from the simulator")
    return failed


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--hub-url", required=True, help="hub B, with an operator token")
    p.add_argument("--local-url", required=True, help="the agent's local rosbridge listener")
    p.add_argument("--robot", required=True)
    p.add_argument("--hz", type=float, default=20)
    p.add_argument("--log", required=True)
    p.add_argument("--stop", required=True, help="a file whose appearance ends the run")
    p.add_argument("--down-at", required=True,
                   help="a file with the time hub A stopped answering, ns since the epoch")
    p.add_argument("--max-seconds", type=float, default=60)
    a = p.parse_args()

    rec = Record(a.log)
    sub = subscribe(a.hub_url, a.robot, rec)
    pub = ros_connect(a.local_url)
    stop = threading.Event()
    publisher = threading.Thread(target=publish, args=(pub, a.hz, rec, stop), daemon=True)
    publisher.start()
    print("ready", flush=True)

    wait_for(a.stop, a.max_seconds)
    stop.set()
    publisher.join(timeout=5)
    try:
        with open(a.down_at, encoding="ascii") as f:
            down_at = int(f.read().strip())
    except (OSError, ValueError) as e:
        print(f"FAIL: no time in {a.down_at}: {e}", flush=True)
        return 1
    # Drain: every value from the first B got up to the last published (bounded).
    deadline = time.monotonic() + DRAIN_S
    while time.monotonic() < deadline:
        with rec.lock:
            have = {n for n, _ in rec.got}
            last = rec.sent[-1][0] if rec.sent else 0
            first = rec.got[0][0] if rec.got else None
        if first is not None and all(n in have for n in range(first, last + 1)):
            break
        time.sleep(0.05)
    failed = audit(rec, down_at)
    time.sleep(0.3)  # what publish() queued leaves before the close
    pub.close()
    sub.close()
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())

"""ROS 1 actions through the hub with roslibpy 1.8's actionlib (issue 56): its
SimpleActionServer and ActionClient, both connected to the hub, exchange a goal, the
client cancels it, and the goal ends preempted.

The point is the cancel: `Goal.cancel()` publishes a partial `actionlib_msgs/GoalID`
(`{"id": ...}`), which the hub completes with the type's defaults before the server sees
it. The server reads `stamp.secs`, ROS 1's name: a type only ROS 1 has gets ROS 1's
field names (docs/msg.md, "ROS 1 names"). Also checked: the status array the server
publishes reaches the client with ROS 1's header (`seq`, `stamp.secs`).

Run with the roslibpy 1.8 venv (scripts/setup.d/12-roslibpy-1.sh):
    .venv-roslibpy1/bin/python actionlib_check.py --url ws://HOST:PORT/?token=T
Exits 0 when every check passed, 1 naming the failed one. Every wait is bounded.
"""

import argparse
import os
import sys
import threading
import time
import urllib.parse

import roslibpy
from roslibpy import actionlib

TIMEOUT = 10
ACTION = "actionlib_tutorials/FibonacciAction"


class Failed(Exception):
    pass


def check(cond, what):
    if not cond:
        raise Failed(what)
    print(f"  ok: {what}")


def connect(url):
    u = urllib.parse.urlparse(url)
    token = urllib.parse.parse_qs(u.query).get("token", [None])[0]
    headers = {"Authorization": f"Bearer {token}"} if token else None
    ros = roslibpy.Ros(host=u.hostname, port=u.port, headers=headers)
    ros.run(timeout=TIMEOUT)
    return ros


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--url", required=True)
    p.add_argument("--name", default="/interop_fibonacci")
    a = p.parse_args()
    print(f"actionlib (roslibpy {roslibpy.__version__}) through {a.url.split('?')[0]}")
    server_ros, client_ros = connect(a.url), connect(a.url)
    try:
        # The server: a goal runs until it is preempted (then says so) or 10 s pass.
        server = actionlib.SimpleActionServer(server_ros, a.name, ACTION)
        started, preempted = threading.Event(), threading.Event()
        # What the server's cancel listener gets, seen by a listener of its own (on the
        # client's connection, which publishes the cancels).
        cancels = []
        roslibpy.Topic(client_ros, a.name + "/cancel", "actionlib_msgs/GoalID").subscribe(
            cancels.append)

        def execute(goal):
            started.set()
            deadline = time.monotonic() + TIMEOUT
            while time.monotonic() < deadline:
                if server.is_preempt_requested():
                    server.set_preempted()
                    preempted.set()
                    return
                server.send_feedback({"sequence": [0, 1]})
                time.sleep(0.1)
            server.set_succeeded({"sequence": [0, 1, 1]})

        server.start(execute)

        client = actionlib.ActionClient(client_ros, a.name, ACTION)
        statuses = []
        roslibpy.Topic(server_ros, a.name + "/status", "actionlib_msgs/GoalStatusArray").subscribe(
            statuses.append)
        goal = actionlib.Goal(client, roslibpy.Message({"order": 5}))
        results = []
        goal.on("result", results.append)
        goal.send()
        check(started.wait(TIMEOUT), "the server got the goal")

        goal.cancel()
        check(preempted.wait(TIMEOUT), "the server took Goal.cancel()'s partial GoalID and "
                                        "preempted the goal")
        cancel = cancels[0] if cancels else {}
        check(cancel.get("id") == goal.goal_id
              and cancel.get("stamp") == {"secs": 0, "nsecs": 0},
              f"the GoalID as the server got it: its id, a zero stamp as ROS 1 names it ({cancel})")

        def ended():
            return goal.status is not None and goal.status.get("status") == actionlib.GoalStatus.PREEMPTED

        deadline = time.monotonic() + TIMEOUT
        while not ended() and time.monotonic() < deadline:
            time.sleep(0.05)
        check(ended(), f"the client saw the goal PREEMPTED (status {goal.status})")
        # The status listener is a subscription of its own: its first array may come after
        # the client's (bounded wait, not a sleep).
        deadline = time.monotonic() + TIMEOUT
        while not statuses and time.monotonic() < deadline:
            time.sleep(0.05)
        header = statuses[-1]["header"] if statuses else {}
        check("seq" in header and set(header.get("stamp", {})) == {"secs", "nsecs"},
              f"the status array's header as ROS 1 has it ({header})")
        print("actionlib check passed")
        return 0
    except Failed as e:
        print(f"FAIL: {e}", file=sys.stderr)
        return 1
    finally:
        for ros in (server_ros, client_ros):
            ros.close()
        sys.stdout.flush()
        sys.stderr.flush()


if __name__ == "__main__":
    # roslibpy's reactor thread does not end on close: leave at once.
    os._exit(main())

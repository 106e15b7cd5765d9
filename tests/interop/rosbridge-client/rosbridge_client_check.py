#!/usr/bin/env python3
"""The agent's rosbridge client, checked end to end with roslibpy (PyPI) programs on both
sides: on the robot's rosbridge server (--robot-server, a fleetlink hub standing in for
the robot's server) and on the fleet's hub (--hub) the agent is connected to.

Checks, each bounded by WAIT seconds (the bridge's discovery and, in phase `after`, its
reconnect are inside that bound):

  chatter   a /chatter publisher on the robot's server; /<robot>/chatter on the hub
            carries its values (this run's own, by a random tag)
  service   a /set_flag provider (std_srvs/srv/SetBool) on the robot's server; a call of
            /<robot>/set_flag at the hub gets the provider's answer for that request
  cmd_vel   /<robot>/cmd_vel published at the hub reaches a /cmd_vel subscriber on the
            robot's server with the values sent

--phase only names the run in the output (`before` / `after` the server's restart): both
runs do the same checks with new programs and new values. Prints `ok <check>` or
`FAIL <check>: why` and exits 1 if any failed.
"""

import argparse
import secrets
import sys
import threading
import time
import urllib.parse

import roslibpy

WAIT = 15.0  # seconds for each check (discovery every 0.5 s, reconnect backoff <= 2 s)


class CheckFailed(Exception):
    pass


def connect(url, what):
    u = urllib.parse.urlparse(url)
    token = urllib.parse.parse_qs(u.query).get("token", [None])[0]
    headers = {"Authorization": f"Bearer {token}"} if token else None
    ros = roslibpy.Ros(host=u.hostname, port=u.port, headers=headers)
    try:
        ros.run(timeout=10)
    except Exception as e:
        raise CheckFailed(f"connect {what} ({u.netloc}): {e}") from e
    if not ros.is_connected:
        raise CheckFailed(f"connect {what}: not connected")
    return ros


class Inbox:
    def __init__(self):
        self.items = []
        self.cond = threading.Condition()

    def put(self, item):
        with self.cond:
            self.items.append(item)
            self.cond.notify_all()

    def wait_for(self, pred, until, count=1):
        """The items matching `pred` once there are `count` of them, or what there is
        at `until`."""
        with self.cond:
            while True:
                found = [i for i in self.items if pred(i)]
                if len(found) >= count:
                    return found
                left = until - time.monotonic()
                if left <= 0:
                    return found
                self.cond.wait(left)


def check_chatter(robot, hub, name, tag):
    got = Inbox()
    sub = roslibpy.Topic(hub, f"/{name}/chatter", "std_msgs/msg/String")
    sub.subscribe(lambda m: got.put(m.get("data")))
    pub = roslibpy.Topic(robot, "/chatter", "std_msgs/msg/String")
    pub.advertise()
    until = time.monotonic() + WAIT
    sent = []
    n = 0
    # Published every 0.1 s until three of this run's values have arrived (or WAIT).
    while time.monotonic() < until:
        value = f"{tag} chatter {n}"
        pub.publish(roslibpy.Message({"data": value}))
        sent.append(value)
        n += 1
        mine = got.wait_for(lambda d: isinstance(d, str) and d.startswith(tag), time.monotonic() + 0.1, 3)
        if len(mine) >= 3:
            break
    mine = [d for d in got.items if isinstance(d, str) and d.startswith(tag)]
    sub.unsubscribe()
    if len(mine) < 3:
        raise CheckFailed(f"/{name}/chatter: {len(mine)} of {len(sent)} values arrived within {WAIT} s; others seen: {got.items[:5]}")
    unknown = [d for d in mine if d not in sent]
    if unknown:
        raise CheckFailed(f"/{name}/chatter: values nobody sent: {unknown[:3]}")
    numbers = [int(d.rsplit(" ", 1)[1]) for d in mine]
    if numbers != sorted(numbers):
        raise CheckFailed(f"/{name}/chatter: values out of order: {numbers}")
    print(f"    {len(mine)} values arrived, first {mine[0]!r}", flush=True)
    return pub


def check_service(robot, hub, name, tag):
    def answer(request, response):
        response["success"] = bool(request.get("data"))
        response["message"] = f"{tag} flag {request.get('data')}"
        return True

    provider = roslibpy.Service(robot, "/set_flag", "std_srvs/srv/SetBool")
    provider.advertise(answer)
    caller = roslibpy.Service(hub, f"/{name}/set_flag", "std_srvs/srv/SetBool")
    until = time.monotonic() + WAIT
    last = None
    while time.monotonic() < until:
        try:
            r = caller.call(roslibpy.ServiceRequest({"data": True}), timeout=3)
        except Exception as e:  # not exposed yet (discovery), or the link is coming back
            last = e
            time.sleep(0.2)
            continue
        if r.get("message") != f"{tag} flag True" or r.get("success") is not True:
            raise CheckFailed(f"/{name}/set_flag answered {dict(r)}, expected this run's provider's answer")
        print(f"    answer: {dict(r)}", flush=True)
        return provider
    raise CheckFailed(f"/{name}/set_flag: no answer within {WAIT} s; last: {last}")


def check_cmd_vel(robot, hub, name, tag):
    got = Inbox()
    sub = roslibpy.Topic(robot, "/cmd_vel", "std_msgs/msg/String")
    sub.subscribe(lambda m: got.put(m.get("data")))
    pub = roslibpy.Topic(hub, f"/{name}/cmd_vel", "std_msgs/msg/String")
    pub.advertise()
    until = time.monotonic() + WAIT
    sent = []
    while time.monotonic() < until:
        value = f"{tag} cmd {len(sent)}"
        pub.publish(roslibpy.Message({"data": value}))
        sent.append(value)
        if got.wait_for(lambda d: isinstance(d, str) and d.startswith(tag), time.monotonic() + 0.1):
            break
    mine = [d for d in got.items if isinstance(d, str) and d.startswith(tag)]
    sub.unsubscribe()
    pub.unadvertise()
    if not mine:
        raise CheckFailed(f"/cmd_vel on the robot's server: none of {len(sent)} values from /{name}/cmd_vel arrived within {WAIT} s; seen: {got.items[:5]}")
    if any(d not in sent for d in mine):
        raise CheckFailed(f"/cmd_vel: values nobody sent: {mine[:3]}")
    print(f"    {len(mine)} values arrived, first {mine[0]!r}", flush=True)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--robot-server", required=True)
    ap.add_argument("--hub", required=True)
    ap.add_argument("--robot", required=True)
    ap.add_argument("--phase", required=True)
    a = ap.parse_args()
    tag = f"{a.phase}-{secrets.token_hex(4)}"
    failed = []
    try:
        robot = connect(a.robot_server, "the robot's server")
        hub = connect(a.hub, "the hub")
    except CheckFailed as e:
        print(f"FAIL connect ({a.phase}): {e}", flush=True)
        return 1
    keep = []
    for check in (check_chatter, check_service, check_cmd_vel):
        what = check.__name__.removeprefix("check_")
        started = time.monotonic()
        try:
            keep.append(check(robot, hub, a.robot, tag))
            print(f"ok {what} ({a.phase}, {time.monotonic() - started:.1f} s)", flush=True)
        except CheckFailed as e:
            print(f"FAIL {what} ({a.phase}): {e}", flush=True)
            failed.append(what)
    for ros in (robot, hub):
        try:
            ros.close(timeout=3)
        except Exception:
            pass
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())

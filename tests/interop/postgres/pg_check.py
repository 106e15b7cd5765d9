#!/usr/bin/env python3
"""The clients of the PostgreSQL suite (run.sh): two hubs, A and B, sharing one database.

Every change goes through one hub's REST API and is checked on the other with real clients
(roslibpy for rosbridge, plain HTTP for the API):

  1. a robot token minted through A authenticates a roslibpy client on B; a user added
     through A logs in on B;
  2. the user (group ops) subscribes on B to /demo/chatter, published at 200 Hz on B by
     an admin client; an ops rule removed through A stops the delivery on B, and added
     again through A resumes it, each within 1 s (measured: the send time of the last
     message delivered after the removal, the receive time of the first after the add);
  3. the robot token revoked through B is refused by A within 1 s (measured);
  4. the database is killed: a new login on A fails with a clear 503 error, a new
     rosbridge connection is refused, and B's established sessions keep delivering;
     the database comes back: logins work again (time measured) and a rule change
     through A applies on B within 1 s again (the listeners reconnected).

Prints a PASS or FAIL line per check, with figures; exits 1 if any failed. Every wait is
bounded. The database is stopped and started with the functions of cluster.sh (its
PG_* variables in the environment).
"""

import argparse
import json
import os
import subprocess
import sys
import threading
import time
import urllib.error
import urllib.request

import roslibpy

STRING = "std_msgs/msg/String"
TOPIC = "/demo/chatter"
HZ = 200
LIMIT_MS = 1000
HERE = os.path.dirname(os.path.abspath(__file__))

failures = []


def result(ok, what):
    print(("PASS: " if ok else "FAIL: ") + what, flush=True)
    if not ok:
        failures.append(what)
    return ok


def http(addr, method, path, token=None, body=None, timeout=5):
    """(status, parsed JSON or text) of one request; (0, error text) if none came back."""
    data = json.dumps(body).encode() if body is not None else None
    req = urllib.request.Request(f"http://{addr}{path}", data=data, method=method)
    if token:
        req.add_header("Authorization", f"Bearer {token}")
    if data is not None:
        req.add_header("Content-Type", "application/json")
    try:
        with urllib.request.urlopen(req, timeout=timeout) as r:
            status, text = r.status, r.read().decode()
    except urllib.error.HTTPError as e:
        status, text = e.code, e.read().decode()
    except OSError as e:
        return 0, repr(e)
    try:
        return status, json.loads(text)
    except ValueError:
        return status, text


def must(addr, method, path, token, body=None, want=(200, 201)):
    status, got = http(addr, method, path, token, body)
    if status not in want:
        raise SystemExit(f"FAIL: {method} {path} on {addr}: {status} {got}")
    return got


def ros_connect(addr, token, timeout=10, name=None):
    host, port = addr.rsplit(":", 1)
    ros = roslibpy.Ros(host=host, port=int(port),
                       headers={"Authorization": f"Bearer {token}"})
    ros.run(timeout=timeout)
    proto = getattr(ros.factory, "_proto", None)
    if name and proto is not None:
        # rosbridge `status` messages (a refusal, a warning) shown instead of roslibpy's
        # "no handler" traceback.
        proto._message_handlers["status"] = (lambda m: print(
            f"    status to {name}: {m.get('level')}: {m.get('msg')}", flush=True))
    return ros


def connects(addr, token):
    """Whether a rosbridge client with `token` gets in (closed again at once)."""
    try:
        ros = ros_connect(addr, token, timeout=3)
    except Exception:  # refused at the upgrade: roslibpy times out or raises
        return False
    ok = ros.is_connected
    ros.close()
    return ok


class Feed:
    """What the subscriber got: (send ns, receive ns) per message."""

    def __init__(self):
        self.lock = threading.Lock()
        self.got = []

    def on_message(self, m):
        recv = time.time_ns()
        with self.lock:
            self.got.append((int(m["data"]), recv))

    def since(self, t_ns):
        with self.lock:
            return [(s, r) for s, r in self.got if s > t_ns]

    def count(self):
        with self.lock:
            return len(self.got)


def publish(ros, stop):
    topic = roslibpy.Topic(ros, TOPIC, STRING)
    topic.advertise()
    period, next_at = 1.0 / HZ, time.monotonic()
    while not stop.is_set():
        topic.publish(roslibpy.Message({"data": str(time.time_ns())}))
        next_at += period
        delay = next_at - time.monotonic()
        if delay > 0:
            stop.wait(delay)
        else:
            next_at = time.monotonic()


def wait_until(seconds, ok, step=0.005):
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        if ok():
            return True
        time.sleep(step)
    return ok()


def database(action):
    """Stops or starts the suite's cluster (cluster.sh's pg_cluster_kill / pg_cluster_up)."""
    fn = {"kill": "pg_cluster_kill", "up": "pg_cluster_up"}[action]
    subprocess.run(["bash", "-c", f'. "{HERE}/cluster.sh" && {fn}'], check=True, timeout=60)


def rule_applies(a, b, admin, feed, rule, rule_id, label):
    """Removes the ops rule through A and adds it again; checks B within 1 s. Returns the
    new rule id."""
    t_del = time.time_ns()
    must(a, "DELETE", f"/api/v1/rules/{rule_id}", admin, want=(200, 204))
    time.sleep(1.5)
    after = feed.since(t_del)
    last_ms = (max(s for s, _ in after) - t_del) / 1e6 if after else 0.0
    late = [s for s, _ in after if s > t_del + LIMIT_MS * 1_000_000]
    result(not late,
           f"{label}: rule removed through A stops delivery on B after {last_ms:.0f} ms "
           f"(last message sent then; limit {LIMIT_MS} ms; {len(late)} sent later got through)")

    t_add = time.time_ns()
    rule_id = must(a, "POST", "/api/v1/rules", admin, rule)["id"]
    resumed = wait_until(3, lambda: feed.since(t_add))
    first_ms = (min(r for _, r in feed.since(t_add)) - t_add) / 1e6 if resumed else None
    result(resumed and first_ms < LIMIT_MS,
           f"{label}: rule added through A resumes delivery on B after "
           f"{first_ms if first_ms is None else round(first_ms)} ms (limit {LIMIT_MS} ms)")
    return rule_id


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--hub-a", required=True, help="host:port of hub A")
    p.add_argument("--hub-b", required=True, help="host:port of hub B")
    p.add_argument("--admin-token", required=True, help="an operator token in group admin")
    a = p.parse_args()
    A, B, admin = a.hub_a, a.hub_b, a.admin_token

    # The ops rule first: carol's subscription on B is checked when she makes it, and
    # the steps between give B the few milliseconds it needs to apply the rule (the
    # propagation itself is measured in step 2).
    rule = {"subject": {"group": "ops"}, "names": "/demo/.*", "ops": ["subscribe"]}
    rule_id = must(A, "POST", "/api/v1/rules", admin, rule)["id"]

    # --- 1. credentials made through A work on B
    minted = must(A, "POST", "/api/v1/robots/r9/tokens", admin)
    robot_token, robot_token_id = minted["token"], minted["id"]
    robot = None
    try:
        robot = ros_connect(B, robot_token)
    except Exception as e:
        print(f"    connecting to B with the robot token: {e!r}")
    result(robot is not None and robot.is_connected,
           "a robot token minted through A's REST API authenticates a roslibpy client on B")
    if robot:
        robot.close()
    must(A, "POST", "/api/v1/users", admin,
         {"name": "carol", "password": "pw-carol", "groups": ["ops"]})
    status, login = http(B, "POST", "/api/v1/login", body={"user": "carol", "password": "pw-carol"})
    if not result(status == 200, f"a user added through A logs in on B ({status})"):
        raise SystemExit(1)
    carol_token = login["token"]

    # --- 2. a rule changed through A applies on B
    feed = Feed()
    carol = ros_connect(B, carol_token, name="carol")
    roslibpy.Topic(carol, TOPIC, STRING).subscribe(feed.on_message)
    pub = ros_connect(B, admin, name="publisher")
    stop = threading.Event()
    publisher = threading.Thread(target=publish, args=(pub, stop), daemon=True)
    publisher.start()
    if not result(wait_until(5, lambda: feed.count() > 0),
                  f"carol (group ops, allowed by a rule added through A) receives {TOPIC} on B"):
        raise SystemExit(1)
    rule_id = rule_applies(A, B, admin, feed, rule, rule_id, "rule change")

    # --- 3. revoked through B, refused by A
    status, _ = http(A, "GET", "/api/v1/robots", robot_token)
    result(status != 401, f"the robot token is accepted by A before the revocation ({status})")
    t_rev = time.monotonic()
    must(B, "DELETE", f"/api/v1/tokens/{robot_token_id}", admin, want=(200, 204))
    refused = wait_until(1, lambda: http(A, "GET", "/api/v1/robots", robot_token)[0] == 401)
    result(refused, f"the robot token revoked through B is refused by A after "
                    f"{(time.monotonic() - t_rev) * 1000:.0f} ms (limit {LIMIT_MS} ms)")
    result(not connects(A, robot_token), "a rosbridge client with the revoked token is refused by A")

    # --- 4. the database goes away and comes back
    database("kill")
    t_kill = time.time_ns()
    status, body = http(A, "POST", "/api/v1/login", body={"user": "carol", "password": "pw-carol"})
    text = body.get("error", "") if isinstance(body, dict) else str(body)
    result(status == 503 and "database" in text,
           f"with the database down, a login on A fails clearly: {status} {text!r}")
    result(not connects(A, carol_token),
           "with the database down, a new rosbridge connection to A is refused")
    time.sleep(1)
    during = len(feed.since(t_kill))
    secs = (time.time_ns() - t_kill) / 1e9
    result(during > HZ // 2,
           f"with the database down, B's established sessions keep delivering "
           f"({during} messages in the {secs:.1f} s since the kill)")

    database("up")
    t_up = time.monotonic()
    back = wait_until(15, lambda: http(A, "POST", "/api/v1/login",
                                       body={"user": "carol", "password": "pw-carol"})[0] == 200,
                      step=0.1)
    result(back, f"the database is back: logins on A work again after "
                 f"{(time.monotonic() - t_up) * 1000:.0f} ms")
    # The listeners reconnect with backoff (at most 5 s apart): give them that, then the
    # rule changes must propagate as before.
    time.sleep(5.5)
    rule_applies(A, B, admin, feed, rule, rule_id, "after the database came back")

    stop.set()
    publisher.join(timeout=5)
    pub.close()
    carol.close()
    print(f"postgres check: {len(failures)} failure(s)", flush=True)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

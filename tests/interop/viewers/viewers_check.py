"""Driver of the viewers suite (issue 56): viewers that vanish without closing their
connection are closed by the hub within its silence limit plus a second, and the robot's
topic they watched goes idle; a slow but live viewer is kept.

Runs in the hub's namespace (run.sh made it and the viewers' one). The hub runs with
`--viewer-ping-secs 2 --viewer-silence-secs 8`; the robot's agent (simulated, a point
cloud of 10,000 points at 5 Hz, about 1 MB/s as rosbridge JSON) beside it. Scenarios:

  1. cut:      a roslibpy viewer across the veth; the viewers' end of the veth goes down;
  2. frozen:   a roslibpy viewer stopped with SIGSTOP (its kernel still acknowledges);
  3. foxglove: a Foxglove viewer (@foxglove/ws-protocol) stopped with SIGSTOP;
  4. slow:     a Python `websockets` viewer behind a 256 kbit/s tbf link for 2 minutes:
               its messages (and the hub's pings behind them) arrive tens of seconds
               late, and it must never be closed;
  5. local:    a roslibpy program on the agent's local rosbridge listener, stopped with
               SIGSTOP: the agent releases its subscription within its own limit (30 s).

In 1-3 the time from the cut or freeze to the hub's API showing the topic `idle` with no
subscriber must be at most the silence limit plus one second. Every wait is bounded.
"""

import argparse
import json
import os
import re
import signal
import subprocess
import sys
import time
import urllib.request

HERE = os.path.dirname(os.path.abspath(__file__))
PING_S = 2
SILENCE_S = 8
TOPIC = "/robot1/points"


class Failed(Exception):
    pass


def wait_until(pred, timeout, what, interval=0.05):
    deadline = time.monotonic() + timeout
    while True:
        v = pred()
        if v:
            return v
        if time.monotonic() >= deadline:
            raise Failed(f"{what}: not within {timeout:g} s")
        time.sleep(interval)


class Suite:
    def __init__(self, a):
        self.a = a
        self.procs = []
        self.data_dir = os.path.join(a.tmp, "hub-data")

    # --- processes
    def start(self, name, ns, argv):
        log = os.path.join(self.a.tmp, f"{name}.out")
        cmd = argv if ns is None else ["ip", "netns", "exec", ns, *argv]
        p = subprocess.Popen(cmd, stdout=open(log, "ab"), stderr=subprocess.STDOUT,
                             start_new_session=True)
        self.procs.append(p)
        return p, log

    def stop(self, p):
        try:
            os.killpg(p.pid, signal.SIGCONT)
            os.killpg(p.pid, signal.SIGTERM)
            p.wait(timeout=5)
        except (ProcessLookupError, subprocess.TimeoutExpired):
            try:
                os.killpg(p.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
            p.wait(timeout=5)

    def stop_all(self):
        for p in self.procs:
            if p.poll() is None:
                self.stop(p)

    def wait_line(self, log, pattern, timeout, what):
        def found():
            with open(log, encoding="utf-8", errors="replace") as f:
                return re.search(pattern, f.read(), re.M)
        return wait_until(found, timeout, what)

    def admin(self, *args):
        r = subprocess.run([self.a.bin, "admin", "--data-dir", self.data_dir, *args],
                           capture_output=True, text=True, timeout=20)
        if r.returncode != 0:
            raise Failed(f"fleetlink admin {' '.join(args)}: {r.stderr.strip()}")
        return r.stdout.strip()

    # --- hub and robot
    def start_hub_and_robot(self):
        robot_token = self.admin("token", "robot", "robot1")
        self.op_token = self.admin("token", "operator", "viewers", "--group", "admin")
        _, self.hub_log = self.start("hub", None, [
            self.a.bin, "hub", "--listen", "0.0.0.0:0", "--data-dir", self.data_dir,
            "--viewer-ping-secs", str(PING_S), "--viewer-silence-secs", str(SILENCE_S)])
        m = self.wait_line(self.hub_log, r"^fleetlink hub listening on [0-9.]+:(\d+)$", 15, "hub start")
        self.port = int(m.group(1))
        cfg = os.path.join(self.a.tmp, "agent.yaml")
        with open(cfg, "w") as f:
            f.write(f"hub: ws://127.0.0.1:{self.port}/\nname: robot1\ntoken: {robot_token}\n"
                    "local_rosbridge: { listen: 127.0.0.1:0 }\n"
                    "sim: { point_cloud: { rate_hz: 5, points: 10000 } }\n")
        _, agent_log = self.start("agent", None, [self.a.bin, "agent", "--config", cfg])
        m = self.wait_line(agent_log, r"^  local rosbridge: (ws://[0-9.:]+/)$", 15, "agent start")
        self.local_url = m.group(1)
        wait_until(lambda: self.topic(TOPIC), 15, f"{TOPIC} listed by the hub")

    def url(self):
        return f"ws://{self.a.hub_ip}:{self.port}/?token={self.op_token}"

    def topic(self, name):
        """`name` in the hub's listing (GET /api/v1/topics), or None."""
        req = urllib.request.Request(f"http://127.0.0.1:{self.port}/api/v1/topics",
                                     headers={"Authorization": f"Bearer {self.op_token}"})
        try:
            with urllib.request.urlopen(req, timeout=2) as r:
                topics = json.load(r)["topics"]
        except (OSError, ValueError, KeyError):
            return None
        return next((t for t in topics if t["name"] == name), None)

    def viewers(self, t):
        """The topic's subscribers that are viewers (the robot's own link, which
        subscribes to its namespace, is listed too)."""
        return [s for s in t["subscribers"] if s.startswith(("/rosbridge_client_", "/foxglove_client_"))]

    def watched(self):
        t = self.topic(TOPIC)
        return t is not None and t["state"] == "flowing" and len(self.viewers(t)) == 1

    def idle(self):
        t = self.topic(TOPIC)
        return t is not None and t["state"] == "idle" and not self.viewers(t)

    def messages(self, log):
        with open(log, encoding="utf-8", errors="replace") as f:
            return [ln.split() for ln in f if ln.startswith("msg ")]

    # --- viewers
    def viewer(self, kind, name, ns, url):
        if kind == "foxglove":
            return self.start(name, ns, ["node", os.path.join(HERE, "foxglove_viewer.mjs"),
                                         "--url", url, "--topic", TOPIC, "--packages",
                                         self.a.node_packages,
                                         "--log", os.path.join(self.a.tmp, f"{name}.log")])[0], \
                os.path.join(self.a.tmp, f"{name}.log")
        log = os.path.join(self.a.tmp, f"{name}.log")
        p, _ = self.start(name, ns, [self.a.python, os.path.join(HERE, "viewer.py"), kind,
                                     "--url", url, "--topic", TOPIC, "--log", log])
        return p, log

    def watching(self, kind, name, clouds=3, within=20):
        """A viewer across the veth that gets the robot's cloud, with the hub listing it."""
        p, log = self.viewer(kind, name, self.a.viewer_ns, self.url())
        open(log, "a").close()
        wait_until(lambda: len(self.messages(log)) >= clouds, within, f"{name}: {clouds} clouds")
        wait_until(self.watched, 5, f"{TOPIC} flowing to one viewer ({self.topic(TOPIC)})")
        return p, log

    def time_to_idle(self, what):
        t0 = time.monotonic()
        wait_until(self.idle, SILENCE_S + 10, f"{what}: {TOPIC} idle with no subscriber", 0.02)
        took = time.monotonic() - t0
        print(f"  {what}: {TOPIC} idle, its viewer closed, {took:.2f} s later "
              f"(limit {SILENCE_S} s + 1 s)")
        if took > SILENCE_S + 1:
            raise Failed(f"{what}: the viewer was closed {took:.2f} s later, over "
                         f"{SILENCE_S + 1} s")

    # --- scenarios
    def cut(self):
        p, _ = self.watching("rosbridge", "cut")
        subprocess.run(["ip", "-n", self.a.viewer_ns, "link", "set", self.a.viewer_dev, "down"],
                       check=True, timeout=10)
        try:
            self.time_to_idle("link cut (veth down)")
        finally:
            subprocess.run(["ip", "-n", self.a.viewer_ns, "link", "set", self.a.viewer_dev, "up"],
                           check=True, timeout=10)
            self.stop(p)

    def frozen(self, kind):
        p, _ = self.watching(kind, f"frozen-{kind}")
        os.killpg(p.pid, signal.SIGSTOP)
        try:
            self.time_to_idle(f"{kind} viewer frozen (SIGSTOP)")
        finally:
            self.stop(p)

    def slow(self, minutes=2):
        dev = self.a.hub_dev
        subprocess.run(["tc", "qdisc", "replace", "dev", dev, "root", "tbf", "rate", "256kbit",
                        "burst", "16000", "latency", "100ms"], check=True, timeout=10)
        try:
            # What the hub logs from here on is this scenario's (the others' closes are
            # earlier in the same log).
            with open(self.hub_log, "rb") as f:
                hub_log_from = len(f.read())
            # A cloud is about 210 kB of JSON: some 7 s at this rate.
            p, log = self.watching("websockets", "slow", clouds=1, within=60)
            end = time.monotonic() + minutes * 60
            last_count, last_at = len(self.messages(log)), time.monotonic()
            while time.monotonic() < end:
                time.sleep(1)
                if p.poll() is not None:
                    raise Failed("slow viewer: its process ended")
                with open(log, encoding="utf-8", errors="replace") as f:
                    if "closed" in f.read():
                        raise Failed("slow viewer: its connection was closed")
                n = len(self.messages(log))
                if n > last_count:
                    last_count, last_at = n, time.monotonic()
                elif time.monotonic() - last_at > 30:
                    raise Failed("slow viewer: no message for 30 s")
            if not self.watched():
                raise Failed(f"slow viewer: the hub no longer lists it as {TOPIC}'s subscriber")
            with open(self.hub_log, "rb") as f:
                f.seek(hub_log_from)
                if b"no progress" in f.read():
                    raise Failed("slow viewer: the hub logged a client closed for no progress")
            delays = [float(m[2]) for m in self.messages(log)]
            print(f"  slow viewer (256 kbit/s): kept {minutes} min, {len(delays)} clouds, "
                  f"up to {max(delays):.1f} s late")
            if max(delays) <= SILENCE_S:
                raise Failed(f"slow viewer: its clouds were at most {max(delays):.1f} s late, "
                             f"not past the silence limit: the scenario proves nothing")
            self.stop(p)
        finally:
            subprocess.run(["tc", "qdisc", "del", "dev", dev, "root"], capture_output=True,
                           timeout=10)

    def local(self):
        """A frozen program on the agent's local listener (the agent's defaults: a ping
        every 10 s, closed after 30 s); a second local client asks rosapi."""
        from websockets.sync.client import connect

        def subscribers():
            with connect(self.local_url, open_timeout=5) as ws:
                ws.send(json.dumps({"op": "call_service", "service": "/rosapi/subscribers",
                                    "args": {"topic": "/points"}, "id": "s"}))
                while True:
                    op = json.loads(ws.recv(timeout=5))
                    if op.get("op") == "service_response":
                        # Local programs only (the uplink subscribes to every topic).
                        return len([n for n in op["values"]["subscribers"]
                                    if n.startswith("/rosbridge_client_")])

        log = os.path.join(self.a.tmp, "local.log")
        p, _ = self.start("local", None, [self.a.python, os.path.join(HERE, "viewer.py"),
                                          "rosbridge", "--url", self.local_url, "--topic",
                                          "/points", "--log", log])
        open(log, "a").close()
        wait_until(lambda: len(self.messages(log)) >= 3, 20, "local viewer: three clouds")
        if subscribers() != 1:
            raise Failed("local viewer: not listed as /points' subscriber")
        os.killpg(p.pid, signal.SIGSTOP)
        t0 = time.monotonic()
        try:
            wait_until(lambda: subscribers() == 0, 45, "local viewer released", 0.5)
        finally:
            self.stop(p)
        took = time.monotonic() - t0
        print(f"  local viewer frozen (SIGSTOP): released by the agent {took:.1f} s later "
              f"(limit 30 s + 1 s)")
        if took > 31.5:
            raise Failed(f"local viewer: released {took:.1f} s later, over 31 s")


def main():
    p = argparse.ArgumentParser()
    for a in ("viewer-ns", "hub-ip", "viewer-dev", "hub-dev", "bin", "python", "tmp",
              "node-packages"):
        p.add_argument(f"--{a}", required=True)
    p.add_argument("--scenarios", default="cut frozen foxglove slow local")
    a = p.parse_args()
    s = Suite(a)
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(1))
    try:
        s.start_hub_and_robot()
        for name in a.scenarios.split():
            print(f"scenario {name}")
            {"cut": s.cut, "frozen": lambda: s.frozen("rosbridge"),
             "foxglove": lambda: s.frozen("foxglove"), "slow": s.slow, "local": s.local}[name]()
        print("viewers suite: all scenarios passed")
    except Failed as e:
        print(f"FAIL: {e}", file=sys.stderr)
        sys.exit(1)
    finally:
        s.stop_all()


if __name__ == "__main__":
    main()

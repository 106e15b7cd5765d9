"""Plumbing of the bad-links suite: processes in the two network namespaces, the hub and
agent as the suite runs them, the link's knobs (down/up, tbf), and the peers' records.

Everything here is bounded: every wait has a deadline and names what it waited for when
it runs out; every process started is registered and stopped by `Procs.stop_all` (the
driver calls it on any exit; run.sh also kills whatever is left in its namespaces).
"""

import datetime
import json
import os
import re
import signal
import subprocess
import sys
import time
import urllib.error
import urllib.request
from dataclasses import dataclass, field

HERE = os.path.dirname(os.path.abspath(__file__))
PEERS = os.path.join(HERE, "peers.py")
CLOUD_RULES = """rules:
  - subject: any_robot
    names: "/cloud/.*"
    ops: [call_service]
"""


class Failed(Exception):
    """A harness step could not be done (not an outcome that was measured)."""


def now_ns():
    return time.time_ns()


def wait_until(pred, timeout, what, interval=0.05):
    deadline = time.monotonic() + timeout
    while True:
        v = pred()
        if v:
            return v
        if time.monotonic() >= deadline:
            raise Failed(f"{what}: not within {timeout:g} s")
        time.sleep(interval)


@dataclass
class Net:
    """The topology run.sh made: hub namespace and robot namespace joined by a veth pair."""
    hub_ns: str
    robot_ns: str
    hub_ip: str
    robot_dev: str
    hub_dev: str = "vh"

    def run(self, ns, *argv):
        r = subprocess.run(["ip", "netns", "exec", ns, *argv], capture_output=True, text=True, timeout=10)
        if r.returncode != 0:
            raise Failed(f"{' '.join(argv)} in {ns}: {r.stderr.strip()}")
        return r.stdout

    def link(self, up):
        self.run(self.robot_ns, "ip", "link", "set", self.robot_dev, "up" if up else "down")

    def far_link(self, up):
        """The hub's end of the veth pair: down, the robot's interface stays up (with no
        carrier) and its packets vanish, as when a robot's radio stays associated but
        the path beyond it is dead; connects hang instead of failing at once.

        The robot first gets a permanent neighbour entry for the hub, as it keeps its
        gateway's while associated: without it the robot's kernel would find the hub
        unresolvable (ARP) and fail connects with "no route to host" after 3 s, and on
        the way back every sender would wait for the same ARP answer; that is a LAN's
        behaviour, not a radio path's."""
        if not up:
            mac = re.search(r"link/ether ([0-9a-f:]{17})",
                            self.run(self.hub_ns, "ip", "link", "show", self.hub_dev)).group(1)
            self.run(self.robot_ns, "ip", "neigh", "replace", self.hub_ip, "lladdr", mac,
                     "dev", self.robot_dev, "nud", "permanent")
        self.run(self.hub_ns, "ip", "link", "set", self.hub_dev, "up" if up else "down")

    def robot_tx_bytes(self):
        """Bytes the robot's interface has sent (the uplink's cost, headers included)."""
        return int(self.run(self.robot_ns, "cat", f"/sys/class/net/{self.robot_dev}/statistics/tx_bytes"))

    def robot_rx_bytes(self):
        """Bytes the robot's interface has received (the downlink's cost, headers included)."""
        return int(self.run(self.robot_ns, "cat", f"/sys/class/net/{self.robot_dev}/statistics/rx_bytes"))

    def shape(self, mbit):
        """Robot egress (the uplink) through a token bucket; None removes it.

        burst: 10 ms of the rate, at least 16 kB (so the kernel's timer granularity is not
        what limits the rate); latency 100 ms: the bucket's queue holds at most 100 ms of
        traffic, a moderate buffer like a cellular modem's (a deeper one only makes a
        sender that overfills it look worse)."""
        if mbit is None:
            subprocess.run(["ip", "netns", "exec", self.robot_ns, "tc", "qdisc", "del", "dev",
                            self.robot_dev, "root"], capture_output=True, timeout=10)
            return
        burst = max(int(mbit * 1e6 / 8 * 0.010), 16000)
        self.run(self.robot_ns, "tc", "qdisc", "replace", "dev", self.robot_dev, "root", "tbf",
                 "rate", f"{mbit}mbit", "burst", str(burst), "latency", "100ms")


@dataclass
class Proc:
    name: str
    popen: subprocess.Popen
    log: str

    def alive(self):
        return self.popen.poll() is None

    def text(self):
        try:
            with open(self.log, encoding="utf-8", errors="replace") as f:
                return f.read()
        except FileNotFoundError:
            return ""

    def kill9(self):
        # `ip netns exec` execs the command, so this pid is the command itself.
        if self.alive():
            self.popen.send_signal(signal.SIGKILL)
        self.popen.wait(timeout=5)


@dataclass
class Procs:
    tmp: str
    running: list = field(default_factory=list)
    counter: int = 0

    def start(self, name, ns, argv):
        self.counter += 1
        log = os.path.join(self.tmp, f"{self.counter:02d}-{name}.out")
        f = open(log, "w")
        p = subprocess.Popen(["ip", "netns", "exec", ns, *argv], stdout=f, stderr=subprocess.STDOUT,
                             stdin=subprocess.DEVNULL)
        f.close()
        proc = Proc(name, p, log)
        self.running.append(proc)
        return proc

    def stop(self, proc, grace=3.0):
        if proc.alive():
            proc.popen.send_signal(signal.SIGTERM)
            try:
                proc.popen.wait(timeout=grace)
            except subprocess.TimeoutExpired:
                proc.popen.kill()
                proc.popen.wait(timeout=5)
        if proc in self.running:
            self.running.remove(proc)

    def stop_all(self):
        for p in list(self.running):
            try:
                self.stop(p, grace=2.0)
            except Exception as e:  # keep stopping the others
                print(f"warning: stopping {p.name}: {e}", file=sys.stderr)

    def wait_line(self, proc, pattern, timeout, what):
        rx = re.compile(pattern, re.M)

        def found():
            m = rx.search(proc.text())
            if m:
                return m
            if not proc.alive():
                tail = "\n".join(proc.text().splitlines()[-15:])
                raise Failed(f"{what}: {proc.name} exited ({proc.popen.returncode}):\n{tail}")
            return None
        return wait_until(found, timeout, what)


@dataclass
class Fleet:
    """The hub, one agent (robot1) and the peers, as the scenarios start and kill them."""
    net: Net
    procs: Procs
    bin: str
    python: str
    tmp: str
    robot_token: str = ""
    op_token: str = ""
    hub: Proc = None
    hub_port: int = 0
    agent: Proc = None
    local_url: str = ""
    outbox: bool = False
    outbox_dir: str = ""
    state_dir: str = ""
    agents: int = 0
    data_dir: str = ""

    def admin(self, *args, stdin=None):
        r = subprocess.run([self.bin, "admin", "--data-dir", self.data_dir, *args], input=stdin,
                           capture_output=True, text=True, timeout=20)
        if r.returncode != 0:
            raise Failed(f"fleetlink admin {' '.join(args)}: {r.stderr.strip()}")
        return r.stdout.strip()

    def mint_tokens(self):
        self.data_dir = os.path.join(self.tmp, "hub-data")
        self.robot_token = self.admin("token", "robot", "robot1")
        self.op_token = self.admin("token", "operator", "links", "--group", "admin")
        # Robots may call the fleet's services under /cloud/ (what a deployment writes in
        # its rules file; as the calls suite does). Only the calls scenario uses them.
        self.admin("rules", "import", "-", stdin=CLOUD_RULES)

    # --- hub
    def start_hub(self, extra=()):
        """Listens on every address of the hub namespace (veth for the agent, loopback for
        the subscriber). Port 0 the first time; a restart reuses the port it got."""
        self.hub = self.procs.start("hub", self.net.hub_ns, [
            self.bin, "hub", "--listen", f"0.0.0.0:{self.hub_port}", "--data-dir", self.data_dir, *extra])
        m = self.procs.wait_line(self.hub, r"^fleetlink hub listening on [0-9.]+:(\d+)$", 15, "hub start")
        self.hub_port = int(m.group(1))
        return self.hub

    def metrics(self):
        """The hub's /metrics text, or None if it did not answer within 5 s."""
        req = urllib.request.Request(f"http://127.0.0.1:{self.hub_port}/metrics",
                                     headers={"Authorization": f"Bearer {self.op_token}"})
        try:
            with urllib.request.urlopen(req, timeout=5) as r:
                return r.read().decode()
        except OSError:
            return None

    def hub_drops(self, topic):
        """Messages of `topic` the hub's subscriber queues lost (its /metrics), or None."""
        text = self.metrics()
        if text is None:
            return None
        return sum(float(ln.rsplit(" ", 1)[1]) for ln in text.splitlines()
                   if ln.startswith("fleetlink_topic_drops") and f'topic="{topic}"' in ln)

    def robot_status(self, name="robot1"):
        """The hub's listing of `name` (GET /api/v1/robots: "online", "connected_at_ms",
        ...), None if it is not listed or the hub did not answer within 2 s."""
        req = urllib.request.Request(f"http://127.0.0.1:{self.hub_port}/api/v1/robots",
                                     headers={"Authorization": f"Bearer {self.op_token}"})
        try:
            with urllib.request.urlopen(req, timeout=2) as r:
                robots = json.load(r)["robots"]
        except (OSError, ValueError, KeyError):
            return None
        return next((x for x in robots if x.get("name") == name), None)

    def hub_topics(self):
        """The hub's topic listing (GET /api/v1/topics), [] if it did not answer in 2 s."""
        req = urllib.request.Request(f"http://127.0.0.1:{self.hub_port}/api/v1/topics",
                                     headers={"Authorization": f"Bearer {self.op_token}"})
        try:
            with urllib.request.urlopen(req, timeout=2) as r:
                return json.load(r)["topics"]
        except (OSError, ValueError, KeyError):
            return []

    def api(self, method, path, body=None, timeout=5):
        """(status, JSON) of a call of the hub's API as the operator."""
        data = None if body is None else json.dumps(body).encode()
        req = urllib.request.Request(f"http://127.0.0.1:{self.hub_port}{path}", data=data, method=method,
                                     headers={"Authorization": f"Bearer {self.op_token}",
                                              "Content-Type": "application/json"})
        try:
            with urllib.request.urlopen(req, timeout=timeout) as r:
                return r.status, json.load(r)
        except urllib.error.HTTPError as e:
            return e.code, json.loads(e.read() or b"{}")

    def hub_url(self, across_link=False):
        """From the hub namespace (loopback), or across the veth from the robot's."""
        host = self.net.hub_ip if across_link else "127.0.0.1"
        return f"ws://{host}:{self.hub_port}/?token={self.op_token}"

    # --- agent
    def agent_yaml(self, sim, topics=None, link=None, extra=(), heartbeat_ms=1000):
        """`sim`: False (no simulator), True (the point cloud only) or the `sim:` map as
        YAML text. `topics`: more entries of the `topics:` map, local name -> QoS as YAML
        text (`{ compression: none }`). `link`: the `link:` map as YAML text
        (`{ budget: { max_kbps: 400 } }`), None for none. `extra`: more top-level lines
        (`blackbox: {...}`)."""
        lines = [
            f"hub: ws://{self.net.hub_ip}:{self.hub_port}/",
            "name: robot1",
            f"token: {self.robot_token}",
            f"heartbeat_ms: {heartbeat_ms}",
            "local_rosbridge: { listen: 127.0.0.1:0 }",
        ]
        # Its own kept runtime changes (none unless a scenario makes some), never the
        # user's: a change kept by an earlier robot1 would apply here too.
        lines.append(f"runtime_file: {self.state_dir}/runtime.json")
        if self.outbox:
            lines.append(f"outbox: {{ dir: {self.outbox_dir}, max_mb: 64, fsync: batch }}")
        lines += [
            "topics:",
            "  /probe/reliable: { no_drop: true }",
            "  /probe/fast: { priority: 10, policy: latest }",
        ]
        lines += [f"  {name}: {qos}" for name, qos in (topics or {}).items()]
        if link is not None:
            lines.append(f"link: {link}")
        lines += list(extra)
        if isinstance(sim, str):
            lines.append(f"sim: {sim}")
        elif sim:
            lines.append("sim: { point_cloud: { rate_hz: 5, points: 13300 } }")
        return "\n".join(lines) + "\n"

    def start_agent(self, sim=False, same_outbox=False, topics=None, link=None, extra=(),
                    heartbeat_ms=1000):
        """A fresh outbox and state directory per agent, unless this is a restart of the
        last one (a fresh agent must not replay an earlier scenario's leftovers). `topics`, `link`,
        `extra`, `heartbeat_ms`: see `agent_yaml`."""
        if not same_outbox:
            self.agents += 1
            self.outbox_dir = os.path.join(self.tmp, f"outbox-{self.agents}")
            self.state_dir = os.path.join(self.tmp, f"state-{self.agents}")
        path = os.path.join(self.tmp, "agent-sim.yaml" if sim else "agent.yaml")
        with open(path, "w") as f:
            f.write(self.agent_yaml(sim, topics, link, extra, heartbeat_ms))
        self.agent = self.procs.start("agent", self.net.robot_ns, [self.bin, "agent", "--config", path])
        m = self.procs.wait_line(self.agent, r"^  local rosbridge: (ws://[0-9.:]+/)$", 15, "agent start")
        self.local_url = m.group(1)
        return self.agent

    def stop_agent(self):
        if self.agent:
            self.procs.stop(self.agent)
            self.agent = None

    # --- peers
    def peer(self, kind, ns, log, *args):
        return self.procs.start(kind, ns, [self.python, PEERS, kind, "--log", log, *args])

    def start_sub(self, tag):
        log = os.path.join(self.tmp, f"{tag}.sub")
        p = self.peer("sub", self.net.hub_ns, log, "--url", self.hub_url())
        self.procs.wait_line(p, r"^sub: subscribed", 15, "subscriber start")
        return p, log

    def start_points(self, tag):
        log = os.path.join(self.tmp, f"{tag}.points")
        p = self.peer("points", self.net.hub_ns, log, "--url", self.hub_url())
        self.procs.wait_line(p, r"^points: subscribed", 15, "point cloud subscriber start")
        return p, log

    def start_direct(self, tag, hz=50):
        """A rosbridge client on the robot that talks to the hub itself (no agent)."""
        log = os.path.join(self.tmp, f"{tag}.direct")
        p = self.peer("direct", self.net.robot_ns, log, "--url", self.hub_url(across_link=True),
                      "--hz", str(hz))
        self.procs.wait_line(p, r"^direct: connected", 15, "direct rosbridge client start")
        return p, log

    def start_caller(self, tag, robot_side, service, args="{}", period=0.5, timeout=10.0):
        """A program calling `service` every `period` s: on the robot at the agent's local
        listener (robot_side), else an operator at the hub (its token)."""
        log = os.path.join(self.tmp, f"{tag}.calls")
        ns, url = (self.net.robot_ns, self.local_url) if robot_side else (self.net.hub_ns, self.hub_url())
        p = self.peer("caller", ns, log, "--url", url, "--service", service, "--args", args,
                      "--period", str(period), "--timeout", str(timeout))
        self.procs.wait_line(p, r"^caller: connected", 15, f"caller of {service} start")
        return p, log

    def start_provider(self, tag, service):
        """A fleet service at the hub (std_srvs/srv/SetBool), offered by an operator."""
        log = os.path.join(self.tmp, f"{tag}.provider")
        p = self.peer("provider", self.net.hub_ns, log, "--url", self.hub_url(), "--service", service)
        self.procs.wait_line(p, r"^provider: advertised", 15, f"provider of {service} start")
        return p, log

    def start_sensors(self, tag, hz):
        """The robot's lidar and camera drivers (peers.py sensors) on the agent's local
        listener: /cloud and /camera/compressed at `hz`, as rosbridge CBOR."""
        log = os.path.join(self.tmp, f"{tag}.sensors")
        p = self.peer("sensors", self.net.robot_ns, log, "--url", self.local_url, "--hz", str(hz))
        self.procs.wait_line(p, r"^sensors: connected", 15, "lidar and camera publisher start")
        return p, log

    def start_sensorsub(self, tag):
        """A roslibpy viewer at the hub of the robot's /cloud and /camera/compressed."""
        log = os.path.join(self.tmp, f"{tag}.sensorsub")
        p = self.peer("sensorsub", self.net.hub_ns, log, "--url", self.hub_url())
        self.procs.wait_line(p, r"^sensorsub: subscribed", 15, "lidar and camera subscriber start")
        return p, log

    def start_twist(self, tag, topic, hz):
        """A program on the robot publishing a motion command (geometry_msgs/msg/Twist) on
        `topic` at `hz` on the agent's local listener."""
        log = os.path.join(self.tmp, f"{tag}.twist")
        p = self.peer("twist", self.net.robot_ns, log, "--url", self.local_url, "--topic", topic,
                      "--hz", str(hz))
        self.procs.wait_line(p, r"^twist: connected", 15, f"{topic} publisher start")
        return p, log

    def start_watch(self, tag, topics):
        """A roslibpy viewer at the hub of `topics`: {short: (hub name, ROS type)}."""
        log = os.path.join(self.tmp, f"{tag}.watch")
        args = []
        for short, (name, ros_type) in topics.items():
            args += ["--topic", f"{short}={name}={ros_type}"]
        p = self.peer("watch", self.net.hub_ns, log, "--url", self.hub_url(), *args)
        self.procs.wait_line(p, r"^watch: subscribed", 15, "hub viewer start")
        return p, log

    def start_pub(self, tag, fast_hz=50, reliable_hz=50, start_seq=1, count=0, duration=0):
        log = os.path.join(self.tmp, f"{tag}.pub")
        p = self.peer("pub", self.net.robot_ns, log, "--url", self.local_url,
                      "--fast-hz", str(fast_hz), "--reliable-hz", str(reliable_hz),
                      "--start-seq", str(start_seq), "--count", str(count), "--duration", str(duration))
        self.procs.wait_line(p, r"^pub: connected", 15, "publisher start")
        return p, log


# --- records written by the peers

@dataclass
class Call:
    n: int
    sent: int                # ns
    answer: int = None       # ns, None: not answered (yet)
    ok: bool = None
    text: str = ""           # the values (ok) or the error text
    gave_up: int = None      # ns the caller stopped waiting (its deadline + grace), or None


def read_calls(path):
    """A caller's records (peers.py caller) -> [Call] in call order."""
    calls = {}
    try:
        with open(path, encoding="ascii", errors="replace") as f:
            lines = f.read().splitlines()
    except FileNotFoundError:
        return []
    for ln in lines:
        p = ln.split(" ", 3)
        if len(p) < 3 or ln.startswith("#"):
            continue
        try:
            n, t = int(p[1]), int(p[2])
        except ValueError:
            continue  # a half-written last line
        if p[0] == "call":
            calls[n] = Call(n, t)
        elif p[0] in ("ok", "err") and n in calls and calls[n].answer is None:
            c = calls[n]
            c.answer, c.ok, c.text = t, p[0] == "ok", p[3] if len(p) > 3 else ""
        elif p[0] == "timeout" and n in calls:
            calls[n].gave_up = t
    return [calls[k] for k in sorted(calls)]


def log_time_ns(line):
    """The timestamp fleetlink's log puts first on a line (RFC 3339, UTC), in ns; None if
    the line has none."""
    m = re.match(r"^(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d)(?:\.(\d+))?Z\s", line)
    if not m:
        return None
    t = datetime.datetime.fromisoformat(m.group(1)).replace(tzinfo=datetime.timezone.utc)
    frac = (m.group(2) or "0")[:9].ljust(9, "0")
    return int(t.timestamp()) * 1_000_000_000 + int(frac)


@dataclass
class Rx:
    topic: str
    recv: int  # ns
    seq: int
    sent: int  # ns

    @property
    def latency_ms(self):
        return (self.recv - self.sent) / 1e6


def read_lines(path):
    try:
        with open(path, encoding="ascii", errors="replace") as f:
            lines = f.read().splitlines()
    except FileNotFoundError:
        return []
    # The last line may be half-written while the peer runs.
    return [ln.split() for ln in lines if ln and not ln.startswith("#")]


def read_sub(path):
    out = []
    for p in read_lines(path):
        if len(p) == 4 and p[0] in ("fast", "reliable", "direct"):
            out.append(Rx(p[0], int(p[1]), int(p[2]), int(p[3])))
    return out


def read_pub(path):
    """-> {short topic: [(seq, sent ns)]}"""
    out = {"fast": [], "reliable": [], "direct": []}
    for p in read_lines(path):
        if len(p) == 3 and p[0].startswith("/probe/"):
            out[p[0][len("/probe/"):]].append((int(p[1]), int(p[2])))
    return out


def read_twist(path):
    """A twist publisher's log -> [(seq, sent ns)]."""
    out = []
    for p in read_lines(path):
        if len(p) == 3 and p[0] == "twist":
            try:
                out.append((int(p[1]), int(p[2])))
            except ValueError:
                continue  # a half-written last line
    return out


def read_watch(path):
    """A hub viewer's log (peers.py watch) -> {short: [(recv ns, id or None)]}."""
    out = {}
    for p in read_lines(path):
        if len(p) != 3:
            continue
        try:
            rec = (int(p[1]), None if p[2] == "-" else int(p[2]))
        except ValueError:
            continue  # a half-written last line
        out.setdefault(p[0], []).append(rec)
    return out


def read_points(path):
    """-> [(recv ns, raw bytes)]"""
    return [(int(p[1]), int(p[2])) for p in read_lines(path) if len(p) == 3 and p[0] == "points"]


@dataclass
class Blob:
    """One sensor message's data as a peer logged it (peers.py sensors / sensorsub)."""
    topic: str        # "cloud" or "jpeg"
    stamp: int        # header.stamp, ns: the message's identity in both logs
    sha256: str       # of the `data` bytes
    size: int         # bytes of `data`
    zstd1: int = None # the publisher's: `data` compressed by zstd at level 1 (None: no zstd module)


def read_blobs(path):
    """A sensors or sensorsub log -> {topic: [Blob]} in log order."""
    out = {"cloud": [], "jpeg": []}
    for p in read_lines(path):
        if len(p) in (5, 6) and p[0] in out:
            try:
                out[p[0]].append(Blob(p[0], int(p[2]), p[3], int(p[4]),
                                      int(p[5]) if len(p) == 6 and p[5] != "-" else None))
            except ValueError:
                continue  # a half-written last line
    return out


def percentile(xs, q):
    if not xs:
        return float("nan")
    s = sorted(xs)
    k = min(len(s) - 1, max(0, int(round(q / 100 * (len(s) - 1)))))
    return s[k]


def reliable_audit(sent_seqs, rx):
    """Exactly once, in order, none missing: compares what was published with what the
    subscriber got (`rx`: reliable records in arrival order)."""
    got = [r.seq for r in rx]
    seen, dups = set(), 0
    for s in got:
        if s in seen:
            dups += 1
        seen.add(s)
    missing = sorted(set(sent_seqs) - seen)
    reordered = sum(1 for a, b in zip(got, got[1:]) if b < a)
    return {"sent": len(sent_seqs), "received": len(got), "missing": len(missing),
            "duplicated": dups, "reordered": reordered,
            "first_missing": missing[:5]}

#!/usr/bin/env python3
"""ROS Gateway's frame experiment, the driver and its peers (scripts/bench-rosgw.sh makes
the network namespaces and runs `drive` inside the hub's).

  drive  starts the hub (hub namespace) and, per run, an agent, the camera publisher
         (robot namespace) and the subscriber (hub namespace); measures a window after a
         warm-up and prints the tables. Runs: every --variants x --rates, a fresh agent,
         publisher and subscriber each, the hub kept.
  pub    two camera drivers on the agent's local rosbridge listener, each on its own
         connection, speaking rosbridge v2 CBOR (binary `advertise` and `publish`):
         /camera/rgb (sensor_msgs/msg/Image rgb8 400 x 258, 309,600 bytes of data) and
         /camera/depth (16UC1 400 x 250, 200,000 bytes), at --hz each. The data is random
         (no codec can shrink it); header.stamp is the send time (both namespaces share
         the machine's clock). Logs "<rgb|depth> <seq> <stamp ns>" per publish.
  sub    one rosbridge client at the hub subscribed to /robot1/camera/rgb and
         /robot1/camera/depth with `compression: "cbor"` (binary frames, the data as a
         byte string: no base64); logs "<rgb|depth> <recv ns> <stamp ns> <bytes of data>".

The ideal (what the issue measures delivery against): min(source rate, link capacity /
frame size), on the two topics' bytes together: one frame of each is a *pair* of
PAIR_BYTES (each message as the link carries it, see frame_bytes), the capacity is tbf's
rate, 12.5 MB/s for 100 Mbit/s. tbf counts every byte of each Ethernet frame
(headers included), so the same rate also bounds TCP's payload at MSS / frame size =
1448 / 1514 of it (timestamps on, MTU 1500); the second table gives the share against
that ceiling too.
"""

import argparse
import json
import os
import random
import re
import signal
import struct
import subprocess
import sys
import threading
import time
import urllib.request

import cbor2
from websockets.sync.client import connect as ws_connect

ROBOT = "robot1"
# short name -> (local topic, encoding, width, height, bytes per pixel, frame_id)
CAMERAS = {
    "rgb": ("/camera/rgb", "rgb8", 400, 258, 3, "camera_rgb"),
    "depth": ("/camera/depth", "16UC1", 400, 250, 2, "camera_depth"),
}
IMAGE = "sensor_msgs/msg/Image"
POOL = 16  # distinct random frames per camera, sent in turn
MSS, WIRE_PACKET = 1448, 1514  # TCP payload per full packet; its bytes as tbf counts them
CONNECT_TIMEOUT = 10.0

stop = threading.Event()


def on_term(_sig, _frame):
    stop.set()


def image_message(short, stamp_ns, data):
    _, enc, w, h, bpp, fid = CAMERAS[short]
    return {"header": {"stamp": {"sec": stamp_ns // 1_000_000_000, "nanosec": stamp_ns % 1_000_000_000},
                       "frame_id": fid},
            "height": h, "width": w, "encoding": enc, "is_bigendian": 0, "step": w * bpp, "data": data}


def frame_bytes(short):
    """A camera message's size as the link carries it: the agent forwards a rosbridge
    client's message in the encoding it was published in, here CBOR (the hub counts the
    same bytes as the topic's payload). Its stamp's nanoseconds take 5 bytes in all but
    0.007 % of messages (those under 65,536 ns into a second take fewer)."""
    _, enc, w, h, bpp, fid = CAMERAS[short]
    return len(cbor2.dumps(image_message(short, 1_800_000_000_123_456_789, bytes(w * h * bpp))))


PAIR_BYTES = sum(frame_bytes(s) for s in CAMERAS)


def open_log(path):
    return open(path, "a", buffering=1, encoding="ascii")  # line-buffered


# --- pub

def run_pub(a):
    log_lock = threading.Lock()
    log = open_log(a.log)
    conns = []
    for short, (name, *_rest) in CAMERAS.items():  # one connection per camera driver
        ws = ws_connect(a.url, open_timeout=CONNECT_TIMEOUT, close_timeout=1, max_size=64 << 20,
                        compression=None)
        ws.send(cbor2.dumps({"op": "advertise", "topic": name, "type": IMAGE}))
        conns.append((ws, short))
    print("pub: connected", flush=True)

    def camera(ws, short):
        name, _enc, w, h, bpp, _fid = CAMERAS[short]
        rnd = random.Random(short)
        pool = [rnd.randbytes(w * h * bpp) for _ in range(POOL)]
        period, seq, next_at = 1.0 / a.hz, 0, time.monotonic()
        while not stop.is_set():
            seq += 1
            stamp = time.time_ns()
            msg = image_message(short, stamp, pool[seq % POOL])
            try:
                ws.send(cbor2.dumps({"op": "publish", "topic": name, "msg": msg}))
            except Exception as e:  # the agent went away: the run is over
                print(f"pub: {name}: {type(e).__name__}: {e}", flush=True)
                return
            with log_lock:
                log.write(f"{short} {seq} {stamp}\n")
            while True:  # a refused publish says why in a status op
                try:
                    reply = ws.recv(timeout=0)
                except TimeoutError:
                    break
                text = reply if isinstance(reply, str) else json.dumps(cbor2.loads(reply), default=repr)
                print(f"pub: {name}: {' '.join(text.split())[:300]}", flush=True)
            next_at += period
            delay = next_at - time.monotonic()
            if delay > 0:
                stop.wait(delay)
            else:
                next_at = time.monotonic()  # fell behind: no burst to catch up

    threads = [threading.Thread(target=camera, args=c, daemon=True) for c in conns]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for ws, _ in conns:
        ws.close()


# --- sub

def run_sub(a):
    log = open_log(a.log)
    shorts = {f"/{ROBOT}{name}": short for short, (name, *_r) in CAMERAS.items()}
    with ws_connect(a.url, additional_headers={"Authorization": f"Bearer {a.token}"},
                    open_timeout=CONNECT_TIMEOUT, close_timeout=1, max_size=64 << 20,
                    compression=None) as ws:
        for topic in shorts:
            ws.send(json.dumps({"op": "subscribe", "id": f"rosgw:{topic}", "topic": topic,
                                "type": IMAGE, "compression": "cbor"}))
        print("sub: subscribed", flush=True)
        while not stop.is_set():
            try:
                frame = ws.recv(timeout=0.2)
            except TimeoutError:
                continue
            recv = time.time_ns()
            if isinstance(frame, str):
                log.write(f"# {' '.join(frame.split())[:300]}\n")
                continue
            m = cbor2.loads(frame)
            if m.get("op") != "publish" or m.get("topic") not in shorts:
                continue
            st = m["msg"]["header"]["stamp"]
            log.write(f"{shorts[m['topic']]} {recv} {st['sec'] * 1_000_000_000 + st['nanosec']} "
                      f"{len(m['msg']['data'])}\n")


# --- drive

class Failed(Exception):
    """A setup step could not be done (a measurement that came out low is not this)."""


def wait_until(pred, timeout, what, interval=0.05):
    deadline = time.monotonic() + timeout
    while True:
        v = pred()
        if v:
            return v
        if time.monotonic() >= deadline:
            raise Failed(f"{what}: not within {timeout:g} s")
        time.sleep(interval)


class Procs:
    """Every process the driver starts, each with its log; stop_all on any exit."""

    def __init__(self, tmp):
        self.tmp, self.running, self.n = tmp, [], 0

    def start(self, name, ns, argv):
        self.n += 1
        log = os.path.join(self.tmp, f"{self.n:02d}-{name}.out")
        with open(log, "w") as f:
            # `ip netns exec` execs the command: this pid is the command's own.
            p = subprocess.Popen(["ip", "netns", "exec", ns, *argv], stdout=f, stderr=subprocess.STDOUT,
                                 stdin=subprocess.DEVNULL)
        p.name, p.log = name, log
        self.running.append(p)
        return p

    def stop(self, p, grace=3.0):
        if p.poll() is None:
            p.send_signal(signal.SIGTERM)
            try:
                p.wait(timeout=grace)
            except subprocess.TimeoutExpired:
                p.kill()
                p.wait(timeout=5)
        if p in self.running:
            self.running.remove(p)

    def stop_all(self):
        for p in reversed(list(self.running)):
            try:
                self.stop(p, grace=2.0)
            except Exception as e:  # keep stopping the others
                print(f"warning: stopping {p.name}: {e}", file=sys.stderr)

    @staticmethod
    def text(p):
        with open(p.log, encoding="utf-8", errors="replace") as f:
            return f.read()

    def wait_line(self, p, pattern, timeout, what):
        rx = re.compile(pattern, re.M)

        def found():
            m = rx.search(self.text(p))
            if m:
                return m
            if p.poll() is not None:
                tail = "\n".join(self.text(p).splitlines()[-15:])
                raise Failed(f"{what}: {p.name} exited ({p.returncode}):\n{tail}")
            return None
        return wait_until(found, timeout, what)


def admin(a, data_dir, *args):
    r = subprocess.run([a.bin, "admin", "--data-dir", data_dir, *args], capture_output=True, text=True,
                       timeout=20)
    if r.returncode != 0:
        raise Failed(f"fleetlink admin {' '.join(args)}: {r.stderr.strip()}")
    return r.stdout.strip()


def cpu_ticks(pid):
    """utime + stime of a process, all its threads, in clock ticks; None once it is gone."""
    try:
        with open(f"/proc/{pid}/stat") as f:
            fields = f.read().rsplit(")", 1)[1].split()
    except OSError:
        return None
    return int(fields[11]) + int(fields[12])  # fields 14 and 15 of proc(5)


def machine_ticks():
    """(busy, total) ticks of all CPUs from /proc/stat (idle and iowait are not busy)."""
    with open("/proc/stat") as f:
        v = [int(x) for x in f.readline().split()[1:9]]
    return sum(v) - v[3] - v[4], sum(v)


def tx_counters(a):
    """Bytes and packets the robot's interface sent (its uplink, every header included)."""
    out = subprocess.run(["ip", "-n", a.robot_ns, "-s", "-j", "link", "show", a.robot_dev],
                         capture_output=True, text=True, timeout=10, check=True).stdout
    tx = json.loads(out)[0]["stats64"]["tx"]
    return tx["bytes"], tx["packets"]


def hub_get(port, token, path):
    req = urllib.request.Request(f"http://127.0.0.1:{port}{path}", headers={"Authorization": f"Bearer {token}"})
    with urllib.request.urlopen(req, timeout=5) as r:
        return r.read().decode()


def hub_topics(port, token):
    """{short: (messages, payload bytes)} the hub received of the two topics."""
    listed = {t["name"]: t for t in json.loads(hub_get(port, token, "/api/v1/topics"))["topics"]}
    out = {}
    for short, (name, *_r) in CAMERAS.items():
        t = listed.get(f"/{ROBOT}{name}", {})
        out[short] = (t.get("messages") or 0, t.get("bytes") or 0)
    return out


def hub_drops(port, token):
    """{short: messages the hub's subscriber queues lost} (its /metrics)."""
    text = hub_get(port, token, "/metrics")
    out = {}
    for short, (name, *_r) in CAMERAS.items():
        out[short] = sum(float(ln.rsplit(" ", 1)[1]) for ln in text.splitlines()
                         if ln.startswith("fleetlink_topic_drops") and f'topic="/{ROBOT}{name}"' in ln)
    return out


def snapshot(a, port, token, pids):
    return {"t": time.time_ns(), "mono": time.monotonic(), "cpu": {k: cpu_ticks(p) for k, p in pids.items()},
            "machine": machine_ticks(), "tx": tx_counters(a), "topics": hub_topics(port, token),
            "drops": hub_drops(port, token)}


def others_busy():
    """What else is running that spoils a throughput figure on two cores."""
    found = []
    r = subprocess.run(["pgrep", "-f", "interop/links/run.sh"], capture_output=True, text=True)
    if r.stdout.strip():
        found.append("the bad-links suite (tests/interop/links/run.sh)")
    for name in ("rustc", "cargo"):
        r = subprocess.run(["pgrep", "-x", name], capture_output=True, text=True)
        if r.stdout.strip():
            found.append(name)
    return found


def machine_busy(secs=2.0):
    """Percent of one CPU the whole machine was busy over the next `secs`."""
    b0, t0 = machine_ticks()
    time.sleep(secs)
    b1, t1 = machine_ticks()
    return (b1 - b0) / (t1 - t0) * 100 * os.cpu_count() if t1 > t0 else 0.0


def wait_quiet(a):
    """Before every run: the bad-links suite must be gone (it shares the two cores; waited
    for up to --wait-suite s); rustc/cargo, and anything else that keeps the machine busier
    than --quiet-pct of one CPU (the idle hub included), are waited for up to --wait-build
    s, then the run goes ahead and the table says what ran beside it."""
    t0, said = time.monotonic(), None
    while True:
        busy = others_busy()
        load = machine_busy()
        if load >= a.quiet_pct:
            busy.append(f"machine {load:.0f} % busy before the run")
        suite = any("bad-links" in b for b in busy)
        waited = time.monotonic() - t0
        if not busy or (not suite and waited >= a.wait_build):
            return busy
        if suite and waited >= a.wait_suite:
            raise Failed(f"the bad-links suite still runs after {a.wait_suite:g} s")
        names = [b for b in busy if not b.startswith("machine")]
        if said != names:
            print(f"   waiting: {', '.join(busy)}", flush=True)
            said = names


def read_rows(path, width):
    try:
        with open(path, encoding="ascii", errors="replace") as f:
            lines = f.read().splitlines()
    except FileNotFoundError:
        return []
    out = []
    for ln in lines:
        p = ln.split()
        if len(p) == width and p[0] in CAMERAS and not ln.startswith("#"):
            try:
                out.append((p[0], *map(int, p[1:])))
            except ValueError:
                continue  # a half-written last line
    return out


def percentile(xs, q):
    if not xs:
        return float("nan")
    s = sorted(xs)
    return s[min(len(s) - 1, max(0, int(round(q / 100 * (len(s) - 1)))))]


def agent_yaml(hub_ip, port, token, variant):
    qos = "{ compression: none }" if variant == "defaults" else f"{{ compression: none, policy: {variant} }}"
    lines = [f"hub: ws://{hub_ip}:{port}/", f"name: {ROBOT}", f"token: {token}",
             "local_rosbridge: { listen: 127.0.0.1:0 }", "topics:"]
    lines += [f"  {name}: {qos}" for name, *_r in CAMERAS.values()]
    return "\n".join(lines) + "\n"


def one_run(a, procs, hub, port, robot_token, op_token, variant, hz):
    busy_before = wait_quiet(a)
    tag = f"{variant}-{hz:g}hz"
    cfg = os.path.join(a.tmp, f"agent-{tag}.yaml")
    with open(cfg, "w") as f:
        f.write(agent_yaml(a.hub_ip, port, robot_token, variant))
    agent = procs.start(f"agent-{tag}", a.robot_ns, [a.bin, "agent", "--config", cfg])
    local = procs.wait_line(agent, r"^  local rosbridge: (ws://[0-9.:]+/)$", 15, "agent start").group(1)
    procs.wait_line(agent, r"connected to hub", 15, "agent's link to the hub")
    me = os.path.abspath(__file__)
    sub_log, pub_log = os.path.join(a.tmp, f"{tag}.sub"), os.path.join(a.tmp, f"{tag}.pub")
    sub = procs.start(f"sub-{tag}", a.hub_ns, [a.python, me, "sub", "--url", f"ws://127.0.0.1:{port}/",
                                               "--token", op_token, "--log", sub_log])
    procs.wait_line(sub, r"^sub: subscribed", 15, "subscriber start")
    pub = procs.start(f"pub-{tag}", a.robot_ns, [a.python, me, "pub", "--url", local, "--hz", str(hz),
                                                 "--log", pub_log])
    procs.wait_line(pub, r"^pub: connected", 15, "publisher start")
    try:
        wait_until(lambda: {r[0] for r in read_rows(sub_log, 4)} == set(CAMERAS), 20,
                   f"{tag}: both cameras at the hub's subscriber")
        time.sleep(a.warmup)
        for p in (hub, agent, pub, sub):
            if p.poll() is not None:
                raise Failed(f"{tag}: {p.name} exited ({p.returncode}) during the warm-up")
        pids = {"hub": hub.pid, "agent": agent.pid, "pub": pub.pid, "sub": sub.pid}
        s0 = snapshot(a, port, op_token, pids)
        with open("/proc/loadavg") as f:
            load0 = f.read().split()[0]
        time.sleep(a.seconds)
        s1 = snapshot(a, port, op_token, pids)
        busy_after = others_busy()
    finally:
        for p in (pub, sub, agent):
            procs.stop(p)
    return summarize(a, variant, hz, s0, s1, read_rows(pub_log, 3), read_rows(sub_log, 4),
                     load0, sorted(set(busy_before) | set(busy_after)))


def summarize(a, variant, hz, s0, s1, sent, got, load0, busy):
    t0, t1 = s0["t"], s1["t"]
    secs = (t1 - t0) / 1e9
    capacity = a.mbit * 1e6 / 8                                  # bytes/s, tbf's rate
    ideal = min(hz, capacity / PAIR_BYTES)                        # pairs/s = frames/s per camera
    ceiling = min(hz, capacity * MSS / WIRE_PACKET / PAIR_BYTES)  # the same on TCP's payload
    run = {"variant": variant, "hz": hz, "secs": secs, "ideal": ideal, "ceiling": ceiling,
           "load": load0, "busy": busy, "topics": {}}
    lat_all, delivered_bytes, published_bytes = [], 0, 0
    for short in CAMERAS:
        pubs = [r for r in sent if r[0] == short and t0 <= r[2] < t1]
        rx = [r for r in got if r[0] == short and t0 <= r[1] < t1]
        lat = [(r[1] - r[2]) / 1e6 for r in rx]
        lat_all += lat
        size = frame_bytes(short)
        delivered_bytes += len(rx) * size
        published_bytes += len(pubs) * size
        short_bytes = [r for r in rx if r[3] != CAMERAS[short][2] * CAMERAS[short][3] * CAMERAS[short][4]]
        hub_msgs = s1["topics"][short][0] - s0["topics"][short][0]
        hub_bytes = s1["topics"][short][1] - s0["topics"][short][1]
        run["topics"][short] = {
            "published": len(pubs) / secs, "delivered": len(rx) / secs, "at_hub": hub_msgs / secs,
            "hub_bytes_per_msg": hub_bytes / hub_msgs if hub_msgs else None,
            "hub_drops": s1["drops"][short] - s0["drops"][short], "wrong_size": len(short_bytes),
            "share": len(rx) / secs / ideal, "p50": percentile(lat, 50), "p99": percentile(lat, 99),
        }
    run["both"] = {"published": published_bytes / PAIR_BYTES / secs, "delivered": delivered_bytes / PAIR_BYTES / secs,
                   "share": delivered_bytes / PAIR_BYTES / secs / ideal,
                   "ceiling_share": delivered_bytes / PAIR_BYTES / secs / ceiling,
                   "p50": percentile(lat_all, 50), "p99": percentile(lat_all, 99),
                   "payload_bps": delivered_bytes / secs}
    (b0, k0), (b1, k1) = s0["tx"], s1["tx"]
    run["wire_bps"] = (b1 - b0) / secs
    run["wire_bytes_per_packet"] = (b1 - b0) / (k1 - k0) if k1 > k0 else None
    tick = os.sysconf("SC_CLK_TCK")
    run["cpu"] = {k: (None if s0["cpu"][k] is None or s1["cpu"][k] is None
                      else (s1["cpu"][k] - s0["cpu"][k]) / tick / secs * 100) for k in s0["cpu"]}
    busy_t, total_t = s1["machine"][0] - s0["machine"][0], s1["machine"][1] - s0["machine"][1]
    run["cpu"]["machine"] = busy_t / total_t * 100 * os.cpu_count() if total_t else None
    ours = [run["cpu"][k] for k in ("hub", "agent", "pub", "sub")]
    run["cpu"]["rest"] = (run["cpu"]["machine"] - sum(ours)
                          if run["cpu"]["machine"] is not None and None not in ours else None)
    return run


def pct(x):
    return "–" if x is None or x != x else f"{x * 100:.1f} %"


def ms(x):
    return "–" if x != x else f"{x:.0f} ms"


def tables(runs):
    out = ["| QoS | rate | topic | published/s | delivered/s | ideal/s | delivered share | latency p50 | latency p99 |",
           "|---|---|---|---|---|---|---|---|---|"]
    for r in runs:
        q = "defaults (afr, queue 8, priority 2)" if r["variant"] == "defaults" else f"policy: {r['variant']}"
        for short in CAMERAS:
            t = r["topics"][short]
            out.append(f"| {q} | {r['hz']:g} Hz | {CAMERAS[short][0]} | {t['published']:.1f} | {t['delivered']:.2f} | "
                       f"{r['ideal']:.2f} | {pct(t['share'])} | {ms(t['p50'])} | {ms(t['p99'])} |")
        b = r["both"]
        out.append(f"| {q} | {r['hz']:g} Hz | **both** (pairs) | {b['published']:.1f} | {b['delivered']:.2f} | "
                   f"{r['ideal']:.2f} | **{pct(b['share'])}** | {ms(b['p50'])} | {ms(b['p99'])} |")
    out += ["", "| QoS | rate | payload at the subscriber | robot's veth sent | bytes/packet | share of TCP payload ceiling | "
            "hub CPU | agent CPU | publisher CPU | subscriber CPU | rest of the machine | machine busy (of 200 %) | "
            "load (1 min) | also running |",
            "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in runs:
        c = r["cpu"]

        def cp(k):
            return "–" if c.get(k) is None else f"{c[k]:.0f} %"
        bpp = "–" if r["wire_bytes_per_packet"] is None else f"{r['wire_bytes_per_packet']:.0f}"
        out.append(f"| {r['variant']} | {r['hz']:g} Hz | {r['both']['payload_bps'] / 1e6:.2f} MB/s | "
                   f"{r['wire_bps'] / 1e6:.2f} MB/s | {bpp} | {pct(r['both']['ceiling_share'])} | {cp('hub')} | "
                   f"{cp('agent')} | {cp('pub')} | {cp('sub')} | {cp('rest')} | {cp('machine')} | {r['load']} | "
                   f"{', '.join(r['busy']) or '–'} |")
    out += ["", "| QoS | rate | topic | at the hub/s | hub subscriber-queue drops | bytes/message at the hub | "
            "data of the wrong size |", "|---|---|---|---|---|---|---|"]
    for r in runs:
        for short in CAMERAS:
            t = r["topics"][short]
            hb = "–" if t["hub_bytes_per_msg"] is None else f"{t['hub_bytes_per_msg']:,.0f}"
            out.append(f"| {r['variant']} | {r['hz']:g} Hz | {CAMERAS[short][0]} | {t['at_hub']:.2f} | "
                       f"{t['hub_drops']:.0f} | {hb} (computed {frame_bytes(short):,}) | {t['wrong_size']} |")
    return "\n".join(out)


def run_drive(a):
    procs = Procs(a.tmp)
    runs = []
    try:
        data_dir = os.path.join(a.tmp, "hub-data")
        robot_token = admin(a, data_dir, "token", "robot", ROBOT)
        op_token = admin(a, data_dir, "token", "operator", "rosgw", "--group", "admin")
        hub = procs.start("hub", a.hub_ns, [a.bin, "hub", "--listen", "0.0.0.0:0", "--data-dir", data_dir])
        port = int(procs.wait_line(hub, r"^fleetlink hub listening on [0-9.]+:(\d+)$", 15, "hub start").group(1))
        print(f"frames: /camera/rgb {frame_bytes('rgb'):,} B + /camera/depth {frame_bytes('depth'):,} B = "
              f"{PAIR_BYTES:,} B a pair (rosbridge CBOR, as the link carries them); link {a.mbit:g} Mbit/s = "
              f"{a.mbit * 1e6 / 8:,.0f} B/s -> {a.mbit * 1e6 / 8 / PAIR_BYTES:.2f} pairs/s "
              f"(TCP payload ceiling x {MSS}/{WIRE_PACKET}: {a.mbit * 1e6 / 8 * MSS / WIRE_PACKET / PAIR_BYTES:.2f})",
              flush=True)
        for variant in a.variants:
            for hz in a.rates:
                print(f"== {variant}, {hz:g} Hz: warm-up {a.warmup:g} s, window {a.seconds:g} s", flush=True)
                r = one_run(a, procs, hub, port, robot_token, op_token, variant, hz)
                runs.append(r)
                b = r["both"]
                print(f"   delivered {b['delivered']:.2f} pairs/s of {r['ideal']:.2f} ideal ({pct(b['share'])}), "
                      f"p50 {ms(b['p50'])}, p99 {ms(b['p99'])}; hub CPU {r['cpu']['hub']:.0f} %, "
                      f"agent CPU {r['cpu']['agent']:.0f} %", flush=True)
    finally:
        procs.stop_all()
    print()
    print(tables(runs))
    with open(os.path.join(a.tmp, "results.json"), "w") as f:
        json.dump(runs, f, indent=1)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sp = ap.add_subparsers(dest="cmd", required=True)
    p = sp.add_parser("pub")
    p.add_argument("--url", required=True, help="the agent's local listener")
    p.add_argument("--hz", type=float, required=True)
    p.add_argument("--log", required=True)
    p = sp.add_parser("sub")
    p.add_argument("--url", required=True, help="the hub")
    p.add_argument("--token", required=True)
    p.add_argument("--log", required=True)
    p = sp.add_parser("drive")
    p.add_argument("--hub-ns", required=True)
    p.add_argument("--robot-ns", required=True)
    p.add_argument("--hub-ip", required=True)
    p.add_argument("--robot-dev", required=True)
    p.add_argument("--bin", required=True)
    p.add_argument("--python", required=True)
    p.add_argument("--tmp", required=True)
    p.add_argument("--mbit", type=float, required=True, help="tbf's rate on the robot's uplink")
    p.add_argument("--rates", type=float, nargs="+", required=True)
    p.add_argument("--variants", nargs="+", required=True, help="defaults, or a policy (latest, ...)")
    p.add_argument("--seconds", type=float, required=True)
    p.add_argument("--warmup", type=float, required=True)
    p.add_argument("--wait-suite", type=float, default=3600)
    p.add_argument("--wait-build", type=float, default=600)
    p.add_argument("--quiet-pct", type=float, default=30, help="machine busy (%% of one CPU) that counts as quiet")
    a = ap.parse_args()
    signal.signal(signal.SIGTERM, on_term)
    signal.signal(signal.SIGINT, on_term)
    if a.cmd == "drive":
        # TERM from the script: leave through the `finally` that stops every process.
        signal.signal(signal.SIGTERM, lambda *_: sys.exit(143))
        signal.signal(signal.SIGINT, lambda *_: sys.exit(130))
        try:
            run_drive(a)
        except Failed as e:
            print(f"FAIL (setup): {e}", file=sys.stderr, flush=True)
            return 1
        return 0
    {"pub": run_pub, "sub": run_sub}[a.cmd](a)
    return 0


if __name__ == "__main__":
    sys.exit(main())

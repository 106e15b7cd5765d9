#!/usr/bin/env python3
"""Every seam attacked as a stranger would (tests/interop/security/run.sh sets the stage).

Each attack is one function named after it; each asserts the refusal it must meet and,
where a refusal could also come from something being broken, a control that the same path
works for someone allowed (so no check passes because nothing works). The attacks are the
rows of docs/security.md, "Attacks and the answers they meet".

Exits 0 when every attack met its answer, 1 naming those that did not.
"""

import argparse
import json
import subprocess
import sys
import time
import urllib.error
import urllib.request
from pathlib import Path

import zenoh
from mcap.reader import make_reader
from websockets.sync.client import connect as ws_connect

FLEET = "sec"
ROOT = f"fleetlink/{FLEET}"
TWIST = "geometry_msgs/msg/Twist"
JSON_ENC = 0  # fleetlink.v1's Encoding::Json
FORBIDDEN = 4  # CallStatus::Forbidden


class CheckFailed(Exception):
    pass


def check(cond, why):
    if not cond:
        raise CheckFailed(why)


def wait(fn, what, timeout=10.0, every=0.1):
    end = time.monotonic() + timeout
    last = None
    while time.monotonic() < end:
        last = fn()
        if last:
            return last
        time.sleep(every)
    raise CheckFailed(f"{what}: not within {timeout:.0f} s (last: {str(last)[:300]})")


class Hub:
    def __init__(self, spec):
        name, rest = spec.split("=", 1)
        self.name = name
        self.addr, self.root, self.alice, self.nobody = rest.split(",")

    def api(self, path, token=None, body=None, method=None):
        data = None if body is None else json.dumps(body).encode()
        req = urllib.request.Request(
            f"http://{self.addr}{path}", data=data, method=method,
            headers={"Authorization": f"Bearer {token or self.root}",
                     "Content-Type": "application/json"})
        try:
            with urllib.request.urlopen(req, timeout=10) as r:
                raw = r.read()
                return r.status, (json.loads(raw) if raw[:1] in (b"{", b"[") else raw)
        except urllib.error.HTTPError as e:
            return e.code, e.read().decode(errors="replace")

    def audit(self, **query):
        q = "&".join(f"{k}={urllib.request.quote(str(v))}" for k, v in query.items())
        status, body = self.api(f"/api/v1/audit?limit=200&{q}")
        check(status == 200, f"hub {self.name}'s audit log: {status} {body}")
        return body["records"]


class Rosbridge:
    """A plain rosbridge v2 JSON client: sees every status message the hub sends."""

    def __init__(self, addr, token=None):
        headers = {"Authorization": f"Bearer {token}"} if token else {}
        self.ws = ws_connect(f"ws://{addr}/", additional_headers=headers, open_timeout=10)
        self.inbox = []
        self.n = 0

    def send(self, **op):
        self.ws.send(json.dumps(op))

    def pump(self, seconds):
        end = time.monotonic() + seconds
        while time.monotonic() < end:
            try:
                m = self.ws.recv(timeout=max(0.01, end - time.monotonic()))
            except TimeoutError:
                break
            if isinstance(m, str):
                self.inbox.append(json.loads(m))

    def until(self, pred, what, timeout=10.0):
        end = time.monotonic() + timeout
        while True:
            for m in self.inbox:
                if pred(m):
                    self.inbox.remove(m)
                    return m
            if time.monotonic() >= end:
                raise CheckFailed(f"{what}: nothing within {timeout:.0f} s "
                                  f"(seen: {json.dumps(self.inbox)[:400]})")
            self.pump(0.1)

    def call(self, service, args=None, timeout=10.0):
        self.n += 1
        cid = f"c{self.n}"
        self.send(op="call_service", id=cid, service=service, args=args or {})
        return self.until(lambda m: m.get("op") == "service_response" and m.get("id") == cid,
                          f"answer of {service}", timeout)

    def messages(self, topic):
        return [m for m in self.inbox if m.get("op") == "publish" and m.get("topic") == topic]

    def close(self):
        self.ws.close()


def zenoh_session(endpoint, tls=None):
    """An eclipse-zenoh client session; `tls` = (ca, cert or None, key or None)."""
    conf = zenoh.Config()
    conf.insert_json5("mode", '"client"')
    conf.insert_json5("connect/endpoints", json.dumps([endpoint]))
    conf.insert_json5("scouting/multicast/enabled", "false")
    if tls:
        ca, cert, key = tls
        conf.insert_json5("transport/link/tls/root_ca_certificate", json.dumps(ca))
        if cert:
            conf.insert_json5("transport/link/tls/connect_certificate", json.dumps(cert))
            conf.insert_json5("transport/link/tls/connect_private_key", json.dumps(key))
            conf.insert_json5("transport/link/tls/enable_mtls", "true")
    return zenoh.open(conf)


def log_has(path, needle, timeout=5.0):
    return wait(lambda: needle in Path(path).read_text(errors="replace"),
                f"hub log line with {needle!r}", timeout)


def zenoh_call(session, hub_zid, service, header, payload=b"{}"):
    """A call as the federation makes it: a query to hub_zid's call queryable."""
    key = f"{ROOT}/call/{hub_zid}/{service.lstrip('/')}"
    replies = session.get(key, payload=payload, attachment=json.dumps(header).encode(),
                          consolidation=zenoh.ConsolidationMode.NONE, timeout=5)
    out = []
    for r in replies:
        if r.ok is not None:
            att = r.ok.attachment
            out.append(json.loads(att.to_bytes()) if att is not None else {})
        else:
            out.append({"error": r.err.payload.to_string()})
    return out


# ----------------------------------------------------------------------------------------
# Attacks on the federation port (hub A's), as eclipse-zenoh sessions

def refused_at_tls(ctx, label, endpoint, tls, log_needle):
    try:
        s = zenoh_session(endpoint, tls)
    except Exception as e:  # zenoh.ZError: no link could be made
        log_has(ctx.args.hub_log, log_needle)
        return f"{label}: no session ({str(e)[:80]}), hub A logged {log_needle!r}"
    s.close()
    raise CheckFailed(f"{label}: a Zenoh session was opened")


def attack_plain_tcp_on_the_federation_port(ctx):
    ep = ctx.args.zenoh.replace("tls/", "tcp/", 1)
    return refused_at_tls(ctx, "plain TCP, no credentials", ep, None, "InvalidContentType")


def attack_tls_without_a_certificate(ctx):
    return refused_at_tls(ctx, "TLS without a certificate", ctx.args.zenoh,
                          (ctx.ca, None, None), "peer sent no certificates")


def attack_certificate_of_another_ca(ctx):
    t = ctx.args.tmp
    return refused_at_tls(ctx, "certificate of another CA", ctx.args.zenoh,
                          (ctx.ca, f"{t}/stranger.pem", f"{t}/stranger.key"), "UnknownIssuer")


def attack_certificate_of_another_fleet(ctx):
    """Passes TLS (the fleet's CA signed it) but is not admitted: its calls are refused,
    what it offers and puts never reaches the robot, its wants are not served."""
    t = ctx.args.tmp
    s = zenoh_session(ctx.args.zenoh, (ctx.ca, f"{t}/otherfleet.pem", f"{t}/otherfleet.key"))
    try:
        me = str(s.info.zid())
        log_has(ctx.args.hub_log, f"refused hub {me}")
        log_has(ctx.args.hub_log, 'names fleet "globex"')
        header = {"from": me, "id": 1, "enc": JSON_ENC, "goal": False}
        answers = zenoh_call(s, ctx.a_zid, "/robot1/get_status", header)
        check(answers and answers[-1].get("status") == FORBIDDEN and "not admitted" in answers[-1].get("text", ""),
              f"its call of /robot1/get_status was answered {answers}")
        # Offer and put /robot1/cmd_vel; a want for /robot1/odom.
        offer = s.liveliness().declare_token(f"{ROOT}/cat/{me}/t/0/geometry_msgs:msg:Twist/robot1/cmd_vel")
        want = s.liveliness().declare_token(f"{ROOT}/cat/{me}/w/0/-/robot1/odom")
        heard = []
        sub = s.declare_subscriber(f"{ROOT}/t/*/robot1/odom", lambda sample: heard.append(1))
        time.sleep(1.0)  # the hub would react to the tokens within this
        ctx.local.inbox.clear()
        for i in range(20):
            s.put(f"{ROOT}/t/{me}/robot1/cmd_vel", json.dumps({"linear": {"x": 9.0}}),
                  attachment=bytes([1, JSON_ENC, 0]) + i.to_bytes(8, "little") + bytes(8))
            time.sleep(0.05)
        ctx.local.pump(1.0)
        forged = [m for m in ctx.local.messages("/cmd_vel") if m["msg"]["linear"]["x"] == 9.0]
        check(not forged, f"the robot received {len(forged)} /cmd_vel messages it put")
        check(not heard, f"it heard {len(heard)} /robot1/odom messages after declaring a want")
        sub.undeclare()
        offer.undeclare()
        want.undeclare()
        # Keyframe asks (docs/video.md) from a hub not admitted: refused before anything
        # else is looked at, each counted.
        _, fed = ctx.a.api("/api/v1/federation")
        before = fed["counters"]
        for name in ("robot1/camera/video", "robot1/odom"):
            for _ in range(3):
                s.put(f"{ROOT}/keyframe/{ctx.a_zid}/{me}/{name}", b"")
        counters = lambda: ctx.a.api("/api/v1/federation")[1]["counters"]
        wait(lambda: counters()["refused"] >= before["refused"] + 6,
             "hub A counting the six keyframe asks it refused", timeout=5.0)
        after = counters()
        check(after["keyframe_asks_in"] == before["keyframe_asks_in"]
              and after["keyframe_asks_acted"] == before["keyframe_asks_acted"],
              f"hub A heard keyframe asks of a hub not admitted: {before} -> {after}")
    finally:
        s.close()
    # Control: the same topic from an admitted hub's operator reaches the robot.
    ctx.publish_from_b("/robot1/cmd_vel", 1.5)
    ctx.local.until(lambda m: m.get("topic") == "/cmd_vel" and m["msg"]["linear"]["x"] == 1.5,
                    "control: hub B's operator publishing /robot1/cmd_vel reaches the robot")
    return "not admitted (logged with its fleet); call refused; its /cmd_vel never reached the robot; its want got no /odom; its keyframe asks refused"


def attack_admitted_hub_calls_hub_only_services(ctx):
    """A hub of the fleet (valid certificate) calls robot1's configuration service
    directly through Zenoh, as itself and claiming an admin: the robot's hub refuses both
    and audits them; the robot's kept configuration stays untouched."""
    c = ctx.args.certs
    s = zenoh_session(ctx.args.zenoh, (ctx.ca, f"{c}/hub-rogue.pem", f"{c}/hub-rogue.key"))
    try:
        me = str(s.info.zid())
        log_has(ctx.args.hub_log, f"hub hub-rogue ({me}) admitted")
        change = json.dumps({"change": json.dumps({"remap": {"/odom": "/stolen"}}), "by": "rogue"})
        for caller in (None, {"user": "root", "groups": ["admin"]}):
            header = {"from": me, "id": 7, "enc": JSON_ENC, "goal": False, "caller": caller}
            for svc in ("/robot1/fleetlink/config/set", "/robot1/fleetlink/blackbox/fetch"):
                answers = zenoh_call(s, ctx.a_zid, svc, header, change.encode())
                check(answers and answers[-1].get("status") == FORBIDDEN,
                      f"{svc} called by hub-rogue as {caller}: {answers}")
        # Control: an ordinary service of the robot is served to it.
        header = {"from": me, "id": 8, "enc": JSON_ENC, "goal": False,
                  "caller": {"user": "root", "groups": ["admin"]}}
        answers = zenoh_call(s, ctx.a_zid, "/robot1/get_status", header)
        check(answers and answers[-1].get("status") == 0,
              f"control: /robot1/get_status for hub-rogue's admin: {answers}")
    finally:
        s.close()
    check(not Path(ctx.args.runtime_file).exists(), "the robot kept a configuration change")
    recs = ctx.a.audit(name="/robot1/fleetlink/config/set")
    by = {(r["principal"], r["allowed"]) for r in recs}
    check(("hub:hub-rogue", False) in by and ("hub:hub-rogue/user:root", False) in by,
          f"hub A's audit of the refusals: {sorted(by)}")
    return "refused (Forbidden) as itself and for an admin it vouches for; audited; config untouched"


# ----------------------------------------------------------------------------------------
# Attacks through the hubs' client doors

def attack_anonymous_rosbridge(ctx):
    rb = Rosbridge(ctx.a.addr)
    try:
        rb.send(op="subscribe", topic="/robot1/scan", type="sensor_msgs/msg/LaserScan")
        st = rb.until(lambda m: m.get("op") == "status" and m.get("level") == "error",
                      "a status error for an anonymous subscribe")
        check("auth" in st["msg"] or "authenticat" in st["msg"], f"the refusal: {st['msg']}")
        rb.pump(1.0)
        check(not rb.messages("/robot1/scan"), "an anonymous client got /robot1/scan")
    finally:
        rb.close()
    return f"refused: {st['msg'][:90]}"


def attack_rightless_rest_listings(ctx):
    for path in ("/api/v1/robots", "/api/v1/topics"):
        status, body = ctx.a.api(path, token=ctx.a.nobody)
        check(status == 200, f"{path} for a rights-less token: {status}")
        listed = body.get("robots") or body.get("topics") or []
        check(not listed, f"{path} lists {listed[:3]} to a token without rights")
        status, body = ctx.a.api(path)
        check(body.get("robots") or body.get("topics"), f"control: {path} for the admin is empty")
    status, _ = ctx.a.api("/api/v1/audit", token=ctx.a.nobody)
    check(status == 403, f"the audit log for a rights-less token: {status}")
    return "empty robot and topic listings, 403 on the audit log"


def attack_forged_robot_name(ctx):
    """An agent claims robot1 with robot2's token: HELLO is refused, the agent says so
    (a refusal it does not retry soon), robot1's own link stays."""
    cfg = Path(ctx.args.tmp) / "forged.yaml"
    log = Path(ctx.args.tmp) / "forged.log"
    cfg.write_text(f"hub: ws://{ctx.a.addr}/\nname: robot1\ntoken: {ctx.args.robot2_token}\n"
                   f"runtime_file: {ctx.args.tmp}/forged-state/runtime.json\n")
    with open(log, "w") as out:
        p = subprocess.Popen([ctx.bin, "agent", "--config", str(cfg)], stdout=out,
                             stderr=subprocess.STDOUT)
    try:
        line = wait(lambda: next((l for l in log.read_text(errors="replace").splitlines()
                                  if "refused the token of robot robot1" in l), None),
                    "the forged agent's refusal", 15)
    finally:
        p.kill()
        p.wait()
    _, robots = ctx.a.api("/api/v1/robots")
    me = [r for r in robots.get("robots", []) if r.get("name") == "robot1"]
    check(me and me[0].get("online"), f"robot1's own link after the forgery: {me}")
    return "refused: " + line.split("hub link down: ", 1)[-1][:110]


def attack_federated_call_the_robots_hub_denies(ctx):
    """alice may call /robot1/set_mode on hub B (its rules) but not on hub A, where the
    robot is: the call from B is refused by A, and both the refusal and the allowed control
    call are in A's audit log under hub B's name."""
    rb = Rosbridge(ctx.b.addr, ctx.b.alice)
    try:
        ok = rb.call("/robot1/get_status")
        check(ok.get("result") is True, f"control: alice's /robot1/get_status through hub B: {ok}")
        r = rb.call("/robot1/set_mode", {"data": True})
        check(r.get("result") is False, f"alice's /robot1/set_mode through hub B was served: {r}")
        text = json.dumps(r.get("values"))
        check("hub:hub-b/user:alice" in text, f"the refusal does not name who: {text}")
    finally:
        rb.close()
    recs = ctx.a.audit(principal="hub:hub-b/user:alice")
    seen = {(r["name"], r["allowed"]) for r in recs}
    check(("/robot1/set_mode", False) in seen and ("/robot1/get_status", True) in seen,
          f"hub A's audit for hub:hub-b/user:alice: {sorted(seen)}")
    return "refused by the robot's hub and audited there as hub:hub-b/user:alice (control call audited too)"


def attack_rule_naming_a_hub(ctx):
    """A rule on hub A denies hub B publishing /robot1/joint_cmd: an admin on B publishes
    it and /robot1/cmd_vel; the robot gets cmd_vel only; A counts the refusals and audits
    what B's messages did to the robot."""
    ctx.local.inbox.clear()
    ctx.publish_from_b("/robot1/joint_cmd", 7.0, count=10)
    ctx.publish_from_b("/robot1/cmd_vel", 2.5, count=10)
    ctx.local.until(lambda m: m.get("topic") == "/cmd_vel" and m["msg"]["linear"]["x"] == 2.5,
                    "control: /robot1/cmd_vel from hub B")
    ctx.local.pump(1.0)
    check(not ctx.local.messages("/joint_cmd"), "the robot got /robot1/joint_cmd from hub B")
    _, fed = ctx.a.api("/api/v1/federation")
    check(fed["counters"]["refused"] > 0, f"hub A counted no refusal: {fed['counters']}")
    recs = ctx.a.audit(principal="hub:hub-b", name="/robot1/cmd_vel")
    check(any(r["allowed"] for r in recs), "hub A did not audit hub B's /robot1/cmd_vel")
    return f"joint_cmd dropped ({fed['counters']['refused']} refused at A), cmd_vel delivered and audited as hub:hub-b"


def attack_blackbox_around_a_deny_rule(ctx):
    """alice may call and read /robot1/.* but not /robot1/odom: the black box's service and
    data topic are the hub's alone, and the slice she asks the API for has no odometry."""
    rb = Rosbridge(ctx.a.addr, ctx.a.alice)
    admin = Rosbridge(ctx.a.addr, ctx.a.root)
    try:
        r = rb.call("/robot1/fleetlink/blackbox/fetch", {})
        check(r.get("result") is False, f"alice's call of the black-box service: {r}")
        for client in (rb, admin):
            client.send(op="subscribe", topic="/robot1/fleetlink/blackbox/data")
        # The slice, through the API, as alice.
        status, rec = ctx.a.api("/api/v1/recordings/blackbox", token=ctx.a.alice,
                                body={"robot": "robot1", "last_s": 5})
        check(status == 201, f"alice's black-box fetch: {status} {rec}")
        rid = rec["id"]
        done = wait(lambda: (lambda s_b: s_b[1] if s_b[1].get("state") in ("stopped", "failed") else None)(
            ctx.a.api(f"/api/v1/recordings/{rid}", token=ctx.a.alice)), "the black-box slice", 60)
        check(done["state"] == "stopped", f"the fetch ended {done}")
        for client in (rb, admin):
            client.pump(0.5)
            pieces = client.messages("/robot1/fleetlink/blackbox/data")
            check(not pieces, f"a client subscribed to the black-box data got {len(pieces)} pieces")
        topics = admin.call("/rosapi/topics")["values"]["topics"]
        check(not any("blackbox" in t for t in topics), f"/rosapi/topics lists {topics}")
        _, listed = ctx.a.api("/api/v1/topics")
        names = [t.get("name") for t in listed.get("topics", [])]
        check(not any("blackbox" in (n or "") for n in names), f"/api/v1/topics lists {names}")
        check(any(n == "/robot1/odom" for n in names), "control: /api/v1/topics lists /robot1/odom")
    finally:
        rb.close()
        admin.close()
    f = done["files"][0]["name"]
    status, data = ctx.a.api(f"/api/v1/recordings/{rid}/files/{f}", token=ctx.a.alice)
    check(status == 200, f"downloading the slice: {status}")
    path = Path(ctx.args.tmp) / "slice.mcap"
    path.write_bytes(data)
    counts = {}
    with open(path, "rb") as fh:
        for _schema, channel, _msg in make_reader(fh).iter_messages():
            counts[channel.topic] = counts.get(channel.topic, 0) + 1
    check(not any(t.endswith("odom") for t in counts), f"the slice holds odometry: {counts}")
    check(any(t.endswith("scan") for t in counts), f"control: the slice holds no scans: {counts}")
    return f"service and data topic refused, unlisted; alice's slice: {counts} (no /odom)"


def attack_parameter_spelled_another_way(ctx):
    """A deny rule hides /robot1/secret_param from alice: Foxglove getParameters and
    rosbridge's /rosapi/get_param with a trailing slash get nothing."""
    admin = Rosbridge(ctx.a.addr, ctx.a.root)
    rb = Rosbridge(ctx.a.addr, ctx.a.alice)
    try:
        for name, value in (("/robot1/secret_param", "hidden"), ("/robot1/public_param", "shown")):
            r = admin.call("/rosapi/set_param", {"name": name, "value": json.dumps(value)})
            check(r.get("result") is True, f"setting {name}: {r}")
        for spelling in ("/robot1/secret_param/", "robot1/secret_param"):
            r = rb.call("/rosapi/get_param", {"name": spelling})
            check(r.get("result") is False or "hidden" not in json.dumps(r.get("values")),
                  f"rosbridge get_param {spelling!r} for alice: {r}")
        r = rb.call("/rosapi/get_param", {"name": "/robot1/public_param/"})
        check("shown" in json.dumps(r.get("values")), f"control: rosbridge get_param: {r}")
    finally:
        admin.close()
        rb.close()
    script = Path(__file__).resolve().parents[1] / "foxglove" / "foxglove_param_attack.mjs"
    p = subprocess.run(["node", str(script), "--url", f"ws://{ctx.a.addr}/?token={ctx.a.alice}",
                        "--hidden", "/robot1/secret_param/", "--shown", "/robot1/public_param"],
                       capture_output=True, text=True, timeout=60)
    check(p.returncode == 0, f"the Foxglove client: {p.stdout[-400:]} {p.stderr[-400:]}")
    return "Foxglove getParameters and rosbridge get_param return nothing for the hidden name in any spelling"


ATTACKS = [
    attack_plain_tcp_on_the_federation_port,
    attack_tls_without_a_certificate,
    attack_certificate_of_another_ca,
    attack_certificate_of_another_fleet,
    attack_admitted_hub_calls_hub_only_services,
    attack_anonymous_rosbridge,
    attack_rightless_rest_listings,
    attack_forged_robot_name,
    attack_federated_call_the_robots_hub_denies,
    attack_rule_naming_a_hub,
    attack_blackbox_around_a_deny_rule,
    attack_parameter_spelled_another_way,
]


class Ctx:
    def __init__(self, args):
        self.args = args
        hubs = {h.name: h for h in map(Hub, args.hub)}
        self.a, self.b = hubs["a"], hubs["b"]
        self.ca = f"{args.certs}/ca.pem"
        self.bin = args.bin
        _, fed = self.a.api("/api/v1/federation")
        self.a_zid = fed["hub"]["id"]
        # The robot's side: a local rosbridge client of the agent, subscribed to the
        # topics operators send it.
        self.local = Rosbridge(args.local)
        for t in ("/cmd_vel", "/joint_cmd"):
            self.local.send(op="subscribe", topic=t, type=TWIST)
        self.b_admin = Rosbridge(self.b.addr, self.b.root)
        for t in ("/robot1/cmd_vel", "/robot1/joint_cmd"):
            self.b_admin.send(op="advertise", topic=t, type=TWIST)
        # Interest reaches hub B through A's want: wait until B sends what it publishes.
        wait(lambda: self.b_sends("/robot1/cmd_vel"), "hub B sending /robot1/cmd_vel to hub A", 15)

    def b_sends(self, topic):
        _, fed = self.b.api("/api/v1/federation")
        return any(t["topic"] == topic and t["wanted_remotely"] for t in fed.get("exported", []))

    def publish_from_b(self, topic, x, count=3):
        wait(lambda: self.b_sends(topic), f"hub B sending {topic}", 15)
        for _ in range(count):
            self.b_admin.send(op="publish", topic=topic, msg={"linear": {"x": x}})
            time.sleep(0.05)


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--hub", action="append", required=True, help="NAME=ADDR,ROOT,ALICE,NOBODY")
    ap.add_argument("--zenoh", required=True, help="hub A's federation endpoint")
    ap.add_argument("--certs", required=True, help="the fleet's federation certificates")
    ap.add_argument("--tmp", required=True)
    ap.add_argument("--local", required=True, help="the agent's local rosbridge address")
    ap.add_argument("--robot2-token", required=True)
    ap.add_argument("--hub-log", required=True)
    ap.add_argument("--runtime-file", required=True)
    ap.add_argument("--bin", default=None)
    args = ap.parse_args()
    if args.bin is None:
        import os
        args.bin = os.environ.get("FLEETLINK_BIN", "fleetlink")
    ctx = Ctx(args)
    failed = []
    for attack in ATTACKS:
        name = attack.__name__.removeprefix("attack_").replace("_", " ")
        try:
            print(f"PASS: {name}: {attack(ctx)}", flush=True)
        except Exception as e:  # noqa: BLE001 - every failure is reported by name
            failed.append(name)
            print(f"FAIL: {name}: {type(e).__name__}: {e}", flush=True)
    if failed:
        print(f"FAIL: {len(failed)} of {len(ATTACKS)} attacks were not refused as they must be: {failed}")
        sys.exit(1)
    print(f"PASS: all {len(ATTACKS)} attacks met their answers")


if __name__ == "__main__":
    main()

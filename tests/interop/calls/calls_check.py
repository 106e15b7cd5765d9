#!/usr/bin/env python3
"""Services and actions through fleetlink, driven by roslibpy (PyPI) and raw WebSocket
clients (the `websockets` package) where roslibpy cannot express a case.

Needs a hub (--hub-url, an admin operator's token in the URL), an agent for --robot with
the simulator (which offers /<robot>/set_mode, /<robot>/get_status and the action
/<robot>/navigate_to_pose) and its local rosbridge listener (--local-url), a non-admin
operator token without rules (--viewer-url) and the hub's HTTP address for the audit log
(--api, --op-token). The checks, in order (later ones use what earlier ones left):

  set_mode          operator calls /<robot>/set_mode; /<robot>/get_status reflects it
  cloud_service     a hub client advertises /cloud/add_two_ints; a second hub client and
                    a program on the robot's local listener call it
  robot_service     a program on the local listener advertises /robot_echo; the operator
                    calls /<robot>/robot_echo at the hub; unadvertise removes it
  concurrent        50 concurrent calls from 5 clients, each answered with its own sum;
                    p50/p99 round trip printed
  timeout           a provider that never answers: `timeout: 1.0` fails in ~1 s naming
                    the timeout; the provider leaving fails a pending call at once
  action            navigate_to_pose: feedback then SUCCEEDED with reached true; a second
                    goal cancelled after its first feedback ends CANCELED
  acl_audit         a non-admin token is refused ("not allowed"); the audit log holds
                    every robot call and goal (allowed, with an outcome) and the denial
  malformed         broken service/action operations get errors naming the problem and
                    the connection keeps working
  rosapi            /rosapi/services, service_type, service_providers, action_servers

Prints `ok <check>` or `FAIL <check>: why` per check; exits 1 if any failed. Every wait
is bounded.
"""

import argparse
import json
import math
import random
import re
import sys
import threading
import time
import urllib.error
import urllib.parse
import urllib.request

import cbor2
import roslibpy
from roslibpy.core import GoalStatus, RosTimeoutError, ServiceException
from websockets.sync.client import connect as ws_connect

TIMEOUT = 10.0  # seconds, for any single wait unless a check says otherwise
LIST_WAIT = 10.0  # seconds for an advertisement to show up where it is called
ADD = "/cloud/add_two_ints"
ADD_TYPE = "example_interfaces/srv/AddTwoInts"
NEVER = "/cloud/never_answers"
NAV_TYPE = "fleetlink_sim/action/NavigateTo"
SPEED = 0.5  # m/s, the simulated robot's navigation speed (spec)


class CheckFailed(Exception):
    pass


def check(cond, what):
    if not cond:
        raise CheckFailed(what)


def note(what):
    print(f"    {what}", flush=True)


def short(v, n=300):
    s = v if isinstance(v, str) else json.dumps(v, default=str)
    return s if len(s) <= n else s[:n] + "..."


class Inbox:
    """Collects values from callbacks or reader threads; waits are bounded."""

    def __init__(self):
        self.items = []
        self.seen = []  # everything ever put, for failure messages
        self.cond = threading.Condition()

    def put(self, item):
        with self.cond:
            self.items.append(item)
            self.seen.append(item)
            self.cond.notify_all()

    def wait(self, n, timeout, what, pred=lambda _: True):
        """The first `n` items matching `pred` (left in place)."""
        deadline = time.monotonic() + timeout
        with self.cond:
            while True:
                matching = [i for i in self.items if pred(i)]
                if len(matching) >= n:
                    return matching[:n]
                left = deadline - time.monotonic()
                if left <= 0:
                    raise CheckFailed(f"{what}: got {len(matching)} of {n} within {timeout:.1f}s; "
                                      f"arrived: {self.summary()}")
                self.cond.wait(left)

    def take(self, pred, timeout, what):
        """Removes and returns the first item matching `pred`."""
        deadline = time.monotonic() + timeout
        with self.cond:
            while True:
                for i, item in enumerate(self.items):
                    if pred(item):
                        del self.items[i]
                        return item
                left = deadline - time.monotonic()
                if left <= 0:
                    raise CheckFailed(f"{what}: nothing within {timeout:.1f}s; arrived: {self.summary()}")
                self.cond.wait(left)

    def count(self):
        with self.cond:
            return len(self.seen)

    def summary(self, n=6):
        with self.cond:
            if not self.seen:
                return "nothing"
            tail = self.seen[-n:]
            more = f"({len(self.seen) - n} earlier) " if len(self.seen) > n else ""
            return more + "; ".join(short(dict(i) if hasattr(i, "keys") else i, 200) for i in tail)


# --- roslibpy connections -------------------------------------------------------------

CLIENTS = []


def connect(url, what):
    u = urllib.parse.urlparse(url)
    # roslibpy builds the URL from host and port; a token in the URL's query goes in an
    # Authorization header instead (both are accepted by the hub).
    token = urllib.parse.parse_qs(u.query).get("token", [None])[0]
    headers = {"Authorization": f"Bearer {token}"} if token else None
    ros = roslibpy.Ros(host=u.hostname, port=u.port, is_secure=u.scheme == "wss", headers=headers)
    CLIENTS.append(ros)
    try:
        ros.run(timeout=TIMEOUT)
    except Exception as e:  # RosTimeoutError
        raise CheckFailed(f"connect {what} ({u.scheme}://{u.netloc}/): {e}") from e
    check(ros.is_connected, f"connect {what}: not connected")
    # roslibpy has no handler for 'status' ops (it logs a traceback and drops them); show
    # them instead: an error the server sent explains a check that then fails.
    proto = ros.factory._proto
    if proto is not None:
        proto._message_handlers["status"] = lambda m: note(f"status op to {what}: {short(dict(m))}")
    return ros


def close(ros):
    try:
        ros.close(timeout=3)
    except Exception:
        pass


def call_result(ros, service, args=None, timeout=TIMEOUT):
    """(True, values) or (False, values) of the service_response; CheckFailed if none came.

    roslibpy turns a response with result false into ServiceException(values)."""
    svc = roslibpy.Service(ros, service, "")
    try:
        return True, dict(svc.call(roslibpy.ServiceRequest(args or {}), timeout=timeout))
    except ServiceException as e:
        return False, e.args[0] if e.args else None
    except RosTimeoutError as e:
        raise CheckFailed(f"call {service} {short(args or {})}: no service_response within {timeout:.1f}s") from e


def call_ok(ros, service, args=None, timeout=TIMEOUT):
    ok, v = call_result(ros, service, args, timeout)
    check(ok, f"call {service} {short(args or {})}: result false: {short(v)}")
    return v


def call_until_ok(ros, service, args, timeout, what):
    """Retries while the call fails (the route may still be settling); bounded."""
    deadline = time.monotonic() + timeout
    last = None
    while True:
        left = deadline - time.monotonic()
        if left <= 0:
            raise CheckFailed(f"{what}: no successful call to {service} within {timeout:.0f}s; last: {last}")
        try:
            ok, v = call_result(ros, service, args, timeout=max(0.5, min(left, 3.0)))
        except CheckFailed as e:
            ok, v = False, str(e)
        if ok:
            return v
        last = f"result false: {short(v)}"
        time.sleep(0.2)


def services_of(ros):
    v = call_ok(ros, "/rosapi/services")
    check(isinstance(v.get("services"), list), f"/rosapi/services: no 'services' list in {short(v)}")
    return v["services"]


def wait_listed(ros, name, timeout=LIST_WAIT, present=True):
    """Polls /rosapi/services until `name` is (or is no longer) listed."""
    deadline = time.monotonic() + timeout
    while True:
        names = services_of(ros)
        if (name in names) == present:
            return
        if time.monotonic() > deadline:
            state = "listed" if present else "gone"
            raise CheckFailed(f"{name} not {state} in /rosapi/services within {timeout:.0f}s: {names}")
        time.sleep(0.1)


def spy_calls(ros):
    """Records the `service` of every call_service op the server sends this client."""
    proto = ros.factory._proto
    check(proto is not None, "roslibpy has no live protocol object")
    seen = []
    orig = proto._message_handlers["call_service"]

    def spy(message):
        seen.append(message.get("service"))
        orig(message)

    proto._message_handlers["call_service"] = spy
    return seen


# --- raw rosbridge WebSocket client -----------------------------------------------------


class Raw:
    """A plain rosbridge client: sends any JSON op; a reader thread keeps every frame
    (JSON text or CBOR binary) for wait()."""

    def __init__(self, url, name):
        self.name = name
        try:
            self.ws = ws_connect(url, open_timeout=TIMEOUT, close_timeout=2, max_size=16 << 20)
        except Exception as e:
            raise CheckFailed(f"connect {name}: {type(e).__name__}: {e}") from e
        self.inbox = Inbox()
        self.closed = threading.Event()
        self.thread = threading.Thread(target=self._read, daemon=True)
        self.thread.start()

    def _read(self):
        try:
            for frame in self.ws:
                try:
                    m = cbor2.loads(frame) if isinstance(frame, bytes) else json.loads(frame)
                except Exception as e:
                    m = {"op": "<undecodable>", "error": str(e)}
                self.inbox.put(m)
        except Exception:
            pass
        finally:
            self.closed.set()

    def send(self, op):
        self.ws.send(json.dumps(op))

    def wait(self, pred, timeout, what):
        return self.inbox.take(pred, timeout, f"{self.name}: {what}")

    def reply_to(self, id_, ops, timeout, what):
        """The first frame of one of `ops` carrying `id_`."""
        return self.wait(lambda m: m.get("op") in ops and m.get("id") == id_, timeout, what)

    def close(self):
        try:
            self.ws.close()
        except Exception:
            pass
        self.thread.join(3)


def is_call_for(service):
    return lambda m: m.get("op") == "call_service" and m.get("service") == service


# --- the checks ---------------------------------------------------------------------------


class Ctx:
    def __init__(self, a):
        self.a = a
        self.robot = a.robot
        self.op = None  # the admin operator's roslibpy connection at the hub
        self.adder = None  # the roslibpy client at the hub providing /cloud/add_two_ints
        self.add_calls = 0  # calls its callback answered
        self.add_lock = threading.Lock()
        # What the operator asked of robot services and actions, for the audit check:
        # name -> number of attempts.
        self.robot_calls = {}
        self.robot_goals = {}
        self.viewer_denied = 0

    def robot_call(self, service, args=None, timeout=TIMEOUT):
        self.robot_calls[service] = self.robot_calls.get(service, 0) + 1
        return call_ok(self.op, service, args, timeout)

    def status(self):
        """get_status's message, parsed: at least mode, x, y."""
        name = f"/{self.robot}/get_status"
        v = self.robot_call(name)
        check(v.get("success") is True, f"{name}: success is {v.get('success')!r}: {short(v)}")
        try:
            st = json.loads(v.get("message"))
        except (TypeError, ValueError) as e:
            raise CheckFailed(f"{name}: message is not JSON text ({e}): {short(v)}") from e
        check(isinstance(st, dict), f"{name}: message is JSON but not an object: {short(st)}")
        for k in ("mode", "x", "y"):
            check(k in st, f"{name}: status lacks {k!r}: {short(st)}")
        for k in ("x", "y"):
            check(isinstance(st[k], (int, float)) and math.isfinite(st[k]),
                  f"{name}: {k} is not a finite number: {short(st)}")
        return st


def check_set_mode(ctx):
    name = f"/{ctx.robot}/set_mode"
    steps = []
    for data in (True, False, True):
        v = ctx.robot_call(name, {"data": data})
        check(v.get("success") is True, f"{name} {{data: {data}}}: success is {v.get('success')!r}: {short(v)}")
        check(isinstance(v.get("message"), str) and v["message"].strip(),
              f"{name} {{data: {data}}}: empty or missing message: {short(v)}")
        st = ctx.status()
        if data:
            check(st["mode"] == "active",
                  f"after {name} {{data: true}} (answered {v['message']!r}), get_status mode is "
                  f"{st['mode']!r}, want 'active'")
        else:
            check(st["mode"] != "active",
                  f"after {name} {{data: false}} (answered {v['message']!r}), get_status mode is "
                  f"still 'active'")
        steps.append(f"{str(data).lower()} -> {v['message']!r}, mode {st['mode']!r}")
    return f"{name}: " + "; ".join(steps)


def check_cloud_service(ctx):
    a = ctx.a
    ctx.adder = adder = connect(a.hub_url, "provider A (hub)")

    def add(req, resp):
        try:
            resp["sum"] = int(req["a"]) + int(req["b"])
        except Exception as e:  # answer false rather than leave the caller waiting
            resp["error"] = f"{type(e).__name__}: {e}"
            return False
        with ctx.add_lock:
            ctx.add_calls += 1
        return True

    roslibpy.Service(adder, ADD, ADD_TYPE).advertise(add)
    wait_listed(ctx.op, ADD)
    caller = connect(a.hub_url, "caller B (hub)")
    try:
        v = call_ok(caller, ADD, {"a": 2, "b": 40})
        check(v == {"sum": 42}, f"hub client B: {ADD} {{a: 2, b: 40}} answered {short(v)}, want {{sum: 42}}")
    finally:
        close(caller)
    local = connect(a.local_url, "local program (agent listener)")
    try:
        v = call_until_ok(local, ADD, {"a": 1000, "b": -7}, LIST_WAIT,
                          f"local program calling {ADD} through the agent")
        check(v == {"sum": 993}, f"local program: {ADD} {{a: 1000, b: -7}} answered {short(v)}, want {{sum: 993}}")
    finally:
        close(local)
    return f"{ADD} advertised at the hub, answered to a hub client (42) and a local program (993)"


def check_robot_service(ctx):
    a = ctx.a
    local = connect(a.local_url, "local provider (agent listener)")
    hub_name = f"/{ctx.robot}/robot_echo"
    try:
        seen = spy_calls(local)
        nonce = random.randint(1, 1 << 30)

        def echo(req, resp):
            resp["success"] = True
            resp["message"] = f"echo {nonce}"
            return True

        svc = roslibpy.Service(local, "/robot_echo", "std_srvs/srv/Trigger")
        svc.advertise(echo)
        wait_listed(ctx.op, hub_name)
        try:
            v = ctx.robot_call(hub_name)
        except CheckFailed as e:
            raise CheckFailed(f"{e} (the local provider was sent call_service for: {seen})") from e
        check(v == {"success": True, "message": f"echo {nonce}"},
              f"{hub_name} answered {short(v)}, want {{success: true, message: 'echo {nonce}'}}")
        check(seen and all(s == "/robot_echo" for s in seen),
              f"the local provider got call_service ops for {seen}, want the local name /robot_echo")
        svc.unadvertise()
        wait_listed(ctx.op, hub_name, present=False)
    finally:
        close(local)
    return f"/robot_echo advertised locally answered the operator's {hub_name}; gone after unadvertise"


def check_concurrent(ctx):
    a = ctx.a
    n_clients, per_client = 5, 10
    clients = [connect(a.hub_url, f"concurrent client {c}") for c in range(n_clients)]
    before = ctx.add_calls
    results = {}  # (client, i) -> (kind, value, rtt, expected)
    done = threading.Condition()
    barrier = threading.Barrier(n_clients)
    errors = []

    def run(c, ros):
        try:
            svc = roslibpy.Service(ros, ADD, "")
            barrier.wait(timeout=TIMEOUT)
            for i in range(per_client):
                av, bv = 1000 * c + i, 100_000 * (c + 1) + 3 * i  # every sum distinct
                t0 = time.monotonic()

                def finish(kind, value, key=(c, i), t0=t0, want=av + bv):
                    with done:
                        results[key] = (kind, value, time.monotonic() - t0, want)
                        done.notify_all()

                svc.call(roslibpy.ServiceRequest({"a": av, "b": bv}),
                         lambda r, finish=finish: finish("ok", dict(r).get("sum")),
                         lambda e, finish=finish: finish("error", e))
        except Exception as e:
            errors.append(f"client {c}: {type(e).__name__}: {e}")

    threads = [threading.Thread(target=run, args=(c, ros), daemon=True) for c, ros in enumerate(clients)]
    t_start = time.monotonic()
    for t in threads:
        t.start()
    for t in threads:
        t.join(TIMEOUT)
    total = n_clients * per_client
    deadline = time.monotonic() + 15
    with done:
        while len(results) < total and time.monotonic() < deadline:
            done.wait(max(0.0, deadline - time.monotonic()))
        got = dict(results)
    wall = time.monotonic() - t_start
    for ros in clients:
        close(ros)
    problems = [f"sending: {errors}"] if errors else []
    missing = sorted(set((c, i) for c in range(n_clients) for i in range(per_client)) - set(got))
    if missing:
        problems.append(f"{len(missing)} of {total} calls unanswered after 15 s: (client, call) {missing[:10]}")
    failed = {str(k): v[1] for k, v in got.items() if v[0] != "ok"}
    if failed:
        problems.append(f"{len(failed)} calls failed: {short(failed)}")
    wrong = {str(k): (v[1], v[3]) for k, v in got.items() if v[0] == "ok" and v[1] != v[3]}
    if wrong:
        problems.append(f"{len(wrong)} calls answered with another call's sum (got, want): {short(wrong)}")
    answered = ctx.add_calls - before
    if answered != total:
        problems.append(f"the provider answered {answered} calls for {total} sent")
    check(not problems, " | ".join(problems))
    rtts = sorted(v[2] * 1000 for v in got.values())
    p50 = rtts[len(rtts) // 2]
    p99 = rtts[max(0, math.ceil(0.99 * len(rtts)) - 1)]
    print(f"    round trip over {total} concurrent calls: p50 {p50:.1f} ms, p99 {p99:.1f} ms, "
          f"max {rtts[-1]:.1f} ms, all answered in {wall:.2f} s", flush=True)
    return f"{total} concurrent calls from {n_clients} clients, each its own sum; p50 {p50:.1f} ms p99 {p99:.1f} ms"


TIMEOUT_WORDS = re.compile(r"time[sd]?[\s_-]*out", re.I)


def check_timeout(ctx):
    a = ctx.a
    provider = Raw(a.hub_url, "silent provider")
    caller = Raw(a.hub_url, "caller")
    try:
        provider.send({"op": "advertise_service", "id": "adv-never", "service": NEVER,
                       "type": "std_srvs/srv/Trigger"})
        wait_listed(ctx.op, NEVER)
        # 1. timeout: 1.0 on a call nobody answers.
        t0 = time.monotonic()
        caller.send({"op": "call_service", "id": "slow-1", "service": NEVER, "args": {}, "timeout": 1.0})
        req = provider.wait(is_call_for(NEVER), 5, f"call_service for {NEVER}")
        check(req.get("id") not in (None, ""), f"call_service sent to the provider has no id: {short(req)}")
        r = caller.reply_to("slow-1", ("service_response",), 5, "service_response to the call with timeout 1.0")
        el = time.monotonic() - t0
        check(r.get("result") is False, f"call with timeout 1.0 to a silent provider: result {r.get('result')!r}: {short(r)}")
        check(0.9 <= el <= 2.0, f"call with timeout 1.0 failed after {el:.2f} s, want about 1 s (0.9-2.0)")
        check(isinstance(r.get("values"), str) and TIMEOUT_WORDS.search(r["values"]),
              f"timed-out call: values should be a string saying 'timeout'/'timed out': {short(r)}")
        first = f"timeout 1.0 -> result false after {el:.2f} s: {r['values']!r}"
        # 2. The provider leaves while a call (no timeout) is pending at it.
        caller.send({"op": "call_service", "id": "slow-2", "service": NEVER, "args": {}})
        provider.wait(is_call_for(NEVER), 5, f"second call_service for {NEVER}")
        t1 = time.monotonic()
        provider.close()
        r = caller.reply_to("slow-2", ("service_response",), 5, "service_response after the provider disconnected")
        el = time.monotonic() - t1
        check(r.get("result") is False, f"pending call when the provider left: result {r.get('result')!r}: {short(r)}")
        check(el < 2.0, f"pending call failed {el:.2f} s after the provider left, want < 2 s")
        check(isinstance(r.get("values"), str) and "provider" in r["values"].lower(),
              f"call whose provider left: values should be a string mentioning the provider: {short(r)}")
        second = f"provider gone -> result false after {el:.2f} s: {r['values']!r}"
        # 3. And the service is gone: a new call fails at once.
        t2 = time.monotonic()
        caller.send({"op": "call_service", "id": "slow-3", "service": NEVER, "args": {}, "timeout": 5.0})
        r = caller.reply_to("slow-3", ("service_response",), 5, "service_response to a call after the provider left")
        el = time.monotonic() - t2
        check(r.get("result") is False and el < 2.0,
              f"call after the provider left: result {r.get('result')!r} after {el:.2f} s (want false, < 2 s): {short(r)}")
        for line in (first, second, f"afterwards -> result false after {el:.2f} s: {r.get('values')!r}"):
            note(line)
        return "timeout and provider-gone failures arrive promptly and say why"
    finally:
        provider.close()
        caller.close()


def nav_goal_towards_origin(x, y, dist):
    d = math.hypot(x, y)
    ux, uy = (-x / d, -y / d) if d > 1.5 else (1.0, 0.0)
    return round(x + dist * ux, 3), round(y + dist * uy, 3)


def status_value(s):
    return s.value if isinstance(s, GoalStatus) else s


def send_nav_goal(ctx, ac, gx, gy):
    name = f"/{ctx.robot}/navigate_to_pose"
    ctx.robot_goals[name] = ctx.robot_goals.get(name, 0) + 1
    feedback, outcome = Inbox(), Inbox()
    gid = ac.send_goal(roslibpy.Goal({"x": gx, "y": gy}),
                       lambda r: outcome.put(("resultback", dict(r))),
                       lambda f: feedback.put(dict(f)),
                       lambda e: outcome.put(("errback", dict(e) if hasattr(e, "keys") else e)))
    return gid, feedback, outcome


def check_action(ctx):
    name = f"/{ctx.robot}/navigate_to_pose"
    ac = roslibpy.ActionClient(ctx.op, name, NAV_TYPE)
    # 1. A short trip to success.
    st = ctx.status()
    dist = 1.0
    gx, gy = nav_goal_towards_origin(st["x"], st["y"], dist)
    t0 = time.monotonic()
    _, feedback, outcome = send_nav_goal(ctx, ac, gx, gy)
    kind, res = outcome.wait(1, dist / SPEED * 3 + 8, f"action_result of {name} to ({gx}, {gy})")[0]
    el = time.monotonic() - t0
    check(isinstance(res, dict), f"{name}: roslibpy {kind} got {short(res)}")
    status, values = status_value(res.get("status")), res.get("values")
    check(kind == "resultback" and status == GoalStatus.SUCCEEDED.value,
          f"{name} to ({gx}, {gy}): {kind} with status {status!r} (want resultback, SUCCEEDED 4): {short(res)}")
    check(isinstance(values, dict) and values.get("reached") is True,
          f"{name}: result values {short(values)}, want reached: true")
    rx, ry = values.get("x"), values.get("y")
    check(isinstance(rx, (int, float)) and isinstance(ry, (int, float)) and math.hypot(rx - gx, ry - gy) < 0.5,
          f"{name}: result at ({rx}, {ry}), want within 0.5 m of the goal ({gx}, {gy})")
    fbs = list(feedback.seen)
    check(len(fbs) >= 2, f"{name}: {len(fbs)} feedback message(s) before the result, want >= 2: {short(fbs)}")
    dr = [f.get("distance_remaining") for f in fbs]
    check(all(isinstance(d, (int, float)) and 0 <= d <= dist + 1.0 for d in dr),
          f"{name}: feedback distance_remaining values {short(dr)}, want numbers in [0, {dist + 1.0}]")
    check(dr[-1] < dr[0], f"{name}: distance_remaining did not decrease: {short(dr)}")
    first = (f"goal ({gx}, {gy}) {dist} m away: SUCCEEDED in {el:.1f} s at ({rx:.2f}, {ry:.2f}), "
             f"{len(fbs)} feedbacks, distance_remaining {dr[0]:.2f} -> {dr[-1]:.2f}")
    # 2. A long trip, cancelled after the first feedback.
    st = ctx.status()
    gx, gy = nav_goal_towards_origin(st["x"], st["y"], 5.0)
    gid, feedback, outcome = send_nav_goal(ctx, ac, gx, gy)
    feedback.wait(1, 5, f"first feedback of {name} to ({gx}, {gy})")
    t1 = time.monotonic()
    ac.cancel_goal(gid)
    kind, res = outcome.wait(1, 5, f"action_result after cancel_action_goal of {gid}")[0]
    el = time.monotonic() - t1
    check(isinstance(res, dict), f"{name} cancelled: roslibpy {kind} got {short(res)}")
    status, values = status_value(res.get("status")), res.get("values")
    check(status == GoalStatus.CANCELED.value,
          f"{name} cancelled: status {status!r}, want CANCELED 5 ({kind}): {short(res)}")
    check(not (isinstance(values, dict) and values.get("reached") is True),
          f"{name} cancelled, yet the result says reached: {short(values)}")
    for line in (first, f"goal ({gx}, {gy}) 5 m away cancelled after its first feedback: CANCELED "
                 f"{el:.2f} s after cancel_action_goal ({kind}, values {short(values, 120)})"):
        note(line)
    return f"{name}: feedback + SUCCEEDED, and cancel -> CANCELED"


def audit_records(a, **query):
    url = f"http://{a.api}/api/v1/audit?" + urllib.parse.urlencode({**query, "limit": 1000})
    req = urllib.request.Request(url, headers={"Authorization": f"Bearer {a.op_token}"})
    try:
        with urllib.request.urlopen(req, timeout=5) as r:
            body = json.load(r)
    except urllib.error.HTTPError as e:
        raise CheckFailed(f"GET {url}: HTTP {e.code}: {e.read()[:300]!r}") from e
    except (OSError, ValueError) as e:
        raise CheckFailed(f"GET {url}: {type(e).__name__}: {e}") from e
    check(isinstance(body, dict) and isinstance(body.get("records"), list),
          f"GET {url}: no 'records' list: {short(body)}")
    return body["records"]


def check_acl_audit(ctx):
    a = ctx.a
    name = f"/{ctx.robot}/set_mode"
    viewer = connect(a.viewer_url, f"non-admin operator {a.viewer_name}")
    try:
        ctx.viewer_denied += 1
        ok, v = call_result(viewer, name, {"data": False})
    finally:
        close(viewer)
    check(not ok, f"non-admin {a.viewer_name} calling {name}: succeeded ({short(v)}), want result false")
    check(isinstance(v, str) and "not allowed" in v,
          f"non-admin {a.viewer_name} calling {name}: values {short(v)}, want a string containing 'not allowed'")
    me, them = f"user:{a.op_name}", f"user:{a.viewer_name}"
    # Calls are audited when they end; poll briefly.
    deadline = time.monotonic() + 5
    while True:
        problems, sample = [], []
        for action, wanted in (("call_service", ctx.robot_calls), ("send_action_goal", ctx.robot_goals)):
            recs = audit_records(a, action=action, name=f"/{ctx.robot}/")
            for svc, n in sorted(wanted.items()):
                mine = [r for r in recs if r.get("name") == svc and r.get("principal") == me and r.get("allowed") is True]
                if len(mine) < n:
                    problems.append(f"{action} {svc}: {len(mine)} allowed record(s) of {me}, want >= {n} "
                                    f"(records for it: {short([r for r in recs if r.get('name') == svc][:4])})")
                bare = [r for r in mine if not (isinstance(r.get("detail"), str) and r["detail"].strip())]
                if bare:
                    problems.append(f"{action} {svc}: {len(bare)} allowed record(s) without an outcome in "
                                    f"'detail': {short(bare[:2])}")
                if svc in (name, f"/{ctx.robot}/navigate_to_pose"):
                    sample += mine[:1]
            if action == "call_service":
                denied = [r for r in recs if r.get("name") == name and r.get("principal") == them
                          and r.get("allowed") is False]
                if len(denied) < ctx.viewer_denied:
                    problems.append(f"call_service {name}: {len(denied)} denied record(s) of {them}, want "
                                    f">= {ctx.viewer_denied} (records of {them}: "
                                    f"{short([r for r in recs if r.get('principal') == them][:4])})")
                sample += denied[:1]
        if not problems or time.monotonic() > deadline:
            break
        time.sleep(0.2)
    check(not problems, "audit log: " + " | ".join(problems))
    for r in sample:
        note(f"audit: {short({k: r.get(k) for k in ('principal', 'action', 'name', 'allowed', 'detail')})}")
    return (f"{a.viewer_name} refused ({v!r}); audit holds {sum(ctx.robot_calls.values())} robot calls "
            f"and {sum(ctx.robot_goals.values())} goals allowed with outcomes, and the denial")


def names_field(msg, op, field):
    """Whether `msg` names `field` somewhere else than inside the op's own name."""
    return re.search(rf"\b{re.escape(field)}\b", msg.replace(op, " ")) is not None


def check_malformed(ctx):
    a = ctx.a
    raw = Raw(a.hub_url, "malformed-ops client")
    problems, answered = [], []

    def expect_status(what, op, id_, field=None):
        raw.send(op)
        try:
            r = raw.reply_to(id_, ("status", "service_response", "action_result"), 5, f"reply to {what}")
        except CheckFailed as e:
            problems.append(f"{what}: {e}")
            return
        msg = r.get("msg")
        if r.get("op") != "status" or r.get("level") != "error" or not isinstance(msg, str):
            problems.append(f"{what}: want a status op with level error, got {short(r)}")
        elif op["op"] not in msg:
            problems.append(f"{what}: status msg does not name the op {op['op']!r}: {msg!r}")
        elif field and not names_field(msg, op["op"], field):
            problems.append(f"{what}: status msg does not name the field {field!r}: {msg!r}")
        else:
            answered.append(f"{what}: {msg!r}")

    def expect_failure_reply(what, op, id_, target, reply_op, status_ok):
        """A reply_op with result false whose values (a string) name `target`, or where
        status_ok, a status error naming the op and `target`."""
        raw.send(op)
        try:
            r = raw.reply_to(id_, ("status", "service_response", "action_result"), 5, f"reply to {what}")
        except CheckFailed as e:
            problems.append(f"{what}: {e}")
            return
        values, msg = r.get("values"), r.get("msg")
        if r.get("op") == reply_op and r.get("result") is False and isinstance(values, str) and target in values:
            answered.append(f"{what}: {reply_op} result false, values {values!r}")
        elif (status_ok and r.get("op") == "status" and r.get("level") == "error" and isinstance(msg, str)
              and op["op"] in msg and target in msg):
            answered.append(f"{what}: status error {msg!r}")
        else:
            want = f"{reply_op} with result false and values a string naming {target}"
            if status_ok:
                want += f", or a status error naming {op['op']} and {target}"
            problems.append(f"{what}: want {want}; got {short(r)}")

    try:
        expect_status("call_service without 'service'",
                      {"op": "call_service", "id": "bad-1", "args": {}}, "bad-1", "service")
        expect_status("service_response for an unknown id",
                      {"op": "service_response", "id": "bad-2-no-such-call", "service": ADD,
                       "values": {"sum": 1}, "result": True}, "bad-2-no-such-call")
        expect_status("advertise_service without 'type'",
                      {"op": "advertise_service", "id": "bad-3", "service": "/cloud/typeless"}, "bad-3", "type")
        expect_failure_reply("call_service to an unknown service",
                             {"op": "call_service", "id": "bad-4", "service": "/no/such_service", "args": {}},
                             "bad-4", "/no/such_service", "service_response", status_ok=False)
        expect_failure_reply("send_action_goal to an unknown action",
                             {"op": "send_action_goal", "id": "bad-5", "action": "/no/such_action",
                              "action_type": "example_interfaces/action/Fibonacci", "args": {"order": 3},
                              "feedback": True}, "bad-5", "/no/such_action", "action_result", status_ok=True)
        expect_status("cancel_action_goal for an unknown id",
                      {"op": "cancel_action_goal", "id": "bad-6-no-such-goal",
                       "action": f"/{ctx.robot}/navigate_to_pose"}, "bad-6-no-such-goal")
        # The connection still works.
        raw.send({"op": "call_service", "id": "after-bad", "service": "/rosapi/get_time", "args": {}})
        try:
            r = raw.reply_to("after-bad", ("service_response", "status"), 5, "/rosapi/get_time after the bad ops")
            if not (r.get("op") == "service_response" and r.get("result") is True
                    and isinstance(r.get("values"), dict) and "time" in r["values"]):
                problems.append(f"/rosapi/get_time after the bad ops: {short(r)}")
        except CheckFailed as e:
            problems.append(str(e))
        if raw.closed.is_set():
            problems.append("the server closed the connection")
    finally:
        raw.close()
    for line in answered:
        note(line)
    try:
        check("/cloud/typeless" not in services_of(ctx.op), "advertise_service without 'type' was registered anyway")
    except CheckFailed as e:
        problems.append(str(e))
    check(not problems, " | ".join(problems))
    return "each bad op got a reply naming the problem; the connection still served /rosapi/get_time"


def check_rosapi(ctx):
    ros = ctx.op
    set_mode, get_status = f"/{ctx.robot}/set_mode", f"/{ctx.robot}/get_status"
    nav = f"/{ctx.robot}/navigate_to_pose"
    try:
        services = ros.get_services()
    except Exception as e:
        raise CheckFailed(f"ros.get_services(): {type(e).__name__}: {e}") from e
    for s in (set_mode, get_status, ADD):
        check(s in services, f"/rosapi/services lacks {s}: {services}")
    for s, want in ((set_mode, "std_srvs/srv/SetBool"), (get_status, "std_srvs/srv/Trigger"), (ADD, ADD_TYPE)):
        try:
            ty = ros.get_service_type(s)
        except Exception as e:
            raise CheckFailed(f"ros.get_service_type({s}): {type(e).__name__}: {e}") from e
        check(ty == want, f"/rosapi/service_type {s} = {ty!r}, want {want!r}")
    v = call_ok(ros, "/rosapi/service_providers", {"service": ADD})
    prov = v.get("providers")
    check(isinstance(prov, list) and prov and all(isinstance(p, str) and p for p in prov),
          f"/rosapi/service_providers {ADD}: {short(v)}, want a non-empty list of names")
    box = Inbox()
    ros.get_action_servers(box.put, lambda e: box.put({"error": e}))
    got = box.wait(1, TIMEOUT, "/rosapi/action_servers")[0]
    got = dict(got) if hasattr(got, "keys") else got
    check(isinstance(got, dict) and isinstance(got.get("action_servers"), list),
          f"/rosapi/action_servers: {short(got)}, want {{action_servers: [...]}}")
    check(nav in got["action_servers"], f"/rosapi/action_servers lacks {nav}: {got['action_servers']}")
    return (f"/rosapi/services has {set_mode}, {get_status}, {ADD}; types right; providers of {ADD}: {prov}; "
            f"action servers include {nav}")


CHECKS = [
    ("set_mode", check_set_mode),
    ("cloud_service", check_cloud_service),
    ("robot_service", check_robot_service),
    ("concurrent", check_concurrent),
    ("timeout", check_timeout),
    ("action", check_action),
    ("acl_audit", check_acl_audit),
    ("malformed", check_malformed),
    ("rosapi", check_rosapi),
]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--hub-url", required=True, help="ws://HUB/?token=ADMIN_OPERATOR_TOKEN")
    ap.add_argument("--local-url", required=True, help="the agent's local rosbridge listener, ws://HOST:PORT/")
    ap.add_argument("--robot", default="robot1")
    ap.add_argument("--viewer-url", required=True, help="ws://HUB/?token=NON_ADMIN_TOKEN (no rules)")
    ap.add_argument("--api", required=True, help="the hub's HOST:PORT for the REST API (audit log)")
    ap.add_argument("--op-token", required=True, help="the admin operator's token, for the audit log")
    ap.add_argument("--op-name", default="interop", help="the admin operator's user name (audit principal)")
    ap.add_argument("--viewer-name", default="viewer", help="the non-admin user's name (audit principal)")
    ap.add_argument("--only", action="append", choices=[n for n, _ in CHECKS],
                    help="run only these checks (repeatable; some rely on earlier ones)")
    a = ap.parse_args()
    roslibpy.set_rosapi_timeout(TIMEOUT)
    print(f"roslibpy {roslibpy.__version__} -> hub {urllib.parse.urlparse(a.hub_url).netloc}, "
          f"local {a.local_url}, robot {a.robot}", flush=True)
    ctx = Ctx(a)
    failed = []
    try:
        try:
            ctx.op = connect(a.hub_url, "admin operator (hub)")
        except CheckFailed as e:
            print(f"FAIL connect: {e}", flush=True)
            return 1
        for name, fn in CHECKS:
            if a.only and name not in a.only:
                continue
            print(f"-- {name}", flush=True)
            t0 = time.monotonic()
            try:
                detail = fn(ctx)
                print(f"ok {name} ({time.monotonic() - t0:.1f} s): {detail}", flush=True)
            except CheckFailed as e:
                failed.append(name)
                print(f"FAIL {name}: {e}", flush=True)
            except Exception as e:  # a reply of the wrong shape (KeyError, TypeError, ...)
                failed.append(name)
                print(f"FAIL {name}: {type(e).__name__}: {e}", flush=True)
    finally:
        for ros in CLIENTS:
            close(ros)
        try:
            ctx.op.terminate() if ctx.op else None
        except Exception:
            pass
    if failed:
        print(f"FAIL calls (roslibpy): {len(failed)} check(s) failed: {', '.join(failed)}", flush=True)
        return 1
    print("PASS calls (roslibpy)", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())

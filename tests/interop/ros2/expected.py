"""The values the ros2 interop suite sends, in rosbridge JSON form (what roslibpy sees at
the hub). The robot's peer (ros2_peer.py) builds its DDS samples from these, the hub's
peer (hub_peer.py) compares what arrives with them; every value is a pure function of
its index, so the two sides never need to talk to each other.

Only standard-library Python here: both peers import it.
"""
import base64
import hashlib
import struct

def scan():
    return {
        "header": {"stamp": {"sec": 1700000000, "nanosec": 250}, "frame_id": "laser"},
        "angle_min": -1.5, "angle_max": 1.5, "angle_increment": 3.0 / 359,
        "time_increment": 0.0001, "scan_time": 0.1, "range_min": 0.1, "range_max": 30.0,
        "ranges": [1.0 + 0.25 * (i % 40) for i in range(360)],
        "intensities": [float(i % 7) for i in range(360)],
    }


POINTS = 100_000


def cloud_data():
    """100,000 points of x, y, z (float32, little endian), 12 bytes each."""
    return b"".join(struct.pack("<fff", i * 0.5, -i * 0.25, 2.0) for i in range(POINTS))


def cloud_sha256():
    return hashlib.sha256(cloud_data()).hexdigest()


def cloud(data=None):
    """The PointCloud2 message; `data` is left out (None) unless given."""
    return {
        "header": {"stamp": {"sec": 1700000001, "nanosec": 500}, "frame_id": "lidar"},
        "height": 1, "width": POINTS,
        "fields": [{"name": n, "offset": 4 * i, "datatype": 7, "count": 1} for i, n in enumerate("xyz")],
        "is_bigendian": False, "point_step": 12, "row_step": 12 * POINTS, "data": data, "is_dense": True,
    }


def battery(n):
    return {
        "label": f"battery-{n}",
        "voltage": 14.0 + 0.25 * (n % 4),
        "cells": 4,
        "balance_mv": [n % 1000, -(n % 1000), 7],
        "temps": [20.5, 21.25, 0.1 * n],
        "stamp": {"sec": 1700000000 + n, "nanosec": 999_999_999},
    }


def robot_description():
    """A URDF-ish text of about 6 kB: more than one Ethernet-sized fragment."""
    links = "".join(f'  <link name="link_{i}"/>\n' for i in range(250))
    return f'<robot name="fltest">\n{links}</robot>\n'


# What the hub publishes on /<robot>/cmd_vel: every field a different value.
TWIST = {"linear": {"x": 0.5, "y": -0.25, "z": 0.0}, "angular": {"x": 0.0, "y": 0.0, "z": 0.25}}
# What the hub's roslibpy publisher sends: TWIST with its zero fields left out, which the
# hub completes with their defaults before the robot gets it (as rosbridge would).
TWIST_PARTIAL = {"linear": {"x": 0.5, "y": -0.25}, "angular": {"z": 0.25}}

ANNOUNCE = "hello fleet"  # the hub's latched /<robot>/announce
GREETING = "hello from the fleet"  # the answer of the hub's /cloud/greet
ONESHOT = "only once"  # the single message of the hub's /<robot>/oneshot

# A node's parameters on the robot: name -> (rcl_interfaces ParameterType, value).
# "serial" is read-only.
PARAMETER_NODE = "/nav_node"
PARAMETERS = {
    "max_speed": (3, 1.5),
    "robot_name": (4, "robot-1"),
    "use_sim_time": (1, False),
    "waypoints": (7, [1, 2, 3]),
    "serial": (4, "SN-42"),
}


def fibonacci(order):
    """The result of example_interfaces' Fibonacci example for `order` (int32 wrap-around,
    so long goals stay representable)."""
    seq = [0, 1]
    for i in range(1, order):
        seq.append(wrap_int32(seq[i] + seq[i - 1]))
    return seq


def wrap_int32(v):
    return (v + 2**31) % 2**32 - 2**31


def f32(x):
    """x rounded to float32, the way it travels in a float32 field."""
    return struct.unpack("<f", struct.pack("<f", x))[0]


# ---------------------------------------------------------------- comparisons
# Each takes a message in rosbridge JSON form and returns a list of problems (empty when
# the message is the expected one). float32 fields are compared after rounding both
# sides to float32: the JSON may print a float32 either way (0.1 or 0.10000000149011612).

def _diff(path, got, want, float32=False):
    if isinstance(want, dict):
        if not isinstance(got, dict) or set(got) != set(want):
            return [f"{path}: {_short(got)}, want keys {sorted(want)}"]
        return [p for k in want for p in _diff(f"{path}.{k}", got[k], want[k], float32)]
    if isinstance(want, list):
        if not isinstance(got, list) or len(got) != len(want):
            return [f"{path}: {_short(got)}, want {len(want)} items"]
        bad = [i for i, (g, w) in enumerate(zip(got, want)) if _diff("", g, w, float32)]
        return [f"{path}[{bad[0]}]: {got[bad[0]]!r}, want {want[bad[0]]!r} ({len(bad)} items differ)"] if bad else []
    if isinstance(want, float) and float32:
        ok = isinstance(got, (int, float)) and not isinstance(got, bool) and f32(got) == f32(want)
    elif isinstance(want, bool) or isinstance(got, bool):
        ok = got is want
    else:
        ok = got == want
    return [] if ok else [f"{path}: {got!r}, want {want!r}"]


def _short(v, n=120):
    s = repr(v)
    return s if len(s) <= n else s[:n] + "..."


def check_scan(m):
    want = scan()
    return (_diff("scan.header", m.get("header"), want.pop("header"))
            + _diff("scan", {k: m.get(k) for k in want}, want, float32=True)
            + _extra("scan", m, scan()))


def check_cloud(m):
    """PointCloud2: `data` (uint8[]) arrives base64-encoded in rosbridge JSON (a list of
    numbers is accepted too); compared by length and SHA-256."""
    want = cloud()
    problems = _diff("points", {k: m.get(k) for k in want if k != "data"},
                     {k: v for k, v in want.items() if k != "data"}) + _extra("points", m, want)
    data = m.get("data")
    try:
        raw = base64.b64decode(data, validate=True) if isinstance(data, str) else bytes(data)
    except Exception as e:
        return problems + [f"points.data: not base64 or a byte list ({type(data).__name__}: {e})"]
    if len(raw) != 12 * POINTS or hashlib.sha256(raw).hexdigest() != cloud_sha256():
        problems.append(f"points.data: {len(raw)} bytes, sha256 {hashlib.sha256(raw).hexdigest()[:16]}..., "
                        f"want {12 * POINTS} bytes, sha256 {cloud_sha256()[:16]}...")
    return problems


def check_battery(m):
    """fltest_msgs/msg/Battery: any index n, the rest must follow from it."""
    label = m.get("label")
    try:
        n = int(str(label).split("-")[1])
    except (IndexError, ValueError):
        return [f"battery.label: {label!r}, want 'battery-<n>'"]
    want = battery(n)
    return (_diff("battery", {k: m.get(k) for k in ("voltage",)}, {"voltage": want["voltage"]}, float32=True)
            + _diff("battery", {k: m.get(k) for k in want if k != "voltage"},
                    {k: v for k, v in want.items() if k != "voltage"})
            + _extra("battery", m, want))


def _extra(what, got, want):
    extra = sorted(set(got) - set(want))
    return [f"{what}: unexpected fields {extra}"] if extra else []


def chatter_problems(counts, own, own_sent, other, other_sent, side):
    """The loop check of one side's /chatter counts ({text: times seen}), after both
    sides stopped publishing and a quiet period. `own`-1 .. `own`-<own_sent> were
    published on this side, `other`-1 .. `other`-<other_sent> on the other one.
      - every text seen exactly once: a second copy is a loop (or a duplicate);
      - of each side's messages, none missing after the first one seen (the first few
        may go before the route is up; after that the bridge is reliable);
      - at least 5 of the other side's messages crossed."""
    problems = [f"{side} saw {k} {c} times" for k, c in sorted(counts.items()) if c != 1]
    for prefix, sent in ((own, own_sent), (other, other_sent)):
        seen = sorted(int(k.split("-")[1]) for k in counts if k.startswith(prefix + "-"))
        if prefix == other and len(seen) < 5:
            problems.append(f"only {len(seen)} {other} messages reached the {side}")
        if seen:
            missing = sorted(set(range(seen[0], sent + 1)) - set(seen))
            if missing:
                problems.append(f"{side} missed {len(missing)} {prefix} messages after the first it saw "
                                f"({prefix}-{seen[0]}): {[f'{prefix}-{k}' for k in missing[:4]]}")
    strange = [k for k in counts if not k.startswith((own + "-", other + "-"))]
    if strange:
        problems.append(f"{side} saw unexpected texts {strange[:3]}")
    return problems[:6]

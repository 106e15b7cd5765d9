#!/usr/bin/env python3
"""Live cross-check of the fleetlink binary against the real peers.

For every committed vector: `fleetlink msg encode` turns the JSON value into bytes,
which must equal the peer's bytes and which the peer (rosbags for CDR, rospy for ROS 1)
must decode to the same message; `fleetlink msg decode` turns the peer's bytes into
JSON, which must denote the same value.
Usage: peer_check.py FLEETLINK_BIN
"""
import base64
import importlib
import io
import json
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
VECTORS = os.path.join(ROOT, "crates", "msg", "tests", "vectors")
FIXTURES = os.path.join(ROOT, "crates", "msg", "tests", "fixtures")
sys.path.insert(0, HERE)
import gen_vectors  # noqa: E402


def run(binary, args, data):
    p = subprocess.run([binary, "msg", "--msg-path", FIXTURES, *args], input=data,
                       capture_output=True, timeout=30)
    if p.returncode != 0:
        raise RuntimeError(f"fleetlink msg {' '.join(args)} failed: {p.stderr.decode(errors='replace')[:300]}")
    return p.stdout


def same(a, b):
    """JSON-level equality; floats compare as float32 or float64, null == NaN."""
    if isinstance(a, dict) and isinstance(b, dict):
        keys = set(a) | set(b)
        return all(same(a.get(k), b.get(k)) for k in keys if k != "structure_needs_at_least_one_member")
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
    if isinstance(a, (int, float)) and isinstance(b, (int, float)) and not isinstance(a, bool):
        return a == b or gen_vectors.f32(a) == gen_vectors.f32(b)
    return a == b


def main():
    binary = sys.argv[1]
    from rosbags.typesys import get_typestore, Stores
    store = get_typestore(Stores.EMPTY)
    types, _ = gen_vectors.load_ros2_types()
    store.register(types)
    failures, checked = [], 0
    for line in open(os.path.join(VECTORS, "cdr.jsonl")):
        v = json.loads(line)
        ty, theirs = v["type"], bytes.fromhex(v["cdr"])
        rb = gen_vectors.rosbags_name(ty)
        try:
            ours = run(binary, ["encode", ty, "--format", "cdr"], json.dumps(v["json"]).encode())
            if ours != theirs:
                failures.append(f"cdr encode {ty} [{v['mode']}]: bytes differ")
            back = store.deserialize_cdr(ours, rb)
            if bytes(store.serialize_cdr(back, rb)) != theirs:
                failures.append(f"cdr {ty} [{v['mode']}]: rosbags decodes our bytes to another value")
            decoded = json.loads(run(binary, ["decode", ty, "--format", "cdr"], theirs))
            if not same(decoded, v["json"]):
                failures.append(f"cdr decode {ty} [{v['mode']}]: JSON differs: {decoded} vs {v['json']}")
        except Exception as e:  # noqa: BLE001 - report and continue
            failures.append(f"cdr {ty} [{v['mode']}]: {e}")
        checked += 1
    ros1_checked = 0
    for line in open(os.path.join(VECTORS, "ros1.jsonl")):
        v = json.loads(line)
        ty, theirs = v["type"], bytes.fromhex(v["ros1"])
        pkg, name = ty.split("/")
        try:
            cls = None
            for kind in ("msg", "srv"):
                try:
                    cls = cls or getattr(importlib.import_module(f"{pkg}.{kind}"), name, None)
                except ImportError:
                    pass
            if cls is None:
                raise RuntimeError(f"rospy has no class for {ty}")
            ours = run(binary, ["encode", ty, "--format", "ros1"], json.dumps(v["json"]).encode())
            if ours != theirs:
                failures.append(f"ros1 encode {ty} [{v['mode']}]: bytes differ")
            msg = cls().deserialize(ours)
            buf = io.BytesIO()
            msg.serialize(buf)
            if buf.getvalue() != theirs:
                failures.append(f"ros1 {ty} [{v['mode']}]: rospy decodes our bytes to another value")
            decoded = json.loads(run(binary, ["decode", ty, "--format", "ros1"], theirs))
            if not same(decoded, v["json"]):
                failures.append(f"ros1 decode {ty} [{v['mode']}]: JSON differs")
        except Exception as e:  # noqa: BLE001
            failures.append(f"ros1 {ty} [{v['mode']}]: {e}")
        ros1_checked += 1
    print(f"checked {checked} CDR vectors against rosbags and {ros1_checked} ROS 1 vectors against rospy")
    for f in failures[:20]:
        print("FAIL", f)
    if failures:
        print(f"{len(failures)} failures")
        sys.exit(1)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Generates the cross-check vectors for fleetlink-msg from the real peers.

CDR: our bundled ROS 2 definitions (crates/msg/defs/ros2) and the test fixtures are
registered in rosbags (PyPI); rosbags serializes seeded random and edge values; each
vector is the value in rosbridge JSON form plus the bytes rosbags produced; rosbags'
REP-2016 hash of every type is recorded too.
ROS 1: Debian's rospy/genpy message classes serialize seeded random values; each vector
records the JSON value, the bytes, and per type the md5sum and full text rospy carries.

Usage: gen_vectors.py OUT_DIR   (run via the venv made by scripts/setup.d/30-msg-peers.sh)
The output is deterministic; tests/interop/msg/run.sh regenerates and diffs it.
"""
import base64
import importlib
import io
import json
import math
import os
import random
import struct
import sys
import zlib

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
DEFS = os.path.join(ROOT, "crates", "msg", "defs", "ros2")
FIXTURES = os.path.join(ROOT, "crates", "msg", "tests", "fixtures")

INT_RANGES = {
    "int8": (-2**7, 2**7 - 1), "uint8": (0, 2**8 - 1), "byte": (0, 255), "char": (0, 255),
    "int16": (-2**15, 2**15 - 1), "uint16": (0, 2**16 - 1),
    "int32": (-2**31, 2**31 - 1), "uint32": (0, 2**32 - 1),
    "int64": (-2**63, 2**63 - 1), "uint64": (0, 2**64 - 1),
}
TEXTS = ["", "a", "fleetlink", "ünïcödé", "日本語テキスト", "emoji 🚀🤖", "tab\tquote\"back\\slash", "line\nbreak"]
MODES = ["zero", "edge", "rand1", "rand2"]


def f32(x):
    return struct.unpack("<f", struct.pack("<f", x))[0]


def rng_for(typename, mode):
    return random.Random(zlib.crc32(f"{typename}:{mode}".encode()))


def rand_float(rng, mode, single):
    if mode == "zero":
        return 0.0
    if mode == "edge":
        x = rng.choice([math.nan, -0.0, 1e-30, -3.4e38 if single else -1.7e308, 3.4e38 if single else 1.7e308])
    else:
        x = rng.choice([rng.uniform(-1e6, 1e6), rng.uniform(-1, 1), float(rng.randint(-1000, 1000)), math.nan])
    return f32(x) if single else x


def rand_int(rng, mode, typ):
    lo, hi = INT_RANGES[typ]
    if mode == "zero":
        return 0
    if mode == "edge":
        return rng.choice([lo, hi])
    return rng.randint(lo, hi)


def rand_text(rng, mode, bound):
    if mode == "zero":
        return ""
    t = rng.choice(TEXTS[1:]) if mode == "edge" else rng.choice(TEXTS)
    if bound:
        t = "".join(rng.choice("abcxyz") for _ in range(bound if mode == "edge" else rng.randint(0, bound)))
    return t


def seq_len(rng, mode, bound, nested):
    if mode == "zero":
        return 0
    if mode == "edge":
        return bound if bound else (1 if nested else 5)
    return rng.randint(0, min(bound or 3, 3) if nested else (bound or 6))


def float_json(x):
    return None if math.isnan(x) else x


# ---------------------------------------------------------------- CDR via rosbags

def load_ros2_types():
    from rosbags.typesys import get_types_from_msg
    types = {}
    sources = []
    for base in (DEFS, FIXTURES):
        for pkg in sorted(os.listdir(base)):
            for kind in ("msg", "srv", "action"):
                d = os.path.join(base, pkg, kind)
                if not os.path.isdir(d):
                    continue
                for f in sorted(os.listdir(d)):
                    name, ext = os.path.splitext(f)
                    if ext != "." + kind:
                        continue
                    with open(os.path.join(d, f)) as fh:
                        text = fh.read()
                    sections = [s for s in split_sections(text)]
                    suffixes = {"msg": [""], "srv": ["_Request", "_Response"],
                                "action": ["_Goal", "_Result", "_Feedback"]}[kind]
                    for suffix, body in zip(suffixes, sections):
                        sources.append((f"{pkg}/{kind}/{name}{suffix}", body))
                    if kind == "action":
                        n = name
                        for suffix, body in [
                            ("_SendGoal_Request", f"unique_identifier_msgs/UUID goal_id\n{n}_Goal goal\n"),
                            ("_SendGoal_Response", "bool accepted\nbuiltin_interfaces/Time stamp\n"),
                            ("_GetResult_Request", "unique_identifier_msgs/UUID goal_id\n"),
                            ("_GetResult_Response", f"int8 status\n{n}_Result result\n"),
                            ("_FeedbackMessage", f"unique_identifier_msgs/UUID goal_id\n{n}_Feedback feedback\n"),
                        ]:
                            sources.append((f"{pkg}/action/{n}{suffix}", body))
    for name, body in sources:
        types.update(get_types_from_msg(body, rosbags_name(name)))
    return types, [name for name, _ in sources]


def rosbags_name(name):
    """rosbags resolves relative names only for `pkg/msg/T`, so service and action
    parts are registered there; their bytes do not depend on the name."""
    pkg, _, t = name.split("/")
    return f"{pkg}/msg/{t}"


def split_sections(text):
    sections, cur = [], []
    for line in text.splitlines():
        if line.strip() == "---":
            sections.append("\n".join(cur) + "\n")
            cur = []
        else:
            cur.append(line)
    sections.append("\n".join(cur) + "\n")
    return sections


def gen_cdr(store, typename, rng, mode, depth=0):
    from rosbags.typesys.store import Nodetype
    _, fields = store.fielddefs[typename]
    cls = store.types[typename]
    kwargs, js = {}, {}
    for name, (nt, det) in fields:
        if name == "structure_needs_at_least_one_member":
            # The placeholder of empty messages: always 0 on the wire, absent in JSON.
            kwargs[name] = 0
            continue
        kwargs[name], js[name] = gen_node(store, nt, det, rng, mode, depth)
    return cls(**kwargs), js


def gen_node(store, nt, det, rng, mode, depth):
    import numpy as np
    from rosbags.typesys.store import Nodetype
    if nt == Nodetype.BASE:
        typ, bound = det
        if typ == "bool":
            v = mode != "zero" and rng.random() < 0.5
            return v, v
        if typ == "byte":
            # rosbags packs `byte` as signed; ROS 2 (and fleetlink) read it as an octet.
            v = rand_int(rng, mode, "int8")
            return v, v & 0xFF
        if typ in INT_RANGES:
            v = rand_int(rng, mode, typ)
            return v, v
        if typ in ("float32", "float64"):
            v = rand_float(rng, mode, typ == "float32")
            return v, float_json(v)
        if typ == "string":
            v = rand_text(rng, mode, bound)
            return v, v
        raise SystemExit(f"unsupported base type {typ}")
    if nt == Nodetype.NAME:
        return gen_cdr(store, det, rng, mode, depth + 1)
    (ent, edet), size = det
    if nt == Nodetype.ARRAY:
        n = size
    else:
        n = seq_len(rng, mode, size, ent == Nodetype.NAME)
        if depth > 2:
            n = min(n, 1)
    items = [gen_node(store, ent, edet, rng, mode, depth + 1) for _ in range(n)]
    if ent == Nodetype.BASE and edet[0] not in ("string",):
        typ = edet[0]
        dtype = {"bool": np.bool_, "int8": np.int8, "uint8": np.uint8, "byte": np.int8, "char": np.uint8,
                 "int16": np.int16, "uint16": np.uint16, "int32": np.int32, "uint32": np.uint32,
                 "int64": np.int64, "uint64": np.uint64, "float32": np.float32, "float64": np.float64}[typ]
        arr = np.array([i[0] for i in items], dtype=dtype)
        if typ in ("uint8", "byte", "char"):
            return arr, base64.b64encode(arr.astype(np.uint8).tobytes()).decode()
        return arr, [i[1] for i in items]
    return [i[0] for i in items], [i[1] for i in items]


def cdr_vectors(out):
    from rosbags.typesys import get_typestore, Stores
    store = get_typestore(Stores.EMPTY)
    types, names = load_ros2_types()
    store.register(types)
    with open(os.path.join(out, "cdr.jsonl"), "w") as fh:
        for name in sorted(set(names)):
            for mode in MODES:
                rb = rosbags_name(name)
                msg, js = gen_cdr(store, rb, rng_for(name, mode), mode)
                data = bytes(store.serialize_cdr(msg, rb))
                back = store.deserialize_cdr(data, rb)
                if bytes(store.serialize_cdr(back, rb)) != data:
                    raise SystemExit(f"rosbags does not round-trip {name}")
                vector = {"type": name, "mode": mode, "json": js, "cdr": data.hex()}
                if mode == "rand1":
                    # Big-endian CDR of the same value, for the reader's byte-order path.
                    vector["cdr_be"] = bytes(store.serialize_cdr(msg, rb, little_endian=False)).hex()
                fh.write(json.dumps(vector, ensure_ascii=False, sort_keys=True) + "\n")
    with open(os.path.join(out, "rihs01.json"), "w") as fh:
        json.dump({n: store.hash_rihs01(n) for n in sorted(set(names)) if "/msg/" in n}, fh, indent=1, sort_keys=True)
        fh.write("\n")
    return sorted(set(names))


# ---------------------------------------------------------------- ROS 1 via rospy

ROS1_PRIMS = set(INT_RANGES) | {"bool", "float32", "float64", "string", "time", "duration"}


def ros1_class(typename):
    pkg, kind, name = typename.split("/")
    try:
        mod = importlib.import_module(f"{pkg}.{kind}")
    except ImportError:
        return None
    return getattr(mod, name, None)


def gen_ros1(cls, rng, mode, depth=0):
    import genpy
    msg = cls()
    js = {}
    for slot, typ in zip(cls.__slots__, cls._slot_types):
        v, j = gen_ros1_field(typ, rng, mode, depth)
        setattr(msg, slot, v)
        js[slot] = j
    return msg, js


def gen_ros1_field(typ, rng, mode, depth):
    import genpy
    from genpy.message import get_message_class
    if "[" in typ:
        base, rest = typ.split("[", 1)
        size = rest[:-1]
        nested = base not in ROS1_PRIMS
        n = int(size) if size else seq_len(rng, mode, 0, nested)
        if depth > 2 and not size:
            n = min(n, 1)
        if base in ("uint8", "char"):
            b = bytes(rand_int(rng, mode, "uint8") for _ in range(n))
            return b, base64.b64encode(b).decode()
        items = [gen_ros1_field(base, rng, mode, depth + 1) for _ in range(n)]
        return [i[0] for i in items], [i[1] for i in items]
    if typ == "bool":
        v = mode != "zero" and rng.random() < 0.5
        return v, v
    if typ in INT_RANGES:
        v = rand_int(rng, mode, "int8" if typ == "byte" else typ)
        return v, v
    if typ in ("float32", "float64"):
        v = rand_float(rng, mode, typ == "float32")
        return v, float_json(v)
    if typ == "string":
        v = rand_text(rng, mode, 0)
        return v, v
    if typ in ("time", "duration"):
        if typ == "time":
            secs = rand_int(rng, mode, "uint32")
            v = genpy.Time(secs, 0 if mode == "zero" else rng.randint(0, 999_999_999))
        else:
            secs = rand_int(rng, mode, "int32")
            v = genpy.Duration(secs, 0 if mode == "zero" else rng.randint(0, 999_999_999))
        return v, {"secs": v.secs, "nsecs": v.nsecs}
    return gen_ros1(get_message_class(typ), rng, mode, depth + 1)


def ros1_vectors(out, ros2_names):
    wanted = []
    for n in ros2_names:
        pkg, kind, name = n.split("/")
        if kind == "srv":
            for suffix, ros1 in (("_Request", "Request"), ("_Response", "Response")):
                if name.endswith(suffix):
                    wanted.append((f"{pkg}/srv/{name[: -len(suffix)]}{ros1}", n))
        elif kind == "msg":
            wanted.append((n, n))
    wanted += [("std_msgs/msg/Time", None), ("std_msgs/msg/Duration", None)]
    types, services = {}, {}
    with open(os.path.join(out, "ros1.jsonl"), "w") as fh:
        for ros1_name, _ in sorted(set(wanted)):
            cls = ros1_class(ros1_name)
            if cls is None:
                continue
            types[cls._type] = {"md5": cls._md5sum, "full_text": cls._full_text}
            for mode in MODES:
                msg, js = gen_ros1(cls, rng_for(cls._type, mode), mode)
                buf = io.BytesIO()
                msg.serialize(buf)
                fh.write(json.dumps({"type": cls._type, "mode": mode, "json": js, "ros1": buf.getvalue().hex()},
                                    ensure_ascii=False, sort_keys=True) + "\n")
    for n in ros2_names:
        pkg, kind, name = n.split("/")
        if kind == "srv" and name.endswith("_Request"):
            srv = ros1_class(f"{pkg}/srv/{name[:-8]}")
            if srv is not None:
                services[srv._type] = srv._md5sum
    with open(os.path.join(out, "ros1_types.json"), "w") as fh:
        json.dump({"messages": types, "services": services}, fh, indent=1, sort_keys=True, ensure_ascii=False)
        fh.write("\n")


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "crates", "msg", "tests", "vectors")
    os.makedirs(out, exist_ok=True)
    names = cdr_vectors(out)
    ros1_vectors(out, names)
    print(f"vectors written to {out}")


if __name__ == "__main__":
    main()

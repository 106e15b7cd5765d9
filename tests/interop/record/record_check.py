#!/usr/bin/env python3
"""MCAP recording on the hub and replay, checked with the reference MCAP readers.

Needs hub A (--hub) with --robot online (simulated laser scan with --scan-ranges beams,
odometry), an empty hub B (--hub2), an admin operator token for each, and a token
without rights on hub A. The checks, in order:

  refused      `fleetlink record` with the token without rights fails, naming the refusal
  record       `fleetlink record` starts a recording of the robot's scan, odometry and
               camera video and of /interop/.*; a roslibpy client publishes 100 std_msgs/String at 20 Hz,
               a Foxglove WebSocket client 20 ROS 1 std_msgs/String; `fleetlink record
               stop`, `list --json` and `download`
  read         Python's mcap reader (indexed, with summary) and its stream reader:
               channels with their schemas and encodings, counts equal to the hub's,
               chunks zstd and at most 4 MiB, the recording's metadata (no drops); every
               message decoded by mcap-ros2-support / mcap-ros1-support: the strings as
               published, in order; scans with the configured beams and sane values;
               the video's frames decoded by FFmpeg's H.264 decoder (PyAV) from the
               first message on, which is a keyframe
  replay       `fleetlink play` of the file to hub B: a roslibpy subscriber there gets the
               100 strings, in order, with the recorded spacing (median and span within
               10 %)

Prints `ok <check>` or `FAIL <check>: why`; exits 1 on the first failure. Every wait is
bounded.
"""

import argparse
import json
import os
import statistics
import struct
import subprocess
import sys
import threading
import time
import urllib.parse

import roslibpy
from mcap.reader import make_reader
from mcap.stream_reader import StreamReader
from mcap.records import Message as McapMessage
from mcap_ros1.decoder import DecoderFactory as Ros1Decoders
from mcap_ros2.decoder import DecoderFactory as Ros2Decoders
from websockets.sync.client import connect as ws_connect

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "video"))
from video_peer import decode_frames  # noqa: E402

TIMEOUT = 15.0
CHATTER = "/interop/chatter"
LEVEL = "/interop/level"
N_CHATTER = 100
N_LEVEL = 20
PERIOD = 0.05  # s between the strings


class CheckFailed(Exception):
    pass


def check(cond, why):
    if not cond:
        raise CheckFailed(why)


def run(args, *cmd, ok=True, timeout=60):
    """Runs the fleetlink binary; returns (rc, stdout, stderr)."""
    p = subprocess.run([args.bin, *cmd], capture_output=True, text=True, timeout=timeout)
    if ok and p.returncode != 0:
        raise CheckFailed(f"fleetlink {' '.join(cmd[:2])} failed ({p.returncode}): {p.stderr.strip()}")
    return p.returncode, p.stdout, p.stderr


def connect(url, token):
    u = urllib.parse.urlparse(url)
    ros = roslibpy.Ros(host=u.hostname, port=u.port, headers={"Authorization": f"Bearer {token}"})
    ros.run(timeout=TIMEOUT)
    check(ros.is_connected, f"roslibpy could not connect to {url}")
    return ros


def ros1_string(s):
    b = s.encode()
    return struct.pack("<I", len(b)) + b


def foxglove_publish_ros1(hub, token, topic, texts):
    """Publishes std_msgs/String in ROS 1 encoding as a Foxglove client does."""
    url = f"{hub}/?token={token}"
    with ws_connect(url, subprotocols=["foxglove.websocket.v1"], open_timeout=TIMEOUT) as ws:
        info = json.loads(ws.recv(timeout=TIMEOUT))
        check(info.get("op") == "serverInfo", f"foxglove: first message {info}")
        check("clientPublish" in info.get("capabilities", []), f"foxglove: no clientPublish in {info}")
        ws.send(json.dumps({"op": "advertise", "channels": [{
            "id": 7, "topic": topic, "encoding": "ros1", "schemaName": "std_msgs/String",
            "schema": "string data\n", "schemaEncoding": "ros1msg"}]}))
        for t in texts:
            ws.send(b"\x01" + struct.pack("<I", 7) + ros1_string(t))
            time.sleep(PERIOD)
        # A status error would mean the hub refused something: none may come.
        try:
            while True:
                m = ws.recv(timeout=0.5)
                if isinstance(m, str) and '"status"' in m and '"level":2' in m.replace(" ", ""):
                    raise CheckFailed(f"foxglove publish refused: {m}")
        except TimeoutError:
            pass


def has_idr(au):
    """Whether an H.264 access unit (Annex B) holds an IDR slice (NAL type 5)."""
    at = au.find(b"\x00\x00\x01")
    while at >= 0 and at + 3 < len(au):
        if au[at + 3] & 0x1F == 5:
            return True
        at = au.find(b"\x00\x00\x01", at + 3)
    return False


def step_refused(args):
    rc, _, err = run(args, "record", "--hub", args.hub, "--token", args.denied_token,
                     "--topics", "/robot1/.*", ok=False)
    check(rc != 0, "a token without rights started a recording")
    check("403" in err and "recordings" in err, f"the refusal does not say why: {err.strip()}")


def step_record(args):
    ros = connect(args.hub, args.op_token)
    pub = roslibpy.Topic(ros, CHATTER, "std_msgs/msg/String")
    pub.advertise()
    time.sleep(0.3)
    _, out, _ = run(args, "record", "--hub", args.hub, "--token", args.op_token, "--topics",
                    f"/{args.robot}/(scan|odom|camera/video)", "/interop/.*", "--name", "interop")
    rec_id = out.split()[0]
    check(rec_id.startswith("rec-"), f"no recording id in: {out}")
    threading.Thread(target=foxglove_publish_ros1, daemon=True,
                     args=(args.hub, args.op_token, LEVEL, [f"level {i}" for i in range(N_LEVEL)])).start()
    for i in range(N_CHATTER):
        pub.publish(roslibpy.Message({"data": f"msg {i}"}))
        time.sleep(PERIOD)
    time.sleep(1.0)
    _, out, _ = run(args, "record", "stop", rec_id, "--hub", args.hub, "--token", args.op_token)
    check(" stopped " in out, f"stop: {out}")
    _, out, _ = run(args, "record", "list", "--json", "--hub", args.hub, "--token", args.op_token)
    info = next((r for r in json.loads(out)["recordings"] if r["id"] == rec_id), None)
    check(info is not None, f"{rec_id} not listed: {out[:300]}")
    check(info["state"] == "stopped" and info["dropped"] == 0, f"recording: {info}")
    check(info["started_by"] == "user:interop", f"started_by: {info['started_by']}")
    os.makedirs(args.work, exist_ok=True)
    run(args, "record", "download", rec_id, "--hub", args.hub, "--token", args.op_token, "--out", args.work)
    files = [os.path.join(args.work, f["name"]) for f in info["files"]]
    check(len(files) == 1 and os.path.getsize(files[0]) == info["files"][0]["bytes"],
          f"downloaded files differ from {info['files']}")
    pub.unadvertise()
    ros.close()
    return info, files[0]


def step_read(args, info, path):
    with open(path, "rb") as f:
        reader = make_reader(f, decoder_factories=[Ros2Decoders(), Ros1Decoders()])
        header = reader.get_header()
        check(header.library.startswith("fleetlink"), f"library {header.library!r}")
        summary = reader.get_summary()
        check(summary is not None and summary.statistics is not None, "no summary with statistics")
        check(summary.statistics.message_count == info["messages"],
              f"{summary.statistics.message_count} messages in the summary, the hub says {info['messages']}")
        check(summary.chunk_indexes, "no chunk indexes")
        for c in summary.chunk_indexes:
            check(c.compression == "zstd", f"chunk compression {c.compression!r}")
            check(c.uncompressed_size <= 4 << 20, f"chunk of {c.uncompressed_size} bytes")
        by_topic = {c.topic: c for c in summary.channels.values()}
        want = {
            f"/{args.robot}/scan": ("cdr", "ros2msg", "sensor_msgs/msg/LaserScan"),
            f"/{args.robot}/odom": ("cdr", "ros2msg", "nav_msgs/msg/Odometry"),
            f"/{args.robot}/camera/video": ("cdr", "ros2msg", "foxglove_msgs/msg/CompressedVideo"),
            CHATTER: ("cdr", "ros2msg", "std_msgs/msg/String"),
            LEVEL: ("ros1", "ros1msg", "std_msgs/String"),
        }
        check(set(by_topic) == set(want), f"channels {sorted(by_topic)}")
        for topic, (menc, senc, name) in want.items():
            c = by_topic[topic]
            s = summary.schemas[c.schema_id]
            check((c.message_encoding, s.encoding, s.name) == (menc, senc, name),
                  f"{topic}: {c.message_encoding} {s.encoding} {s.name}")
            if menc == "cdr":
                check("reliability" in c.metadata.get("offered_qos_profiles", ""),
                      f"{topic}: no offered_qos_profiles in {c.metadata}")
        scan_schema = summary.schemas[by_topic[f"/{args.robot}/scan"].schema_id].data.decode()
        check("MSG: std_msgs/Header" in scan_schema, "the scan's schema lacks its dependencies")
        meta = {m.name: m.metadata for m in reader.iter_metadata()}
        check(meta.get("fleetlink.recording", {}).get("dropped") == "0",
              f"metadata {meta}")

        texts, levels, scans, odoms, video = [], [], 0, 0, []
        counted = 0
        for _schema, channel, _msg, decoded in reader.iter_decoded_messages():
            counted += 1
            if channel.topic.endswith("/camera/video"):
                t = decoded.timestamp
                video.append((decoded.format, bytes(decoded.data), t.sec * 1_000_000_000 + t.nanosec))
            elif channel.topic == CHATTER:
                texts.append(decoded.data)
            elif channel.topic == LEVEL:
                levels.append(decoded.data)
            elif channel.topic.endswith("/scan"):
                scans += 1
                check(len(decoded.ranges) == args.scan_ranges, f"scan with {len(decoded.ranges)} ranges")
                check(decoded.angle_min < decoded.angle_max and decoded.range_max > 0, "scan limits")
                check(decoded.header.frame_id != "", "scan without frame_id")
            else:
                odoms += 1
                p = decoded.pose.pose.position
                check(all(abs(v) < 1e6 for v in (p.x, p.y, p.z)), f"odometry position {p}")
        check(counted == info["messages"], f"read {counted} messages, the hub wrote {info['messages']}")
        check(texts == [f"msg {i}" for i in range(N_CHATTER)], f"strings read back: {texts[:3]}… ({len(texts)})")
        check(levels == [f"level {i}" for i in range(N_LEVEL)], f"ROS 1 strings read back: {levels[:3]}… ({len(levels)})")
        # The recording ran for over 6 s: at 10 and 20 Hz, well over these.
        check(scans >= 30 and odoms >= 60, f"{scans} scans, {odoms} odometry messages")
        # The camera's video, as Foxglove would play it from the file: every frame decodes
        # from the first, which is a keyframe (the hub's kept group, or the one asked for).
        check(video and video[0][0] == "h264" and has_idr(video[0][1]),
              f"the recording's first video frame is not an H.264 keyframe ({len(video)} frames)")
        decoded, _, found, failed = decode_frames(video, "320x240")
        check(not failed, f"the recorded video: {found}: {'; '.join(failed)}")
        # 90 frames in 6 s at 15 fps; a floor, for a loaded machine.
        check(decoded >= 20, f"the recorded video: {found}; want at least 20 frames")
        print(f"  video: {found}")
    with open(path, "rb") as f:
        streamed = sum(1 for r in StreamReader(f).records if isinstance(r, McapMessage))
    check(streamed == info["messages"], f"the stream reader found {streamed} messages")
    return scans, odoms


def chatter_times(path):
    with open(path, "rb") as f:
        reader = make_reader(f)
        return [m.log_time / 1e9 for _s, _c, m in reader.iter_messages(topics=[CHATTER])]


def step_replay(args, path):
    ros = connect(args.hub2, args.op2_token)
    got, times = [], []
    done = threading.Event()

    def on(msg):
        got.append(msg["data"])
        times.append(time.monotonic())
        if len(got) >= N_CHATTER:
            done.set()

    sub = roslibpy.Topic(ros, CHATTER, "std_msgs/msg/String", queue_length=200)
    sub.subscribe(on)
    time.sleep(0.5)
    run(args, "play", path, "--hub", args.hub2, "--token", args.op2_token, "--topics", "/interop/.*",
        timeout=60)
    done.wait(TIMEOUT)
    check(got == [f"msg {i}" for i in range(N_CHATTER)], f"replayed: {len(got)} strings, first {got[:3]}")
    rec = chatter_times(path)
    want_gaps = [b - a for a, b in zip(rec, rec[1:])]
    got_gaps = [b - a for a, b in zip(times, times[1:])]
    m_want, m_got = statistics.median(want_gaps), statistics.median(got_gaps)
    span_want, span_got = rec[-1] - rec[0], times[-1] - times[0]
    print(f"  spacing: recorded median {m_want * 1e3:.1f} ms, span {span_want:.2f} s; "
          f"replayed median {m_got * 1e3:.1f} ms, span {span_got:.2f} s")
    check(abs(m_got - m_want) <= 0.1 * m_want, "median spacing off by more than 10 %")
    check(abs(span_got - span_want) <= 0.1 * span_want, "span off by more than 10 %")
    ros.close()


def main():
    p = argparse.ArgumentParser()
    for a in ("--bin", "--hub", "--hub2", "--op-token", "--op2-token", "--denied-token", "--robot", "--work"):
        p.add_argument(a, required=True)
    p.add_argument("--scan-ranges", type=int, required=True)
    args = p.parse_args()
    try:
        step_refused(args)
        print("ok refused")
        info, path = step_record(args)
        print(f"ok record ({info['messages']} messages, {info['bytes']} bytes)")
        scans, odoms = step_read(args, info, path)
        print(f"ok read ({scans} scans, {odoms} odometry, {N_CHATTER} + {N_LEVEL} strings decoded)")
        step_replay(args, path)
        print("ok replay")
    except CheckFailed as e:
        print(f"FAIL: {e}")
        sys.exit(1)


if __name__ == "__main__":
    main()

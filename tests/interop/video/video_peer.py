"""Peers of the video interop suite (tests/interop/video/run.sh).

    camera SECONDS          a Cyclone DDS node publishing /camera/image_raw,
                            sensor_msgs/msg/Image 640x480 rgb8 at 15 Hz: a test scene
                            that is a function of the message's stamp (scene()).
    watch URL TOPIC SECONDS a roslibpy client of the hub subscribed to a video topic
                            (foxglove_msgs/msg/CompressedVideo) for SECONDS; every frame
                            is decoded by PyAV (FFmpeg's H.264 decoder) from the first
                            message on. Checks the size, the count, that each frame
                            decodes, and with --scene the luma PSNR of each decoded frame
                            against the scene its stamp names.
    decode FILE             the same decoding of frames another peer wrote to FILE (the
                            Foxglove client's): per frame a little-endian u32 length and
                            the H.264 access unit.

Prints what it found; exits 1 with FAIL lines when a check fails.
"""
import argparse
import base64
import dataclasses
import os
import sys
import time
import urllib.parse

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "ros2"))

W, H, HZ = 640, 480, 15


def scene(stamp_ns):
    """The camera's picture at a stamp: colour gradients and a bright box that moves."""
    x = np.arange(W, dtype=np.uint32)
    y = np.arange(H, dtype=np.uint32)
    img = np.empty((H, W, 3), dtype=np.uint8)
    img[:, :, 0] = (x * 255 // W)[None, :]
    img[:, :, 1] = (y * 255 // H)[:, None]
    img[:, :, 2] = 96
    t = (stamp_ns // 1_000_000) % 4000
    bx = int(t * (W - 96) // 4000)
    img[160:320, bx:bx + 96, :] = (250, 250, 240)
    return img


def luma(rgb):
    """Full-range BT.601 luma, as the encoder's input."""
    r, g, b = (rgb[:, :, i].astype(np.float64) for i in range(3))
    return 0.299 * r + 0.587 * g + 0.114 * b


def camera(seconds):
    from cyclonedds.domain import DomainParticipant
    from cyclonedds.idl import IdlStruct
    from cyclonedds.idl.types import sequence, uint8, uint32
    from cyclonedds.pub import DataWriter
    from cyclonedds.topic import Topic

    import ros2_types as t

    @dataclasses.dataclass
    class Image(IdlStruct, typename=t.dds_name("sensor_msgs/msg/Image")):
        header: t.Header
        height: uint32
        width: uint32
        encoding: str
        is_bigendian: uint8
        step: uint32
        data: sequence[uint8]

    dp = DomainParticipant(int(os.environ.get("ROS_DOMAIN_ID", "0")))
    topic = Topic(dp, "rt/camera/image_raw", Image)
    writer = DataWriter(dp, topic, qos=t.qos(reliable=False, depth=2))
    print("camera ready", flush=True)
    start = time.monotonic()
    n = 0
    while time.monotonic() - start < seconds:
        now = time.time_ns()
        img = scene(now)
        msg = Image(
            header=t.Header(stamp=t.Time(sec=now // 1_000_000_000, nanosec=now % 1_000_000_000),
                            frame_id="camera"),
            height=H, width=W, encoding="rgb8", is_bigendian=0, step=W * 3,
            data=img.tobytes(),
        )
        writer.write(msg)
        n += 1
        time.sleep(max(0.0, start + n / HZ - time.monotonic()))
    print(f"camera published {n}", flush=True)


def watch(url, topic, seconds, size, min_frames, scene_check, min_psnr, throttle_ms=0, queue_length=0,
          resume_after=None, min_resumed=0, tail=None, tail_min_frames=0, tail_max_age_ms=None):
    import roslibpy

    u = urllib.parse.urlparse(url)
    # roslibpy builds the URL from host and port: the token goes in a header instead.
    token = urllib.parse.parse_qs(u.query).get("token", [None])[0]
    headers = {"Authorization": f"Bearer {token}"} if token else None
    ros = roslibpy.Ros(host=u.hostname, port=u.port, headers=headers)
    ros.run(timeout=10)
    got = []
    sub = roslibpy.Topic(ros, topic, "foxglove_msgs/msg/CompressedVideo",
                         throttle_rate=throttle_ms, queue_length=queue_length)
    arrived, wall = [], []
    since = time.monotonic()
    sub.subscribe(lambda m: (got.append(m), arrived.append(time.monotonic()), wall.append(time.time_ns())))
    print(f"watch subscribed to {topic}", flush=True)
    time.sleep(seconds)
    sub.unsubscribe()
    ros.terminate()

    if not got:
        print(f"FAIL: no message on {topic} in {seconds} s")
        return 1
    frames = []
    for m in got:
        data = m["data"]
        ts = m["timestamp"]
        frames.append((m.get("format"), base64.b64decode(data) if isinstance(data, str) else bytes(data),
                       int(ts["sec"]) * 1_000_000_000 + int(ts["nanosec"])))
    rc = report(f"watch {topic}", frames, size, min_frames, scene_check, min_psnr)
    # The source's stamp is its wall clock, on this machine: the age of each frame as it
    # arrived here (decoding adds PyAV's 1-2 ms), and how long the first one took.
    ages = sorted((w - f[2]) / 1e6 for w, f in zip(wall, frames))
    print(f"watch {topic}: first frame {1e3 * (arrived[0] - since):.0f} ms after subscribing; "
          f"age on arrival p50 {ages[len(ages) // 2]:.1f} ms, p95 {ages[int(len(ages) * 0.95)]:.1f} ms")
    if tail is not None:
        # The last `tail` seconds: enough frames, and their age on arrival.
        end = since + seconds
        late = sorted((w - f[2]) / 1e6 for a, w, f in zip(arrived, wall, frames) if a > end - tail)
        p50 = late[len(late) // 2] if late else float("inf")
        print(f"watch {topic}: last {tail} s: {len(late)} frames, age on arrival p50 {p50:.0f} ms")
        if len(late) < tail_min_frames:
            print(f"FAIL: {len(late)} frames in the last {tail} s, want at least {tail_min_frames}")
            rc = 1
        if tail_max_age_ms is not None and p50 > tail_max_age_ms:
            print(f"FAIL: frames {p50:.0f} ms old on arrival in the last {tail} s (median), "
                  f"want at most {tail_max_age_ms}")
            rc = 1
    if resume_after is not None:
        resumed = sum(1 for t in arrived if t - since > resume_after)
        gaps = [b - a for a, b in zip(arrived, arrived[1:])]
        print(f"watch {topic}: {resumed} frames after {resume_after} s; longest gap {max(gaps, default=0):.1f} s")
        if resumed < min_resumed:
            print(f"FAIL: {resumed} frames came after {resume_after} s, want at least {min_resumed}")
            rc = 1
    return rc


def decode_frames(frames, size, scene_check=False):
    """Decodes (format, access unit, stamp) frames in order with FFmpeg's H.264 decoder,
    from the first on. Returns (what was found, failures)."""
    import av

    failed = []
    codec = av.CodecContext.create("h264", "r")
    decoded, psnrs, sizes = 0, [], set()
    for i, (fmt, data, stamp) in enumerate(frames):
        if fmt != "h264":
            failed.append(f"message {i}: format {fmt!r}, not h264")
            continue
        try:
            pictures = codec.decode(av.Packet(data))
        except av.error.FFmpegError as e:
            failed.append(f"message {i} of {len(frames)} does not decode: {e}")
            continue
        if len(pictures) != 1:
            failed.append(f"message {i}: {len(pictures)} pictures, not one")
        for f in pictures:
            decoded += 1
            sizes.add((f.width, f.height))
            if scene_check:
                y = f.to_ndarray(format="gray")[:H, :W].astype(np.float64)
                # The stream says full range; FFmpeg's gray keeps the samples as they are.
                ref = luma(scene(stamp))
                mse = float(np.mean((y - ref) ** 2))
                psnrs.append(10 * np.log10(255 * 255 / max(mse, 1e-9)))
    want = tuple(int(v) for v in size.split("x"))
    if sizes != {want}:
        failed.append(f"decoded sizes {sorted(sizes)}, want {want}")
    found = (f"{len(frames)} messages, {decoded} decoded from the first, sizes {sorted(sizes)}"
             + (f", luma PSNR min {min(psnrs):.1f} median {float(np.median(psnrs)):.1f} dB" if psnrs else ""))
    return decoded, psnrs, found, failed


def report(what, frames, size, min_frames, scene_check=False, min_psnr=30.0):
    """Decodes `frames` (decode_frames) and prints the outcome; 1 if a check failed."""
    decoded, psnrs, found, failed = decode_frames(frames, size, scene_check)
    if decoded < min_frames:
        failed.append(f"{decoded} frames decoded, want at least {min_frames}")
    if psnrs and min(psnrs) < min_psnr:
        failed.append(f"luma PSNR down to {min(psnrs):.1f} dB against the scene, want >= {min_psnr}")
    print(f"{what}: {found}")
    for f in failed:
        print(f"FAIL: {f}")
    return 1 if failed else 0


def read_frames(path):
    """Frames written by another peer: per frame a little-endian u32 length, then the
    access unit; all in format h264."""
    with open(path, "rb") as f:
        b = f.read()
    frames, at = [], 0
    while at + 4 <= len(b):
        n = int.from_bytes(b[at:at + 4], "little")
        frames.append(("h264", b[at + 4:at + 4 + n], 0))
        at += 4 + n
    return frames


def main():
    ap = argparse.ArgumentParser()
    sp = ap.add_subparsers(dest="cmd", required=True)
    c = sp.add_parser("camera")
    c.add_argument("seconds", type=float)
    w = sp.add_parser("watch")
    w.add_argument("url")
    w.add_argument("topic")
    w.add_argument("seconds", type=float)
    w.add_argument("--size", default=f"{W}x{H}")
    w.add_argument("--min-frames", type=int, default=1)
    w.add_argument("--scene", action="store_true")
    w.add_argument("--min-psnr", type=float, default=30.0)
    w.add_argument("--throttle", type=int, default=0, help="rosbridge throttle_rate, ms")
    w.add_argument("--queue", type=int, default=0, help="rosbridge queue_length")
    w.add_argument("--tail", type=float, help="seconds at the end checked on their own")
    w.add_argument("--tail-min-frames", type=int, default=0)
    w.add_argument("--tail-max-age-ms", type=float, help="median age on arrival in the tail")
    w.add_argument("--resume-after", type=float, help="seconds after subscribing")
    w.add_argument("--min-resumed", type=int, default=0,
                   help="frames that must come after --resume-after seconds")
    d = sp.add_parser("decode")
    d.add_argument("file")
    d.add_argument("--size", default=f"{W}x{H}")
    d.add_argument("--min-frames", type=int, default=1)
    a = ap.parse_args()
    if a.cmd == "decode":
        return report(f"decode {os.path.basename(a.file)}", read_frames(a.file), a.size, a.min_frames)
    if a.cmd == "camera":
        camera(a.seconds)
        return 0
    return watch(a.url, a.topic, a.seconds, a.size, a.min_frames, a.scene, a.min_psnr,
                 a.throttle, a.queue, a.resume_after, a.min_resumed, a.tail, a.tail_min_frames,
                 a.tail_max_age_ms)


if __name__ == "__main__":
    sys.exit(main())

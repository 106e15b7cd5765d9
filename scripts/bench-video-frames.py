"""Turns a video clip into raw frames for `fleetlink bench video` (scripts/bench-video.sh):
decoded with PyAV (FFmpeg), taken at one frame every 1/FPS s of the clip's own time,
scaled to WIDTHxHEIGHT, written as rgb24 back to back.

Usage: bench-video-frames.py CLIP OUT --frames N --fps F --size WxH
"""
import argparse

import av


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("clip")
    ap.add_argument("out")
    ap.add_argument("--frames", type=int, default=150)
    ap.add_argument("--fps", type=float, default=15.0)
    ap.add_argument("--size", default="640x480")
    a = ap.parse_args()
    w, h = (int(v) for v in a.size.split("x"))
    written, next_t = 0, 0.0
    with av.open(a.clip) as src, open(a.out, "wb") as out:
        for frame in src.decode(video=0):
            if frame.time is not None and frame.time + 1e-6 < next_t:
                continue
            next_t += 1.0 / a.fps
            out.write(frame.reformat(width=w, height=h, format="rgb24").to_ndarray().tobytes())
            written += 1
            if written == a.frames:
                break
    print(f"{a.clip}: {written} frames of {w}x{h} at {a.fps:g} fps")


if __name__ == "__main__":
    main()

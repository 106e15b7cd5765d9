#!/usr/bin/env bash
# Camera video against JPEG on the same frames (docs/benchmarks.md, "Camera video"): public
# camera footage (fetched once, not committed) and the demo robots' camera, each as
# 640x480 frames at 15 fps; for each, JPEG quality 80's bytes and luma PSNR, the lowest
# H.264 bitrate that matches that PSNR, its bytes, and the encoder's time per frame.
#
#   scripts/bench-video.sh [fleetlink bench video options, e.g. --json]
#
# Env: FLEETLINK_BIN (default target/release/fleetlink), PYTHON (default .venv/bin/python,
# with PyAV: scripts/setup.d/10-python-venv.sh), CLIPS_DIR (default target/video-clips:
# where the clips are fetched to; put them there by hand where the network is closed),
# FRAMES (per clip, default 150: 10 s).
set -euo pipefail
cd "$(dirname "$0")/.."
bin="${FLEETLINK_BIN:-target/release/fleetlink}"
python="${PYTHON:-.venv/bin/python}"
dir="${CLIPS_DIR:-target/video-clips}"
frames="${FRAMES:-150}"
[ -x "$bin" ] || { echo "no fleetlink binary at $bin (cargo build --release, or set FLEETLINK_BIN)" >&2; exit 1; }
"$python" -c 'import av' 2>/dev/null || { echo "$python lacks PyAV; run scripts/setup.d/10-python-venv.sh" >&2; exit 1; }
mkdir -p "$dir"

# Real camera footage, from Intel's sample videos (CC BY 4.0) at a pinned commit:
# car-detection (768x432, 12.5 fps), one-by-one-person-detection (768x432, 10 fps) and
# bottle-detection (640x360, 30 fps), each scaled to 640x480.
intel=https://raw.githubusercontent.com/intel-iot-devkit/sample-videos/57978890822836f2b4743852f04f62fc511757e4
clips=(
    "car-detection.mp4 $intel/car-detection.mp4"
    "one-by-one-person-detection.mp4 $intel/one-by-one-person-detection.mp4"
    "bottle-detection.mp4 $intel/bottle-detection.mp4"
)
args=()
for c in "${clips[@]}"; do
    name="${c%% *}"; url="${c#* }"
    if [ ! -s "$dir/$name" ]; then
        curl -fsSL -o "$dir/$name.part" "$url" && mv "$dir/$name.part" "$dir/$name" || {
            echo "cannot fetch $url: put $name in $dir yourself (CLIPS_DIR)" >&2; exit 1; }
    fi
    "$python" scripts/bench-video-frames.py "$dir/$name" "$dir/$name.rgb" --frames "$frames" --fps 15 --size 640x480
    args+=(--clip "$name=$dir/$name.rgb")
done
"$bin" bench video "${args[@]}" --demo-frames "$frames" --width 640 --height 480 --fps 15 "$@"

#!/usr/bin/env bash
# Camera video live (docs/benchmarks.md, "Camera video: live"): a hub and an agent on this
# machine's loopback, the agent's simulated camera rendering 640x480 JPEG pictures at 15 Hz
# with its video topic beside it (H.264, 1000 kbit/s). Measures, with roslibpy viewers at
# the hub (the frames decoded by PyAV):
#   1. the agent's CPU while one viewer watches the JPEG topic, then while one watches the
#      video topic instead (from /proc, over 8 s once the stream runs): the camera's
#      rendering and JPEG encoding are in both, the video's JPEG decoding and H.264
#      encoding in the second;
#   2. each video frame's age when it reached the viewer: the viewer's clock minus the
#      stamp the simulator gave the picture when it rendered it (one clock: one machine);
#      PyAV's decoding (1-2 ms a frame) comes after;
#   3. a new viewer's first frame: from its subscription to the first frame it can decode,
#      over 8 viewers that come at random points of the stream, while another viewer
#      watches (the hub gives it the last keyframe and the frames since), then over 8 that
#      come alone (the hub kept nothing for nobody and asks the robot for a keyframe).
#
#   scripts/bench-video-live.sh
#
# Env: FLEETLINK_BIN (default target/release/fleetlink), PYTHON (default .venv/bin/python,
# with roslibpy and PyAV: scripts/setup.d/10-python-venv.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
root="$PWD"
bin="${FLEETLINK_BIN:-target/release/fleetlink}"
python="${PYTHON:-.venv/bin/python}"
[ -x "$bin" ] || { echo "no fleetlink binary at $bin (cargo build --release, or set FLEETLINK_BIN)" >&2; exit 1; }
"$python" -c 'import av, roslibpy' 2>/dev/null || { echo "$python lacks PyAV or roslibpy; run scripts/setup.d/10-python-venv.sh" >&2; exit 1; }
tmp="$(mktemp -d)"
pids=()
trap 'for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done; wait 2>/dev/null; rm -rf "$tmp"' EXIT
export NO_COLOR=1

"$bin" admin --data-dir "$tmp/hub" token robot robot1 >"$tmp/robot.token"
"$bin" admin --data-dir "$tmp/hub" token operator bench --group admin >"$tmp/op.token"
op="$(cat "$tmp/op.token")"
"$bin" hub --listen 127.0.0.1:0 --data-dir "$tmp/hub" >"$tmp/hub.log" 2>&1 &
pids+=($!)
for _ in $(seq 100); do
    hub="$(sed -nE 's#^fleetlink hub listening on ([0-9.:]+)$#\1#p' "$tmp/hub.log")"
    [ -n "$hub" ] && break
    sleep 0.1
done
[ -n "$hub" ] || { echo "the hub did not start: $(tail -3 "$tmp/hub.log")" >&2; exit 1; }
cat >"$tmp/agent.yaml" <<YAML
hub: ws://$hub/
name: robot1
token: $(cat "$tmp/robot.token")
local_rosbridge: null
sim:
  laser_scan: null
  odometry: null
  pose: null
  point_cloud: null
  image: { rate_hz: 15, width: 640, height: 480 }
video:
  /camera/image/compressed: { topic: /camera/video, fps: 15, bitrate_kbps: 1000 }
YAML
"$bin" agent --config "$tmp/agent.yaml" >"$tmp/agent.log" 2>&1 &
agent=$!
pids+=($agent)
sleep 3
url="ws://$hub/?token=$op"

# The agent's CPU (user + system, % of one core) over the next $1 seconds.
cpu() {
    local a b ticks
    ticks="$(getconf CLK_TCK)"
    a="$(awk '{print $14 + $15}' "/proc/$agent/stat")"
    sleep "$1"
    b="$(awk '{print $14 + $15}' "/proc/$agent/stat")"
    awk -v a="$a" -v b="$b" -v s="$1" -v t="$ticks" 'BEGIN { printf "%.1f", 100 * (b - a) / t / s }'
}

# A roslibpy viewer of the JPEG topic for $1 seconds (counts what it got).
"$python" - "$url" 14 >"$tmp/jpeg.log" 2>&1 <<'PY' &
import sys, time, urllib.parse, roslibpy
u = urllib.parse.urlparse(sys.argv[1])
tok = urllib.parse.parse_qs(u.query)["token"][0]
ros = roslibpy.Ros(host=u.hostname, port=u.port, headers={"Authorization": f"Bearer {tok}"})
ros.run(timeout=10)
n = []
t = roslibpy.Topic(ros, "/robot1/camera/image/compressed", "sensor_msgs/msg/CompressedImage")
t.subscribe(lambda m: n.append(len(m["data"])))
time.sleep(float(sys.argv[2]))
t.unsubscribe(); ros.terminate()
print(f"jpeg viewer: {len(n)} pictures")
PY
viewer=$!
sleep 5
jpeg_cpu="$(cpu 8)"
wait "$viewer"
# The video's encoder is not running yet (nobody asked for it).
"$python" scripts/../tests/interop/video/video_peer.py watch "$url" /robot1/camera/video 14 \
    >"$tmp/video.log" 2>&1 &
viewer=$!
sleep 5
video_cpu="$(cpu 8)"
wait "$viewer" || { cat "$tmp/video.log"; echo "the video viewer failed" >&2; exit 1; }

echo "agent CPU, one 640x480 15 fps camera watched (% of one core, 8 s):"
echo "  as JPEG pictures:     $jpeg_cpu %   ($(cat "$tmp/jpeg.log"))"
echo "  as H.264 video:       $video_cpu %"
grep -E "age on arrival|decoded" "$tmp/video.log" | sed 's/^/  /'

# New viewers at random points of the stream: the first frame's delay. While someone
# else watches, the hub gives a newcomer the group it kept; once nobody does, the hub has
# let the group go (it would be stale), and asks the robot for a keyframe instead.
first_frames() {
    local firsts=() line i
    for i in $(seq 8); do
        sleep "0.$((RANDOM % 10))"
        line="$("$python" tests/interop/video/video_peer.py watch "$url" /robot1/camera/video 1.5 2>&1 \
            | sed -nE 's#.*first frame ([0-9]+) ms after subscribing.*#\1#p')"
        [ -n "$line" ] && firsts+=("$line")
    done
    printf '%s\n' "${firsts[@]}" | sort -n | awk -v what="$1" '{a[NR]=$1} END {
        if (NR == 0) { print "new viewers " what ": no first frame measured"; exit }
        printf "new viewer first frame after subscribing, %s, %d viewers: median %d ms, max %d ms\n", what, NR, a[int((NR + 1) / 2)], a[NR] }'
}
"$python" tests/interop/video/video_peer.py watch "$url" /robot1/camera/video 30 >/dev/null 2>&1 &
watching=$!
sleep 2
first_frames "while another viewer watches (the hub's kept group)"
kill "$watching" 2>/dev/null || true
wait "$watching" 2>/dev/null || true
first_frames "each alone (a keyframe asked of the robot)"

#!/usr/bin/env bash
# Video interop suite (issue 60): camera topics offered as H.264 video, encoded on the
# robot only while someone watches, decoded by FFmpeg (PyAV) from the first message on.
# Real `fleetlink hub` and `fleetlink agent` processes in network namespaces of the run's
# own, the robot's (DDS discovery on its loopback) and the hub's; the robot's camera is a Cyclone DDS node
# publishing 640x480 rgb8 sensor_msgs/msg/Image at 15 Hz, a test scene that is a function
# of each message's stamp; the agent's simulated camera adds a 640x480 JPEG topic.
#
# Checks:
#   1. both video topics are listed at the hub as foxglove_msgs/msg/CompressedVideo, and
#      with nobody watching neither they nor the cameras send anything;
#   2. a roslibpy viewer of /robot1/camera/video gets frames that PyAV decodes from the
#      first message on, 640x480, at least 20 in 6 s (the camera, a Python process, slows
#      down on a loaded machine; the rate is not what is checked), each within 30 dB luma PSNR of the
#      scene its stamp names; a second viewer who comes in the middle of a group of
#      pictures decodes from its first message too (the hub gives it the last keyframe
#      and the frames since);
#   3. meanwhile the raw camera topic itself was not sent to the hub (nobody there wants
#      it: 0 messages);
#   4. the simulated JPEG camera's video decodes too, 640x480;
#   5. the robot's link (a veth pair between the robot's namespace and the hub's) down for
#      5 s while a viewer watches: every picture it decodes, before and after, matches its
#      scene, and pictures come again (at least 8 in its last 5.5 s, which begin 3.5 s
#      after the link's return);
#   6. the robot's link slowed to 300 kbit/s (tbf) under the simulated camera's stream,
#      which takes most of its 1000 kbit/s: its bitrate comes down (the agent's log), and
#      in the last 6 s of a 24 s watch at least 10 frames arrive, half of them under 1 s
#      old, every one decoding;
#   7. nobody watching any more, the agent stops encoding (its log says so).
#
# Needs root (network namespaces). Bounded: about 80 s; every process runs under
# `timeout`, killed on exit.
#
# Env: FLEETLINK_BIN (default target/release/fleetlink), PYTHON (default .venv/bin/python
# with cyclonedds, av, numpy: scripts/setup.d/10-python-venv.sh, 35-ros2-peers.sh).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
bin="${FLEETLINK_BIN:-$root/target/release/fleetlink}"
python="${PYTHON:-$root/.venv/bin/python}"
export ROS_DOMAIN_ID=31 PYTHONDONTWRITEBYTECODE=1 NO_COLOR=1
unset ROS_DISTRO

[ -x "$bin" ] || { echo "FAIL: fleetlink binary not found at $bin (set FLEETLINK_BIN)" >&2; exit 1; }
[ -x "$python" ] || { echo "FAIL: $python missing; run scripts/setup.d/10-python-venv.sh" >&2; exit 1; }
"$python" -c 'import cyclonedds.domain, av, numpy, roslibpy' 2>/dev/null \
    || { echo "FAIL: $python lacks cyclonedds, av, numpy or roslibpy; run scripts/setup-test-env.sh" >&2; exit 1; }
[ "$(id -u)" -eq 0 ] || { echo "FAIL: the video suite needs root for its network namespace" >&2; exit 1; }
bin="$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")"

# shellcheck source=../lib.sh
. "$here/../lib.sh"
interop_begin video
# The robot (camera, agent; DDS on its loopback) and the hub (and the viewers) in
# namespaces of their own, joined by a veth pair: the robot's link to the hub, which step 5
# takes down. The pair is created straight into the namespaces.
ns="flvid-$$"
hns="flvidh-$$"
interop_netns "$ns"
interop_netns "$hns"
ip link add vh netns "$hns" type veth peer name vr netns "$ns"
ip -n "$hns" addr add 10.231.0.1/30 dev vh
ip -n "$ns" addr add 10.231.0.2/30 dev vr
ip -n "$hns" link set vh up
ip -n "$ns" link set vr up
# Wire-sized packets into step 6's tbf, as over a radio (see tests/interop/links/run.sh);
# multicast off, so DDS (the camera, the agent's bridge) keeps to the robot's loopback and
# step 5's outage of the hub link is not an outage of the robot's DDS graph.
ip -n "$ns" link set vr gso_max_size 1500 gso_max_segs 1 multicast off
in_ns() { ip netns exec "$ns" timeout --kill-after=5 "$@"; }
in_hub() { ip netns exec "$hns" timeout --kill-after=5 "$@"; }
failed=()
fail() { echo "FAIL: $*"; failed+=("$*"); }
step() { echo "== $1"; }

admin() { in_hub 30 "$bin" admin --data-dir "$tmp/hub-data" "$@"; }
robot_token="$(admin token robot robot1)"
op_token="$(admin token operator video --group admin)"
in_hub 150 "$bin" hub --listen 0.0.0.0:0 --data-dir "$tmp/hub-data" >"$tmp/hub.log" 2>&1 &
pids+=($!)
hub_port="$(wait_for_line "$tmp/hub.log" '^fleetlink hub listening on [0-9.]+:([0-9]+)$' "hub start" "${pids[-1]}")"
hub="127.0.0.1:$hub_port"
api() { in_hub 10 curl -sf -H "Authorization: Bearer $op_token" "http://$hub$1"; }

# The camera's DDS on the robot's loopback (Cyclone would take the veth, the one
# interface that is not a loopback, and lose the agent when it goes down).
CYCLONEDDS_URI='<CycloneDDS><Domain><General><Interfaces><NetworkInterface name="lo" multicast="true"/></Interfaces></General></Domain></CycloneDDS>' \
    in_ns 120 "$python" "$here/video_peer.py" camera 110 >"$tmp/camera.log" 2>&1 &
pids+=($!)
wait_for_line "$tmp/camera.log" '^(camera) ready$' "the Cyclone camera" "${pids[-1]}" >/dev/null

cat >"$tmp/agent.yaml" <<YAML
hub: ws://10.231.0.1:$hub_port/
name: robot1
token: $robot_token
local_rosbridge: null
runtime_file: $tmp/robot-state/runtime.json
ros2:
  publish: [/camera/image_raw]
sim:
  laser_scan: null
  odometry: null
  pose: null
  point_cloud: null
  image: { rate_hz: 15, width: 640, height: 480 }
video:
  /camera/image_raw: { topic: /camera/video, fps: 15, bitrate_kbps: 1500 }
  /camera/image/compressed: { topic: /camera/jpeg_video, bitrate_kbps: 1000, min_bitrate_kbps: 100 }
YAML
in_ns 150 "$bin" agent --config "$tmp/agent.yaml" >"$tmp/agent.log" 2>&1 &
pids+=($!)
agent_pid=${pids[-1]}

# A topic's field from the hub's listing: topic_field NAME FIELD.
topic_field() {
    api /api/v1/topics | "$python" -c 'import json,sys
ts={t["name"]: t for t in json.load(sys.stdin)["topics"]}
t=ts.get(sys.argv[1]); print("-" if t is None else t.get(sys.argv[2]))' "$1" "$2"
}

step "1. the video topics are listed, and nothing flows unwatched"
for _ in $(seq 100); do
    [ "$(topic_field /robot1/camera/image_raw state)" != "-" ] \
        && [ "$(topic_field /robot1/camera/video state)" != "-" ] && break
    kill -0 "$agent_pid" 2>/dev/null || break
    sleep 0.1
done
for t in /robot1/camera/video /robot1/camera/jpeg_video; do
    ty="$(topic_field "$t" type)"
    [ "$ty" = "foxglove_msgs/msg/CompressedVideo" ] || fail "$t is listed as ${ty:-nothing}, not foxglove_msgs/msg/CompressedVideo"
done
sleep 2
for t in /robot1/camera/video /robot1/camera/jpeg_video /robot1/camera/image_raw /robot1/camera/image/compressed; do
    n="$(topic_field "$t" messages)"
    [ "$n" = "0" ] || fail "unwatched, $t reached the hub anyway: $n messages"
done

step "2. a viewer decodes the camera's video from its first message, and so does one who comes mid-stream"
in_hub 60 "$python" "$here/video_peer.py" watch "ws://$hub/?token=$op_token" /robot1/camera/video 6 \
    --min-frames 20 --scene >"$tmp/watch.log" 2>&1 &
first=$!
# The second comes 2.7 s in: after the stream's first keyframe interval (2 s), in the
# middle of a group, which it decodes from the keyframe the hub kept.
sleep 2.7
in_hub 60 "$python" "$here/video_peer.py" watch "ws://$hub/?token=$op_token" /robot1/camera/video 3 \
    --min-frames 10 --scene | sed 's/^/  mid-stream: /' \
    || fail "a viewer who came mid-stream did not decode from its first message (see above)"
wait "$first" || { cat "$tmp/watch.log"; fail "the video of the Cyclone camera (see above)"; }
cat "$tmp/watch.log"

step "3. the raw camera was not sent for the video"
n="$(topic_field /robot1/camera/image_raw messages)"
[ "$n" = "0" ] || fail "/robot1/camera/image_raw reached the hub while only its video was watched: $n messages"

step "4. the JPEG camera's video decodes too, and a throttled viewer's keyframes"
# roslibjs's throttle_rate cannot thin a chain of frames: a viewer throttled to 5 a second
# with a queue of one is given keyframes (which its losses ask the robot for), every one
# decodable, rather than P-frames it could not decode.
in_hub 60 "$python" "$here/video_peer.py" watch "ws://$hub/?token=$op_token" /robot1/camera/jpeg_video 5 \
    --min-frames 3 --throttle 200 --queue 1 >"$tmp/watch-throttled.log" 2>&1 &
throttled=$!
in_hub 60 "$python" "$here/video_peer.py" watch "ws://$hub/?token=$op_token" /robot1/camera/jpeg_video 4 \
    --min-frames 10 | tee "$tmp/watch-jpeg.log" || fail "the video of the simulated JPEG camera (see above)"
wait "$throttled" || { cat "$tmp/watch-throttled.log"; fail "a throttled viewer of the video (see above)"; }
sed 's/^/  throttled: /' "$tmp/watch-throttled.log"

step "5. a 5 s blackout of the robot's link: the viewer's pictures stop, then resume whole"
# Frames lost in the outage (the robot's link queue, the link's end) are never given to a
# decoder: every picture decoded matches the scene its stamp names, before and after.
in_hub 60 "$python" "$here/video_peer.py" watch "ws://$hub/?token=$op_token" /robot1/camera/video 17 \
    --min-frames 20 --scene --resume-after 11.5 --min-resumed 8 >"$tmp/watch-blackout.log" 2>&1 &
blackout_viewer=$!
# Three seconds of pictures after the viewer subscribed, then the link goes for 5 s.
wait_for_line "$tmp/watch-blackout.log" '^watch (subscribed) to' "the blackout viewer" "$blackout_viewer" >/dev/null
sleep 3
ip -n "$ns" link set vr down
sleep 5
ip -n "$ns" link set vr up
wait "$blackout_viewer" || { cat "$tmp/watch-blackout.log"; fail "the video across a 5 s blackout (see above)"; }
sed 's/^/  blackout: /' "$tmp/watch-blackout.log"

step "6. a slow link (300 kbit/s): the bitrate comes down and the video keeps up"
# The simulated camera's video takes most of its 1000 kbit/s: on this link it would queue
# and its frames arrive seconds old; following the link, they arrive about as fresh as the
# link allows.
ip netns exec "$ns" tc qdisc add dev vr root tbf rate 300kbit burst 8kb latency 300ms
in_hub 60 "$python" "$here/video_peer.py" watch "ws://$hub/?token=$op_token" /robot1/camera/jpeg_video 24 \
    --min-frames 10 --tail 6 --tail-min-frames 10 --tail-max-age-ms 1000 \
    >"$tmp/watch-slow.log" 2>&1 || { cat "$tmp/watch-slow.log"; fail "the video on a 300 kbit/s link (see above)"; }
sed 's/^/  slow link: /' "$tmp/watch-slow.log"
ip netns exec "$ns" tc qdisc del dev vr root

step "7. video: changed while the agent runs: a watched stream's bitrate, a stream renamed"
# The hub's configuration API (docs/runtime-config.md): the watched stream restarts its
# encoder with the new settings and its viewer goes on decoding every picture; the JPEG
# camera's stream leaves the hub under its old name and is offered under the new one.
in_hub 60 "$python" "$here/video_peer.py" watch "ws://$hub/?token=$op_token" /robot1/camera/video 8 \
    --min-frames 40 --scene --resume-after 5 --min-resumed 20 >"$tmp/watch-change.log" 2>&1 &
change_viewer=$!
wait_for_line "$tmp/watch-change.log" '^watch (subscribed) to' "the viewer of the change" "$change_viewer" >/dev/null
sleep 2
answer="$(in_hub 10 curl -s -X PUT -H "Authorization: Bearer $op_token" --data-binary @- \
    "http://$hub/api/v1/robots/robot1/config" <<'YAML'
video:
  /camera/image_raw: { bitrate_kbps: 600, keyframe_s: 1 }
  /camera/image/compressed: { topic: /camera/small_video, fps: 5 }
YAML
)"
echo "$answer" | "$python" -c 'import json,sys; a=json.load(sys.stdin); sys.exit(0 if a.get("changed")==["video"] else 1)' \
    || fail "the hub did not take the video change: $answer"
wait_for_line "$tmp/agent.log" '(video /camera/video: settings changed: 15 fps, 600 kbit/s)' \
    "the stream taking its new bitrate" "$agent_pid" >/dev/null || fail "the watched stream did not take its new settings"
for _ in $(seq 100); do
    [ "$(topic_field /robot1/camera/small_video type)" = "foxglove_msgs/msg/CompressedVideo" ] \
        && [ "$(topic_field /robot1/camera/jpeg_video state)" = "-" ] && break
    sleep 0.1
done
[ "$(topic_field /robot1/camera/small_video type)" = "foxglove_msgs/msg/CompressedVideo" ] \
    || fail "the renamed stream is not listed as /robot1/camera/small_video"
[ "$(topic_field /robot1/camera/jpeg_video state)" = "-" ] \
    || fail "/robot1/camera/jpeg_video is still listed after its stream was renamed"
wait "$change_viewer" || { cat "$tmp/watch-change.log"; fail "the video across its settings' change (see above)"; }
sed 's/^/  changed: /' "$tmp/watch-change.log"
in_hub 60 "$python" "$here/video_peer.py" watch "ws://$hub/?token=$op_token" /robot1/camera/small_video 3 \
    --min-frames 8 | sed 's/^/  renamed: /' || fail "the renamed stream's video (see above)"

step "8. nobody watching, the encoders stop"
# Each stream's encoder has stopped as often as it started.
running() {
    local v started stopped n=0
    for v in /camera/video /camera/jpeg_video /camera/small_video; do
        started="$(grep -c "video $v: someone watches" "$tmp/agent.log" || true)"
        stopped="$(grep -cE "video $v: [a-z ]+; stopped after" "$tmp/agent.log" || true)"
        [ "$started" -gt "$stopped" ] && n=$((n + 1))
    done
    echo "$n"
}
for _ in $(seq 250); do
    [ "$(running)" -eq 0 ] && break
    sleep 0.1
done
[ "$(running)" -eq 0 ] || fail "the agent did not stop every encoder within 25 s of the last viewer leaving"
grep -E ': [a-z ]+; stopped after' "$tmp/agent.log" | sed 's/^/  agent: /'
# The simulated camera's stream came down to fit the slow link (the range is in the stop
# line of its last run).
low="$(sed -nE 's#.*video /camera/jpeg_video: [a-z ]+; stopped .* bitrate ([0-9]+) to [0-9]+ kbit/s.*#\1#p' "$tmp/agent.log" | tail -n1)"
[ -n "$low" ] && [ "$low" -le 300 ] \
    || fail "the simulated camera's bitrate did not come down to the 300 kbit/s link (lowest: ${low:-not logged} kbit/s)"

if [ ${#failed[@]} -ne 0 ]; then
    echo "--- agent log"; tail -n 20 "$tmp/agent.log"
    echo "video suite: ${#failed[@]} check(s) failed"
    exit 1
fi
echo "video suite: all checks passed"

#!/usr/bin/env bash
# Debian's ROS 1 graph tools for the ROS 1 bridge interop suite (tests/interop/ros1):
# the master (roscore/rosmaster, rosout), the command-line tools (rostopic, rosservice,
# rosnode) and the message packages the suite publishes. rospy itself comes from
# 30-msg-peers.sh. Idempotent: installs only what is missing; waits for the apt lock.
set -euo pipefail

apt_packages=(
    python3-rospy python3-genpy python3-roslaunch python3-rosmaster rosout
    python3-rostopic python3-rosservice python3-rosnode
    python3-std-msgs python3-geometry-msgs python3-sensor-msgs python3-nav-msgs
    python3-std-srvs
)
missing=()
for p in "${apt_packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if [ ${#missing[@]} -ne 0 ]; then
    sudo_cmd=()
    [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
    "${sudo_cmd[@]}" apt-get -o DPkg::Lock::Timeout=600 update
    DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get -o DPkg::Lock::Timeout=600 install -y --no-install-recommends "${missing[@]}"
fi

for tool in roscore rostopic rosservice; do
    command -v "$tool" >/dev/null || { echo "ros1: $tool not found after install" >&2; exit 1; }
done
/usr/bin/python3 -c "import rospy, rosgraph, std_srvs.srv, sensor_msgs.msg" \
    || { echo "ros1: import check failed" >&2; exit 1; }
echo "ros1 peers ready: $(command -v roscore)"

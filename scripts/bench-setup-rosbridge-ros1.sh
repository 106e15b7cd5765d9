#!/usr/bin/env bash
# Bench only (not part of the test set-up): what rosbridge_suite's ROS 1 server needs from Debian to run from its source with
# Debian's rospy, for the comparison in scripts/bench-ros1.sh (rosbridge itself is not
# installed: the bench takes its source from ROSBRIDGE_SRC). Its package.xml exec_depends:
# autobahn and twisted (the WebSocket server), tornado and bson (imported by its
# packages), PIL (png compression); and libsensor-msgs-dev for /usr/share/sensor_msgs/
# package.xml, which rosbridge's message loader asks rospkg for (Debian's python3-*-msgs
# packages ship none). About 7 MB to download. Idempotent: installs only what is missing.
set -euo pipefail

apt_packages=(
    python3-autobahn python3-twisted python3-tornado python3-bson python3-pil
    libsensor-msgs-dev libstd-msgs-dev
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

/usr/bin/python3 -c "import autobahn, twisted, tornado, bson, PIL; bson.BSON" \
    || { echo "rosbridge deps: import check failed" >&2; exit 1; }
[ -f /usr/share/sensor_msgs/package.xml ] || { echo "rosbridge deps: no sensor_msgs package.xml" >&2; exit 1; }
echo "rosbridge (ROS 1) dependencies ready"

#!/usr/bin/env bash
# Real peers for the fleetlink-msg cross-checks (tests/interop/msg): Debian's ROS 1
# Python stack (rospy/genpy and the generated message classes) and rosbags from PyPI
# in a venv of our own. Idempotent: installs only what is missing.
set -euo pipefail
cd "$(dirname "$0")/../.."

apt_packages=(
    python3-venv python3-rospy python3-genpy
    python3-std-msgs python3-geometry-msgs python3-sensor-msgs python3-nav-msgs
    python3-std-srvs python3-tf2-msgs python3-visualization-msgs
    python3-diagnostic-msgs python3-rosgraph-msgs
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

# Debian's python (not the pyenv one first on PATH) so rospy is importable, plus rosbags.
venv=tests/interop/msg/.venv
rosbags_version=0.11.9
if [ ! -x "$venv/bin/python" ]; then
    /usr/bin/python3 -m venv --system-site-packages "$venv"
fi
if ! "$venv/bin/python" -c "import rosbags, sys; from importlib.metadata import version; sys.exit(version('rosbags') != '$rosbags_version')" 2>/dev/null; then
    "$venv/bin/pip" install --quiet "rosbags==$rosbags_version"
fi
"$venv/bin/python" -c "import rospy, genpy, rosbags, std_msgs.msg, sensor_msgs.msg" \
    || { echo "msg peers: import check failed" >&2; exit 1; }
echo "msg peers ready: $("$venv/bin/python" -c 'import rosbags; from importlib.metadata import version; print("rosbags", version("rosbags"))')"

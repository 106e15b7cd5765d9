#!/usr/bin/env bash
# Peers of the ROS 2 bridge interop suite (tests/interop/ros2): Cyclone DDS's Python
# binding and rosbags (tests/interop/ros2/requirements.txt) in the repo's .venv (made by
# 10-python-venv.sh), Fast DDS (libfastrtps-dev, g++), `ip` (iproute2) for the
# suite's network namespace, and strace (step 10 attaches it to the agent). Idempotent:
# quiet and quick when everything is already there; waits for another apt's lock.
set -euo pipefail
cd "$(dirname "$0")/../.."
req=tests/interop/ros2/requirements.txt
stamp=.venv/.fleetlink-ros2-requirements

# Debian packages: iproute2, strace, and Fast DDS (eProsima's libfastrtps, the DDS under
# ROS 2's default middleware) with a C++ compiler for the suite's Fast DDS node
# (fastdds_peer.cpp).
apt_missing=()
command -v ip >/dev/null || apt_missing+=(iproute2)
command -v g++ >/dev/null || apt_missing+=(g++)
command -v strace >/dev/null || apt_missing+=(strace)
[ -f /usr/include/fastdds/dds/domain/DomainParticipant.hpp ] || apt_missing+=(libfastrtps-dev)
if [ ${#apt_missing[@]} -ne 0 ]; then
    sudo_cmd=()
    [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
    "${sudo_cmd[@]}" apt-get -o DPkg::Lock::Timeout=600 update
    DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get -o DPkg::Lock::Timeout=600 \
        install -y --no-install-recommends "${apt_missing[@]}"
fi

[ -x .venv/bin/python ] || { echo "ros2 peers: .venv missing; run scripts/setup.d/10-python-venv.sh first" >&2; exit 1; }
# The stamp holds the requirements that were installed; reinstall only when they change
# (or when an import fails, e.g. after the venv was recreated).
probe='import cyclonedds.domain, rosbags.serde'
if [ -f "$stamp" ] && cmp -s "$req" "$stamp" && .venv/bin/python -c "$probe" 2>/dev/null; then
    echo "ros2 peers up to date"
    exit 0
fi
.venv/bin/python -m pip install --quiet --disable-pip-version-check -r "$req"
.venv/bin/python -c "$probe" || { echo "ros2 peers: import check failed" >&2; exit 1; }
cp "$req" "$stamp"
echo "ros2 peers ready: $(.venv/bin/python -c 'from importlib.metadata import version as v; print("cyclonedds", v("cyclonedds"), "rosbags", v("rosbags"))')"

#!/usr/bin/env bash
# Python virtualenv at the repo root (.venv) with the Python peers the interop suites
# drive (roslibpy, ...). Idempotent: does nothing when the pinned requirements are
# already installed.
set -euo pipefail
cd "$(dirname "$0")/../.."
req=tests/interop/rosbridge/requirements.txt
stamp=.venv/.fleetlink-requirements
if [ ! -x .venv/bin/python ]; then
    # Debian's python3 makes venvs only with python3-venv (ensurepip); install it first
    # (waiting for another apt's lock) rather than fail half-way.
    if ! command -v python3 >/dev/null || ! python3 -c 'import ensurepip, venv' 2>/dev/null; then
        sudo_cmd=()
        [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
        "${sudo_cmd[@]}" apt-get -o DPkg::Lock::Timeout=600 update
        DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get -o DPkg::Lock::Timeout=600 \
            install -y --no-install-recommends python3 python3-venv
    fi
    python3 -m venv .venv
fi
# The stamp holds the requirements that were installed; reinstall only when they change.
if [ -f "$stamp" ] && cmp -s "$req" "$stamp" && .venv/bin/python -c 'import roslibpy' 2>/dev/null; then
    echo "python venv up to date"
    exit 0
fi
.venv/bin/python -m pip install --quiet --disable-pip-version-check -r "$req"
cp "$req" "$stamp"
echo "python venv ready: $(.venv/bin/python -c 'import roslibpy; print("roslibpy", roslibpy.__version__)')"

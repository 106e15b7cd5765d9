#!/usr/bin/env bash
# A second Python virtualenv (.venv-roslibpy1) with roslibpy 1.8, whose actionlib
# (ActionClient, SimpleActionServer: ROS 1 actions over topics) the rosbridge suite's
# actionlib check drives: programs written for ROS 1 still use it. Idempotent.
set -euo pipefail
cd "$(dirname "$0")/../.."
want=1.8.1
if .venv-roslibpy1/bin/python -c "import roslibpy, sys; sys.exit(roslibpy.__version__ != '$want')" 2>/dev/null; then
    echo "roslibpy $want venv up to date"
    exit 0
fi
python3 -m venv .venv-roslibpy1
.venv-roslibpy1/bin/python -m pip install --quiet --disable-pip-version-check "roslibpy==$want"
echo "roslibpy venv ready: $(.venv-roslibpy1/bin/python -c 'import roslibpy; print("roslibpy", roslibpy.__version__)')"

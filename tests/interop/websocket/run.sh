#!/usr/bin/env bash
# WebSocket interop suite: an RFC 6455 conformance check of the hub's server side, with a
# client the project did not write doing the framing (the Python `websockets` library,
# pinned in tests/interop/rosbridge/requirements.txt) and the cases modelled on the
# Autobahn TestSuite's sections (conformance.py; the client plumbing is peer.py).
#
# Starts a hub with a small --max-message-size (for the limit cases), mints an operator
# token (rosbridge clients publish with it) and a robot token (agent links say HELLO with
# it), runs every case under an overall timeout, checks that the hub survived them, and
# exits non-zero if any case failed. The hub is stopped on exit (trap), also on failure.
# The whole suite takes a few seconds (each wait for the hub is bounded at 2 s).
#
# Env: FLEETLINK_BIN (default: target/ci/fleetlink, what scripts/test.sh builds),
#      PYTHON (default: .venv/bin/python).
# Args are passed to conformance.py (e.g. --only 7. to run section 7 alone).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
bin="${FLEETLINK_BIN:-$root/target/ci/fleetlink}"
python="${PYTHON:-$root/.venv/bin/python}"
robot=ws_conformance
# Small and not a power of two: the limit cases send messages of exactly this size and
# one byte more, and it is above 65536 so that those use 64-bit frame lengths.
max_message=100000
started=$SECONDS

[ -x "$bin" ] || { echo "FAIL: fleetlink binary not found at $bin (set FLEETLINK_BIN)" >&2; exit 1; }
[ -x "$python" ] || { echo "FAIL: $python missing; run scripts/setup.d/10-python-venv.sh" >&2; exit 1; }
"$python" -c 'import websockets, cbor2, sys; sys.exit(websockets.__version__ != "17.4")' 2>/dev/null ||
    { echo "FAIL: $python lacks websockets 17.4 or cbor2; run scripts/setup.d/10-python-venv.sh" >&2; exit 1; }

# shellcheck source=../lib.sh
. "$here/../lib.sh"
interop_begin websocket

# --- credentials, minted in the hub's database before it starts (fleetlink admin)
admin() { timeout 30 "$bin" admin --data-dir "$tmp/hub-data" "$@"; }
op_token="$(admin token operator ws_conformance --group admin)"
robot_token="$(admin token robot "$robot")"

# --- hub (the log file exists before the background start, so the reader never races it)
: >"$tmp/hub.log"
"$bin" hub --listen 127.0.0.1:0 --data-dir "$tmp/hub-data" --max-message-size "$max_message" \
    >"$tmp/hub.log" 2>&1 &
pids+=($!)
hub_addr="$(wait_for_line "$tmp/hub.log" '^fleetlink hub listening on ([0-9.:]+)$' "hub start" "${pids[0]}")"
echo "hub: ws://$hub_addr/ (--max-message-size $max_message)"

# --- the cases (bounded as a whole; each read in them is bounded too)
rc=0
# -B: no __pycache__ left in the source tree.
timeout --kill-after=5 60 "$python" -B "$here/conformance.py" \
    --rosbridge-url "ws://$hub_addr/?token=$op_token" --agent-url "ws://$hub_addr/" \
    --robot "$robot" --robot-token "$robot_token" --max-message-size "$max_message" "$@" || rc=$?
if [ "$rc" -eq 124 ] || [ "$rc" -eq 137 ]; then
    echo "FAIL: conformance.py killed after 60 s"
fi

# The hub must have survived everything the cases sent it.
if ! kill -0 "${pids[0]}" 2>/dev/null; then
    echo "FAIL: the hub died during the cases"
    rc=1
fi

echo "websocket interop: $((SECONDS - started)) s"
if [ "$rc" -ne 0 ]; then
    echo "FAIL: websocket conformance (see the failed cases above)" >&2
    exit 1
fi
echo "PASS: websocket interop (RFC 6455 server conformance, rosbridge and fleetlink.v1 paths)"

#!/usr/bin/env bash
# TLS interop suite: a fleetlink hub serving wss:// with certificates made here by the
# openssl CLI (a CA, the hub's certificate for 127.0.0.1/localhost, a robot client
# certificate), an agent whose uplink is wss:// authenticated by that client
# certificate alone (no token), and Python clients (ssl module, roslibpy) that trust
# only the test CA. Exits non-zero on any failure; every process started here is
# stopped by the trap; every wait is bounded (whole suite well under 2 minutes).
#
# Env: FLEETLINK_BIN (default: target/release/fleetlink), PYTHON (default: .venv/bin/python).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
bin="${FLEETLINK_BIN:-$root/target/release/fleetlink}"
python="${PYTHON:-$root/.venv/bin/python}"
robot=robot1
started=$SECONDS

[ -x "$bin" ] || { echo "FAIL: fleetlink binary not found at $bin (set FLEETLINK_BIN)" >&2; exit 1; }
[ -x "$python" ] || { echo "FAIL: $python missing; run scripts/setup.d/10-python-venv.sh" >&2; exit 1; }
command -v openssl >/dev/null || { echo "FAIL: the openssl CLI is needed to make test certificates" >&2; exit 1; }

# shellcheck source=../lib.sh
. "$here/../lib.sh"
interop_begin tls

# --- certificates (EC P-256; v3 extensions so rustls/webpki accept them)
c="$tmp/certs"; mkdir -p "$c"
ossl() { openssl "$@" 2>>"$tmp/openssl.log"; }
ossl req -x509 -newkey ec -pkeyopt ec_paramgen_curve:P-256 -nodes -days 2 \
    -subj "/CN=fleetlink interop CA" -keyout "$c/ca.key" -out "$c/ca.pem" \
    -addext "basicConstraints=critical,CA:TRUE" -addext "keyUsage=critical,keyCertSign,cRLSign"
leaf() { # name, subjectAltName, extendedKeyUsage
    ossl req -newkey ec -pkeyopt ec_paramgen_curve:P-256 -nodes -subj "/CN=$1" \
        -keyout "$c/$1.key" -out "$c/$1.csr"
    printf 'basicConstraints=CA:FALSE\nkeyUsage=critical,digitalSignature\nsubjectAltName=%s\nextendedKeyUsage=%s\n' "$2" "$3" >"$c/$1.ext"
    ossl x509 -req -in "$c/$1.csr" -CA "$c/ca.pem" -CAkey "$c/ca.key" -CAcreateserial \
        -days 2 -extfile "$c/$1.ext" -out "$c/$1.pem"
}
leaf hub "IP:127.0.0.1,DNS:localhost" serverAuth
leaf "$robot" "DNS:$robot" clientAuth
echo "certificates: CA, hub (127.0.0.1, localhost), $robot (client)"

# --- operator token, minted in the hub's database before it starts
op_token="$("$bin" admin --data-dir "$tmp/hub-data" token operator interop --group admin)"

# --- hub on wss://, client certificates verified when presented
: >"$tmp/hub.log"; : >"$tmp/agent.log"
"$bin" hub --listen 127.0.0.1:0 --data-dir "$tmp/hub-data" \
    --tls-cert "$c/hub.pem" --tls-key "$c/hub.key" --tls-client-ca "$c/ca.pem" \
    >"$tmp/hub.log" 2>&1 &
pids+=($!)
hub_addr="$(wait_for_line "$tmp/hub.log" '^fleetlink hub listening on ([0-9.:]+)$' "hub start" "${pids[0]}")"
echo "hub: wss://$hub_addr/"

# --- agent: wss:// uplink, no token: the client certificate names the robot
cat >"$tmp/agent.yaml" <<YAML
hub: wss://localhost:${hub_addr##*:}/
name: $robot
tls: { ca: $c/ca.pem, cert: $c/$robot.pem, key: $c/$robot.key }
local_rosbridge: null
sim:
  odometry: { rate_hz: 20 }
YAML
"$bin" agent --config "$tmp/agent.yaml" >"$tmp/agent.log" 2>&1 &
pids+=($!)

# --- ready: robot1 online with /robot1/odom (bounded: 15 s), checked over https
"$python" - "$hub_addr" "$robot" "$op_token" "$c/ca.pem" <<'PY'
import json, ssl, sys, time, urllib.request
addr, robot, token, ca = sys.argv[1:5]
ctx = ssl.create_default_context(cafile=ca)
deadline, last = time.monotonic() + 15, None
while time.monotonic() < deadline:
    try:
        req = urllib.request.Request(f"https://{addr}/api/v1/robots",
                                     headers={"Authorization": f"Bearer {token}"})
        with urllib.request.urlopen(req, timeout=2, context=ctx) as r:
            me = [x for x in json.load(r)["robots"] if x["name"] == robot]
        last = me
        if me and me[0]["online"] and f"/{robot}/odom" in me[0]["topics"]:
            print(f"ready: {robot} online over wss with {sorted(me[0]['topics'])}")
            sys.exit(0)
    except Exception as e:
        last = repr(e)
    time.sleep(0.1)
print(f"FAIL: {robot} not online within 15 s; last: {last}", file=sys.stderr)
sys.exit(1)
PY

# --- the Python clients over TLS
timeout --kill-after=5 60 "$python" "$here/tls_check.py" \
    --addr "$hub_addr" --ca "$c/ca.pem" --token "$op_token" --robot "$robot"

# --- a plain (non-TLS) WebSocket client gets nowhere on the TLS port
if timeout 10 "$python" - "$hub_addr" <<'PY'
import sys, urllib.request
try:
    urllib.request.urlopen(f"http://{sys.argv[1]}/healthz", timeout=5)
except Exception:
    sys.exit(1)
PY
then
    echo "FAIL: plain http:// was answered on the TLS port" >&2
    exit 1
fi
echo "ok: plain http:// refused on the TLS port"

for pid in "${pids[@]}"; do
    kill -0 "$pid" 2>/dev/null || { echo "FAIL: process $pid died" >&2; exit 1; }
done
echo "PASS: TLS interop (openssl certificates, agent over wss with a client certificate, roslibpy over wss) in $((SECONDS - started)) s"

#!/usr/bin/env bash
# Login latency with the hub's state in SQLite and in PostgreSQL (docs/benchmarks/log.md,
# "Shared state in PostgreSQL"): one hub on each, side by side, measured by the same
# client. PostgreSQL runs as tests/interop/postgres/cluster.sh starts it, with fsync on
# (PG_FSYNC=on) so a commit costs what it costs on a real server.
#
#   password login   POST /api/v1/login (argon2 verification, session token written)
#   token request    GET /api/v1/robots with an operator token (token read and its
#                    last_used_at written, then the robots table read)
#
# Env: FLEETLINK_BIN (default: target/ci/fleetlink), PYTHON (default: .venv/bin/python),
# N (requests per kind, default 200).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/.." && pwd)"
bin="${FLEETLINK_BIN:-$root/target/ci/fleetlink}"
python="${PYTHON:-$root/.venv/bin/python}"
n="${N:-200}"
. "$root/tests/interop/lib.sh"
. "$root/tests/interop/postgres/cluster.sh"
interop_begin bench-postgres
trap 'rc=$?; set +e; pg_cluster_remove; (exit $rc); interop_cleanup' EXIT
PG_FSYNC=on pg_cluster_start

declare -A addr
for kind in sqlite postgres; do
    if [ "$kind" = sqlite ]; then db=(--data-dir "$tmp/hub-data"); else db=(--database "$PG_URL"); fi
    timeout 30 "$bin" admin "${db[@]}" token operator bench --group admin >"$tmp/$kind.token"
    echo pw-bench-1 | timeout 30 "$bin" admin "${db[@]}" users add bench >/dev/null
    "$bin" hub --listen 127.0.0.1:0 "${db[@]}" >"$tmp/$kind.log" 2>&1 &
    pids+=($!)
    addr[$kind]="$(wait_for_line "$tmp/$kind.log" '^fleetlink hub listening on ([0-9.:]+)$' "$kind hub" "$!")"
done

"$python" - "$n" "${addr[sqlite]}" "$(cat "$tmp/sqlite.token")" "${addr[postgres]}" "$(cat "$tmp/postgres.token")" <<'PY'
import http.client, json, statistics, sys, time
n = int(sys.argv[1])
hubs = {"sqlite": (sys.argv[2], sys.argv[3]), "postgres": (sys.argv[4], sys.argv[5])}

def timed(addr, method, path, headers, body=None):
    host, port = addr.rsplit(":", 1)
    c = http.client.HTTPConnection(host, int(port), timeout=10)
    c.connect()  # the TCP handshake is not part of the figure
    t = time.perf_counter()
    c.request(method, path, body=body, headers=headers)
    r = c.getresponse()
    r.read()
    took = (time.perf_counter() - t) * 1000
    c.close()
    assert r.status == 200, (path, r.status)
    return took

def summary(xs):
    xs = sorted(xs)
    return f"p50 {statistics.median(xs):6.2f} ms  p99 {xs[int(len(xs) * 0.99) - 1]:6.2f} ms  mean {statistics.mean(xs):6.2f} ms"

login = json.dumps({"user": "bench", "password": "pw-bench-1"})
for kind, (addr, token) in hubs.items():
    for _ in range(10):  # warm up: connections opened, statements prepared
        timed(addr, "GET", "/api/v1/robots", {"Authorization": f"Bearer {token}"})
    logins = [timed(addr, "POST", "/api/v1/login", {"Content-Type": "application/json"}, login)
              for _ in range(n)]
    tokens = [timed(addr, "GET", "/api/v1/robots", {"Authorization": f"Bearer {token}"})
              for _ in range(n)]
    print(f"{kind:9s} password login  {summary(logins)}")
    print(f"{kind:9s} token request   {summary(tokens)}")
PY

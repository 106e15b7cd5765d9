#!/usr/bin/env bash
# PostgreSQL interop suite (issue 38 item 5): hubs sharing their state in one database.
#
# Starts a throwaway PostgreSQL cluster (cluster.sh: Debian's server, an unprivileged
# cluster in a temp dir, a free port on 127.0.0.1), then:
#
#   1. runs the Rust tests' PostgreSQL variants (the auth store, audit and shared-change
#      tests, the hub store, parameter and delivery tests; ignored in a plain test run)
#      with FLEETLINK_TEST_POSTGRES pointing at it, reusing the ci profile's build;
#   2. starts two `fleetlink hub --database URL` processes (A and B) on 127.0.0.1:0 and
#      runs pg_check.py against them: a token minted through A authenticates on B, a rule
#      change through A applies on B within 1 s, a token revoked through B is refused by A
#      within 1 s, and with the database killed new logins fail clearly while established
#      sessions keep working, until it comes back (figures printed);
#   3. checks `fleetlink admin --database URL` sees what the hubs did.
#
# Every wait is bounded; the hubs and the cluster are stopped on exit, also on failure.
#
# Env: FLEETLINK_BIN (default: target/release/fleetlink), PYTHON (default: .venv/bin/python),
# PG_SUITE_SKIP_RUST=1 to skip step 1 (e.g. when only the binary was built).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
bin="${FLEETLINK_BIN:-$root/target/release/fleetlink}"
python="${PYTHON:-$root/.venv/bin/python}"
started=$SECONDS

[ -x "$bin" ] || { echo "FAIL: fleetlink binary not found at $bin (set FLEETLINK_BIN)" >&2; exit 1; }
[ -x "$python" ] || { echo "FAIL: $python missing; run scripts/setup.d/10-python-venv.sh" >&2; exit 1; }

# shellcheck source=../lib.sh
. "$here/../lib.sh"
# shellcheck source=cluster.sh
. "$here/cluster.sh"
interop_begin postgres
# The cluster goes too, whatever happens (lib.sh's cleanup keeps the exit status;
# `set +e` so that replaying a failed status does not end the trap before it).
trap 'rc=$?; set +e; pg_cluster_remove; (exit $rc); interop_cleanup' EXIT

pg_cluster_start
echo "PostgreSQL: $PG_URL (data in $PG_DIR)"
failed=()

# --- 1. the Rust tests' PostgreSQL variants
if [ "${PG_SUITE_SKIP_RUST:-}" = 1 ]; then
    echo "SKIP: Rust PostgreSQL variants (PG_SUITE_SKIP_RUST=1)"
else
    echo "== Rust tests on PostgreSQL"
    # The same profile and package set (--workspace, so the same features) as
    # scripts/test.sh's test run: nothing compiles again; the filter picks the crates.
    if ! (cd "$root" && FLEETLINK_TEST_POSTGRES="$PG_URL" timeout 900 \
        cargo nextest run --locked --workspace --cargo-profile ci --no-fail-fast --run-ignored only \
        -E 'package(fleetlink-auth) | package(fleetlink-hub) | package(fleetlink-postgres)'); then
        failed+=("rust")
    fi
fi

# --- 2. two hubs on one database
admin_token="$(timeout 30 "$bin" admin --database "$PG_URL" token operator interop --group admin)"
declare -A addr pid
for h in a b; do
    log="$tmp/hub-$h.log"
    : >"$log"
    "$bin" hub --listen 127.0.0.1:0 --data-dir "$tmp/hub-$h" --database "$PG_URL" >"$log" 2>&1 &
    pids+=($!)
    pid[$h]=$!
    addr[$h]="$(wait_for_line "$log" '^fleetlink hub listening on ([0-9.:]+)$' "hub $h start" "${pid[$h]}")"
    echo "hub ${h^^}: ws://${addr[$h]}/ (pid ${pid[$h]})"
done
# lib.sh shows the tail of $tmp/hub.log on failure: hub A's.
ln -s "$tmp/hub-a.log" "$tmp/hub.log"

rc=0
timeout 120 "$python" "$here/pg_check.py" --hub-a "${addr[a]}" --hub-b "${addr[b]}" \
    --admin-token "$admin_token" || rc=$?
[ "$rc" -eq 0 ] || failed+=("hubs (pg_check.py exit $rc)")
for h in a b; do
    kill -0 "${pid[$h]}" 2>/dev/null || failed+=("hub ${h^^} died")
done

# --- 3. the CLI sees the same database
if timeout 30 "$bin" admin --database "$PG_URL" users list | grep -q '^carol'; then
    echo "PASS: fleetlink admin --database lists the user added through hub A"
else
    failed+=("admin --database")
fi
audit="$(timeout 30 "$bin" admin --database "$PG_URL" audit --limit 1000)"
if grep -q '"action":"rule_change"' <<<"$audit" && grep -q '"action":"credential_change"' <<<"$audit"; then
    echo "PASS: both hubs' audit records are in the shared database ($(wc -l <<<"$audit") shown)"
else
    failed+=("audit")
fi
# A wrong URL stops at once and says why, without the password.
if out="$(timeout 30 "$bin" hub --listen 127.0.0.1:0 --database "postgres://fleetlink:s3cret@127.0.0.1:1/x" 2>&1)"; then
    failed+=("a hub with an unreachable database started")
elif grep -q "cannot reach PostgreSQL at postgres://fleetlink@127.0.0.1:1/x" <<<"$out" && ! grep -q s3cret <<<"$out"; then
    echo "PASS: a hub whose database is unreachable exits naming it: $(grep -o 'cannot reach.*' <<<"$out" | head -c 160)..."
else
    echo "$out" >&2
    failed+=("unreachable database message")
fi

echo "postgres interop: ${#failed[@]} failure(s), $((SECONDS - started)) s"
if [ ${#failed[@]} -ne 0 ]; then
    echo "FAIL: ${failed[*]}" >&2
    exit 1
fi
echo "PASS: postgres interop (two hubs, one database: credentials, rules, revocation, outage)"

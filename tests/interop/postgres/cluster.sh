# A throwaway PostgreSQL cluster for the tests (sourced, not run): Debian's server binaries,
# a data directory and Unix socket directory under one temp dir, TCP on 127.0.0.1 on a
# free port, `trust` authentication for the one superuser `fleetlink`. PostgreSQL refuses
# to run as root, so when the tests run as root the server runs as the `postgres` user
# (created by Debian's package, scripts/setup.d/70-postgresql.sh); otherwise as the
# current user. Every step is bounded in time.
#
#   pg_cluster_start        initdb + start; sets PG_DIR, PG_PORT, PG_URL (the `fleetlink`
#                           database) and PG_ADMIN_URL (the `postgres` database)
#   pg_cluster_kill         stops the server at once (immediate: clients are cut off)
#   pg_cluster_up           starts it again on the same port, same data
#   pg_cluster_remove       stops it (fast) and deletes its directory
#
# PG_FSYNC=on keeps fsync (for measurements); the default turns it off, as the tests
# check behaviour, not durability. PG_TMPDIR: where the cluster's directory goes (/tmp).

pg_bin_dir() {
    local d
    d="$(ls -d /usr/lib/postgresql/*/bin 2>/dev/null | sort -V | tail -n1)"
    [ -x "$d/initdb" ] || { echo "FAIL: PostgreSQL server binaries not found under /usr/lib/postgresql; run scripts/setup.d/70-postgresql.sh" >&2; return 1; }
    echo "$d"
}

# Runs a server binary as the cluster's owner, for at most $1 seconds, from / (the
# caller's directory may be closed to that user).
pg_as_owner() {
    local secs=$1
    shift
    if [ "$(id -u)" -eq 0 ]; then
        (cd / && timeout "$secs" runuser -u postgres -- "$@")
    else
        (cd / && timeout "$secs" "$@")
    fi
}

pg_free_port() {
    python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'
}

pg_cluster_start() {
    local bin
    bin="$(pg_bin_dir)" || return 1
    PG_BIN="$bin"
    # Under /tmp rather than $TMPDIR: the server's user must reach it.
    PG_DIR="$(mktemp -d "${PG_TMPDIR:-/tmp}/fleetlink-pg.XXXXXX")"
    chmod 755 "$PG_DIR"
    [ "$(id -u)" -eq 0 ] && chown postgres: "$PG_DIR"
    if ! pg_as_owner 60 "$bin/initdb" -D "$PG_DIR/data" -U fleetlink --auth=trust \
        --no-locale -E UTF8 >"$PG_DIR/initdb.log" 2>&1; then
        echo "FAIL: initdb failed:" >&2
        tail -n 20 "$PG_DIR/initdb.log" >&2
        return 1
    fi
    local try
    for try in 1 2 3; do
        PG_PORT="$(pg_free_port)"
        pg_cluster_up && break
        [ "$try" -eq 3 ] && return 1
    done
    PG_URL="postgres://fleetlink@127.0.0.1:$PG_PORT/fleetlink"
    PG_ADMIN_URL="postgres://fleetlink@127.0.0.1:$PG_PORT/postgres"
    timeout 20 "$bin/createdb" -h 127.0.0.1 -p "$PG_PORT" -U fleetlink fleetlink || {
        echo "FAIL: createdb failed" >&2
        return 1
    }
    export PG_BIN PG_DIR PG_PORT PG_URL PG_ADMIN_URL
}

pg_cluster_up() {
    local fsync="${PG_FSYNC:-off}"
    if ! pg_as_owner 40 "$PG_BIN/pg_ctl" -D "$PG_DIR/data" -l "$PG_DIR/server.log" -w -t 30 \
        -o "-p $PG_PORT -k $PG_DIR -c listen_addresses=127.0.0.1 -c fsync=$fsync -c max_connections=200" \
        start >/dev/null; then
        echo "FAIL: PostgreSQL did not start on port $PG_PORT:" >&2
        tail -n 20 "$PG_DIR/server.log" >&2
        return 1
    fi
}

pg_cluster_kill() {
    pg_as_owner 30 "$PG_BIN/pg_ctl" -D "$PG_DIR/data" -m immediate -w -t 20 stop >/dev/null
}

pg_cluster_remove() {
    [ -n "${PG_DIR:-}" ] && [ -d "$PG_DIR" ] || return 0
    if [ -f "$PG_DIR/data/postmaster.pid" ]; then
        pg_as_owner 30 "$PG_BIN/pg_ctl" -D "$PG_DIR/data" -m fast -w -t 20 stop >/dev/null 2>&1 \
            || pg_cluster_kill 2>/dev/null || true
    fi
    rm -rf "$PG_DIR"
    PG_DIR=""
}

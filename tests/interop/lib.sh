# Shared by the interop suites (sourced, not run): a temp directory, processes started
# in the background that are always stopped (gracefully, then by force) with their log
# tails shown on failure, and a bounded wait for a line in a log.
#
# After `interop_begin NAME`: $tmp is the suite's directory; append background pids to
# the `pids` array; logs named $tmp/hub.log and $tmp/agent.log are shown on failure.
# Every agent a suite starts keeps its state in $tmp/state: XDG_STATE_HOME points there
# (and STATE_DIRECTORY is unset), so an agent's default runtime_file is
# $tmp/state/fleetlink/<robot>/runtime.json, never the user's (changes kept there by an
# earlier agent of the same name, a demo or a manual try, would apply to the suite's).
# INTEROP_KEEP=DIR copies the suite's directory (logs, records) there before it is removed.
# `interop_netns NS` makes a network namespace that is deleted on exit too, with whatever
# still runs in it.

interop_begin() {
    tmp="$(mktemp -d "${TMPDIR:-/tmp}/fleetlink-interop-$1.XXXXXX")"
    export XDG_STATE_HOME="$tmp/state"
    unset STATE_DIRECTORY
    pids=()
    interop_namespaces=()
    trap interop_cleanup EXIT
    trap 'exit 130' INT TERM
}

interop_cleanup() {
    local rc=$?
    for pid in "${pids[@]}"; do kill -TERM "$pid" 2>/dev/null || true; done
    for pid in "${pids[@]}"; do
        # Bounded wait for a graceful stop, then force.
        for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
        kill -KILL "$pid" 2>/dev/null || true
        wait "$pid" 2>/dev/null || true
    done
    for ns in "${interop_namespaces[@]}"; do
        # What was started in it beyond `pids` (children of a shell function, say).
        for _ in $(seq 50); do [ -z "$(ip netns pids "$ns" 2>/dev/null)" ] && break; sleep 0.1; done
        for pid in $(ip netns pids "$ns" 2>/dev/null); do kill -KILL "$pid" 2>/dev/null || true; done
        ip netns del "$ns" 2>/dev/null || echo "warning: could not delete network namespace $ns" >&2
    done
    if [ "$rc" -ne 0 ]; then
        for f in hub agent; do
            [ -f "$tmp/$f.log" ] && { echo "--- last lines of $f log"; tail -n 30 "$tmp/$f.log"; } >&2
        done
    fi
    if [ -n "${INTEROP_KEEP:-}" ]; then cp -r "$tmp" "$INTEROP_KEEP" && echo "kept: $INTEROP_KEEP" >&2; fi
    rm -rf "$tmp"
    exit "$rc"
}

# A network namespace named $1, deleted on exit: its loopback up, with multicast routed on
# it (DDS discovery stays inside the namespace).
interop_netns() {
    ip netns add "$1" || { echo "FAIL: cannot create network namespace $1" >&2; exit 1; }
    interop_namespaces+=("$1")
    ip netns exec "$1" ip link set lo up multicast on
    ip netns exec "$1" ip route add 224.0.0.0/4 dev lo
}

# Waits (bounded, 10 s) until a line matching $2 appears in log $1 written by process $4;
# prints the first capture group. $3 names the wait in the failure message.
wait_for_line() {
    local log=$1 pattern=$2 what=$3 pid=$4
    for _ in $(seq 200); do # 200 x 0.05 s
        local m
        m="$(sed -nE "s#${pattern}#\\1#p" "$log" | head -n1)"
        if [ -n "$m" ]; then echo "$m"; return 0; fi
        kill -0 "$pid" 2>/dev/null || { echo "FAIL: $what: process exited" >&2; return 1; }
        sleep 0.05
    done
    echo "FAIL: $what: no line matching '$pattern' within 10 s" >&2
    return 1
}

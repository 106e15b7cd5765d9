#!/usr/bin/env bash
# A hostile user state for the test suite (issue 57): changes kept by an earlier agent
# called robot1 — a demo, a manual try, another suite — in the place an agent keeps them by
# default (`runtime_file`: <state dir>/robot1/runtime.json), written the way an older agent
# wrote them. Any test agent called robot1 that read it would run broken: the links
# suite's no_drop probe remapped away from where its viewer listens, its no_drop turned
# off, /pose rate-limited. No test may read or write the user's state (every agent the
# suites start keeps its state in the test's temporary directory), so with this file in
# place every suite must still pass, and the file must be left as it was.
#
#   scripts/hostile-state.sh plant    puts the file there (an existing one is set aside)
#   scripts/hostile-state.sh remove   checks nothing wrote to it or beside it, removes it
#                                     and puts back what was there; exits 1 if a test
#                                     wrote there
#
# The state directory is found as the agent finds it: $STATE_DIRECTORY (its first entry),
# else $XDG_STATE_HOME/fleetlink, else ~/.local/state/fleetlink, else /var/lib/fleetlink.
set -euo pipefail

if [ -n "${STATE_DIRECTORY:-}" ]; then
    dir="${STATE_DIRECTORY%%:*}"
elif [ -n "${XDG_STATE_HOME:-}" ]; then
    dir="$XDG_STATE_HOME/fleetlink"
elif [ -n "${HOME:-}" ]; then
    dir="$HOME/.local/state/fleetlink"
else
    dir=/var/lib/fleetlink
fi
robot_dir="$dir/robot1"
file="$robot_dir/runtime.json"
# What `plant` did, for `remove`: the user's own file set aside, directories it made.
marker="$robot_dir/.fleetlink-tests-planted"
hostile='{"topics": {"/pose": {"rate_limit_hz": 0.5}, "/probe/reliable": {"no_drop": false}}, "remap": {"/probe/reliable": "/hostile/probe/reliable"}}'

case "${1:-}" in
plant)
    if [ -e "$marker" ]; then
        echo "hostile state: already planted in $file (a run before did not remove it); removing it first" >&2
        "$0" remove || true
    fi
    made=()
    d="$robot_dir"
    while [ ! -d "$d" ]; do
        made+=("$d")
        d="$(dirname "$d")"
    done
    mkdir -p "$robot_dir"
    {
        for d in "${made[@]+"${made[@]}"}"; do echo "made $d"; done
        if [ -e "$file" ]; then
            mv "$file" "$file.before-tests"
            echo "kept $file.before-tests"
        fi
        for beside in "$file.audit.jsonl" "$file.tmp"; do
            if [ -e "$beside" ]; then echo "had $beside"; fi
        done
    } >"$marker"
    printf '%s\n' "$hostile" >"$file"
    echo "hostile state: planted $file (a kept change for robot1 that no test may read)"
    ;;
remove)
    [ -e "$marker" ] || { echo "hostile state: nothing planted in $file"; exit 0; }
    rc=0
    if [ "$(cat "$file" 2>/dev/null)" != "$hostile" ]; then
        echo "FAIL: hostile state: $file was changed or removed by a test: tests must keep their state in their own directory" >&2
        rc=1
    fi
    for beside in "$file.audit.jsonl" "$file.tmp"; do
        if [ -e "$beside" ] && ! grep -qxF "had $beside" "$marker"; then
            echo "FAIL: hostile state: a test wrote $beside: tests must keep their state in their own directory" >&2
            rm -f "$beside"
            rc=1
        fi
    done
    rm -f "$file"
    if grep -q '^kept ' "$marker"; then mv "$file.before-tests" "$file"; fi
    made_dirs="$(sed -n 's/^made //p' "$marker" | sort -r)"
    rm -f "$marker"
    # The directories it made, deepest first, if nothing else is in them.
    while IFS= read -r d; do
        if [ -n "$d" ]; then rmdir "$d" 2>/dev/null || true; fi
    done <<<"$made_dirs"
    [ "$rc" -eq 0 ] && echo "hostile state: $file untouched by the tests; removed"
    exit "$rc"
    ;;
*)
    echo "usage: $0 plant|remove" >&2
    exit 2
    ;;
esac

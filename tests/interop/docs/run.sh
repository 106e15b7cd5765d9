#!/usr/bin/env bash
# Docs suite: every shell block of README.md and docs/**/*.md (subdirectories included,
# e.g. docs/benchmarks/log.md) marked runnable is run, so a recipe that stops working
# fails the tests instead of the next reader. First, check_benchmarks.py checks the
# results table of docs/benchmarks.md (every figure has a command that exists, a commit
# that resolves and a met / not met / blocked status), the links into the benchmark
# pages, and that README.md states Cargo.toml's rust-version.
#
# Marking a block: put the line
#
#     <!-- runnable -->
#
# (invisible when rendered) directly above a ```sh or ```bash fence. Extra environment
# for that block only: `<!-- runnable DURATION=1 RUNS=1 -->` (how a recipe that measures
# for minutes is kept short here; the recipe reads `${DURATION:-5}`).
#
# How blocks run: the marked blocks of one file run in order in one bash process
# (`set -euo pipefail`) in a fresh directory (not the file's own, so a page in a
# subdirectory runs the same), and a later block sees the files and variables of an
# earlier one, as a reader following the page would. Before the first:
#
#   - a fresh hub runs on 127.0.0.1:<free port> with `--data-dir ./fleetlink-data`, so
#     `fleetlink admin --data-dir ./fleetlink-data ...` acts on it;
#   - HUB_ADDR=127.0.0.1:<port>, HUB=ws://$HUB_ADDR, and FLEETLINK_TOKEN, an operator
#     token of its admin group (what `bench relay` and `curl` recipes use);
#   - PORT and PORT2: free ports for hubs a recipe starts itself (recipes write
#     `${PORT:-8443}`);
#   - `fleetlink` on PATH is $FLEETLINK_BIN.
#
# Each file's blocks get $DOCS_TIMEOUT seconds (default 120); whatever they started in the
# background is stopped (the whole process group) when they end. A marker not followed
# by a shell fence is an error, and so is finding no runnable block at all.
#
# Env: FLEETLINK_BIN (default: target/release/fleetlink), DOCS_TIMEOUT.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
bin="${FLEETLINK_BIN:-$root/target/release/fleetlink}"
limit="${DOCS_TIMEOUT:-120}"
started=$SECONDS

[ -x "$bin" ] || { echo "FAIL: fleetlink binary not found at $bin (set FLEETLINK_BIN)" >&2; exit 1; }
for tool in python3 curl openssl; do
    command -v "$tool" >/dev/null || { echo "FAIL: the docs recipes need $tool" >&2; exit 1; }
done

python3 "$here/check_benchmarks.py" --bin "$bin"

# shellcheck source=../lib.sh
. "$here/../lib.sh"
interop_begin docs
groups=()
stop_groups() {
    for g in "${groups[@]}"; do kill -TERM -- "-$g" 2>/dev/null || true; done
    for g in "${groups[@]}"; do
        for _ in $(seq 50); do kill -0 -- "-$g" 2>/dev/null || break; sleep 0.1; done
        kill -KILL -- "-$g" 2>/dev/null || true
    done
    groups=()
}
trap 'rc=$?; stop_groups; (exit $rc); interop_cleanup' EXIT

mkdir -p "$tmp/bin"
ln -s "$bin" "$tmp/bin/fleetlink"
export PATH="$tmp/bin:$PATH"

# Whether process $1 still runs (a finished child stays a zombie until waited for, and
# `kill -0` succeeds on a zombie).
running() { [ -r "/proc/$1/stat" ] && ! grep -q ') Z ' "/proc/$1/stat"; }

free_port() {
    python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'
}

# Writes the runnable blocks of markdown file $1 as a bash script on stdout; exits 2 on
# a marker without a shell fence. Each block is preceded by its location and env.
extract() {
    awk -v file="$1" '
        function fail(msg) { printf "FAIL: %s:%d: %s\n", file, NR, msg > "/dev/stderr"; bad = 1; exit 2 }
        in_block && /^```/ { in_block = 0; for (i = 1; i <= nenv; i++) { split(env[i], kv, "="); print "unset " kv[1] }; next }
        in_block { print; next }
        marked {
            marked = 0
            if ($0 !~ /^```(sh|bash)[[:space:]]*$/) fail("<!-- runnable --> must be followed by a ```sh or ```bash fence")
            in_block = 1; count++
            printf "\nblock=%s:%d\necho \"== %s:%d\"\n", file, NR, file, NR
            for (i = 1; i <= nenv; i++) print "export " env[i]
            next
        }
        /^<!-- runnable( [A-Za-z_][A-Za-z0-9_]*=[^ ]+)* -->[[:space:]]*$/ {
            marked = 1; nenv = 0
            line = $0; sub(/^<!-- runnable ?/, "", line); sub(/ ?-->[[:space:]]*$/, "", line)
            if (line != "") nenv = split(line, env, " ")
            next
        }
        /<!-- *runnable/ { fail("malformed marker (expected <!-- runnable [KEY=VALUE ...] -->)") }
        END { if (!bad && in_block) { printf "FAIL: %s: unclosed runnable block\n", file > "/dev/stderr"; exit 2 } }
    ' "$root/$1"
}

total=0
cd "$root"
shopt -s globstar
for md in README.md docs/**/*.md; do
    body="$(extract "$md")" || exit 1
    n="$(grep -c '^block=' <<<"$body" || true)"
    [ "$n" -gt 0 ] || continue
    total=$((total + n))

    # Named after the path: docs/msg.md and docs/benchmarks/msg.md must not share one.
    name="${md%.md}"
    name="${name//\//-}"
    work="$tmp/work-$name"
    mkdir -p "$work"
    hub_log="$tmp/hub-$name.log"
    (cd "$work" && exec "$bin" hub --listen 127.0.0.1:0 --data-dir ./fleetlink-data) >"$hub_log" 2>&1 &
    hub_pid=$!
    pids+=("$hub_pid")
    addr="$(wait_for_line "$hub_log" '^fleetlink hub listening on ([0-9.:]+)$' "hub for $md" "$hub_pid")"
    token="$("$bin" admin --data-dir "$work/fleetlink-data" token operator docs --group admin)"

    script="$tmp/$name.sh"
    {
        echo 'set -euo pipefail'
        echo 'block=start'
        echo 'trap '\''rc=$?; [ $rc -eq 0 ] || echo "FAIL: the block at $block failed (exit $rc)" >&2'\'' EXIT'
        printf '%s\n' "$body"
    } >"$script"

    echo "== docs: $md ($n runnable blocks, hub on $addr)"
    # A session of its own: the blocks and all they start are one process group.
    (cd "$work" && HUB_ADDR="$addr" HUB="ws://$addr" FLEETLINK_TOKEN="$token" \
        PORT="$(free_port)" PORT2="$(free_port)" exec setsid bash "$script") &
    leader=$!
    groups+=("$leader")
    deadline=$((SECONDS + limit))
    while running "$leader" && [ $SECONDS -lt $deadline ]; do sleep 0.2; done
    if running "$leader"; then
        echo "FAIL: $md: runnable blocks still running after $limit s" >&2
        exit 1
    fi
    rc=0; wait "$leader" || rc=$?
    stop_groups
    kill -TERM "$hub_pid" 2>/dev/null || true
    wait "$hub_pid" 2>/dev/null || true
    if [ "$rc" -ne 0 ]; then
        echo "FAIL: $md (exit $rc); its hub's log:" >&2
        tail -n 20 "$hub_log" >&2
        exit 1
    fi
done

[ "$total" -gt 0 ] || { echo "FAIL: no runnable blocks found in README.md or docs/**/*.md" >&2; exit 1; }
echo "PASS: docs: $total runnable blocks in $((SECONDS - started)) s"

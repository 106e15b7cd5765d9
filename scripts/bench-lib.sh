# Shared by the bench scripts (sourced, not run): the release binary, a scratch
# directory and the processes a script starts, all removed on exit; free and awaited
# ports on loopback.
#
#   . "$(dirname "$0")/bench-lib.sh"; bench_init delivery
#   port="$(free_port)"; "$bin" hub --listen "127.0.0.1:$port" ... & pids+=($!)
#   wait_port "$port"

# Sets root, bin (FLEETLINK_BIN or the release build), tmp (removed on exit) and pids
# (killed on exit); refuses to go on without the binary.
bench_init() { # name
    root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
    bin="${FLEETLINK_BIN:-$root/target/release/fleetlink}"
    [ -x "$bin" ] || { echo "build first: cargo build --release -p fleetlink" >&2; exit 1; }
    tmp="$(mktemp -d "${TMPDIR:-/tmp}/fleetlink-bench-$1.XXXXXX")"
    pids=()
    trap bench_cleanup EXIT
}

bench_cleanup() {
    for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done
    wait 2>/dev/null || true
    rm -rf "$tmp"
}

free_port() { python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])'; }

wait_port() { # port
    for _ in $(seq 200); do (exec 3<>"/dev/tcp/127.0.0.1/$1") 2>/dev/null && return 0; sleep 0.05; done
    echo "nothing listens on port $1" >&2; exit 1
}

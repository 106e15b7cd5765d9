#!/usr/bin/env bash
# The whole test suite, as a newcomer and CI run it: installs what the tests need
# (idempotently), checks formatting and lints, runs the Rust tests, then the interop
# suites that drive real peers (roslibpy, roslibjs, rosbags, rospy, ...), several at once.
#
#   ./scripts/test.sh                    everything (CI runs this)
#   ./scripts/test.sh --rust             formatting, lints and the Rust tests only
#   ./scripts/test.sh --interop          the binary and every interop suite only
#   ./scripts/test.sh --only links:7     one interop suite, or some of its scenarios
#                                        (links:1,7 viewers:cut federation:check; several
#                                        --only add up), after building the binary
#
# Env: INTEROP_JOBS (interop suites run at once, default 3), INTEROP_LOGS (where each
# suite's output is kept, default target/interop-logs). docs/testing.md says what each
# part runs, how long it takes and what it needs.
set -euo pipefail
cd "$(dirname "$0")/.."

mode=all
only=()
while [ $# -gt 0 ]; do
    case "$1" in
        --rust) mode=rust ;;
        --interop) mode=only ;;
        --only) [ $# -ge 2 ] || { echo "--only needs SUITE[:SCENARIOS], e.g. --only links:7" >&2; exit 2; }
                mode=only; only+=("$2"); shift ;;
        --only=*) mode=only; only+=("${1#--only=}") ;;
        -h|--help) sed -n '2,15p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
        *) echo "unknown argument '$1' (try --rust, --only SUITE[:SCENARIOS], or none for everything)" >&2; exit 2 ;;
    esac
    shift
done

# Time per stage, reported at the end (also when a stage fails).
stages=()
interop_failed=()
stage_start=$SECONDS
stage_name=""
stage() {
    [ -n "$stage_name" ] && stages+=("$(printf '%-40s %4d s' "$stage_name" $((SECONDS - stage_start)))")
    stage_name="$1"
    stage_start=$SECONDS
    [ -n "$1" ] && echo "== $1"
    return 0
}
report() {
    local rc=$?
    # Never leave the hostile state below on the machine, whatever happened.
    if [ -n "${hostile_planted:-}" ]; then ./scripts/hostile-state.sh remove || rc=1; fi
    stage ""
    # The lines that name what failed, last, where a truncated log still shows them.
    local name
    for name in "${interop_failed[@]}"; do
        echo "== what failed in $name (its log: ${INTEROP_LOGS:-target/interop-logs}/$name.log)"
        # Plain FAIL/ERROR lines, and the rows of a results table marked FAIL.
        grep -E '^(FAIL|ERROR|not ok)|\| FAIL \|' "${INTEROP_LOGS:-$PWD/target/interop-logs}/$name.log" | head -n 20 || true
    done
    echo "== time per stage"
    printf '  %s\n' "${stages[@]}"
    echo "  total: $SECONDS s"
    exit "$rc"
}
trap report EXIT

stage "setup (scripts/setup.d)"
./scripts/setup-test-env.sh

# Interop suites and their parts, longest first (so the job limit packs them well): NAME
# SCRIPT ENV. A suite whose scenarios are independent is split into parts that run at once
# (each part its own namespaces, ports and temporary directory). The suites that time a
# link (links, viewers: recovery within 1 s of link-up, a viewer dropped within its
# silence limit plus 1 s) run first, among themselves; `wait` lets them finish before the
# ones that keep both cores busy (ROS 2 graphs in Python, Chromium, message codecs) start.
interop_plan() {
    echo "links-a tests/interop/links/run.sh LINKS_SCENARIOS=1_2_3_4_5"
    echo "links-b tests/interop/links/run.sh LINKS_SCENARIOS=6_7_8_9_10_11"
    echo "viewers tests/interop/viewers/run.sh -"
    echo "wait - -"
    local known=" links viewers "
    # mirror last: its DDS discovery loses the cloud nodes' readers when the machine is
    # loaded (docs/testing.md), so it runs beside the quick suites at the end.
    for order in runtime-config ros2 msg ros1 dashboard site postgres docs record video \
        rosbridge federation security failover foxglove calls websocket rosbridge-client tls \
        mirror; do
        [ -e "tests/interop/$order/run.sh" ] && echo "$order tests/interop/$order/run.sh -"
        known+="$order "
    done
    local suite
    for suite in tests/interop/*/run.sh; do
        [ -e "$suite" ] || continue
        suite="${suite#tests/interop/}"; suite="${suite%/run.sh}"
        case "$known" in *" $suite "*) ;; *) echo "$suite tests/interop/$suite/run.sh -" ;; esac
    done
}

# What `--only SUITE[:SCENARIOS]` runs: the suite whole, or the scenarios its run.sh can
# select (links and viewers by name or number, federation's `check` without failover).
only_plan() {
    local spec suite scen
    for spec in "${only[@]}"; do
        suite="${spec%%:*}"; scen=""
        [ "$suite" != "$spec" ] && scen="${spec#*:}"
        [ -e "tests/interop/$suite/run.sh" ] || {
            echo "no interop suite '$suite' (there are: $(cd tests/interop && ls -d */ | tr -d / | tr '\n' ' '))" >&2
            return 2
        }
        if [ -z "$scen" ]; then echo "$suite tests/interop/$suite/run.sh -"; continue; fi
        scen="${scen//,/_}"
        case "$suite" in
            links) echo "links tests/interop/links/run.sh LINKS_SCENARIOS=$scen" ;;
            viewers) echo "viewers tests/interop/viewers/run.sh VIEWERS_SCENARIOS=$scen" ;;
            federation)
                [ "$scen" = check ] || { echo "federation's only part is 'check' (the checks without failover)" >&2; return 2; }
                echo "federation tests/interop/federation/run.sh FEDERATION_ONLY_CHECK=1" ;;
            *) echo "suite '$suite' runs whole: drop ':$scen' (scenarios can be chosen in links, viewers, federation)" >&2
               return 2 ;;
        esac
    done
}

# Runs the plan on stdin, at most $INTEROP_JOBS at once; each part's output goes to its own
# log, printed whole when the part fails; one line per part as it ends, with its time.
run_interop() {
    local jobs="${INTEROP_JOBS:-3}" logs="${INTEROP_LOGS:-$PWD/target/interop-logs}"
    mkdir -p "$logs"
    local -a names=() scripts=() envs=()
    local name script env
    local barriers=" "
    while read -r name script env; do
        # `wait`: what follows starts once everything before it has ended.
        if [ "$name" = wait ]; then barriers+="${#names[@]} "; continue; fi
        names+=("$name"); scripts+=("$script"); envs+=("$env")
    done
    local -A started=() pid_of=()
    local i running=0 next=0 done_n=0 total=${#names[@]}
    interop_failed=()
    interop_times=()
    launch() {
        local i=$1 log="$logs/${names[$1]}.log"
        local env="${envs[$1]}"
        (
            # Each part's results directory is its own (the links suite writes one).
            export LINKS_OUT="$logs/${names[$1]}-results"
            # NAME=a_b_c in the plan sets NAME to "a b c".
            if [ "$env" != "-" ]; then
                local value="${env#*=}"
                export "${env%%=*}=${value//_/ }"
            fi
            exec bash "${scripts[$1]}"
        ) >"$log" 2>&1 </dev/null &
        pid_of[$i]=$!
        started[$i]=$SECONDS
        echo "   started ${names[$1]} (log: $log)"
    }
    while [ "$done_n" -lt "$total" ]; do
        while [ "$running" -lt "$jobs" ] && [ "$next" -lt "$total" ]; do
            case "$barriers" in *" $next "*) [ "$running" -eq 0 ] || break ;; esac
            launch "$next"; next=$((next + 1)); running=$((running + 1))
        done
        local finished="" rc=0
        wait -n -p finished || rc=$?
        for i in "${!pid_of[@]}"; do
            [ "${pid_of[$i]}" = "$finished" ] || continue
            unset "pid_of[$i]"
            running=$((running - 1)); done_n=$((done_n + 1))
            local secs=$((SECONDS - started[$i])) log="$logs/${names[$i]}.log"
            interop_times+=("$(printf 'interop: %-36s %4d s' "${names[$i]}" "$secs")")
            if [ "$rc" -eq 0 ]; then
                echo "PASS: ${names[$i]} ($secs s; $(grep -c '^PASS' "$log" || true) PASS lines)"
            else
                interop_failed+=("${names[$i]}")
                echo "FAIL: ${names[$i]} (exit $rc after $secs s); its whole output:"
                sed 's/^/    /' "$log"
                echo "FAIL: ${names[$i]} (end of its output)"
            fi
        done
    done
}

if [ "$mode" != only ]; then
    stage "cargo fmt --check"
    cargo fmt --all --check
    stage "cargo clippy"
    cargo clippy --workspace --all-targets --locked -- -D warnings
    stage "code shape (scripts/check-shape.py)"
    python3 scripts/check-shape.py
fi
# One build for the Rust tests and the interop suites' binary: the `ci` profile (Cargo.toml)
# is optimized, with test-build assertions. The binary the suites run is the one the Rust
# tests' build makes for the integration tests (target/ci/fleetlink): built on its own
# (`cargo build -p fleetlink`) its dependencies would have other features than with the
# tests' dev-dependencies (tokio's among them, and with it most of the tree), and half the
# workspace would compile twice.
build_tests() { cargo test --workspace --locked --profile ci --no-run; }
if [ "$mode" = only ]; then
    stage "cargo build (ci profile: the tests, and the binary for interop suites)"
    build_tests
    export FLEETLINK_BIN="$PWD/target/ci/fleetlink"
    if [ ${#only[@]} -eq 0 ]; then plan="$(interop_plan)"; else plan="$(only_plan)"; fi
    stage "interop: ${only[*]:-every suite} (${INTEROP_JOBS:-3} at once)"
    run_interop <<<"$plan"
    stage ""
    stages+=("${interop_times[@]}")
    [ ${#interop_failed[@]} -eq 0 ] || { echo "interop failed: ${interop_failed[*]}" >&2; exit 1; }
    echo "all chosen interop suites passed"
    exit 0
fi
# Tests never read or write the user's state. A user's machine may hold changes kept by an
# earlier agent called robot1 (a demo, a manual try, another suite) where agents keep them
# by default (~/.local/state/fleetlink/robot1/runtime.json); one that would break the
# suites' robot1 (the links suite's no_drop probe remapped away, its no_drop turned off) is
# planted here, before the Rust tests and the interop suites, and checked untouched and
# removed after them (scripts/hostile-state.sh). Every agent the suites start keeps its
# state in its test's temporary directory, so they pass all the same.
stage "plant a hostile user state (scripts/hostile-state.sh)"
./scripts/hostile-state.sh plant
hostile_planted=1
stage "cargo test (nextest, ci profile; builds the binary for interop suites too)"
cargo nextest run --workspace --locked --no-fail-fast --cargo-profile ci
[ -x target/ci/fleetlink ] || { echo "the test build made no target/ci/fleetlink" >&2; exit 1; }

if [ "$mode" = rust ]; then
    stage ""
    hostile_planted=""
    ./scripts/hostile-state.sh remove
    echo "formatting, lints and Rust tests passed"
    exit 0
fi

# Each interop suite is a directory with a run.sh that exits non-zero on failure.
export FLEETLINK_BIN="$PWD/target/ci/fleetlink"
failed=()
stage "interop suites (${INTEROP_JOBS:-3} at once)"
plan="$(interop_plan)"
run_interop <<<"$plan"
failed+=("${interop_failed[@]}")
stage "the user's state untouched (scripts/hostile-state.sh)"
stages+=("${interop_times[@]}")
hostile_planted=""
./scripts/hostile-state.sh remove || failed+=("hostile state")
if [ ${#failed[@]} -ne 0 ]; then
    echo "interop suites failed: ${failed[*]}" >&2
    exit 1
fi
echo "all test stages passed"

#!/usr/bin/env bash
# The whole test suite, as a newcomer and CI run it: installs what the tests need
# (idempotently), checks formatting and lints, runs the Rust tests, then the interop
# suites that drive real peers (roslibpy, roslibjs, rosbags, rospy, ...).
set -euo pipefail
cd "$(dirname "$0")/.."

./scripts/setup-test-env.sh

echo "== cargo fmt --check"
cargo fmt --all --check
echo "== cargo clippy"
cargo clippy --workspace --all-targets --locked -- -D warnings
echo "== cargo build (release binary for interop suites)"
cargo build --release --locked -p fleetlink
echo "== cargo test"
cargo nextest run --workspace --locked --no-fail-fast

# Each interop suite is a directory with a run.sh that exits non-zero on failure.
export FLEETLINK_BIN="$PWD/target/release/fleetlink"
failed=()
for suite in tests/interop/*/run.sh; do
    [ -e "$suite" ] || continue
    echo "== interop: $suite"
    if ! bash "$suite"; then failed+=("$suite"); fi
done
if [ ${#failed[@]} -ne 0 ]; then
    echo "interop suites failed: ${failed[*]}" >&2
    exit 1
fi
echo "all test stages passed"

#!/usr/bin/env bash
# Dashboard suite: the fleet dashboard (web/) as the hub serves it, in headless Chromium.
#
# 1. The committed bundle (crates/hub/assets/dashboard/) is what web/ builds now: a fresh
#    build into a temp directory must be byte-identical, else the bundle is stale
#    (fix: web/build.sh, commit the result).
# 2. The TypeScript type-checks (esbuild strips types without checking them), and unit
#    tests of the page's message handling (node --test) on CBOR/JSON frames the hub
#    produced (web/test/fixtures).
# 3. `fleetlink demo` (hub + 3 simulated robots) with extra credentials minted in its
#    database first: alice (admin group, signs in with a password), a viewer (operator
#    token with no group, allowed to subscribe only) and robot4, a separate agent that the
#    browser check stops to see a robot go offline, and a mirror of robot1 (`fleetlink
#    agent --mirror robot1`, shown in robot1's link panel with its offload signal). Then dashboard_check.mjs drives Chromium
#    through the fleet view, the robot view, a navigation goal and Cancel, a service form,
#    the admin view, the recordings page's black-box form, and the viewer's disabled
#    tasking and refused forged publish.
#
# Screenshots are kept in the directory printed at the end (outside the suite's temp
# directory, which is removed). Every process started here is stopped on exit. Bounded:
# under 3 minutes. Env: FLEETLINK_BIN (default target/release/fleetlink),
# DASHBOARD_SHOTS (default: a new directory under ${TMPDIR:-/tmp}).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
bin="${FLEETLINK_BIN:-$root/target/release/fleetlink}"
web="$root/web"
started=$SECONDS

[ -x "$bin" ] || { echo "FAIL: fleetlink binary not found at $bin (set FLEETLINK_BIN)" >&2; exit 1; }
[ -x /usr/bin/chromium ] || { echo "FAIL: /usr/bin/chromium missing; run scripts/setup.d/60-browser.sh" >&2; exit 1; }
[ -d "$web/node_modules/puppeteer-core" ] || { echo "FAIL: web/node_modules missing; run scripts/setup.d/55-web-packages.sh" >&2; exit 1; }

# shellcheck source=../lib.sh
. "$here/../lib.sh"
interop_begin dashboard
shots="${DASHBOARD_SHOTS:-$(mktemp -d "${TMPDIR:-/tmp}/fleetlink-dashboard-shots.XXXXXX")}"
failed=()

echo "== committed bundle is up to date"
(cd "$web" && timeout 120 node build.mjs --out "$tmp/bundle" >/dev/null)
if diff -r "$tmp/bundle" "$root/crates/hub/assets/dashboard" >/dev/null; then
    echo "ok   crates/hub/assets/dashboard matches a fresh build of web/"
else
    echo "FAIL the committed dashboard bundle is stale: run web/build.sh and commit crates/hub/assets/dashboard"
    diff -rq "$tmp/bundle" "$root/crates/hub/assets/dashboard" || true
    failed+=("stale bundle")
fi

echo "== type check (tsc --noEmit)"
if (cd "$web" && timeout 120 node node_modules/typescript/bin/tsc --noEmit); then
    echo "ok   web/src type-checks"
else
    failed+=("type check")
fi

echo "== unit tests (web/test, frames from the hub)"
if (cd "$web" && timeout 120 node build.mjs --out "$tmp/bundle-tests" --tests >/dev/null && timeout 60 node --test test-build/); then
    :
else
    failed+=("unit tests")
fi

echo "== fleetlink demo"
data="$tmp/demo-data"
admin() { timeout 30 "$bin" admin --data-dir "$data" "$@"; }
viewer_token="$(admin token operator viewer)"
# An admin who signs in with a password (the page's login form → POST /api/v1/login).
alice_password="dashboard-$RANDOM-$RANDOM"
printf '%s\n' "$alice_password" | admin users add alice --group admin >/dev/null
# A fourth robot outside the demo process, stopped mid-test to see it go offline.
robot4_token="$(admin token robot robot4)"
# A fifth whose /markers is a pull topic (the topic table's pull button).
robot5_token="$(admin token robot robot5)"
admin rules import - >/dev/null <<'RULES'
rules:
  - subject: {user: viewer}
    names: "/.*"
    ops: [subscribe]
    comment: "dashboard suite: a viewer may look, not task"
RULES
: >"$tmp/hub.log"
"$bin" demo --listen 127.0.0.1:0 --data-dir "$data" >"$tmp/hub.log" 2>&1 &
pids+=($!)
addr="$(wait_for_line "$tmp/hub.log" '^  open http://([0-9.:]+)/ in a browser$' "demo start" "${pids[0]}")"
op_token="$(wait_for_line "$tmp/hub.log" '^  the operator token \([^)]*\): (.+)$' "operator token" "${pids[0]}")"
echo "demo hub: http://$addr/"
: >"$tmp/agent.log"
cat >"$tmp/robot4.yaml" <<EOF
hub: ws://$addr/
name: robot4
token: $robot4_token
local_rosbridge: null
sim:
  seed: 4
  pose: { rate_hz: 10 }
EOF
"$bin" agent --name robot4 --config "$tmp/robot4.yaml" >"$tmp/agent.log" 2>&1 &
pids+=($!)
robot4_pid=$!
cat >"$tmp/robot5.yaml" <<EOF
hub: ws://$addr/
name: robot5
token: $robot5_token
local_rosbridge: null
sim:
  seed: 5
  markers: { rate_hz: 2 }
topics:
  /markers: { mode: pull }
EOF
"$bin" agent --config "$tmp/robot5.yaml" >"$tmp/agent5.log" 2>&1 &
pids+=($!)
# A mirror of robot1 (docs/mirror.md), shown in robot1's view with the offload signal; an
# operator token of the admin group may mirror any robot.
printf '%s\n' "$op_token" >"$tmp/mirror.token"
"$bin" agent --mirror robot1 --hub "ws://$addr/" --token-file "$tmp/mirror.token" --no-local \
    >"$tmp/mirror.log" 2>&1 &
pids+=($!)
# Ready: five robots online (bounded, 15 s).
for i in $(seq 150); do
    n="$(curl -fsS -H "Authorization: Bearer $op_token" "http://$addr/api/v1/robots" 2>/dev/null | grep -o '"online":true' | wc -l || true)"
    [ "$n" -ge 5 ] && break
    [ "$i" -eq 150 ] && { echo "FAIL: 5 robots not online within 15 s" >&2; exit 1; }
    sleep 0.1
done

echo "== headless Chromium"
if ! timeout --kill-after=5 120 node "$here/dashboard_check.mjs" --url "http://$addr/" \
        --user alice --password "$alice_password" --viewer-token "$viewer_token" --shots "$shots" \
        --offline-robot robot4 --offline-pid "$robot4_pid" --pull-robot robot5; then
    failed+=("browser checks")
fi
kill -0 "${pids[0]}" 2>/dev/null || failed+=("demo process died")

echo "screenshots: $shots"
echo "dashboard suite: ${#failed[@]} failure(s), $((SECONDS - started)) s"
if [ ${#failed[@]} -ne 0 ]; then
    echo "FAIL: ${failed[*]}" >&2
    exit 1
fi
echo "PASS: dashboard (bundle fresh, unit tests, Chromium against fleetlink demo)"

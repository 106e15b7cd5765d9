#!/usr/bin/env bash
# Node packages of the interop suites, each installed from its committed
# package-lock.json: the rosbridge suite (roslib, the Foxglove parsers) and the Foxglove
# suite (@foxglove/ws-protocol's FoxgloveClient, the Foxglove parsers, ws). Idempotent:
# skips `npm ci` where node_modules already matches the lock file.
set -euo pipefail
interop="$(cd "$(dirname "$0")/../../tests/interop" && pwd)"
# suite directory and the package whose presence says it is installed
for pair in "rosbridge roslib" "foxglove @foxglove/ws-protocol"; do
    read -r suite probe <<<"$pair"
    cd "$interop/$suite"
    stamp=node_modules/.fleetlink-lock
    if [ -f "$stamp" ] && cmp -s package-lock.json "$stamp" && [ -f "node_modules/$probe/package.json" ]; then
        echo "node packages of $suite up to date"
        continue
    fi
    npm ci --no-audit --no-fund --loglevel=error
    cp package-lock.json "$stamp"
    echo "node packages of $suite ready: $probe $(node -p "require('./node_modules/$probe/package.json').version")"
done

#!/usr/bin/env bash
# Rebuilds the dashboard bundle the hub embeds (crates/hub/assets/dashboard/) from web/,
# after installing the pinned npm packages (package-lock.json). Commit the result.
set -euo pipefail
cd "$(dirname "$0")"
[ -d node_modules/esbuild ] && cmp -s package-lock.json node_modules/.fleetlink-lock || {
    npm ci --no-audit --no-fund --loglevel=error
    cp package-lock.json node_modules/.fleetlink-lock
}
npx tsc --noEmit
node build.mjs

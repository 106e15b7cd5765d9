#!/usr/bin/env bash
# npm packages of the dashboard (web/: esbuild, TypeScript, three.js, uPlot, cbor2 and
# puppeteer-core for the browser suite), installed from the committed package-lock.json.
# Idempotent: skips `npm ci` when node_modules already matches the lock file.
set -euo pipefail
cd "$(dirname "$0")/../../web"
stamp=node_modules/.fleetlink-lock
if [ -f "$stamp" ] && cmp -s package-lock.json "$stamp" && [ -d node_modules/puppeteer-core ]; then
    echo "dashboard npm packages up to date"
    exit 0
fi
npm ci --no-audit --no-fund --loglevel=error
cp package-lock.json "$stamp"
echo "dashboard npm packages ready: esbuild $(node -p 'require("./node_modules/esbuild/package.json").version'), puppeteer-core $(node -p 'require("./node_modules/puppeteer-core/package.json").version')"

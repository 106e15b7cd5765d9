#!/usr/bin/env bash
# Node packages of the rosbridge interop suite (roslib from npm), installed from the
# committed package-lock.json. Idempotent: skips `npm ci` when node_modules already
# matches the lock file.
set -euo pipefail
cd "$(dirname "$0")/../../tests/interop/rosbridge"
stamp=node_modules/.fleetlink-lock
if [ -f "$stamp" ] && cmp -s package-lock.json "$stamp" && [ -f node_modules/roslib/package.json ]; then
    echo "node packages up to date"
    exit 0
fi
npm ci --no-audit --no-fund --loglevel=error
cp package-lock.json "$stamp"
echo "node packages ready: roslib $(node -p 'require("./node_modules/roslib/package.json").version')"

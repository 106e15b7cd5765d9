#!/usr/bin/env bash
# Installs everything the test suite needs, idempotently: each file in
# scripts/setup.d is one concern (Debian packages, Python venv, npm packages, ...).
set -euo pipefail
cd "$(dirname "$0")/.."
for step in scripts/setup.d/*.sh; do
    [ -e "$step" ] || continue
    echo "== setup: $step"
    bash "$step"
done

#!/usr/bin/env bash
# Headless Chromium for the dashboard suite (tests/interop/dashboard): Debian's
# `chromium` package, driven by puppeteer-core (no browser download). Idempotent:
# updates the package lists and installs only when the browser is missing.
set -euo pipefail
if [ -x /usr/bin/chromium ] && dpkg-query -W -f='${Status}' chromium 2>/dev/null | grep -q 'install ok installed'; then
    echo "chromium ready: $(/usr/bin/chromium --version 2>/dev/null || echo installed)"
    exit 0
fi
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
# Update the lists only when the package is not known yet (fresh containers).
if ! apt-cache show chromium >/dev/null 2>&1; then
    "${sudo_cmd[@]}" apt-get -o DPkg::Lock::Timeout=600 update
fi
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get -o DPkg::Lock::Timeout=600 \
    install -y --no-install-recommends chromium fonts-dejavu-core
echo "chromium ready: $(/usr/bin/chromium --version 2>/dev/null || echo installed)"

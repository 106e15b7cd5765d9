#!/usr/bin/env bash
# Debian's PostgreSQL server for the shared-state tests (tests/interop/postgres): the
# suite starts a throwaway cluster of its own in a temp dir with these binaries
# (initdb, pg_ctl, postgres) and runs it as the `postgres` user the package creates.
# The package's own cluster service is not used. Idempotent: installs only what is
# missing; waits for the apt lock.
set -euo pipefail

apt_packages=(postgresql postgresql-client)
missing=()
for p in "${apt_packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if [ ${#missing[@]} -ne 0 ]; then
    sudo_cmd=()
    [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
    "${sudo_cmd[@]}" apt-get -o DPkg::Lock::Timeout=600 update
    DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get -o DPkg::Lock::Timeout=600 install -y --no-install-recommends "${missing[@]}"
fi

bin="$(ls -d /usr/lib/postgresql/*/bin 2>/dev/null | sort -V | tail -n1)"
for tool in initdb pg_ctl postgres; do
    [ -x "$bin/$tool" ] || { echo "postgresql: $tool not found under /usr/lib/postgresql/*/bin after install" >&2; exit 1; }
done
id postgres >/dev/null 2>&1 || { echo "postgresql: the postgres user is missing after install" >&2; exit 1; }
command -v runuser >/dev/null || { echo "postgresql: runuser (util-linux) not found" >&2; exit 1; }
echo "postgresql ready: $("$bin/postgres" --version)"

#!/usr/bin/env bash
# The deterministic Rapier adapter's runtime: node (Debian's nodejs and npm through
# scripts/setup.sh, when missing), then the locked npm packages
# (@dimforge/rapier2d-deterministic-compat): `npm ci` here, under this directory's lock
# (.install.lock), when node_modules is absent or was installed from another package-lock.json.
# `bash scripts/setup.sh --engines rapier-deterministic` runs this; run.sh only checks.
#
#   install.sh           installs what is missing
#   install.sh --check   exits 0 when all is installed, else 3 with one line on stderr saying what to run
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
name=rapier-deterministic
# the package whose directory under node_modules shows an install
module=@dimforge/rapier2d-deterministic-compat
# npm ci empties node_modules first, so this copy of the lock file is there only after a
# complete install of that lock file.
stamp=$here/node_modules/.tilesweep-package-lock.json

modules_ready() { [ -d "$here/node_modules/$module" ] && cmp -s "$here/package-lock.json" "$stamp"; }

if [ "${1:-}" = --check ]; then
    if ! command -v node >/dev/null; then
        problem="node is not installed"
    elif [ ! -d "$here/node_modules/$module" ]; then
        problem="adapters/$name/node_modules is not installed"
    elif ! modules_ready; then
        problem="adapters/$name/node_modules does not match package-lock.json"
    else
        exit 0
    fi
    echo "$problem: run  bash scripts/setup.sh --engines $name" >&2
    exit 3
fi

missing=()
command -v node >/dev/null || missing+=(nodejs)
modules_ready || command -v npm >/dev/null || missing+=(npm)
if ((${#missing[@]})); then
    bash "$here/../../scripts/setup.sh" --packages "${missing[@]}"
fi
modules_ready && exit 0
(
    if ! flock -n 9; then
        echo "install: waiting for another npm ci in adapters/$name" >&2
        flock 9
    fi
    modules_ready && exit 0  # installed while this waited
    echo "install: npm ci in adapters/$name" >&2
    if ! (cd "$here" && npm ci --no-audit --no-fund >&2); then
        echo "install: npm ci failed in adapters/$name: run  (cd adapters/$name && npm ci --no-audit --no-fund)" >&2
        exit 1
    fi
    cp "$here/package-lock.json" "$stamp"
) 9>>"$here/.install.lock"

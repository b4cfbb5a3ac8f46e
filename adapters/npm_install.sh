#!/usr/bin/env bash
# The runtime of a JavaScript engine adapter (adapters/ENGINE): node (Debian's nodejs and npm
# through scripts/setup.sh, when missing), then the npm packages locked in ENGINE/package-lock.json,
# installed by `npm ci` under that directory's lock (.install.lock) when node_modules is absent or
# came from another lock file. Each adapter's install.sh calls this with its name and the package
# whose directory under node_modules shows an install; `bash scripts/setup.sh --engines ENGINE`
# runs that install.sh, and run.sh only checks.
#
#   npm_install.sh ENGINE PACKAGE           installs what is missing
#   npm_install.sh ENGINE PACKAGE --check   exits 0 when all is installed, else 3 with one line on
#                                           stderr saying what to run
set -euo pipefail
name=${1:?usage: npm_install.sh ENGINE PACKAGE [--check]}
package=${2:?usage: npm_install.sh ENGINE PACKAGE [--check]}
adapters="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
here=$adapters/$name
# npm ci empties node_modules before it installs, so this copy of the lock file exists only once
# a whole install of that lock file is done.
stamp=$here/node_modules/.tilesweep-package-lock.json

installed() { [ -d "$here/node_modules/$package" ] && cmp -s "$here/package-lock.json" "$stamp"; }

if [ "${3:-}" = --check ]; then
    if ! command -v node >/dev/null; then
        problem="node is not installed"
    elif [ ! -d "$here/node_modules/$package" ]; then
        problem="adapters/$name/node_modules is not installed"
    elif ! installed; then
        problem="adapters/$name/node_modules does not match package-lock.json"
    else
        exit 0
    fi
    echo "$problem: run  bash scripts/setup.sh --engines $name" >&2
    exit 3
fi

wanted=()
command -v node >/dev/null || wanted+=(nodejs)
installed || command -v npm >/dev/null || wanted+=(npm)
if ((${#wanted[@]})); then
    bash "$adapters/../scripts/setup.sh" --packages "${wanted[@]}"
fi
installed && exit 0
(
    if ! flock -n 9; then
        echo "install: another npm ci is running in adapters/$name; waiting for it" >&2
        flock 9
    fi
    installed && exit 0  # done by the other one meanwhile
    echo "install: npm ci in adapters/$name" >&2
    if ! (cd "$here" && npm ci --no-audit --no-fund >&2); then
        echo "install: npm ci failed in adapters/$name: run  (cd adapters/$name && npm ci --no-audit --no-fund)" >&2
        exit 1
    fi
    cp "$here/package-lock.json" "$stamp"
) 9>>"$here/.install.lock"

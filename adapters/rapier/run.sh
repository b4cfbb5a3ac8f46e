#!/usr/bin/env bash
# Runs the Rapier adapter: `run.sh` answers scene lines on stdin (pipe mode), `run.sh IN OUT`
# answers the scene file IN into OUT (file mode). Installs what it needs on first use, with all
# of that installing said on stderr so that stdout carries only answers: Debian's nodejs and npm
# through the project's setup, then the locked packages (`npm ci`) when node_modules is absent.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
    TILESWEEP_EXTRA_PACKAGES="nodejs npm" bash "$here/../../scripts/setup.sh" >&2
fi
if [ ! -d "$here/node_modules/@dimforge/rapier2d-compat" ]; then
    (cd "$here" && npm ci --no-audit --no-fund >&2)
fi
exec node "$here/adapter.js" "$@"

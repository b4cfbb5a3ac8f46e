#!/usr/bin/env bash
# Runs the Rapier adapter (../rapier/adapter.js) on Rapier's cross-platform deterministic build
# (@dimforge/rapier2d-deterministic-compat, installed here): `run.sh` answers scene lines on stdin
# (pipe mode), `run.sh IN OUT` answers the scene file IN into OUT (file mode). Without node, or
# without the locked npm packages in node_modules, it exits 3 at once, saying on stderr what to
# run (`bash scripts/setup.sh --engines rapier-deterministic`, which runs install.sh).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
bash "$here/install.sh" --check || exit
exec node "$here/../rapier/adapter.js" --rapier "$here/node_modules/@dimforge/rapier2d-deterministic-compat" "$@"

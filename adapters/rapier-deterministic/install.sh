#!/usr/bin/env bash
# The deterministic Rapier adapter's runtime: node and the npm packages locked here (@dimforge/rapier2d-deterministic-compat), installed by
# adapters/npm_install.sh. `bash scripts/setup.sh --engines rapier-deterministic` runs this; run.sh only checks.
#
#   install.sh           installs what is missing
#   install.sh --check   exits 0 when all is installed, else 3 with one line on stderr saying what to run
set -euo pipefail
exec bash "$(dirname "${BASH_SOURCE[0]}")/../npm_install.sh" rapier-deterministic @dimforge/rapier2d-deterministic-compat "$@"

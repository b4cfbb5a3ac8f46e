#!/usr/bin/env bash
# The planck adapter's runtime: node and the npm packages locked here (planck), installed by
# adapters/npm_install.sh. `bash scripts/setup.sh --engines planck` runs this; run.sh only checks.
#
#   install.sh           installs what is missing
#   install.sh --check   exits 0 when all is installed, else 3 with one line on stderr saying what to run
set -euo pipefail
exec bash "$(dirname "${BASH_SOURCE[0]}")/../npm_install.sh" planck planck "$@"

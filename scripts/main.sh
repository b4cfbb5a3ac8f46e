#!/usr/bin/env bash
# The main job: builds tilesweep (the plain Release build of scripts/build.sh, installing what is
# missing) and runs the property suite, `tilesweep check`, for its default budget of about a
# minute on all cores.
# Arguments go to `tilesweep check` (for example --seconds 600, --property matchesExact, --seed 7).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
export TILESWEEP_PRESET=${TILESWEEP_PRESET:-plain}
bash "$root/scripts/setup.sh"
bash "$root/scripts/build.sh"
cd "$root"
"${TILESWEEP_BUILD_DIR:-$root/build/$TILESWEEP_PRESET}/cli/tilesweep" check "$@"

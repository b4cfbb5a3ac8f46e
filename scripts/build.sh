#!/usr/bin/env bash
# Configures and builds tilesweep with a preset of CMakePresets.json (TILESWEEP_PRESET, default
# dev) into build/<preset>/, installing missing packages first. TILESWEEP_BUILD_DIR puts the
# build elsewhere; TILESWEEP_BUILD_TYPE overrides the preset's build type; extra arguments go to
# cmake's configure step; TILESWEEP_TARGETS (space-separated) builds only those targets.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
source "$root/scripts/setup.sh"
preset=${TILESWEEP_PRESET:-dev}
args=(--preset "$preset")
[ -z "${TILESWEEP_BUILD_DIR:-}" ] || args+=(-B "$TILESWEEP_BUILD_DIR")
[ -z "${TILESWEEP_BUILD_TYPE:-}" ] || args+=(-DCMAKE_BUILD_TYPE="$TILESWEEP_BUILD_TYPE")
(cd "$root" && cmake "${args[@]}" "$@" >/dev/null)
build=${TILESWEEP_BUILD_DIR:-$root/build/$preset}
read -r -a targets <<<"${TILESWEEP_TARGETS:-}"
if ((${#targets[@]})); then
    cmake --build "$build" --parallel "$(nproc)" --target "${targets[@]}"
else
    cmake --build "$build" --parallel "$(nproc)"
fi

#!/usr/bin/env bash
# Configures and builds tilesweep into build/<preset>/. It installs nothing: a missing Debian
# package is named, with the command that installs it (scripts/setup.sh; main.sh and test.sh run it).
#
# TILESWEEP_PRESET=plain (the default) is the build a user makes, with no preset:
#   cmake -S . -B build/plain -DCMAKE_BUILD_TYPE=Release
# and TILESWEEP_WERROR=ON adds -DTILESWEEP_WERROR=ON (CI does; warnings are not errors by default).
# Any other TILESWEEP_PRESET names a preset of CMakePresets.json (dev, asan, portable, ...).
# TILESWEEP_BUILD_DIR puts the build elsewhere; TILESWEEP_BUILD_TYPE overrides the build type;
# extra arguments go to cmake's configure step; TILESWEEP_TARGETS (space-separated) builds only
# those targets.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
source "$root/scripts/setup.sh"
tilesweep_require_base || exit 2
preset=${TILESWEEP_PRESET:-plain}
build=${TILESWEEP_BUILD_DIR:-$root/build/$preset}
if [ "$preset" = plain ]; then
    args=(-S "$root" -B "$build" -DCMAKE_BUILD_TYPE="${TILESWEEP_BUILD_TYPE:-Release}")
else
    args=(--preset "$preset" -B "$build")
    [ -z "${TILESWEEP_BUILD_TYPE:-}" ] || args+=(-DCMAKE_BUILD_TYPE="$TILESWEEP_BUILD_TYPE")
fi
[ -z "${TILESWEEP_WERROR:-}" ] || args+=(-DTILESWEEP_WERROR="$TILESWEEP_WERROR")
(cd "$root" && cmake "${args[@]}" "$@" >/dev/null)
read -r -a targets <<<"${TILESWEEP_TARGETS:-}"
if ((${#targets[@]})); then
    cmake --build "$build" --parallel "$(nproc)" --target "${targets[@]}"
else
    cmake --build "$build" --parallel "$(nproc)"
fi

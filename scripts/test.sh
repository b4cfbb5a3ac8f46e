#!/usr/bin/env bash
# Builds tilesweep (installing what is missing) and runs every test through ctest.
#
#   bash scripts/test.sh                      # the plain Release build a user makes, build/plain/
#   bash scripts/test.sh -L unit              # arguments go to ctest (here: the unit tests only)
#   TILESWEEP_PRESET=asan-portable bash scripts/test.sh
#
# TILESWEEP_PRESET picks a preset of CMakePresets.json instead (dev, asan, portable, portable-suite,
# asan-portable, fuzz; see scripts/build.sh), TILESWEEP_SANITIZE=ON is short for the asan preset,
# and TILESWEEP_WERROR=ON makes warnings errors (CI sets it). Labels: unit, property, oracle,
# corpus, soak, fuzz-replay, cli, example, engine.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
if [ "${TILESWEEP_SANITIZE:-OFF}" = ON ] && [ -z "${TILESWEEP_PRESET:-}" ]; then
    export TILESWEEP_PRESET=asan
fi
export TILESWEEP_PRESET=${TILESWEEP_PRESET:-plain}
bash "$root/scripts/setup.sh"
bash "$root/scripts/build.sh"
build=${TILESWEEP_BUILD_DIR:-$root/build/$TILESWEEP_PRESET}
# Every property at two seeds (properties/CMakeLists.txt), 4000 cases each: about 25 s on 2 cores.
export TILESWEEP_PROPERTY_CASES=${TILESWEEP_PROPERTY_CASES:-4000}
ctest --test-dir "$build" --output-on-failure --parallel "$(nproc)" "$@"

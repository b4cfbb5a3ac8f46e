#!/usr/bin/env bash
# Builds tilesweep (installing what is missing) and runs every test through ctest.
# TILESWEEP_SANITIZE=ON builds and runs them under AddressSanitizer + UBSan in build-asan/.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
if [ "${TILESWEEP_SANITIZE:-OFF}" = ON ]; then
    export TILESWEEP_BUILD_DIR=${TILESWEEP_BUILD_DIR:-$root/build-asan}
    bash "$root/scripts/build.sh" -DTILESWEEP_SANITIZE=ON -DTILESWEEP_BUILD_BENCH=OFF
else
    bash "$root/scripts/build.sh"
fi
cd "${TILESWEEP_BUILD_DIR:-$root/build}"
# Every property at two seeds (properties/CMakeLists.txt), 4000 cases each: about 25 s on 2 cores.
export TILESWEEP_PROPERTY_CASES=${TILESWEEP_PROPERTY_CASES:-4000}
ctest --output-on-failure --parallel "$(nproc)"

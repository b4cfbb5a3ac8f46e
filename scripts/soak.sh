#!/usr/bin/env bash
# Builds the soak (scripts/build.sh, the plain Release build) and runs the soak: random walkers with gravity, jumps and
# dashes through generated levels, every frame checked against the contract's safety rules.
#
#   bash scripts/soak.sh [SECONDS] [tilesweep_soak options...]    # default: 60 s, float then double
#
# With options (say --scalar double --seed 7 --walkers 256) it runs once with those. Exits 1 if
# any frame broke a rule.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
seconds=${1:-60}
shift || true
export TILESWEEP_PRESET=${TILESWEEP_PRESET:-plain}
bash "$root/scripts/setup.sh"
TILESWEEP_TARGETS=tilesweep_soak bash "$root/scripts/build.sh" >/dev/null
soak=${TILESWEEP_BUILD_DIR:-$root/build/$TILESWEEP_PRESET}/soak/tilesweep_soak
if (($#)); then
    "$soak" --seconds "$seconds" "$@"
else
    half=$(awk -v s="$seconds" 'BEGIN { printf "%g", s / 2 }')
    "$soak" --seconds "$half" --scalar float
    "$soak" --seconds "$half" --scalar double --seed 2
fi

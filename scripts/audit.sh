#!/usr/bin/env bash
# The tolerance audit with its charts: builds the CLI (the plain Release build), runs
# `tilesweep audit` into DIR (default docs/audit), then draws DIR/error_vs_magnitude.svg and
# failures_per_family.svg from DIR/report.json with scripts/plots.py (Debian's
# python3-matplotlib, installed when missing).
#
#   bash scripts/audit.sh [--out DIR] [tilesweep audit options...]   # e.g. --cases 500 --seed 7
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
out=$root/docs/audit
args=()
while (($#)); do
    case "$1" in
        --out) out=${2:?--out needs a directory}; shift 2 ;;
        --out=*) out=${1#*=}; shift ;;
        *) args+=("$1"); shift ;;
    esac
done
export TILESWEEP_PRESET=${TILESWEEP_PRESET:-plain}
export TILESWEEP_EXTRA_PACKAGES=python3-matplotlib
bash "$root/scripts/setup.sh"
TILESWEEP_TARGETS=tilesweep_cli bash "$root/scripts/build.sh" >/dev/null
cd "$root"
"${TILESWEEP_BUILD_DIR:-$root/build/$TILESWEEP_PRESET}/cli/tilesweep" audit --out "$out" "${args[@]}" || status=$?
/usr/bin/python3 "$root/scripts/plots.py" audit "$out"
exit "${status:-0}"

#!/usr/bin/env bash
# Proof that the property suite has teeth: builds the library with one deliberate fault at a
# time (src/fault_injection.h), runs the property suite on it, and prints which properties
# caught the fault and the shrunk counterexample's size. Usage:
#   bash scripts/fault-table.sh [CASES]        (default 300 cases per property)
# TILESWEEP_FAULTS="NAME ..." runs only those faults.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
source "$root/scripts/setup.sh"
cases=${1:-300}
faults=(${TILESWEEP_FAULTS:-TOUCH_OVERLAPS NO_CORNER_MISS TIE_REVERSED DOUBLE_PREDICATE ROUND_NEAREST BROADPHASE_SHORT FMA
         OLD_ROUNDING_RULE TIME_TIES_AWAY END_INCLUSIVE NARROW_TIER ORACLE_SKIPS_TOUCH_AT_0
         FILTER_BOUND_HALVED FAST_RANGE_TOO_WIDE FAST_RANGE_FAR_TOO_WIDE})
out=${TILESWEEP_FAULT_DIR:-$root/build-faults}
mkdir -p "$out"
echo "| fault | caught by (a shrunk counterexample) | smallest counterexample | other failures | seconds |"
echo "|---|---|---|---|---|"
for fault in "${faults[@]}"; do
    build="$out/$fault"
    cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DTILESWEEP_FAULT="$fault" \
        -DTILESWEEP_BUILD_BENCH=OFF -DTILESWEEP_BUILD_CLI=OFF -DTILESWEEP_BUILD_TESTS=OFF \
        -DTILESWEEP_BUILD_AUDIT=OFF >/dev/null 2>&1
    cmake --build "$build" --target tilesweep_properties >/dev/null
    corpus="$build/corpus"
    rm -rf "$corpus"
    start=$SECONDS
    TILESWEEP_PROPERTY_CASES=$cases TILESWEEP_CORPUS_DIR="$corpus" \
        "$build/properties/tilesweep_properties" --gtest_filter='Suite/*' >"$build/run.log" 2>&1 || true
    failed=$( (grep -o 'FAILED  \] Suite/Property.holds/[A-Za-z_]*' "$build/run.log" || true) | sed 's/.*holds\///' | sort -u)
    row=$(python3 - "$corpus" $failed <<'PY'
import glob, json, os, sys
corpus, failed = sys.argv[1], sys.argv[2:]
found = {}
for path in glob.glob(os.path.join(corpus, "*.jsonl")):
    scene = json.loads(open(path).readline())
    rows = scene["map"]["rows"]
    cells = (len(rows[0]) if rows else 0) * len(rows)
    solid = sum(r.count("#") for r in rows)
    found[scene["property"]] = (solid, cells, len(scene["moves"]), f"{len(rows[0]) if rows else 0}x{len(rows)} map, {solid} solid, {len(scene['moves'])} frame(s)")
caught = sorted(found)
smallest = min(found.values())[3] if found else "-"
other = sorted(set(failed) - set(found))
print(f"{' '.join(caught) or 'not caught'} | {smallest} | {' '.join(other) or '-'}")
PY
)
    echo "| $fault | $row | $((SECONDS - start)) |"
done

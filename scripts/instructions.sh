#!/usr/bin/env bash
# Instructions per frame for tilesweep (on its prepared map, and on the bare view), the lean twin
# and the lean grid on every side-by-side
# scenario of the benchmarks, counted by callgrind (bench/frame_instructions.cpp): a measure
# that the machine's load does not change. Prints a Markdown table, with the ratio of tilesweep
# (prepared) to the fewer of the two baselines, then a second table of the conditional branches
# a frame that callgrind's simulated predictor (--branch-sim=yes) mispredicts. That predictor is
# a model (a table of two-bit counters), not the machine's; where it and the instruction counts
# both favour tilesweep and the clock does not, the difference lies in what neither counts.
#
#   bash scripts/instructions.sh [FRAMES [FILTER]]     # FRAMES per scenario (default 16384)
#
# Needs valgrind (installed when missing) and the release preset's bench binaries.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
export TILESWEEP_EXTRA_PACKAGES=valgrind
source "$root/scripts/setup.sh"
tilesweep_setup_base
frames=${1:-16384}
filter=${2:-}
build=${TILESWEEP_BUILD_DIR:-$root/build/release}
(cd "$root" && cmake --preset release >/dev/null && cmake --build "$build" --target tilesweep_frame_instructions >/dev/null)
dumps=$(mktemp -d)
trap 'rm -rf "$dumps"' EXIT
valgrind --tool=callgrind --branch-sim=yes --callgrind-out-file="$dumps/out.%p" \
    "$build/bench/tilesweep_frame_instructions" "$frames" "$filter" >/dev/null 2>"$dumps/valgrind.log"
python3 - "$dumps" <<'PY'
import glob, os, re, sys
rows = {}
missed = {}
for path in glob.glob(os.path.join(sys.argv[1], "out.*")):
    name = events = totals = None
    for line in open(path):
        if line.startswith("desc: Trigger: Client Request: "):
            name = line[len("desc: Trigger: Client Request: "):].strip()
        elif line.startswith("events:"):
            events = line.split()[1:]
        elif line.startswith(("summary:", "totals:")):
            totals = [int(v) for v in line.split()[1:]]
    if name and events and totals:
        impl, scenario, frames = name.split(" ")
        counts = dict(zip(events, totals))  # trailing zero counts are left out of the file
        rows.setdefault(scenario, {})[impl] = counts["Ir"] / int(frames)
        missed.setdefault(scenario, {})[impl] = counts.get("Bcm", 0) / int(frames)
print("| scenario | tilesweep | tilesweep (view) | lean twin | lean grid | dividing twin | tilesweep / fewer lean |")
print("|---|---:|---:|---:|---:|---:|---:|")
for scenario in sorted(rows):
    r = rows[scenario]
    best = min(r.get("Twin", float("inf")), r.get("Grid", float("inf")))
    print(f"| {scenario} | {r.get('Tilesweep', 0):.0f} | {r.get('TilesweepView', 0):.0f} | {r.get('Twin', 0):.0f} | {r.get('Grid', 0):.0f} | {r.get('TwinDividing', 0):.0f} | {r.get('Tilesweep', 0) / best:.2f} |")
print()
print("Conditional branches mispredicted a frame (callgrind's simulated predictor):")
print()
print("| scenario | tilesweep | tilesweep (view) | lean twin | lean grid |")
print("|---|---:|---:|---:|---:|")
for scenario in sorted(missed):
    m = missed[scenario]
    print(f"| {scenario} | {m.get('Tilesweep', 0):.2f} | {m.get('TilesweepView', 0):.2f} | {m.get('Twin', 0):.2f} | {m.get('Grid', 0):.2f} |")
PY

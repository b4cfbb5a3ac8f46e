#!/usr/bin/env bash
# The side-by-side table of issue 19: tilesweep against the lean twin and the lean grid (and
# tilesweep on the bare view, and the libm twin, for reference) on every scenario of
# bench/resolve_bench.cpp, in float and double, as medians of repeated runs in random interleaved
# order within one binary. Prints a Markdown table with the ratio of tilesweep to the faster lean
# baseline per row, the smallest, median and largest ratio, and the machine's load before and
# after the run (read the ratios, which compare runs under the same conditions).
#
#   bash scripts/side-by-side.sh [REPETITIONS [MIN_TIME [FILTER]]]   # defaults 5, 0.1, every scenario
#
# Needs the release preset's bench binary (built here when missing or stale).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
repetitions=${1:-5}
min_time=${2:-0.1}
filter=${3:-}
build=${TILESWEEP_BUILD_DIR:-$root/build/release}
(cd "$root" && cmake --preset release >/dev/null && cmake --build "$build" --target tilesweep_bench >/dev/null)
out=$(mktemp)
trap 'rm -f "$out"' EXIT
load_before=$(cut -d' ' -f1 /proc/loadavg)
started=$(date -u +%Y-%m-%dT%H:%MZ)
"$build/bench/tilesweep_bench" --benchmark_filter="^BM_(Tilesweep|TilesweepView|Twin|Grid|TwinLibm)_.*${filter}" \
    --benchmark_repetitions="$repetitions" --benchmark_min_time="$min_time" \
    --benchmark_enable_random_interleaving=true --benchmark_report_aggregates_only=true \
    --benchmark_format=json --benchmark_out="$out" --benchmark_out_format=json >/dev/null
load_after=$(cut -d' ' -f1 /proc/loadavg)
python3 - "$out" "$load_before" "$load_after" "$started" "$repetitions" <<'PY'
import json, re, statistics, sys
path, before, after, started, reps = sys.argv[1:]
data = json.load(open(path))
scale = {"ns": 1.0, "us": 1e3, "ms": 1e6}
times = {}
for b in data["benchmarks"]:
    if b.get("aggregate_name") != "median":
        continue
    m = re.match(r"BM_(Tilesweep|TilesweepView|Twin|Grid|TwinLibm)_(\w+)<(float|double)>(/\d+)?_median$", b["name"])
    if not m:
        continue
    impl, scenario, scalar, speed = m.groups()
    key = (scenario, speed or "")
    times.setdefault(key, {}).setdefault(scalar, {})[impl] = b["cpu_time"] * scale[b["time_unit"]]
def ns(v):
    return f"{v:.1f}" if v < 100 else f"{v:.0f}"
print(f"Medians of {reps} interleaved repetitions, CPU ns per frame; {started}, load {before} before, {after} after.")
print()
print("| scenario | T | tilesweep | ts (view) | lean twin | lean grid | libm twin | ts / faster lean |")
print("|---|---|---:|---:|---:|---:|---:|---:|")
ratios = []
for (scenario, speed), by_scalar in times.items():
    for scalar in ("float", "double"):
        r = by_scalar.get(scalar)
        if not r or "Tilesweep" not in r:
            continue
        lean = min(r.get("Twin", float("inf")), r.get("Grid", float("inf")))
        ratio = r["Tilesweep"] / lean
        ratios.append(ratio)
        tiles = f", {int(speed[1:]) / 2:g} tiles/frame" if speed else ""
        mark = "" if ratio <= 1.0 else " (over)"
        print(f"| {scenario}{tiles} | {scalar} | {ns(r['Tilesweep'])} | {ns(r.get('TilesweepView', 0))} | "
              f"{ns(r.get('Twin', 0))} | {ns(r.get('Grid', 0))} | {ns(r.get('TwinLibm', 0))} | {ratio:.2f}x{mark} |")
print()
if ratios:
    print(f"tilesweep / faster lean baseline: {min(ratios):.2f}x to {max(ratios):.2f}x, median "
          f"{statistics.median(ratios):.2f}x; at most 1.0x in {sum(r <= 1.0 for r in ratios)} of {len(ratios)} rows.")
PY

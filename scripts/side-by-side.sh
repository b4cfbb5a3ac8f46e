#!/usr/bin/env bash
# The side-by-side table: tilesweep against the lean twin and the lean grid (and
# tilesweep on the bare view, and the dividing and libm twins, for reference) on every scenario of
# bench/resolve_bench.cpp, in float and double, as medians of repeated runs in random interleaved
# order within one binary, in several processes of it: a process runs as a whole faster or
# slower on this VM (by up to 1.4x, every benchmark alike), so each timing is the median of the
# processes' medians. Prints a Markdown table with the ratio of tilesweep to the faster lean
# baseline per row, the smallest, median and largest ratio, and the machine's load before and
# after the run (read the ratios, which compare runs under the same conditions).
#
#   bash scripts/side-by-side.sh [REPETITIONS [MIN_TIME [FILTER [PROCESSES]]]]
#                                   # defaults 5, 0.1, every scenario, 3 processes (about 2 minutes each)
#
# Needs the release preset's bench binary (built here when missing or stale).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
repetitions=${1:-5}
min_time=${2:-0.1}
filter=${3:-}
processes=${4:-3}
build=${TILESWEEP_BUILD_DIR:-$root/build/release}
(cd "$root" && cmake --preset release >/dev/null && cmake --build "$build" --target tilesweep_bench >/dev/null)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
load_before=$(cut -d' ' -f1 /proc/loadavg)
started=$(date -u +%Y-%m-%dT%H:%MZ)
# Each process runs the binary through a link of its own, in a directory of its own, with a
# path 7 characters longer than the last one's: on this VM the path the binary is run by alone
# turned ZeroMove<float> from 11 to 29 ns in one identical binary (3 December: a memory layout
# effect, the instruction count unchanged), so one path can decide a row; across the processes
# the layouts differ and the median takes the typical one.
for ((p = 1; p <= processes; ++p)); do
    echo "side-by-side: process $p of $processes" >&2
    mkdir "$out/run$p"
    link="$out/run$p/bench$(printf '%*s' $((7 * p)) '' | tr ' ' _)"
    ln -s "$build/bench/tilesweep_bench" "$link"
    "$link" --benchmark_filter="^BM_(Tilesweep|TilesweepView|Twin|Grid|TwinDividing|TwinLibm)_.*${filter}" \
        --benchmark_repetitions="$repetitions" --benchmark_min_time="$min_time" \
        --benchmark_enable_random_interleaving=true --benchmark_report_aggregates_only=true \
        --benchmark_format=json --benchmark_out="$out/$p.json" --benchmark_out_format=json >/dev/null
done
load_after=$(cut -d' ' -f1 /proc/loadavg)
python3 - "$out" "$load_before" "$load_after" "$started" "$repetitions" "$processes" <<'PY'
import glob, json, os, re, statistics, sys
folder, before, after, started, reps, processes = sys.argv[1:]
scale = {"ns": 1.0, "us": 1e3, "ms": 1e6}
samples = {}  # (scenario, speed) -> scalar -> impl -> [one median per process]
for path in sorted(glob.glob(os.path.join(folder, "*.json"))):
    for b in json.load(open(path))["benchmarks"]:
        if b.get("aggregate_name") != "median":
            continue
        m = re.match(r"BM_(Tilesweep|TilesweepView|Twin|Grid|TwinDividing|TwinLibm)_(\w+)<(float|double)>(/\d+)?_median$", b["name"])
        if not m:
            continue
        impl, scenario, scalar, speed = m.groups()
        key = (scenario, speed or "")
        samples.setdefault(key, {}).setdefault(scalar, {}).setdefault(impl, []).append(
            b["cpu_time"] * scale[b["time_unit"]])
times = {key: {scalar: {impl: statistics.median(v) for impl, v in by_impl.items()}
               for scalar, by_impl in by_scalar.items()}
         for key, by_scalar in samples.items()}
def ns(v):
    return f"{v:.1f}" if v < 100 else f"{v:.0f}"
print(f"Medians over {processes} processes of the medians of {reps} interleaved repetitions, CPU ns per frame "
      f"(the ratio: the median of each process's ratio); {started}, load {before} before, {after} after.")
print()
print("| scenario | T | tilesweep | ts (view) | lean twin | lean grid | dividing twin | libm twin | ts / faster lean |")
print("|---|---|---:|---:|---:|---:|---:|---:|---:|")
order = ["Random30", "FloorAndWalls", "WideBox", "RestingOnFloor", "FreeFlight", "FarRandom30", "ZeroMove"]
def row_key(key):
    scenario, speed = key
    return (order.index(scenario) if scenario in order else len(order), scenario, int(speed[1:] or 0))
ratios = []
for (scenario, speed), by_scalar in sorted(times.items(), key=lambda item: row_key(item[0])):
    for scalar in ("float", "double"):
        r = by_scalar.get(scalar)
        if not r or "Tilesweep" not in r:
            continue
        # The ratio within each process (its runs share the process's speed), then their median.
        per = samples[(scenario, speed)][scalar]
        inf = [float("inf")] * len(per["Tilesweep"])
        ratio = statistics.median(t / min(tw, g) for t, tw, g in zip(per["Tilesweep"], per.get("Twin", inf),
                                                                      per.get("Grid", inf)))
        ratios.append(ratio)
        tiles = f", {int(speed[1:]) / 2:g} tiles/frame" if speed else ""
        mark = "" if ratio <= 1.0 else " (over)"
        print(f"| {scenario}{tiles} | {scalar} | {ns(r['Tilesweep'])} | {ns(r.get('TilesweepView', 0))} | "
              f"{ns(r.get('Twin', 0))} | {ns(r.get('Grid', 0))} | {ns(r.get('TwinDividing', 0))} | {ns(r.get('TwinLibm', 0))} | "
              f"{ratio:.2f}x{mark} |")
print()
if ratios:
    print(f"tilesweep / faster lean baseline: {min(ratios):.2f}x to {max(ratios):.2f}x, median "
          f"{statistics.median(ratios):.2f}x; at most 1.0x in {sum(r <= 1.0 for r in ratios)} of {len(ratios)} rows.")
PY

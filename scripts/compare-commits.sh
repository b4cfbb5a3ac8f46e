#!/usr/bin/env bash
# Whether a change costs time: builds the benchmark binary (release preset) of two commits, each in
# a worktree of its own under build/compare/, then runs tilesweep's rows of bench/resolve_bench.cpp
# (or every row of bench/batch_bench.cpp, COMPARE_BENCH=batch) in both, alternating the two
# binaries over several processes (each with random interleaving and repetitions), and prints a
# Markdown table: per row the median over the processes of each binary's median, and NEW / OLD.
# Rows only one binary has are left out. Read the ratios: both binaries ran under the same
# conditions, turn about.
#
#   bash scripts/compare-commits.sh OLD NEW [FILTER [PROCESSES [REPETITIONS]]]
#   bash scripts/compare-commits.sh OLD HEAD '' 3 5         # defaults: every row, 3 processes, 5
#   COMPARE_NO_BUILD=1 bash scripts/compare-commits.sh ...  # the binaries already built there
#   COMPARE_BENCH=batch bash scripts/compare-commits.sh ... # the rows of bench/batch_bench.cpp
#                                                           # instead, in real time (a batch spans threads)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
old=${1:?usage: compare-commits.sh OLD NEW [FILTER [PROCESSES [REPETITIONS]]]}
new=${2:?usage: compare-commits.sh OLD NEW [FILTER [PROCESSES [REPETITIONS]]]}
filter=${3:-}
processes=${4:-3}
repetitions=${5:-5}
case "${COMPARE_BENCH:-resolve}" in
    resolve) target=tilesweep_bench prefix=BM_Tilesweep_ time_field=cpu_time ;;
    batch) target=tilesweep_batch_bench prefix=BM_MoveAndSlideBatch_ time_field=real_time ;;
    *) echo "compare-commits: COMPARE_BENCH is resolve or batch, not ${COMPARE_BENCH}" >&2; exit 2 ;;
esac
bash "$root/scripts/setup.sh"
binaries=()
for commit in "$old" "$new"; do
    sha=$(git -C "$root" rev-parse --short "$commit")
    tree=$root/build/compare/$sha
    if [ ! -d "$tree" ]; then
        git -C "$root" worktree add --detach "$tree" "$sha" >/dev/null
    fi
    if [ "${COMPARE_NO_BUILD:-0}" != 1 ]; then
        (cd "$tree" && cmake --preset release -B build/release >/dev/null &&
            cmake --build build/release --target "$target" >/dev/null)
    fi
    binaries+=("$tree/build/release/bench/$target")
done
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
load_before=$(cut -d' ' -f1 /proc/loadavg)
for ((p = 1; p <= processes; ++p)); do
    # Turn about: the first binary of a round is the other one each round.
    for k in 0 1; do
        b=$(((k + p) % 2))
        echo "compare-commits: process $p of $processes, $([ $b = 0 ] && echo "$old" || echo "$new")" >&2
        "${binaries[$b]}" --benchmark_filter="^${prefix}.*${filter}" --benchmark_repetitions="$repetitions" \
            --benchmark_min_time=0.1 --benchmark_enable_random_interleaving=true \
            --benchmark_report_aggregates_only=true --benchmark_format=json \
            --benchmark_out="$out/$b-$p.json" --benchmark_out_format=json >/dev/null
    done
done
load_after=$(cut -d' ' -f1 /proc/loadavg)
python3 - "$out" "$old" "$new" "$load_before" "$load_after" "$prefix" "$time_field" <<'PY'
import glob, json, os, statistics, sys
out, old, new, before, after, prefix, time_field = sys.argv[1:]
def medians(b):
    runs = {}
    for path in glob.glob(os.path.join(out, f"{b}-*.json")):
        for r in json.load(open(path))["benchmarks"]:
            if r.get("aggregate_name") == "median":
                runs.setdefault(r["run_name"], []).append(r[time_field])
    return {name: statistics.median(v) for name, v in runs.items()}
a, b = medians(0), medians(1)
rows = [n for n in a if n in b]
print(f"| row | {old} ns | {new} ns | {new} / {old} |\n|---|---:|---:|---:|")
ratios = []
for n in rows:
    ratios.append(b[n] / a[n])
    print(f"| {n.removeprefix(prefix)} | {a[n]:.1f} | {b[n]:.1f} | {b[n] / a[n]:.3f} |")
if ratios:
    print(f"\n{len(rows)} rows: {new} / {old} from {min(ratios):.3f} to {max(ratios):.3f}, median "
          f"{statistics.median(ratios):.3f}; load {before} before, {after} after.")
PY

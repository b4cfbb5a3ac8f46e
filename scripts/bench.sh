#!/usr/bin/env bash
# Builds tilesweep in Release, runs the Google Benchmark suite (bench/resolve_bench.cpp) with
# repetitions, keeps the aggregates (median, mean, stddev, cv) as JSON in
# OUT/results-<host>.json with the machine beside it (machine-<host>.json), then writes
# OUT/bench.md (medians and target ratios, stamped with the commit and date) and OUT/pareto.svg
# (run time against the audit's error figures, from build/audit/report.json: bash scripts/audit.sh
# runs first when it is missing) with scripts/bench_report.py, whose chart scripts/plots.py draws.
# OUT is build/bench; `--out-dir docs/bench` replaces the committed page.
#
#   bash scripts/bench.sh                      # 5 repetitions of every benchmark
#   bash scripts/bench.sh --repetitions 3      # fewer, on a busy machine
#   bash scripts/bench.sh --filter 'MapSize'   # a subset (the report marks what did not run)
#   bash scripts/bench.sh --no-build -- --benchmark_min_time=1
#
# Options: --repetitions N (or BENCH_REPETITIONS; default 5), --filter REGEX (Google
# Benchmark's --benchmark_filter), --min-time SECONDS (--benchmark_min_time), --no-build (use
# the binary already in the build directory), --out-dir DIR (default build/bench; docs/bench for
# the committed page), and anything after `--` goes to the benchmark
# binary unchanged. The build directory is ${TILESWEEP_BUILD_DIR:-build/release} (the release
# preset), relative to
# the repository root when not absolute; extra configure arguments can be given in
# BENCH_CMAKE_ARGS. Timings are CPU time per item; keep the machine otherwise idle if you can
# (the load average before and after the run is recorded in the report).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

repetitions=${BENCH_REPETITIONS:-5}
filter=""
min_time=""
build=1
out_dir=$root/build/bench
extra=()
while (($#)); do
    case "$1" in
        --repetitions) repetitions=${2:?--repetitions needs a number}; shift 2 ;;
        --repetitions=*) repetitions=${1#*=}; shift ;;
        --filter) filter=${2:?--filter needs a regular expression}; shift 2 ;;
        --filter=*) filter=${1#*=}; shift ;;
        --min-time) min_time=${2:?--min-time needs seconds}; shift 2 ;;
        --min-time=*) min_time=${1#*=}; shift ;;
        --no-build) build=0; shift ;;
        --out-dir) out_dir=${2:?--out-dir needs a directory}; shift 2 ;;
        --out-dir=*) out_dir=${1#*=}; shift ;;
        --) shift; extra=("$@"); break ;;
        -h|--help) awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "${BASH_SOURCE[0]}"; exit 0 ;;
        *) echo "bench.sh: unknown option '$1' (try --help)" >&2; exit 2 ;;
    esac
done
if ! [[ "$repetitions" =~ ^[1-9][0-9]*$ ]]; then
    echo "bench.sh: --repetitions must be a positive integer, got '$repetitions'" >&2
    exit 2
fi

build_dir=${TILESWEEP_BUILD_DIR:-build/release}
[[ "$build_dir" = /* ]] || build_dir=$root/$build_dir
binary=$build_dir/bench/tilesweep_bench

if ((build)); then
    # The release preset: the library, the oracles (the exact reference, the seed and substep
    # baselines) and the benchmarks; no tests.
    # shellcheck disable=SC2086  # BENCH_CMAKE_ARGS is a list of words on purpose
    TILESWEEP_EXTRA_PACKAGES=python3-matplotlib bash "$root/scripts/setup.sh"
    TILESWEEP_PRESET=release TILESWEEP_BUILD_DIR=$build_dir bash "$root/scripts/build.sh" ${BENCH_CMAKE_ARGS:-}
fi
if [ ! -x "$binary" ]; then
    echo "bench.sh: $binary not found (build first, or drop --no-build)" >&2
    exit 1
fi

# One results file per machine, named after it.
host=$(hostname -s 2>/dev/null || cat /etc/hostname 2>/dev/null || true)
host=$(printf '%s' "$host" | tr -c 'A-Za-z0-9._-' '_')
[ -n "$host" ] || host=machine
mkdir -p "$out_dir"
out_dir=$(cd "$out_dir" && pwd)
results=$out_dir/results-$host.json
machine=$out_dir/machine-$host.json

# The machine, for the report: cores, CPU model, compiler, load before and after the run.
cxx=$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$build_dir/CMakeCache.txt" 2>/dev/null | head -n 1)
compiler=$({ "${cxx:-c++}" --version 2>/dev/null || true; } | head -n 1)
cxx_flags=$(sed -n 's/^CMAKE_CXX_FLAGS_RELEASE:[A-Z]*=//p' "$build_dir/CMakeCache.txt" 2>/dev/null | head -n 1)
build_type=$(sed -n 's/^CMAKE_BUILD_TYPE:[A-Z]*=//p' "$build_dir/CMakeCache.txt" 2>/dev/null | head -n 1)
cpu_model=$(sed -n 's/^model name[[:space:]]*:[[:space:]]*//p' /proc/cpuinfo 2>/dev/null | head -n 1)
[ -n "$cpu_model" ] || cpu_model=$(uname -m)
load_before=$(cat /proc/loadavg 2>/dev/null || echo unknown)
commit=$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)
if [ "$commit" != unknown ] && [ -n "$(git -C "$root" status --porcelain --untracked-files=no 2>/dev/null)" ]; then
    commit="$commit (with uncommitted changes)"
fi

args=(--benchmark_repetitions="$repetitions" --benchmark_report_aggregates_only=true
      --benchmark_out="$results" --benchmark_out_format=json)
[ -z "$filter" ] || args+=(--benchmark_filter="$filter")
[ -z "$min_time" ] || args+=(--benchmark_min_time="$min_time")
echo "bench.sh: $binary, $repetitions repetitions, results in ${results#"$root"/}" >&2
started=$(date -u +%Y-%m-%dT%H:%M:%SZ)
"$binary" "${args[@]}" "${extra[@]}"
load_after=$(cat /proc/loadavg 2>/dev/null || echo unknown)

# shellcheck disable=SC2016  # the quotes around the filter are meant literally
BENCH_HOST=$host BENCH_CPU=$cpu_model BENCH_NPROC=$(nproc) BENCH_COMPILER=$compiler \
BENCH_FLAGS=$cxx_flags BENCH_BUILD_TYPE=$build_type BENCH_LOAD_BEFORE=$load_before \
BENCH_LOAD_AFTER=$load_after BENCH_STARTED=$started BENCH_REPS=$repetitions BENCH_COMMIT=$commit \
BENCH_COMMAND="bash scripts/bench.sh --repetitions $repetitions${filter:+ --filter '$filter'}${min_time:+ --min-time $min_time}" \
python3 - "$machine" <<'EOF'
import json, os, sys
keys = {"host": "BENCH_HOST", "cpu_model": "BENCH_CPU", "nproc": "BENCH_NPROC",
        "compiler": "BENCH_COMPILER", "cxx_flags_release": "BENCH_FLAGS",
        "build_type": "BENCH_BUILD_TYPE", "loadavg_before": "BENCH_LOAD_BEFORE",
        "loadavg_after": "BENCH_LOAD_AFTER", "started_utc": "BENCH_STARTED",
        "repetitions": "BENCH_REPS", "command": "BENCH_COMMAND", "commit": "BENCH_COMMIT"}
info = {k: os.environ.get(v, "") for k, v in keys.items()}
with open(sys.argv[1], "w", encoding="utf-8") as f:
    json.dump(info, f, indent=2)
    f.write("\n")
EOF

# The report's chart is drawn by scripts/plots.py with Debian's matplotlib (/usr/bin/python3).
[ -f "$root/build/audit/report.json" ] || bash "$root/scripts/audit.sh"
/usr/bin/python3 "$root/scripts/bench_report.py" --results "$results" --machine "$machine" \
    --audit "$root/build/audit/report.json" --out-dir "$out_dir"

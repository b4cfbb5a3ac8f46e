#!/usr/bin/env bash
# The fast-movers page, regenerated whole: exact tilesweep against the lean baselines at long moves
# (scripts/side-by-side.sh), the throughput of a batch of movers on 1 and 2 threads against its
# targets (build/release/bench/tilesweep_batch_bench, bench/batch_bench.cpp), and where a long
# move's instructions go, phase by phase (scripts/phases.sh). Writes one Markdown page stamped with
# the commit, the date, the machine and its load before and after the whole run; the page is
# written to a scratch file first and moved into place at the end, so an interrupted run leaves
# the old page as it was. Progress goes to stderr. About 11 minutes on 2 cores, most of it the
# side-by-side table; run nothing else meanwhile, the timings are the machine's.
#
#   bash scripts/fast-movers.sh                                  # writes build/bench/fast-movers.md
#   bash scripts/fast-movers.sh --out docs/bench/fast-movers.md  # the committed page
#
# Needs what its three tools need: the release preset's benchmark binaries (built here when
# missing or stale), and for phases.sh valgrind and binutils (valgrind installed when missing)
# and its debug-information tree build/phase (configured and built by it). Each tool uses its
# default build tree, so TILESWEEP_BUILD_DIR is ignored here. Python 3 (standard library only).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
out=$root/build/bench/fast-movers.md
command_line="bash scripts/fast-movers.sh"
while (($#)); do
    case "$1" in
        --out) out=${2:?--out needs a file}; shift 2 ;;
        --out=*) out=${1#*=}; shift ;;
        -h | --help) sed -n '2,/^set -euo/p' "${BASH_SOURCE[0]}" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
        *) echo "fast-movers: unknown option $1 (--out FILE)" >&2; exit 2 ;;
    esac
done
out=$(realpath -m "$out")
if [ "$out" != "$root/build/bench/fast-movers.md" ]; then
    command_line="$command_line --out ${out#"$root"/}"
fi
unset TILESWEEP_BUILD_DIR

# The batch benchmark's targets on 2 threads, in mover-frames a second: float mix, double mix; and
# each mix's rate on 2 threads over its rate on 1 (docs/benchmarks.md).
target_float=60e6
target_double=45e6
target_scaling=1.8
side_args=(5 0.1 '' 3)
# Repetitions interleaved at random across the rows, so that a slow spell of a shared machine
# falls on every row alike rather than on one row's repetitions (the one-thread and two-thread rows,
# whose ratio is the scaling, most of all).
batch_args=(--benchmark_repetitions=9 --benchmark_enable_random_interleaving=true --benchmark_min_time=0.3
    --benchmark_report_aggregates_only=true)

scratch=$(mktemp -d)
partial=$out.partial.$$
trap 'rm -rf "$scratch" "$partial"' EXIT

stamp() {  # the commit, and whether tracked files differ from it
    local commit
    commit=$(git -C "$root" rev-parse --short HEAD)
    if [ -n "$(git -C "$root" status --porcelain --untracked-files=no)" ]; then
        commit="$commit with uncommitted changes"
    fi
    echo "$commit"
}
commit=$(stamp)
started=$(date -u '+%Y-%m-%d %H:%M')
load_before=$(cut -d' ' -f1 /proc/loadavg)
cpu=$(lscpu 2>/dev/null | sed -n 's/^Model name: *//p' | head -1)
[ -n "$cpu" ] || cpu=$(sed -n 's/^model name[[:space:]]*: *//p' /proc/cpuinfo | head -1)
cores=$(nproc)
# The movers in a mix, as bench/batch_bench.cpp sets them.
movers=$(sed -n 's/^constexpr int kMovers = \([0-9]*\);.*/\1/p' "$root/bench/batch_bench.cpp" |
    sed ':a; s/\B[0-9]\{3\}\>/,&/; ta')

# The batch benchmark is built first, so that a failed build stops the run before its long part.
echo "fast-movers: building the batch benchmark..." >&2
(cd "$root" && cmake --preset release >/dev/null && cmake --build build/release --target tilesweep_batch_bench >/dev/null)

echo "fast-movers: side by side (about 6 minutes)..." >&2
bash "$root/scripts/side-by-side.sh" "${side_args[@]}" > "$scratch/side-by-side.md"

echo "fast-movers: batch benchmark (about 2 minutes)..." >&2
"$root/build/release/bench/tilesweep_batch_bench" "${batch_args[@]}" --benchmark_format=json \
    --benchmark_out="$scratch/batch.json" --benchmark_out_format=json >/dev/null

echo "fast-movers: phases (a few minutes)..." >&2
bash "$root/scripts/phases.sh" > "$scratch/phases.md"

load_after=$(cut -d' ' -f1 /proc/loadavg)
finished=$(date -u '+%H:%M')
commit_after=$(stamp)
if [ "$commit_after" != "$commit" ]; then
    echo "fast-movers: the tree changed during the run ($commit, then $commit_after)" >&2
    commit="$commit at the start, $commit_after at the end"
fi

{
    echo "# Fast movers"
    echo
    echo "The evidence for fast movers: exact tilesweep against the lean baselines (the lean twin and"
    echo "the lean grid) at long moves, the throughput of a batch of movers, and where a long move's"
    echo "instructions go. The page is regenerated whole by one command, never edited by hand:"
    echo "\`$command_line\` (about 11 minutes; run nothing else meanwhile). Each section gives the"
    echo "command that made it."
    echo
    echo "- Commit: $commit"
    echo "- Date: $started to $finished UTC"
    echo "- Machine: ${cpu:-unknown CPU}, $cores cores ($(uname -m))"
    echo "- Load average (1 minute): $load_before before the run, $load_after after"
    echo
    echo "## Side by side"
    echo
    echo '```sh'
    echo "bash scripts/side-by-side.sh$(printf ' %q' "${side_args[@]}")"
    echo '```'
    echo
    cat "$scratch/side-by-side.md"
    echo
    echo "## Many movers: the batch"
    echo
    echo '```sh'
    echo "build/release/bench/tilesweep_batch_bench ${batch_args[*]}"
    echo '```'
    echo
    echo "Each batch resolves one frame of every mover on a 256 x 256 map of 16 px tiles with floors and"
    echo "walls (bench/batch_bench.cpp): Mix is a game's mix of ${movers:+$movers }movers of 12 x 14 px, a"
    echo "quarter each resting on a floor, walking, falling through open air and dashing 30 px a frame, in"
    echo "float (MixDouble in double); MixShuffled is the float mix in random order, as a game's list of"
    echo "movers holds its kinds (Mix takes them in turn, which the branch predictor learns); Resting,"
    echo "Walking, Falling and Fast run one quarter alone, one kind."
    echo "MixC is the float mix through the C API's batch call (ts_move_and_slide_batch_f, tilesweep.h)."
    echo "MixAfterIdle runs the float mix once a millisecond, as a game's one batch a frame, so the pool's"
    echo "worker is woken for each batch (only the batch is timed). Times are real time, since a batch"
    echo "spans threads; each figure is the median of 9 repetitions, interleaved at random with the other"
    echo "rows' so that a slow spell of the machine falls on every row alike."
    echo
    python3 - "$scratch/batch.json" "$target_float" "$target_double" "$target_scaling" <<'PY'
import json, re, sys
path, target_float, target_double = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
target_scaling = float(sys.argv[4])
scale = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}
rows = {}  # (kind, threads) -> (mover-frames a second, ns a batch)
for b in json.load(open(path))["benchmarks"]:
    m = re.match(r"BM_MoveAndSlideBatch_(\w+)/threads:(\d+)/(?:real|manual)_time_median$", b["name"])
    if m:
        rows[(m[1], int(m[2]))] = (b["items_per_second"], b["real_time"] * scale[b["time_unit"]])
order = [(k, t) for k in ("Mix", "MixShuffled", "MixDouble", "MixAfterIdle", "MixC") for t in (1, 2)]
order += [(k, 1) for k in ("Resting", "Walking", "Falling", "Fast")]
print("| benchmark | threads | mover-frames/s (millions) | ns a batch |")
print("|---|---:|---:|---:|")
for kind, threads in order + sorted(set(rows) - set(order)):
    if (kind, threads) not in rows:
        print(f"| {kind} | {threads} | not run | |")
        continue
    rate, ns = rows[(kind, threads)]
    print(f"| {kind} | {threads} | {rate / 1e6:.1f} | {ns:,.0f} |")
print()
print("Targets, on 2 threads:")
print()
print("| mix | target (millions/s) | measured (millions/s) | measured / target | |")
print("|---|---:|---:|---:|---|")
for label, kind, target in (("float", "Mix", target_float), ("double", "MixDouble", target_double)):
    rate = rows.get((kind, 2), (None,))[0]
    if rate is None:
        print(f"| {label} ({kind}) | {target / 1e6:g} | not run | | |")
    else:
        print(f"| {label} ({kind}) | {target / 1e6:g} | {rate / 1e6:.1f} | {rate / target:.2f} | "
              f"{'met' if rate >= target else 'not met'} |")
print()
print(f"Scaling, 2 threads over 1 (mover-frames a second), against its target of {target_scaling:g}x:")
print()
print("| mix | 1 thread (millions/s) | 2 threads (millions/s) | 2 over 1 | |")
print("|---|---:|---:|---:|---|")
for kind in ("Mix", "MixDouble"):
    if (kind, 1) in rows and (kind, 2) in rows:
        one, two = rows[(kind, 1)][0], rows[(kind, 2)][0]
        print(f"| {kind} | {one / 1e6:.1f} | {two / 1e6:.1f} | {two / one:.2f}x | "
              f"{'met' if two >= target_scaling * one else 'not met'} |")
    else:
        print(f"| {kind} | | | not run | |")
PY
    echo
    echo "## Where a long move's instructions go"
    echo
    echo '```sh'
    echo "bash scripts/phases.sh"
    echo '```'
    echo
    cat "$scratch/phases.md"
} > "$scratch/page.md"

mkdir -p "$(dirname "$out")"
cp "$scratch/page.md" "$partial"
mv -f "$partial" "$out"
echo "fast-movers: wrote ${out#"$root"/}" >&2

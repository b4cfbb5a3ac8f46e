#!/usr/bin/env bash
# How fast the suite holds each engine to the contract: `tilesweep check --resolver-cmd` against
# every adapter whose runtime is here, one after the other, each for the same budget on all
# cores, every round kept going and none shrinking (--keep-going --no-shrink: every case is
# judged and every failure counted, so the figure is the engine's, not shrinking's). Each
# engine runs --runs times (3 unless told); the page gives the median rate and every run's.
# Writes build/bench/adapters.md (--out docs/bench/adapters.md for the committed page; cases
# judged per second, passed and failed, with the machine's load before and after) unless --out
# says otherwise. A benchmark, not a test: it asserts nothing; read the figures against the
# targets in docs/benchmarks.md.
#
#   bash scripts/bench_adapters.sh                  # 3 runs of 20 s each, 1000 cases a property per round
#   bash scripts/bench_adapters.sh --seconds 60 --cases 2000 --runs 5 --out /tmp/adapters.md
#   bash scripts/bench_adapters.sh --engines "godot rapier"   # only those rows
#
# Needs the dev build (bash scripts/test.sh builds it) and, for the engines, their runtimes
# (bash scripts/setup.sh --engines; adapters/README.md).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
seconds=20
cases=1000
runs=3
out=$root/build/bench/adapters.md
only=""
while [ $# -gt 0 ]; do
    case $1 in
        --seconds) seconds=$2; shift 2 ;;
        --cases) cases=$2; shift 2 ;;
        --runs) runs=$2; shift 2 ;;
        --out) out=$2; shift 2 ;;
        --engines) only=" $2 "; shift 2 ;;
        *) echo "bench_adapters: unknown option $1 (--seconds S, --cases N, --runs N, --out FILE, --engines \"NAME...\")" >&2; exit 2 ;;
    esac
done
if ! [[ $runs =~ ^[1-9][0-9]*$ ]]; then
    echo "bench_adapters: --runs must be a positive whole number, not '$runs'" >&2
    exit 2
fi
build=${TILESWEEP_BUILD_DIR:-$root/build/plain}
tool=$build/cli/tilesweep
if [ ! -x "$tool" ]; then
    echo "bench_adapters: $tool not found: build first (bash scripts/test.sh)" >&2
    exit 2
fi

# name | command | what it is
engines=(
    "tilesweep (built in)|$tool|the main job: tilesweep in this process, every float property, no outside resolver"
    "tilesweep|$tool resolve --scalar float|tilesweep itself through a pipe: the suite's own cost"
    "tilesweep (file mode)|$tool resolve --scalar float {in} > {out}|the same, one process run per batch"
    "twin|$build/adapters/tilesweep_twin_adapter|the inexact game-style twin (C++)"
    "box2d|$build/adapters/tilesweep_box2d_adapter|Box2D 2.4 b2TimeOfImpact per tile (C++)"
    "game-style library|$tool resolve --resolver lib:$build/examples/libtilesweep_example_game_style.so --scalar float|examples/resolver_lib/game_style.c through --resolver-lib (C, in a child process)"
    "godot|${TILESWEEP_ADAPTERS:-$root/adapters}/godot/run.sh {in} {out}|Godot 3 body_test_motion (GDScript, file mode)"
    "rapier|${TILESWEEP_ADAPTERS:-$root/adapters}/rapier/run.sh|Rapier KinematicCharacterController (node, pipe)"
    "planck|${TILESWEEP_ADAPTERS:-$root/adapters}/planck/run.sh|planck (Box2D 2.x in JS doubles) dynamic body and world.step (node, pipe)"
    "matter|${TILESWEEP_ADAPTERS:-$root/adapters}/matter/run.sh|matter-js dynamic body and Engine.update (node, pipe)"
    "phaser|${TILESWEEP_ADAPTERS:-$root/adapters}/phaser/run.sh|Phaser 4 Arcade body vs tilemap layer (node, pipe)"
    "box2d3|${TILESWEEP_ADAPTERS:-$root/adapters}/box2d3/run.sh|Box2D v3 capsule mover, CastMover and SolvePlanes (wasm in node, pipe)"
    "rapier-deterministic|${TILESWEEP_ADAPTERS:-$root/adapters}/rapier-deterministic/run.sh|the Rapier adapter on Rapier's deterministic build (node, pipe)"
)

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
{
    echo "# Conformance throughput: the suite against each engine"
    echo
    commit=$(git -C "$root" rev-parse --short HEAD)
    dirty=$(git -C "$root" status --porcelain --untracked-files=no | grep -q . && echo " (with uncommitted changes)" || true)
    echo "Made on $(date -u '+%Y-%m-%d %H:%M UTC') on commit $commit$dirty; regenerate it whole, never by hand:"
    echo "\`bash scripts/bench_adapters.sh --seconds $seconds --cases $cases --runs $runs\` on $(nproc) cores ($(uname -m),"
    echo "$(lscpu 2>/dev/null | sed -n 's/^Model name: *//p' | head -1)). Each engine runs $runs times, one after the"
    echo "other; cases/s is the median run's, and the cases judged, passed and failed are that run's. Each run is"
    echo "\`tilesweep check --resolver-cmd CMD --scalar S --cases $cases --seconds $seconds --keep-going --no-shrink\`,"
    echo "S being what adapters/ENGINE/scalar says (double for the engines that compute in doubles), else float."
    echo "Cases judged per second count every case, passed or failed; each property round draws its"
    echo "cases and sends every scene they ask for to the engine in one batch."
    echo
    echo "| engine | what | cases judged | passed | failed | cases/s (median) | every run's cases/s | properties failed | load before, after |"
    echo "|---|---|---:|---:|---:|---:|---|---:|---|"
} > "$scratch/report.md"
for entry in "${engines[@]}"; do
    IFS='|' read -r name command what <<<"$entry"
    # --engines names rows by their first word ("tilesweep" is the three tilesweep rows).
    if [ -n "$only" ] && [[ $only != *" ${name%% *} "* ]]; then continue; fi
    first=${command%% *}
    if [ ! -x "$first" ]; then
        echo "bench_adapters: $name skipped: $first is not built or not here" >&2
        echo "| $name | $what | skipped: not here | | | | | | |" >> "$scratch/report.md"
        continue
    fi
    # The engine's arithmetic: adapters/ENGINE/scalar holds "double" for a double engine.
    scalar=float
    scalar_file=${TILESWEEP_ADAPTERS:-$root/adapters}/$name/scalar
    if [ -f "$scalar_file" ]; then scalar=$(tr -d '[:space:]' < "$scalar_file"); fi
    load_before=$(cut -d' ' -f1 /proc/loadavg)
    resolver=(--resolver-cmd "$command")
    [ "$command" = "$tool" ] && resolver=()  # the built-in resolver: no outside process
    # One line per run: "rate judged failed_cases failed_properties".
    : > "$scratch/$name.runs"
    for run in $(seq 1 "$runs"); do
        echo "bench_adapters: $name for $seconds s (run $run of $runs)" >&2
        "$tool" check "${resolver[@]}" --scalar "$scalar" --cases "$cases" --seconds "$seconds" --keep-going --no-shrink \
            --corpus "$scratch/corpus" --json "$scratch/$name.json" > "$scratch/$name.out" 2>&1 || true
        summary=$(grep -E '^[0-9]+ cases in ' "$scratch/$name.out" | tail -1)
        if [ -z "$summary" ]; then
            echo "bench_adapters: $name gave no summary; its output ends:" >&2
            tail -5 "$scratch/$name.out" >&2
            continue
        fi
        judged=$(echo "$summary" | awk '{print $1}')
        rate=$(echo "$summary" | sed -n 's/.*: \([0-9]*\) cases\/s.*/\1/p')
        failed_properties=$(grep -E '^[0-9]+ passed, [0-9]+ failed' "$scratch/$name.out" | awk '{print $3}')
        failed_cases=$(python3 -c 'import json,sys; print(sum(r["failures"] for r in json.load(open(sys.argv[1]))["rows"]))' \
            "$scratch/$name.json")
        echo "$rate $judged $failed_cases $failed_properties" >> "$scratch/$name.runs"
    done
    load_after=$(cut -d' ' -f1 /proc/loadavg)
    if [ ! -s "$scratch/$name.runs" ]; then
        echo "| $name | $what | no summary | | | | | | $load_before, $load_after |" >> "$scratch/report.md"
        continue
    fi
    every=$(awk '{print $1}' "$scratch/$name.runs" | paste -sd, - | sed 's/,/, /g')
    # The median run: the middle of the runs sorted by rate (the lower middle of an even count).
    read -r rate judged failed_cases failed_properties < <(sort -n "$scratch/$name.runs" | \
        awk '{line[NR] = $0} END {print line[int((NR + 1) / 2)]}')
    echo "| $name | $what | $judged | $((judged - failed_cases)) | $failed_cases | $rate | $every | $failed_properties | $load_before, $load_after |" \
        >> "$scratch/report.md"
done
mkdir -p "$(dirname "$out")"
cp "$scratch/report.md" "$out"
cat "$out"

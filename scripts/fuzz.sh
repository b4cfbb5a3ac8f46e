#!/usr/bin/env bash
# Builds the libFuzzer targets of fuzz/ with clang, AddressSanitizer and UBSan (the fuzz preset,
# in build/fuzz/, or $TILESWEEP_FUZZ_BUILD_DIR), runs each for SECONDS_PER_TARGET seconds, prints
# executions per second and corpus size, then replays the seed corpus, the saved regressions and
# the grown corpus through the sanitized replay drivers.
#
#   bash scripts/fuzz.sh [SECONDS_PER_TARGET [TARGET...]]    # default: 60 s, every target
#   bash scripts/fuzz.sh 0                                   # build and replay only
#   bash scripts/fuzz.sh --tests 'unit|property' 30          # first the ctest suite built by clang
#   bash scripts/fuzz.sh --tests 'unit|property' --exclude 'Slow' 30   # leaving out tests by name
#
# --tests LABELS builds the whole fuzz preset (tests, properties, oracles) and runs
# `ctest -L LABELS` in it before fuzzing: the default configuration compiled by clang, under the
# sanitizers (TILESWEEP_PROPERTY_CASES cases a property, 300 unless set).
# A failing input is written to fuzz/regressions/<target>/ (a regression test from then on) and
# makes the script exit 1. The grown corpus stays in <build>/corpus/<target>/ between runs.
# TILESWEEP_FUZZ_PRESET=fuzz-portable builds with the portable integer code (build/fuzz-portable/);
# TILESWEEP_FUZZ_NO_BUILD=1 skips configure and build (to run targets side by side);
# TILESWEEP_FUZZ_FLAGS adds compile options to the core library, after the sanitizer flags
# (say "-fno-sanitize=builtin -mlzcnt -O0", to look past a known finding while it is fixed).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
tests=""
exclude=""
if [ "${1:-}" = --tests ]; then
    tests=${2:?--tests needs ctest labels (a regular expression)}
    shift 2
fi
if [ "${1:-}" = --exclude ]; then
    exclude=${2:?--exclude needs ctest test names (a regular expression)}
    shift 2
fi
seconds=${1:-60}
shift || true
targets=("$@")
((${#targets[@]})) || targets=(scene_reader resolver)
preset=${TILESWEEP_FUZZ_PRESET:-fuzz}
build=${TILESWEEP_FUZZ_BUILD_DIR:-$root/build/$preset}

# clang and its sanitizer and libFuzzer runtimes, from Debian's packages, when missing, with
# what every build needs (scripts/setup.sh).
export TILESWEEP_EXTRA_PACKAGES="clang libclang-rt-14-dev"
source "$root/scripts/setup.sh"
tilesweep_setup_base

if [ "${TILESWEEP_FUZZ_NO_BUILD:-0}" != 1 ]; then
    # Warnings are errors under clang too, as in the g++ builds.
    (cd "$root" && cmake --preset "$preset" -B "$build" -DTILESWEEP_FUZZ_FLAGS="${TILESWEEP_FUZZ_FLAGS:-}" >/dev/null)
    if [ -n "$tests" ]; then
        cmake --build "$build" --parallel "$(nproc)"
    else
        binaries=()
        for target in "${targets[@]}"; do binaries+=("fuzz_$target" "fuzz_${target}_replay"); done
        cmake --build "$build" --parallel "$(nproc)" --target "${binaries[@]}"
    fi
fi

if [ -n "$tests" ]; then
    echo "== ctest -L '$tests' (clang, ASan + UBSan)"
    TILESWEEP_PROPERTY_CASES=${TILESWEEP_PROPERTY_CASES:-300} \
        ctest --test-dir "$build" --output-on-failure --parallel "$(nproc)" -L "$tests" ${exclude:+-E "$exclude"}
fi

# Input size bounds: a scene line of a few KiB covers every field several times over; a resolver
# input is at most 3 + 128 + 10*9 + 1 bytes.
declare -A max_len=([scene_reader]=4096 [resolver]=256)
status=0
for target in "${targets[@]}"; do
    corpus=$build/corpus/$target
    regressions=$root/fuzz/regressions/$target
    mkdir -p "$corpus" "$regressions"
    if ((seconds > 0)); then
        log=$build/fuzz-$target.log
        echo "== fuzz_$target for $seconds s (log: $log)"
        # New inputs go to the first corpus directory; the seeds in fuzz/corpus/ are only read.
        if ! "$build/fuzz/fuzz_$target" -max_total_time="$seconds" -max_len="${max_len[$target]:-4096}" \
            -rss_limit_mb=2048 -malloc_limit_mb=1024 -timeout=10 -print_final_stats=1 \
            -artifact_prefix="$regressions/" "$corpus" "$root/fuzz/corpus/$target" >"$log" 2>&1; then
            echo "fuzz_$target: FAILED, see $log; the input is in $regressions/" >&2
            tail -n 40 "$log" >&2
            status=1
        fi
        execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
        rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -n 1)
        peak=$(sed -n 's/^stat::peak_rss_mb: *//p' "$log" | tail -n 1)
        cov=$(grep -o 'cov: [0-9]*' "$log" | tail -n 1 || true)
        echo "fuzz_$target: ${execs:-?} executions, ${rate:-?} exec/s, corpus $(find "$corpus" -type f | wc -l) files," \
             "${cov:-cov: ?}, peak RSS ${peak:-?} MB"
    fi
    echo "== replay $target: seeds, regressions, grown corpus"
    if ! "$build/fuzz/fuzz_${target}_replay" "$root/fuzz/corpus/$target" "$regressions" "$corpus" 2>"$build/replay-$target.log"; then
        echo "replay $target: FAILED, see $build/replay-$target.log" >&2
        tail -n 20 "$build/replay-$target.log" >&2
        status=1
    fi
done
exit $status

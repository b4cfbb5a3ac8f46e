#!/usr/bin/env bash
# The judge held to its own rules, seen from the judge's side: plants each judge fault of
# scripts/mutants.txt (the JUDGE_ entries, in checks/ and properties/) in a scratch copy of the
# sources, builds `tilesweep check`, the mutant adapter and the judge's unit tests there, and runs
# the tests that hold the judge to its rules: the rule-breaker and variant ctests of
# adapters/CMakeLists.txt, the correct resolver through a pipe, and the checker's and the claims'
# unit tests. A fault is caught when one of them goes red. One row a fault: the tests that failed.
#
#   bash scripts/judge-faults.sh [NAME...]    the faults named (default: every JUDGE_ mutant)
#   TILESWEEP_JUDGE_TESTS=REGEX               the ctests to run (default: those above)
#   TILESWEEP_JUDGE_DIR=DIR                   the scratch copy and its build (default: build-judge-faults/)
#
# scripts/fault-table.sh runs the unit and property tests only, where a weakened judge still passes
# the correct resolver: these faults need the tests of this script. The copy holds the working
# tree's tracked files, so the checkout itself is never changed; one build serves every fault and
# is rebuilt incrementally. Run it under `nice` on a shared machine.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
dir=${TILESWEEP_JUDGE_DIR:-$root/build-judge-faults}
tests=${TILESWEEP_JUDGE_TESTS:-'adapters_check_(fails|passes)_|adapters_check_builtin_through_pipe|^FrameSafety\.|Claims\.'}
faults=("$@")
if [ ${#faults[@]} -eq 0 ]; then
    read -r -a faults <<<"$(sed -n 's/^\(JUDGE_[A-Z0-9_]*\) |||.*/\1/p' "$root/scripts/mutants.txt" | tr '\n' ' ')"
fi
src=$dir/main
build=$src/build
mkdir -p "$src"
# The tracked files of the working tree; only those that differ from the copy are written (with a
# new mtime), so the build is incremental and never trusts a stale object.
(cd "$root" && git ls-files -z) | python3 -c '
import filecmp, os, shutil, sys
root, dest = sys.argv[1:]
for name in sys.stdin.read().split("\0"):
    a, b = os.path.join(root, name), os.path.join(dest, name)
    if not name or not os.path.isfile(a):
        continue
    if not (os.path.isfile(b) and filecmp.cmp(a, b, shallow=False)):
        os.makedirs(os.path.dirname(b), exist_ok=True)
        shutil.copy(a, b)
' "$root" "$src"
cmake -S "$src" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DTILESWEEP_EXAMPLES_DIR="$root/../shared/examples" -DTILESWEEP_BUILD_BENCH=OFF \
    -DTILESWEEP_BUILD_AUDIT=OFF -DTILESWEEP_BUILD_SOAK=OFF -DTILESWEEP_BUILD_EXAMPLES=OFF \
    -DTILESWEEP_BUILD_FUZZ=OFF >/dev/null
targets=(tilesweep_cli tilesweep_mutant_adapter frame_safety_test claims_test)
# Applies (or with "restore", undoes) a mutant of the copy's scripts/mutants.txt in the copy.
mutate() { python3 "$root/scripts/mutate.py" "$src" "$1" "${2:-apply}"; }
echo "| fault | where | failing tests (caught when any) | seconds |"
echo "|---|---|---|---|"
for fault in "${faults[@]}"; do
    start=$SECONDS
    if ! where=$(mutate "$fault" 2>&1); then
        echo "| $fault | - | not applied: $where | - |"
        continue
    fi
    trap 'mutate "$fault" restore >/dev/null' EXIT
    built=0
    cmake --build "$build" --target "${targets[@]}" >"$build/judge-fault.log" 2>&1 || built=$?
    if [ "$built" -eq 0 ]; then
        ctest --test-dir "$build" -R "$tests" >"$build/judge-fault-tests.log" 2>&1 || true
        failed=$( (sed -n '/The following tests FAILED/,$p' "$build/judge-fault-tests.log" |
            grep -o '[0-9]* - [^ ]*' || true) | sed 's/^[0-9]* - //' | sort -u | tr '\n' ' ')
        echo "| $fault | $where | ${failed:-none: not caught} | $((SECONDS - start)) |"
    else
        echo "| $fault | $where | does not build | - |"
    fi
    mutate "$fault" restore >/dev/null
    trap - EXIT
done
# The unmutated sources again, so that the next run starts from a clean build.
cmake --build "$build" --target "${targets[@]}" >/dev/null 2>&1 || true

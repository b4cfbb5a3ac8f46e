#!/usr/bin/env bash
# Proof that the suite has teeth, and the one source of docs/fault-table.md: builds the library
# with one deliberate fault at a time (every fault listed in src/fault_injection.h), runs the
# README's test command on it (ctest over the unit and property tests, two seeds, CASES property
# cases a property) and writes which tests caught it, with the smallest shrunk counterexample.
#
#   bash scripts/fault-table.sh [CASES]            every fault; writes build/fault-table.md (CASES: 4000)
#   bash scripts/fault-table.sh --out docs [CASES] the same into docs/fault-table.md, the committed page
#   TILESWEEP_FAULTS="NAME ..." bash scripts/fault-table.sh [CASES]
#                                                  only those; prints the rows, writes no file
#   TILESWEEP_MUTANTS=1 bash scripts/fault-table.sh [CASES]
#                                                  the mutants of scripts/mutants.txt instead (or
#                                                  TILESWEEP_MUTANTS="NAME ..."): each applied to its
#                                                  file for the build only, then restored; prints rows
#                                                  (the JUDGE_ faults are scripts/judge-faults.sh's)
#
# Each fault gets its own build directory under build-faults/ (TILESWEEP_FAULT_DIR); ccache
# (installed here when missing) shares between them the objects of the targets the fault's
# definition does not reach, the property suite's among them: without it every fault rebuilds
# everything. The directories differ, so ccache is told not to hash them (CCACHE_NOHASHDIR: the
# debug information keeps the first build's directory). Run it under `nice` on a shared machine.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
export TILESWEEP_EXTRA_PACKAGES=ccache
export CCACHE_NOHASHDIR=1
source "$root/scripts/setup.sh"
tilesweep_setup_base
out_dir=$root/build
if [ "${1:-}" = --out ]; then
    out_dir=${2:?--out needs a directory}
    shift 2
fi
case $out_dir in /*) ;; *) out_dir=$PWD/$out_dir ;; esac
mkdir -p "$out_dir"
cases=${1:-4000}
listed=$(sed -n 's|^//   \([A-Z][A-Z0-9_]*\) .*|\1|p' "$root/src/fault_injection.h")
faults=(${TILESWEEP_FAULTS:-$listed})
mutants=${TILESWEEP_MUTANTS:-}
if [ -n "$mutants" ]; then
    # The judge's faults (JUDGE_*) need the rule-breaker tests: scripts/judge-faults.sh runs them.
    all=$(sed -n 's/^\([A-Z][A-Z0-9_]*\) |||.*/\1/p' "$root/scripts/mutants.txt" | grep -v '^JUDGE_')
    [ "$mutants" = 1 ] && mutants=$all
    faults=($mutants)
fi
# Applies (or with "restore", undoes) a mutant of scripts/mutants.txt in the working tree.
mutate() { python3 "$root/scripts/mutate.py" "$root" "$1" "${2:-apply}"; }
out=${TILESWEEP_FAULT_DIR:-$root/build-faults}
launcher=()
if command -v ccache >/dev/null; then
    launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
mkdir -p "$out"
started=$(date -u '+%-d %B %Y, %H:%M')
load_before=$(cut -d' ' -f1 /proc/loadavg)
commit=$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo "an unknown commit")
if [ -n "$(git -C "$root" status --porcelain --untracked-files=no 2>/dev/null)" ]; then
    commit="$commit with uncommitted changes"
fi
table=$(mktemp)
trap 'rm -f "$table"' EXIT
row() { echo "$1" | tee -a "$table"; }
row "| fault | where | caught by (failing tests) | smallest counterexample | seconds |"
row "|---|---|---|---|---|"
for fault in "${faults[@]}"; do
    where=$( (grep -lE "TILESWEEP_FAULT_$fault\b|TILESWEEP_FAULT\},$fault>" -r "$root/src" "$root/oracle" "$root/cmake" 2>/dev/null || true) |
        (grep -v fault_injection.h || true) | sed "s|$root/||" | sort | tr '\n' ' ')
    build="$out/$fault"
    define=$fault
    if [ -n "$mutants" ]; then
        define=""
        if ! where=$(mutate "$fault" 2>&1); then  # its text changed: the row says so
            row "| $fault | - | not applied: $where | - | - |"
            continue
        fi
        trap 'mutate "$fault" restore >/dev/null; rm -f "$table"' EXIT
    fi
    cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTILESWEEP_FAULT="$define" "${launcher[@]}" \
        -DTILESWEEP_BUILD_BENCH=OFF -DTILESWEEP_BUILD_CLI=OFF -DTILESWEEP_BUILD_AUDIT=OFF \
        -DTILESWEEP_BUILD_SOAK=OFF -DTILESWEEP_BUILD_ADAPTERS=OFF -DTILESWEEP_BUILD_EXAMPLES=OFF \
        -DTILESWEEP_BUILD_FUZZ=OFF >/dev/null 2>&1
    built=0
    cmake --build "$build" >"$build/build.log" 2>&1 || built=$?
    if [ -n "$mutants" ]; then
        mutate "$fault" restore >/dev/null
        trap 'rm -f "$table"' EXIT
    fi
    if [ "$built" -ne 0 ]; then
        row "| $fault | $where | does not build | - | - |"
        continue
    fi
    corpus="$build/corpus"
    rm -rf "$corpus"
    start=$SECONDS
    TILESWEEP_PROPERTY_CASES=$cases TILESWEEP_CORPUS_DIR="$corpus" \
        ctest --test-dir "$build" -L 'unit|property' --parallel "$(nproc)" >"$build/run.log" 2>&1 || true
    failed=$( (sed -n '/The following tests FAILED/,$p' "$build/run.log" | grep -o '[0-9]* - [^ ]*' || true) |
        sed 's/^[0-9]* - //; s/^Suite\/Property\.holds\///' | sort -u)
    count=$(echo "$failed" | grep -c . || true)
    caught="not caught"
    [ "$count" -gt 0 ] && caught="$count: $(echo "$failed" | tr '\n' ' ')"
    smallest=$(python3 - "$corpus" <<'PY'
import glob, json, os, sys
found = []
for path in glob.glob(os.path.join(sys.argv[1], "*.jsonl")):
    scene = json.loads(open(path).readline())
    rows = scene["map"]["rows"]
    columns = len(rows[0]) if rows else 0
    solid = sum(r.count("#") for r in rows)
    found.append((solid, columns * len(rows), len(scene["moves"]),
                  f"{columns}x{len(rows)} map, {solid} solid, {len(scene['moves'])} frame(s)"))
print(min(found)[3] if found else "-")
PY
)
    row "| $fault | $where | $caught | $smallest | $((SECONDS - start)) |"
done
if [ -z "${TILESWEEP_FAULTS:-}" ] && [ -z "$mutants" ]; then
    {
        echo "# Fault table"
        echo
        echo "Written by \`bash scripts/fault-table.sh --out docs $cases\` (do not edit by hand): the library built with"
        echo "each deliberate fault of src/fault_injection.h in turn, then the README's test command on it"
        echo "(ctest over the unit and property tests, two seeds, $cases property cases a property). A fault"
        echo "is caught when some test fails; the smallest counterexample is the smallest shrunk scene any"
        echo "property wrote. FMA builds for x86-64-v3 on x86-64 (cmake/warnings.cmake), where the"
        echo "instruction exists and -ffp-contract=fast can fuse."
        echo
        echo "This run: commit $commit, $started to $(date -u +%H:%M) UTC, on $(nproc) cores"
        echo "($(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1)), load average $load_before"
        echo "before and $(cut -d' ' -f1 /proc/loadavg) after; the seconds are each fault's ctest run."
        echo "The mutants of \`scripts/mutants.txt\` are not faults and are not in this table"
        echo "(\`TILESWEEP_MUTANTS=1 bash scripts/fault-table.sh\`)."
        echo
        cat "$table"
    } >"$out_dir/fault-table.md"
    echo "wrote $out_dir/fault-table.md"
fi

#!/usr/bin/env bash
# Where a long move's time goes: the instructions, conditional branches and mispredicted branches
# (callgrind's simulated predictor, --branch-sim=yes: a model, not the machine's) a frame spends in
# each phase of tilesweep::resolveMove on its prepared map and of the lean twin (Impl Twin), on the
# side-by-side scenarios Random30 and FloorAndWalls at 8 and 32 tiles a frame (speed arguments 16
# and 64), in float and double, counted by callgrind (bench/frame_instructions.cpp). Prints one
# Markdown table a scenario (phases by rows, tilesweep and the twin side by side), then tilesweep's
# instructions a frame by source file and phase, averaged over the scenarios.
#
#   bash scripts/phases.sh [FRAMES [FILTER]]   # FRAMES per scenario (default 16384); FILTER an
#                                              # extended regular expression on the scenario labels
#                                              # (default '^(Random30|FloorAndWalls)<(float|double)>/(16|64)$')
#
# Needs valgrind and binutils' addr2line (valgrind installed when missing) and a release tree
# with debug information, TILESWEEP_BUILD_DIR (default build/phase), configured and built here.
#
# How a cost finds its phase. The frame loop is inlined, so callgrind's functions say nothing; its
# self cost a source line does (--dump-line=yes; a call's inclusive cost is left out). The cost of
# each instruction (--dump-instr=yes) goes to the phase of the innermost frame of its inline chain
# (addr2line -i) that the table PHASES below maps to a phase: the helpers shared by several
# phases (tile edges, exact pair sums and compares, cell estimates, the standard library,
# intrinsics) map to none, and so take their caller's phase. Code of a lattice frame (the exact
# solver, its callgrind function named after LatticeFrame or solveOnLattice) is an exact fallback
# whatever its line; code outside the binary (libc) and chains that map to nothing are "other".
# The phases:
#   set-up    the range test and the checks of the input (range_admission.h, input_window.h,
#             validity.h), the frame's axes, ends, swept bounds and reciprocals (FastFrame's
#             constructor; the twin's StepFrame and each step's 1 / r);
#   walk      the broadphase: every cell range and the walk through the cells (firstCellAhead,
#             sweepBothAxesAlong, walkOneAxis, collectNear, listStartOverlaps, the secondary range
#             of FastFrame::secondaryCells, cellOf; the twin's FindHitsInPathOrder), with the reads
#             of the map (solidInMap, solid_block.h, free_move.h's test);
#   tile test the test of one tile, start overlaps included (axis_sweep.h's testTileInline,
#             FastFrame::testTile and screenTile, testAndRecord, heldOverlaps, sweepOneAxisNear;
#             the twin's testTile and slab);
#   exact     the exact arithmetic a filter hands on when it cannot decide (compareEqualProducts,
#             signOfSum, signOfPairProducts, the band of compareProducts on pairs,
#             contact_position.h's Remainder, the midpoint of roundTimeToFloat) and the lattice
#             (lattice.h, lattice_frame.h, wide_int.h);
#   rounding  the contract's final rounding (final_rounding.h, roundEnds, FastFrame's grid-line
#             test), the rounding of contact times (time_rounding.h) and of contact positions
#             (contact_position.h's estimates); the twin has none;
#   other     the entry points and their calls, recording hits (FrameLoop::add, the twin's
#             StepHits), the slide between the steps, writing the contacts and the result, and
#             the benchmark's loop (bench/).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
export TILESWEEP_EXTRA_PACKAGES=valgrind
source "$root/scripts/setup.sh"
tilesweep_setup_base
frames=${1:-16384}
filter=${2:-'^(Random30|FloorAndWalls)<(float|double)>/(16|64)$'}
build=$(realpath -m "${TILESWEEP_BUILD_DIR:-$root/build/phase}")
bin=$build/bench/tilesweep_frame_instructions
if [ ! -f "$build/CMakeCache.txt" ]; then
    (cd "$root" && cmake --preset release -B "$build" -DCMAKE_CXX_FLAGS=-g >/dev/null)
fi
cmake --build "$build" -j1 --target tilesweep_frame_instructions >/dev/null
dumps=$(mktemp -d)
trap 'rm -rf "$dumps"' EXIT
# The scenarios' labels, from one frame of each outside valgrind; then one run under callgrind a
# label (the program selects scenarios by substring: the dumps of other labels are dropped).
mapfile -t labels < <("$bin" 1 | awk '$1 == "Tilesweep" { print $2 }' | grep -E -- "$filter" || true)
if ((${#labels[@]} == 0)); then
    echo "phases: no scenario label matches '$filter'" >&2
    exit 2
fi
for label in "${labels[@]}"; do
    valgrind --tool=callgrind --dump-instr=yes --dump-line=yes --branch-sim=yes --compress-strings=no \
        --compress-pos=no --callgrind-out-file="$dumps/out.%p" "$bin" "$frames" "$label" \
        >/dev/null 2>"$dumps/valgrind.log" || { tail -n 20 "$dumps/valgrind.log" >&2; exit 1; }
done
commit=$(git -C "$root" rev-parse --short HEAD)
if [ -n "$(git -C "$root" status --porcelain --untracked-files=no -- src include baselines)" ]; then
    commit="$commit (with uncommitted changes to src/, include/ or baselines/)"
fi
echo "Made by \`bash scripts/phases.sh $frames '$filter'\` on commit $commit, TILESWEEP_BUILD_DIR=${build#"$root"/}."
echo
python3 - "$root" "$bin" "$dumps" "${labels[@]}" <<'PY'
import collections, glob, os, re, subprocess, sys

root, binary, dumps, labels = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
PHASE_NAMES = ["set-up", "walk", "tile test", "exact", "rounding", "other"]
CALLER = None  # a helper: its cost takes the phase of the code it is inlined into

# Each file's phases, by line: an entry (text, phase) gives the phase from the first line that
# holds `text` after the previous entry's line (the first entry's text is None: line 1). A file
# not listed is "other" (bench/, the entry points), or CALLER when it lies outside the project.
PHASES = {
    "src/frame_loop.h": [
        (None, "other"),  # run: the two steps, the slide, the result
        ("void add(Hits& hits", "other"),  # recording a hit
        ("bool roundEnds(", "rounding"),
        ("bool finishStep(Hits& hits)", "other"),  # contact times written, sorted; placeContacts
        ("bool overlapsCellAtStart(", "tile test"),
        ("std::int32_t listStartOverlaps(", "walk"),  # firstCellAhead, stepEdges, sweepBothAxesAlong, solidInMap
        ("bool testAndRecord(std::int64_t i", "tile test"),  # testOneWayAndRecord, heldOverlaps
        ("void sweepOneAxis(int a", "walk"),
        ("void sweepOneAxisNear(", "tile test"),  # every listed cell's one-axis test
        ("void walkOneAxis(", "walk"),  # skipCellsEnteredBefore, collectNear, listSolidCells
        ("std::int32_t testNear(", "tile test"),
        ("std::int32_t startOverlapsOfNear(", "walk"),
    ],
    "src/fast_frame.h": [
        (None, "set-up"),  # the constructor
        ("bool linesClear(int a)", "rounding"),
        ("bool refined() const", CALLER),  # accessors, edge, nextEdge, cellOf, magnitude
        ("CellRange startCells(int a)", "walk"),  # startCells, sweptCells
        ("Coord nearEdge(int a)", CALLER),  # box edges, touchLow, touchHigh
        ("std::int64_t firstCellNotBefore(", "walk"),
        ("static Time zeroTime()", CALLER),  # compareTimes, certainlyLater
        ("int primaryAxis() const", "walk"),  # prepareWalk, secondaryCells
        ("TileTest<Coord, double> testTile(", "tile test"),
        ("bool roundTime(const Time& t", "rounding"),  # positionAt, final rounding, gridLineAhead
        ("static bool screenTile(", "tile test"),
        ("static bool lineFree(", "rounding"),  # linesClearOf
        ("static double cellMargin(", CALLER),
        ("lanesOf(const Vec2<T>& v)", "set-up"),  # setUpOnLanes, makeAxis
    ],
    "src/fast_axis.h": [(None, CALLER), ("bool hasLineIn(", "rounding")],
    "src/cell_range.h": [(None, CALLER)],
    "src/pair_arithmetic.h": [(None, CALLER)],
    "src/exact_double.h": [
        (None, CALLER),  # productError: the filters' and refinements' alike
        ("int compareEqualProducts(", "exact"),
        ("int compareProducts(double a", CALLER),
        ("// Both products exactly zero", "exact"),
        ("struct ExactSum {", CALLER),  # twoSum, compare
        ("inline int signOfSum(", "exact"),  # signOfPairProducts
        ("int pairProductFilter(", CALLER),
        ("// Inside the band", "exact"),
        ("T stepBy(T v, int steps)", CALLER),  # steps and roundToFloat, for the roundings
    ],
    "src/axis_sweep.h": [(None, CALLER), ("enum class TileVerdict", "tile test")],
    "src/contact_position.h": [
        (None, "rounding"),
        ("struct Remainder {", "exact"),  # signAgainst, remainderOf
        ("inline double lowPartOf(double)", "rounding"),  # the estimates
        ("T c = static_cast<T>(x0 + q * d);", "exact"),  # roundPositionAtTime's exact test
    ],
    "src/time_rounding.h": [
        (None, "rounding"),
        ("// q is a midpoint", "exact"),
        ("inline bool roundTimeToDouble(", "rounding"),  # its filter; signOfSum inside it is exact
    ],
    "src/final_rounding.h": [(None, "rounding")],
    "src/range_admission.h": [(None, "set-up")],
    "src/input_window.h": [(None, "set-up")],
    "src/validity.h": [(None, "set-up")],
    "src/frame_input.h": [(None, "set-up")],
    "src/free_move.h": [(None, "walk"), ("inline bool solveFreeMove(", "other")],
    "src/solid_block.h": [(None, "walk")],
    "src/frame_paths.h": [
        (None, "other"),  # solveFastOn, solveMovingFrame: the calls between the phases
        ("ResolveResult<T> solveOnLatticeAs(", "exact"),
        ("inline ResolveResult<T> solveMovingFrame(", "other"),
    ],
    "src/lattice.h": [(None, "exact")],
    "src/lattice_frame.h": [(None, "exact")],
    "src/wide_int.h": [(None, "exact")],
    "src/bit_ops.h": [(None, CALLER)],
    "src/proof_constants.h": [(None, CALLER)],
    "include/tilesweep/tile_map.h": [(None, CALLER)],  # isSolid: the walk's reads, the tie rule's
    "include/tilesweep/math.h": [(None, CALLER)],
    "include/tilesweep/resolve.h": [(None, CALLER)],
    "include/tilesweep/mover.h": [(None, CALLER)],
    "baselines/include/tilesweep/baselines/twin_resolve.h": [
        (None, "set-up"),  # reciprocalOf, StepFrame, startStep (1 / r once a step)
        ("T timeOf(int a, T distance)", CALLER),
        ("Slab<T> slab(int a", "tile test"),
        ("std::int64_t cellOf(int a, T v)", "walk"),  # cellBefore
        ("T edge(int a, std::int64_t k)", CALLER),
        ("struct StepHits {", "other"),
        ("inline void testTile(", "tile test"),
        ("inline std::int32_t listStartOverlaps(", "walk"),
        ("if (!(f.lo[0] < f.edge(0, i + 1)", "tile test"),
        ("if (count < capacity) store[count]", "walk"),
        ("inline ResolveResult<T> resolveFrame(", "set-up"),  # the StepFrame
        ("result.startOverlapCount = listStartOverlaps(", "other"),  # the steps, the slide, the result
        ("struct FindHitsInPathOrder {", "walk"),
        ("}  // namespace detail", "other"),
    ],
}


def line_phases(path, entries):
    """The phase of each line of `path` (index 0 unused), from its PHASES entries."""
    lines = open(os.path.join(root, path)).read().split("\n")
    starts, at = [], 0
    for text, phase in entries:
        if text is not None:
            found = next((k for k in range(at, len(lines)) if text in lines[k]), None)
            if found is None:
                sys.exit(f"phases: {path} has no line with {text!r} after line {at}: update PHASES")
            at = found
        starts.append((at + 1, phase))
    table = [None] * (len(lines) + 2)
    for (first, phase), (end, _) in zip(starts, starts[1:] + [(len(table), None)]):
        table[first:end] = [phase] * (end - first)
    return table


tables = {path: line_phases(path, entries) for path, entries in PHASES.items()}


def relative(path):
    return path[len(root) + 1 :] if path.startswith(root + "/") else None


def phase_of_frame(path, line):
    """A frame's phase, or CALLER."""
    rel = relative(path)
    if rel is None:
        return CALLER
    if rel in tables:
        table = tables[rel]
        return table[line] if 0 < line < len(table) else CALLER
    return "other"


def read_dump(path):
    """(impl, label, frames, costs, totals) of a dump of tilesweep or the twin on a selected label,
    else None. costs: [Ir, Bc, Bcm] of each (object, address, file, line, in a lattice function),
    self costs alone (the line after calls= is the call's inclusive cost); totals: the summary's."""
    name = events = totals = obj = fn = src = None
    costs = collections.defaultdict(lambda: [0, 0, 0])
    after_call = False
    for line in open(path):
        if line.startswith("desc: Trigger: Client Request: "):
            name = line[len("desc: Trigger: Client Request: ") :].split()
            if len(name) != 3 or name[0] not in ("Tilesweep", "Twin") or name[1] not in labels:
                return None
        elif line.startswith("events:"):
            events = line.split()[1:]
        elif line.startswith(("summary:", "totals:")):
            summary = dict(zip(events, map(int, line.split()[1:])))
            totals = [summary.get(e, 0) for e in ("Ir", "Bc", "Bcm")]
        elif line.startswith("ob="):
            obj = line[3:].strip()
        elif line.startswith("fn="):
            fn = line[3:].strip()
        elif line.startswith(("fl=", "fi=", "fe=")):
            src = line[3:].strip()
        elif line.startswith("calls="):
            after_call = True
        elif line.startswith("0x"):
            if after_call:
                after_call = False
                continue
            fields = line.split()
            values = dict(zip(events, map(int, fields[2:])))  # trailing zeros are left out
            key = (obj, int(fields[0], 16), src, int(fields[1]), any(n in (fn or "") for n in ("LatticeFrame", "solveOnLattice")))
            for k, event in enumerate(("Ir", "Bc", "Bcm")):
                costs[key][k] += values.get(event, 0)
    return None if name is None else (name[0], name[1], int(name[2]), costs, totals)


runs = {}
for path in glob.glob(os.path.join(dumps, "out.*")):
    dump = read_dump(path)
    if dump:
        runs[dump[:2]] = dump[2:]
missing = {(i, l) for i in ("Tilesweep", "Twin") for l in labels} - runs.keys()
if missing:
    sys.exit(f"phases: no callgrind dump for {sorted(missing)} (see valgrind's log)")

# Inline chains of the binary's addresses, innermost frame first.
addresses = sorted({key[1] for _, costs, _ in runs.values() for key in costs if key[0] == binary})
output = subprocess.run(["addr2line", "-a", "-i", "-e", binary], input="\n".join(map(hex, addresses)),
                        capture_output=True, text=True, check=True).stdout
chains, chain = {}, None
for line in output.splitlines():
    if line.startswith("0x"):
        chain = chains.setdefault(int(line, 16), [])
    elif re.match(r".*:\d+", line):
        path, number = re.match(r"(.*):(\d+)", line).groups()
        chain.append((path, int(number)))


def phase_of(key):
    obj, address, _, _, lattice = key
    if obj != binary:
        return "other"
    if lattice:
        return "exact"
    for path, line in chains.get(address, []):
        phase = phase_of_frame(path, line)
        if phase is not CALLER:
            return phase
    return "other"


def file_of(key):
    path = key[2] or "???"
    return relative(path) or "(system) " + os.path.basename(path)


def per_frame_by_phase(impl, label, by_file=None):
    """{phase: [Ir, Bc, Bcm] a frame}; checks that the self costs add up to the dump's totals."""
    frames, costs, totals = runs[(impl, label)]
    phases = {p: [0, 0, 0] for p in PHASE_NAMES}
    for key, cost in costs.items():
        phase = phase_of(key)
        for k in range(3):
            phases[phase][k] += cost[k]
        if by_file is not None:
            by_file[file_of(key)][phase] += cost[0] / frames / len(labels)
    for k, event in enumerate(("Ir", "Bc", "Bcm")):
        counted = sum(phases[p][k] for p in PHASE_NAMES)
        if abs(counted - totals[k]) > 0.001 * max(totals[k], 1):
            sys.exit(f"phases: {impl} {label}: the self costs of {event} add up to {counted}, the dump's total is {totals[k]}")
    return {p: [v / frames for v in phases[p]] for p in PHASE_NAMES}


by_file = collections.defaultdict(collections.Counter)
for label in labels:
    speed = f": {int(label.rsplit('/', 1)[1]) / 2:g} tiles a frame" if "/" in label else ""
    print(f"### {label}{speed}\n")
    print("| phase | tilesweep instr | cond. branches | mispredicted | share "
          "| twin instr | cond. branches | mispredicted | share | tilesweep - twin instr |")
    print("|---|" + "---:|" * 9)
    ours, twin = per_frame_by_phase("Tilesweep", label, by_file), per_frame_by_phase("Twin", label)
    for table in (ours, twin):
        table["**total**"] = [sum(table[p][k] for p in PHASE_NAMES) for k in range(3)]
    for p in PHASE_NAMES + ["**total**"]:
        cells = [p]
        for table in (ours, twin):
            ir, bc, bcm = table[p]
            cells += [f"{ir:,.0f}", f"{bc:,.0f}", f"{bcm:,.1f}", f"{100 * ir / table['**total**'][0]:.0f}%"]
        cells.append(f"{ours[p][0] - twin[p][0]:+,.0f}")
        print("| " + " | ".join(cells) + " |")
    print()
print("Each dump's self costs (Ir, Bc, Bcm) add up to its total (callgrind's summary line) within 0.1%.\n")

print("### tilesweep by source file: instructions a frame, by phase, mean over the scenarios above\n")
print("| file | instr | " + " | ".join(PHASE_NAMES) + " |")
print("|---|---:|" + "---:|" * len(PHASE_NAMES))
small = collections.Counter()
for path in [p for p in by_file if sum(by_file[p].values()) < 1]:
    small.update(by_file.pop(path))
by_file["(files under 1 a frame)"] = small
for path, per in sorted(by_file.items(), key=lambda item: -sum(item[1].values())):
    print(f"| {path} | {sum(per.values()):,.0f} | " + " | ".join(f"{per[p]:,.0f}" if per[p] >= 0.5 else "" for p in PHASE_NAMES) + " |")
print("\nA shared helper's instructions (a file of helpers, the standard library, intrinsics) count in the phase"
      " of the code they are inlined into: scripts/phases.sh says how.")
PY
stale=$(find "$root/src" "$root/include" "$root/baselines" -newer "$bin" -type f | head -3)
if [ -n "$stale" ]; then
    echo "phases: sources changed during the run (${stale//$'\n'/, }): the line mapping may not match the binary" >&2
fi

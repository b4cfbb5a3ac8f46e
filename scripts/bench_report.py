#!/usr/bin/python3
"""Turns one run of the benchmark suite into docs/bench/bench.md and docs/bench/pareto.svg.

Reads the Google Benchmark JSON written by scripts/bench.sh (the median aggregates of repeated
runs, CPU time in ns per item) and the audit's build/audit/report.json (every implementation's
error figures against the exact reference). Writes:

  bench.md    the medians of every benchmark, the performance targets as ratios computed from
              the same run (met or missed, and by how much), the machine and the load it ran under;
  pareto.svg  run time per frame (log scale) against the share of audit scenes whose decisions
              differ from the exact reference, one labelled point per implementation.

The chart is drawn by scripts/plots.py (Debian's python3-matplotlib), the one way every chart of
the project is drawn.

    /usr/bin/python3 scripts/bench_report.py --results docs/bench/results-HOST.json \\
        [--machine docs/bench/machine-HOST.json] [--audit build/audit/report.json] \\
        [--out-dir docs/bench]
"""

import argparse
import json
import os
import statistics
import sys

# --------------------------------------------------------------------------------------------
# Reading the benchmark results

UNIT_TO_NS = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}


class Results:
    """Median CPU (and real) time per item, in ns, and the CPU-time spread, per benchmark."""

    def __init__(self, path):
        with open(path, encoding="utf-8") as f:
            data = json.load(f)
        self.context = data.get("context", {})
        self.order = []          # run names, in the order the suite ran them
        self.cpu = {}            # run name -> median cpu ns per item
        self.real = {}           # run name -> median real ns per item
        self.cv = {}             # run name -> coefficient of variation of cpu time (fraction)
        self.repetitions = {}    # run name -> repetitions
        iterations = {}          # run name -> [(cpu ns, real ns)] when no aggregates are there
        for b in data.get("benchmarks", []):
            name = b.get("run_name", b["name"])
            if b.get("error_occurred"):
                continue
            if name not in self.order:
                self.order.append(name)
            scale = UNIT_TO_NS.get(b.get("time_unit", "ns"), 1.0)
            if b.get("run_type") == "aggregate":
                kind = b.get("aggregate_name")
                if kind == "median":
                    self.cpu[name] = b["cpu_time"] * scale
                    self.real[name] = b["real_time"] * scale
                    self.repetitions[name] = b.get("repetitions", 0)
                elif kind == "cv":
                    self.cv[name] = b["cpu_time"]
            else:
                iterations.setdefault(name, []).append((b["cpu_time"] * scale, b["real_time"] * scale))
        # A run without --benchmark_repetitions has no aggregates: take the median of the runs.
        for name, runs in iterations.items():
            if name not in self.cpu:
                self.cpu[name] = statistics.median(r[0] for r in runs)
                self.real[name] = statistics.median(r[1] for r in runs)
                self.repetitions[name] = len(runs)

    def get(self, name):
        return self.cpu.get(name)


# --------------------------------------------------------------------------------------------
# What each benchmark measures, and how its names map to the audit's implementations

def speed_of(arg):
    """Benchmark argument -> tiles per frame (the argument divided by 2)."""
    v = int(arg) / 2
    return f"{v:g}"


def describe(name):
    """A short description of one benchmark run name."""
    base, _, args = name.partition("/")
    args = args.split("/") if args else []
    scalar = "double" if "<double>" in base else "float"
    if base.startswith("BM_ResolveMove_Random30"):
        return f"production resolve, {scalar}, 256² map 30% solid, {speed_of(args[0])} tiles/frame"
    if base.startswith("BM_ResolveMove_FloorAndWalls"):
        return f"production resolve, {scalar}, 256² floors and walls, {speed_of(args[0])} tiles/frame"
    if base.startswith("BM_ResolveMove_Platforms"):
        return (f"production resolve, {scalar}, floors and walls with one-way platforms, "
                f"{speed_of(args[0])} tiles/frame")
    if base.startswith("BM_ResolveMove_MapSize"):
        return f"production resolve, float, {args[0]}² map 30% solid, 8 tiles/frame"
    if base.startswith("BM_BruteForce_EveryTile"):
        return f"every solid tile of a {args[0]}² map swept (float), 8 tiles/frame"
    if base.startswith("BM_SeedResolve_Random30"):
        return f"seed algorithm, {scalar}, 256² map 30% solid, {speed_of(args[0])} tiles/frame"
    if base.startswith("BM_SubstepFloat_Random30"):
        return f"float substeps N={args[1]}, 64² map 30% solid, {speed_of(args[0])} tiles/frame"
    if base.startswith("BM_ExactReference_Random30"):
        return f"exact reference (GMP), 64² map 30% solid, {speed_of(args[0])} tiles/frame"
    if base.startswith("BM_SweepBox_Pairs"):
        return f"one box against one tile (sweepBox), {scalar}, per pair"
    if base.startswith("BM_Box2D_TimeOfImpact_Pairs"):
        return "Box2D b2TimeOfImpact, float, the same pairs, per pair"
    # Side by side on 65,536 pre-generated frames per scenario (bench/frame_scenarios.h).
    impls = {"BM_Tilesweep_": "tilesweep", "BM_TilesweepView_": "tilesweep on the bare map view",
             "BM_Twin_": "inexact twin", "BM_TwinDividing_": "inexact twin dividing in its tile test",
             "BM_TwinLibm_": "inexact twin with libm calls", "BM_Grid_": "swept-bounds grid"}
    for prefix, impl in impls.items():
        if base.startswith(prefix):
            scenario = base[len(prefix):].split("<")[0]
            where = {"Random30": "256² map 30% solid", "FloorAndWalls": "256² floors and walls",
                     "FarRandom30": "256² map 30% solid at origin 2^20", "FreeFlight": "empty 256² map",
                     "RestingOnFloor": "box resting on a floor, walking, one frame of gravity",
                     "ZeroMove": "zero move, 256² map 30% solid"}.get(scenario, scenario)
            speed = f", {speed_of(args[0])} tiles/frame" if args else ""
            return f"{impl}, {scalar}, {where}{speed}"
    return ""


# Pareto points: audit implementation name -> (benchmark at 8 tiles/frame, benchmarks at every
# speed for the range bar, label, style group). The exact reference is not an audit row: it is
# what the audit measures against, so its error is 0 by definition.
SPEED_ARGS = ("1", "4", "16", "64")
IMPLEMENTATIONS = [
    ("core-float", "BM_ResolveMove_Random30<float>/16",
     [f"BM_ResolveMove_Random30<float>/{a}" for a in SPEED_ARGS], "production float", "production"),
    ("core-double", "BM_ResolveMove_Random30<double>/16",
     [f"BM_ResolveMove_Random30<double>/{a}" for a in SPEED_ARGS], "production double", "production"),
    ("seed-float", "BM_SeedResolve_Random30<float>/16",
     [f"BM_SeedResolve_Random30<float>/{a}" for a in SPEED_ARGS], "seed float", "seed"),
    ("seed-double", "BM_SeedResolve_Random30<double>/16",
     [f"BM_SeedResolve_Random30<double>/{a}" for a in SPEED_ARGS], "seed double", "seed"),
    ("substep4-float", "BM_SubstepFloat_Random30/16/4",
     [f"BM_SubstepFloat_Random30/{a}/4" for a in SPEED_ARGS], "substep float N=4", "substep"),
    ("substep16-float", "BM_SubstepFloat_Random30/16/16",
     [f"BM_SubstepFloat_Random30/{a}/16" for a in SPEED_ARGS], "substep float N=16", "substep"),
    ("substep256-float", "BM_SubstepFloat_Random30/16/256",
     [f"BM_SubstepFloat_Random30/{a}/256" for a in SPEED_ARGS], "substep float N=256", "substep"),
    ("exact-reference", "BM_ExactReference_Random30/16",
     ["BM_ExactReference_Random30/1", "BM_ExactReference_Random30/16"], "exact reference (GMP)", "exact"),
]


# --------------------------------------------------------------------------------------------
# Reading the audit

class Audit:
    """Per implementation, failures summed over every family the audit ran for its scalar."""

    def __init__(self, path):
        with open(path, encoding="utf-8") as f:
            data = json.load(f)
        self.seed = data.get("seed")
        self.cases = data.get("cases_per_family")
        self.command = data.get("command", "")
        self.production_clean = data.get("production_clean")
        self.rows = {}
        for impl in data.get("implementations", []):
            fams = impl.get("families", {})
            scenes = sum(f.get("scenes", 0) for f in fams.values())

            def share(figure):
                fails = sum(f.get("failures", {}).get(figure, 0) for f in fams.values())
                return 100.0 * fails / scenes if scenes else float("nan")

            self.rows[impl["name"]] = {
                "scenes": scenes,
                "families": len(fams),
                "decision": share("decision"),
                "tunnel": share("tunnel"),
                "inside": share("inside"),
                "inexact": share("inexact"),
            }

    def row(self, name):
        if name == "exact-reference":
            return {"scenes": 0, "families": 0, "decision": 0.0, "tunnel": 0.0, "inside": 0.0,
                    "inexact": 0.0, "reference": True}
        return self.rows.get(name)


# --------------------------------------------------------------------------------------------
# Formatting

def fmt_ns(ns):
    if ns is None:
        return "not run"
    if ns >= 1e6:
        return f"{ns / 1e6:.3g} ms"
    if ns >= 1e3:
        return f"{ns / 1e3:.3g} µs"
    return f"{ns:.3g} ns"


def fmt_num(ns):
    """ns with thousands separators, for the table (three significant digits at most)."""
    if ns is None:
        return "not run"
    if ns >= 100:
        return f"{round(ns):,}"
    return f"{ns:.3g}"


def pct(v):
    """A share in percent; exactly 0 is written 0."""
    return "0" if v == 0 else f"{v:.1f}%"


def fmt_ratio(r):
    if r is None:
        return "—"
    return f"{r:,.0f}x" if r >= 100 else f"{r:.2f}x"


def ratio(results, num, den):
    a, b = results.get(num), results.get(den)
    if a is None or b is None or b == 0:
        return None
    return a / b


def verdict_at_most(r, bound):
    """Status text for a target 'ratio <= bound'."""
    if r is None:
        return "not run", "not measured: a benchmark it needs did not run"
    if r <= bound:
        return "met", f"met, {100 * (1 - r / bound):.0f}% under the {bound:g}x bound"
    return "missed", f"**missed** by {100 * (r / bound - 1):.0f}% ({r:.2f}x against ≤ {bound:g}x)"


def verdict_at_least(r, bound):
    """Status text for a target 'ratio >= bound'."""
    if r is None:
        return "not run", "not measured: a benchmark it needs did not run"
    if r >= bound:
        return "met", f"met, {100 * (r / bound - 1):.0f}% above the {bound:g}x floor"
    return "missed", (f"**missed**: {r:.2f}x is {100 * (1 - r / bound):.0f}% short of ≥ {bound:g}x "
                      f"(the ratio would have to grow {bound / r:.1f}x)")


# --------------------------------------------------------------------------------------------
# bench.md

def write_markdown(path, results, audit, machine, results_path, audit_path, out_dir):
    ctx = results.context
    lines = []
    add = lines.append
    reps = sorted(set(results.repetitions.values()))
    add("# tilesweep benchmarks")
    add("")
    add("Medians of repeated runs of `bench/resolve_bench.cpp` (Google Benchmark), **CPU time per "
        "item** (one frame, one pair), and the performance targets (run time against speed and map "
        "size, against a brute force, Box2D and the inexact twin; the exact reference's rate), "
        "computed as ratios from this one run. Written by `scripts/bench_report.py` from "
        f"`{os.path.relpath(results_path, os.path.dirname(path))}` and the audit's "
        f"`{os.path.relpath(audit_path, os.path.dirname(path))}`; regenerate both with "
        "`bash scripts/bench.sh`.")
    add("")
    add("## Machine and run")
    add("")
    cpu = machine.get("cpu_model") or "unknown"
    nproc = machine.get("nproc") or str(ctx.get("num_cpus", "?"))
    add(f"- host `{machine.get('host') or ctx.get('host_name', '?')}`: {cpu}, {nproc} logical CPUs "
        f"(`nproc`), {ctx.get('mhz_per_cpu', '?')} MHz as Google Benchmark reads it, CPU scaling "
        f"{'on' if ctx.get('cpu_scaling_enabled') else 'off'}")
    if machine.get("compiler"):
        flags = machine.get("cxx_flags_release", "")
        add(f"- compiler: {machine['compiler']}; build type {machine.get('build_type') or 'Release'}"
            + (f" (`{flags}`)" if flags else ""))
    add(f"- run started {machine.get('started_utc') or ctx.get('date', '?')}, "
        f"{', '.join(str(r) for r in reps) or '?'} repetitions per benchmark"
        + (f": `{machine['command']}`" if machine.get("command") else "")
        + (f", source at commit {machine['commit']}" if machine.get("commit") else ""))
    lb = machine.get("loadavg_before")
    la = machine.get("loadavg_after")
    if lb or la:
        add(f"- load average (`/proc/loadavg`): before `{lb or '?'}`, after `{la or '?'}`")
    elif ctx.get("load_avg"):
        add(f"- load average at the start (Google Benchmark): {', '.join(f'{x:.2f}' for x in ctx['load_avg'])}")
    try:
        load1 = float((lb or "").split()[0])
        cores = int(nproc)
        if load1 > 0.5 * cores:
            add(f"- **the machine was busy** (load {load1:.1f} on {cores} CPUs): other jobs shared "
                "the cores, so wall-clock times are inflated (the table gives CPU time, which "
                "excludes time spent descheduled, but caches and the memory bus were shared). "
                "Read the ratios, which compare runs under the same conditions, rather than the "
                "absolute figures; rerun on an idle machine for absolute numbers.")
    except (ValueError, IndexError):
        pass
    if ctx.get("library_build_type") == "debug":
        add("- Google Benchmark prints *Library was built as DEBUG*: that is the distribution's "
            "`libbenchmark` itself (how it was compiled), not tilesweep, which is built in Release; "
            "it affects only the measuring loop's own overhead, equally for every benchmark.")
    add("")

    # --- medians
    add("## Medians")
    add("")
    add("Speeds are in tiles per frame (the benchmark argument divided by 2); boxes are 12x12 "
        "on 16x16 tiles, 512 fixed-seed scenes per benchmark (65,536 pre-generated frames for the "
        "side-by-side `BM_Tilesweep_`/`BM_Twin_`/`BM_Grid_` ones), cycled. `cv` is the coefficient of "
        "variation of the CPU time across the repetitions.")
    add("")
    add("| benchmark | what | CPU ns/item (median) | real ns/item (median) | cv |")
    add("|---|---|---:|---:|---:|")
    for name in results.order:
        if name not in results.cpu:
            continue
        cv = results.cv.get(name)
        add(f"| `{name}` | {describe(name)} | {fmt_num(results.cpu[name])} | "
            f"{fmt_num(results.real.get(name))} | {'' if cv is None else f'{100 * cv:.1f}%'} |")
    add("")

    # --- targets
    add("## Targets, as ratios from this run")
    add("")
    add("| target | ratio | figures (median CPU time) | verdict |")
    add("|---|---:|---|---|")
    summary = []

    # (a) speed does not blow up
    for level in ("Random30", "FloorAndWalls"):
        for scalar in ("float", "double"):
            fast = f"BM_ResolveMove_{level}<{scalar}>/64"
            slow = f"BM_ResolveMove_{level}<{scalar}>/1"
            r = ratio(results, fast, slow)
            status, text = verdict_at_most(r, 2.0)
            level_text = "256² 30% random" if level == "Random30" else "256² floors and walls"
            add(f"| (a) speed does not blow up: 32 over 0.5 tiles/frame, {level_text}, {scalar} "
                f"| {fmt_ratio(r)} | {fmt_ns(results.get(fast))} / {fmt_ns(results.get(slow))} "
                f"| ≤ 2x: {text} |")
            summary.append((f"(a) 32 over 0.5 tiles/frame, {level_text}, {scalar}, ≤ 2x", status, fmt_ratio(r) if r else None))

    # (b) map size costs nothing
    r = ratio(results, "BM_ResolveMove_MapSize/4096", "BM_ResolveMove_MapSize/64")
    status, text = verdict_at_most(r, 1.1)
    r1024 = ratio(results, "BM_ResolveMove_MapSize/1024", "BM_ResolveMove_MapSize/64")
    add(f"| (b) map size costs nothing: 4096² over 64², 8 tiles/frame, float | {fmt_ratio(r)} | "
        f"{fmt_ns(results.get('BM_ResolveMove_MapSize/4096'))} / "
        f"{fmt_ns(results.get('BM_ResolveMove_MapSize/64'))} (1024²: {fmt_ratio(r1024)}) | ≤ 1.1x: {text} |")
    summary.append(("(b) 4096² over 64², ≤ 1.1x", status, fmt_ratio(r) if r else None))

    # (c) broadphase vs brute force
    r = ratio(results, "BM_BruteForce_EveryTile/256", "BM_ResolveMove_Random30<float>/16")
    r64 = ratio(results, "BM_BruteForce_EveryTile/64", "BM_ResolveMove_MapSize/64")
    add(f"| (c) what the broadphase buys: every solid tile of 256² swept, over the resolver's whole "
        f"frame, 8 tiles/frame, float | {fmt_ratio(r)} | "
        f"{fmt_ns(results.get('BM_BruteForce_EveryTile/256'))} / "
        f"{fmt_ns(results.get('BM_ResolveMove_Random30<float>/16'))} (on 64²: {fmt_ratio(r64)}) | "
        f"no numeric target; the brute force is the narrow phase alone, without the frame's slide "
        f"or rounding, so this understates the gain |")
    summary.append(("(c) brute force over the resolver, 256²", "no target", f"the broadphase buys {fmt_ratio(r)}" if r else None))

    # (d) single sweep vs Box2D
    r = ratio(results, "BM_Box2D_TimeOfImpact_Pairs", "BM_SweepBox_Pairs<float>")
    rd = ratio(results, "BM_Box2D_TimeOfImpact_Pairs", "BM_SweepBox_Pairs<double>")
    status, text = verdict_at_least(r, 10.0)
    if results.get("BM_Box2D_TimeOfImpact_Pairs") is None:
        text = ("not measured: `BM_Box2D_TimeOfImpact_Pairs` did not run (filtered out, or Box2D, "
                "Debian's `libbox2d-dev`, was not found at build time and it was not built)")
    add(f"| (d) one box-against-tile sweep vs Box2D: `b2TimeOfImpact` over `sweepBox<float>`, same "
        f"pairs | {fmt_ratio(r)} | {fmt_ns(results.get('BM_Box2D_TimeOfImpact_Pairs'))} / "
        f"{fmt_ns(results.get('BM_SweepBox_Pairs<float>'))} (over `sweepBox<double>`: {fmt_ratio(rd)}) "
        f"| ≥ 10x: {text}. The target is set against Box2D's shape cast (`b2ShapeCast`); the suite "
        f"measures `b2TimeOfImpact` (its swept-shape time of impact), which stops short of contact "
        f"by its target separation |")
    summary.append(("(d) Box2D over sweepBox<float>, ≥ 10x", status, fmt_ratio(r) if r else None))

    # (e) exact reference cost
    e1 = results.get("BM_ExactReference_Random30/1")
    e16 = results.get("BM_ExactReference_Random30/16")
    solid_estimate = round(0.3 * 64 * 64)
    if e1 is not None or e16 is not None:
        per_frame = " and ".join(
            f"{fmt_ns(v)} per frame ({1e9 / v:,.0f} frames/s per core) at {s} tiles/frame"
            for v, s in ((e1, "0.5"), (e16, "8")) if v is not None)
        worst = max(v for v in (e1, e16) if v is not None)
        per_tile = worst / solid_estimate
        add(f"| (e) exact reference cost: one frame on a 64² map, 30% solid (every solid tile "
            f"tested, about {solid_estimate:,}) | — | {per_frame} | target ≥ 100k single-tile "
            f"scenes/s per core: **not measured as stated** (this benchmark's frames test about "
            f"{solid_estimate:,} tiles each, not one). Spread over its tiles, the 8 tiles/frame "
            f"case costs {fmt_ns(per_tile)} per solid tile, {1e9 / per_tile:,.0f} tiles/s; a "
            f"single-tile scene also pays the frame's fixed costs, so it runs slower than that "
            f"share. A guide, not a measurement: `oracle/README.md` gives about 8 µs per one-frame "
            f"single-tile scene (~130k/s) from a separate timing loop, not from this run |")
        summary.append(("(e) exact reference, ≥ 100k single-tile scenes/s", "not measured as stated", f"{1e9 / worst:,.0f} frames/s on a 64² map, {1e9 / per_tile:,.0f} tile tests/s"))
    else:
        add("| (e) exact reference cost | — | not run | not measured |")
        summary.append(("(e) exact reference", "not run", None))

    # (f) exactness nearly free: tilesweep over the inexact twin (bench/twin_resolve.h: plain
    # float arithmetic, the same path-order walk), on the same frames, at every speed
    for level in ("Random30", "FloorAndWalls"):
        for scalar in ("float", "double"):
            pairs = [(a, ratio(results, f"BM_Tilesweep_{level}<{scalar}>/{a}", f"BM_Twin_{level}<{scalar}>/{a}"))
                     for a in SPEED_ARGS]
            measured = [r for _, r in pairs if r is not None]
            r = max(measured) if len(measured) == len(pairs) else None
            status, text = verdict_at_most(r, 1.3)
            level_text = "256² 30% random" if level == "Random30" else "256² floors and walls"
            per_speed = ", ".join(f"{speed_of(a)}: {fmt_ratio(x)}" for a, x in pairs)
            add(f"| (f) exactness nearly free: tilesweep over the inexact twin (same walk, plain "
                f"{scalar} arithmetic), worst speed, {level_text}, {scalar} | {fmt_ratio(r)} | "
                f"per tiles/frame {per_speed} | ≤ 1.3x: {text}"
                f"{'' if scalar == 'float' else ' (the bound is set for float; double is shown beside it)'}"
                f" |")
            if scalar == "float":
                summary.append((f"(f) tilesweep over the inexact twin, worst speed, {level_text}, float, ≤ 1.3x",
                                status, fmt_ratio(r) if r else None))
    add("")

    # --- Pareto
    add("## Run time against error")
    add("")
    add("![run time against error](pareto.svg)")
    add("")
    add("Run time: median CPU time per frame at 8 tiles/frame from this run. Error: share of the "
        "audit's scenes whose decisions (the tiles hit and their normals, on some frame) differ "
        "from the exact reference, summed over every family the audit ran for that scalar "
        f"(`{audit.command}`, seed {audit.seed}, {audit.cases} scenes per family). Tunnelling "
        "and ending inside a tile are given beside it. The exact reference is what the audit "
        "measures against: 0 by definition.")
    add("")
    add("| implementation (audit) | benchmark (8 tiles/frame) | ns/frame | 0.5 → 32 tiles/frame | "
        "decisions differ | tunnels | ends inside | audit scenes |")
    add("|---|---|---:|---|---:|---:|---:|---:|")
    for impl, bench, speeds, _label, _group in IMPLEMENTATIONS:
        row = audit.row(impl)
        times = [results.get(b) for b in speeds]
        span = " → ".join(fmt_num(t) for t in times)
        if row is None:
            figures = "— | — | — | not in the audit"
        elif row.get("reference"):
            figures = "0 (the reference) | 0 | 0 | —"
        else:
            figures = (f"{pct(row['decision'])} | {pct(row['tunnel'])} | {pct(row['inside'])} | "
                       f"{row['scenes']:,} ({row['families']} families)")
        add(f"| {impl} | `{bench}` | {fmt_num(results.get(bench))} | {span} | {figures} |")
    add("")
    add("Read the time axis with care: the production resolver and the seed algorithm run on a "
        "256² map, the substep loops and the exact reference on a 64² map (as the suite defines "
        "them). The seed algorithm and the substep loops look for candidate tiles by scanning "
        "every cell of the map, the exact reference tests every solid tile; the production "
        "resolver walks only the cells the move reaches (see (b): the map's size does not "
        "change its cost). The error axis comes from the audit's scenario families, not from the "
        "benchmark's scenes.")
    add("")
    add("## Summary")
    add("")
    for label, status, value in summary:
        add(f"- {label}: {status}" + (f" ({value})" if value else ""))
    add("")
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(lines))
    return summary


# --------------------------------------------------------------------------------------------
# pareto.svg, drawn by scripts/plots.py (matplotlib), the one way every chart is drawn

def write_svg(path, results, audit, machine):
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import plots  # noqa: E402  (scripts/plots.py; needs python3-matplotlib)

    points = []
    for impl, bench, speeds, label, group in IMPLEMENTATIONS:
        t = results.get(bench)
        row = audit.row(impl)
        if t is None or row is None:
            continue
        span = [v for v in (results.get(b) for b in speeds) if v is not None]
        points.append({"impl": impl, "label": label, "group": group, "t": t, "err": row["decision"],
                       "tunnel": row["tunnel"], "lo": min(span), "hi": max(span)})
    host = machine.get("host") or results.context.get("host_name", "")
    cpu = machine.get("cpu_model", "")
    footnotes = [
        "Time: production and seed on a 256² map, substeps and exact reference on a 64² map, 30% solid; "
        "the baselines scan the whole map.",
        f"Error: decisions differ, over all audit families (seed {audit.seed}, {audit.cases} scenes per family). "
        f"Machine: {host}, {cpu}.",
    ]
    plots.pareto(path, points, footnotes)


# --------------------------------------------------------------------------------------------

def main(argv):
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--results", help="Google Benchmark JSON (default: the newest docs/bench/results-*.json)")
    parser.add_argument("--machine", help="machine description written by scripts/bench.sh")
    parser.add_argument("--audit", default=os.path.join(root, "build", "audit", "report.json"))
    parser.add_argument("--out-dir", default=os.path.join(root, "docs", "bench"))
    args = parser.parse_args(argv)

    results_path = args.results
    if results_path is None:
        found = [os.path.join(args.out_dir, f) for f in os.listdir(args.out_dir)
                 if f.startswith("results-") and f.endswith(".json")] if os.path.isdir(args.out_dir) else []
        if not found:
            parser.error("no --results given and no docs/bench/results-*.json found (run scripts/bench.sh)")
        results_path = max(found, key=os.path.getmtime)
    machine_path = args.machine
    if machine_path is None:
        guess = os.path.join(os.path.dirname(results_path),
                             os.path.basename(results_path).replace("results-", "machine-", 1))
        machine_path = guess if os.path.exists(guess) else None
    machine = {}
    if machine_path:
        with open(machine_path, encoding="utf-8") as f:
            machine = json.load(f)

    results = Results(results_path)
    if not results.cpu:
        print(f"bench_report: no benchmark results in {results_path}", file=sys.stderr)
        return 1
    audit = Audit(args.audit)
    os.makedirs(args.out_dir, exist_ok=True)
    md = os.path.join(args.out_dir, "bench.md")
    svg = os.path.join(args.out_dir, "pareto.svg")
    summary = write_markdown(md, results, audit, machine, results_path, args.audit, args.out_dir)
    write_svg(svg, results, audit, machine)
    for label, status, value in summary:
        print(f"bench_report: {label}: {status}" + (f" ({value})" if value else ""), file=sys.stderr)
    print(f"bench_report: wrote {os.path.relpath(md)} and {os.path.relpath(svg)}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

#!/usr/bin/python3
"""Every chart of tilesweep, drawn one way: matplotlib (Debian's python3-matplotlib).

  plots.py audit DIR     DIR/report.json (tilesweep audit --out DIR) -> DIR/error_vs_magnitude.svg
                         and DIR/failures_per_family.svg
  plots.py rates FILE    FILE, the rates.json of tilesweep audit --resolver-cmd -> tolerance_vs_distance.svg
                         beside it: each engine's measured tolerance per claim against the distance
                         from the origin, with the engine's own documented tolerance
  bench                  scripts/bench_report.py imports pareto() for docs/bench/pareto.svg

The scene pictures (tilesweep render, counterexamples) are drawings of one scene, not charts;
the scene library writes them (scene/, render.h). Output is deterministic: no dates, fixed ids.
"""

import json
import math
import os
import sys

import matplotlib

matplotlib.use("agg")  # savefig writes SVG; Agg measures text for label placement
import matplotlib.pyplot as plt  # noqa: E402  (after the backend is chosen)

plt.rcParams.update({
    "svg.hashsalt": "tilesweep",          # stable element ids: the SVG changes only with the data
    "svg.fonttype": "none",               # text stays text
    "font.family": "DejaVu Sans",
    "font.size": 10,
    "axes.spines.top": False,
    "axes.spines.right": False,
    "axes.grid": True,
    "grid.color": "#dddddd",
    "grid.linewidth": 0.8,
})

# One palette for every chart: rows (implementations) by index, groups by name.
PALETTE = ["#1b9e77", "#0b5d43", "#d95f02", "#a63603", "#7570b3", "#e7298a", "#66a61e", "#e6ab02",
           "#1f78b4", "#b15928", "#6a3d9a"]
GROUP_STYLE = {  # group -> (colour, matplotlib marker)
    "production": ("#1a9850", "o"),
    "seed": ("#d73027", "s"),
    "substep": ("#f08c00", "^"),
    "exact": ("#2c5aa0", "D"),
}


def colour(i):
    return PALETTE[i % len(PALETTE)]


def save(fig, path):
    fig.savefig(path, format="svg", metadata={"Date": None, "Creator": "tilesweep scripts/plots.py"},
                bbox_inches="tight")
    plt.close(fig)


# ---- the audit ------------------------------------------------------------------------------

NON_FINITE = 20.2  # where a non-finite error is drawn on the log10(1 + ulps) axis


def log_ulps(value):
    """log10(1 + ulps), so that 0 ulps sits on the axis; "non-finite" goes to the top band."""
    if value is None:
        return None
    if isinstance(value, str):
        return NON_FINITE
    return math.log10(1.0 + float(value))


def error_vs_magnitude(report):
    """Position error (max and 99th percentile) against the translation of the far-* families."""
    far = [f["name"] for f in report["families"] if f["name"].startswith("far-")]
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.7), sharey=True)
    fig.suptitle("Position error against distance from the origin (ulps of the scalar type, log scale)")
    ticks = [(0, "0"), (math.log10(11), "10"), (3, "1e3"), (6, "1e6"), (9, "1e9"), (12, "1e12"), (15, "1e15"),
             (18, "1e18"), (NON_FINITE, "inf")]
    for panel, (ax, key, title) in enumerate(zip(axes, ("max", "p99"), ("max over the scenes", "99th percentile"))):
        ax.set_title(title, fontweight="bold")
        for i, impl in enumerate(report["implementations"]):
            xs, ys = [], []
            for b, name in enumerate(far):
                cell = impl["families"].get(name)
                if not cell:
                    continue  # float rows stop where float cannot hold the map
                y = log_ulps(cell["position_ulps"][key])
                if y is None:
                    continue
                xs.append(b + (i - 3.0) * 0.03)  # a small offset keeps coincident lines visible
                ys.append(y)
            ax.plot(xs, ys, marker="o", markersize=4, linewidth=1.8, color=colour(i),
                    label=impl["name"] if panel == 0 else None)
        ax.set_xticks(range(len(far)), [name[4:] for name in far])
        ax.set_yticks([v for v, _ in ticks], [label for _, label in ticks])
        ax.set_ylim(-0.5, 21)
        ax.set_xlabel("translation of the scene (far-* families)")
    axes[0].set_ylabel("position error (ulps at the position's magnitude, tile size at least)")
    fig.legend(loc="center left", bbox_to_anchor=(1.0, 0.55), frameon=False,
               title="float rows stop at 2^23\n0 ulps sits on the axis")
    fig.tight_layout()
    return fig


def failures_per_family(report):
    """Share of scenes whose decisions differ, and that tunnel or end inside, per family."""
    families = [f["name"] for f in report["families"]]
    impls = report["implementations"]
    fig, axes = plt.subplots(2, 1, figsize=(max(12.5, 0.45 * len(families) + 3), 7.5), sharex=True)
    fig.suptitle("Failures per family (% of scenes)")
    width = 0.8 / len(impls)
    titles = ("decisions differ from the exact reference (tiles hit or normals)",
              "tunnels, or ends inside a tile it did not start in")
    for panel, ax in enumerate(axes):
        ax.set_title(titles[panel], fontweight="bold")
        for i, impl in enumerate(impls):
            xs, heights, skipped = [], [], []
            for c, name in enumerate(families):
                x = c - 0.4 + width * (i + 0.5)
                cell = impl["families"].get(name)
                if not cell:
                    skipped.append(x)
                    continue
                failures = cell["failures"]
                # A scene can both tunnel and end inside: the larger count is a lower bound of
                # the union (exact when one implies the other).
                n = failures["decision"] if panel == 0 else max(failures["tunnel"], failures["inside"])
                xs.append(x)
                heights.append(100.0 * n / cell["scenes"] if cell["scenes"] else 0.0)
            ax.bar(xs, heights, width=width * 0.92, color=colour(i), label=impl["name"] if panel == 0 else None)
            ax.plot(skipped, [0.5] * len(skipped), linestyle="none", marker=".", color="#999999")
        ax.set_ylim(0, 100)
        ax.set_yticks([0, 25, 50, 75, 100], ["0%", "25%", "50%", "75%", "100%"])
        ax.grid(axis="x", visible=False)
    axes[1].set_xticks(range(len(families)), families, rotation=35, ha="right")
    fig.legend(loc="center left", bbox_to_anchor=(1.0, 0.5), frameon=False,
               title="no bar: 0%\ngrey dots: not run\n(float beyond 2^23)")
    fig.tight_layout()
    return fig


def audit(directory):
    with open(os.path.join(directory, "report.json"), encoding="utf-8") as f:
        report = json.load(f)
    save(error_vs_magnitude(report), os.path.join(directory, "error_vs_magnitude.svg"))
    save(failures_per_family(report), os.path.join(directory, "failures_per_family.svg"))


# ---- the benchmarks -------------------------------------------------------------------------

def fmt_ns(ns):
    if ns >= 1e6:
        return f"{ns / 1e6:.3g} ms"
    if ns >= 1e3:
        return f"{ns / 1e3:.3g} µs"
    return f"{ns:.3g} ns"


def pareto(path, points, footnotes):
    """Run time per frame (log scale) against the share of audit scenes whose decisions differ.

    points: dicts with impl, label, group (production, seed, substep, exact), t (ns), err and
    tunnel (% of scenes), lo and hi (ns, the range over speeds); footnotes: lines under the plot.
    """
    fig, ax = plt.subplots(figsize=(10, 6.4))
    ax.set_title("tilesweep: run time against error, one point per implementation\n"
                 "time: median CPU per frame at 8 tiles/frame; error: audit scenes whose decisions differ "
                 "from the exact reference", fontsize=11)
    ax.set_xscale("log")
    ax.set_xlabel("run time per frame (median CPU time, log scale)  →  slower")
    ax.set_ylabel("scenes whose decisions differ from exact (%)")
    if not points:
        ax.text(0.5, 0.5, "no data", transform=ax.transAxes, ha="center")
        save(fig, path)
        return
    ax.xaxis.set_major_formatter(matplotlib.ticker.FuncFormatter(lambda v, _: fmt_ns(v)))
    ymax = max(10.0, math.ceil(max(p["err"] for p in points) / 10.0) * 10.0)
    ax.set_ylim(-ymax * 0.06, ymax * 1.05)
    ax.axhline(0, color="#7bbf8c", linewidth=1.2)
    ax.axhspan(-ymax * 0.06, ymax * 0.03, color="#e6f4e9", zorder=0)
    ax.yaxis.set_major_formatter(matplotlib.ticker.FuncFormatter(lambda v, _: f"{v:g}%"))
    # Dominated: slower and no more exact than the fastest error-free point.
    best = min((p for p in points if p["err"] == 0), key=lambda p: p["t"], default=None)
    if best is not None:
        ax.axvspan(best["t"], max(p["hi"] for p in points) * 3, color="#1a9850", alpha=0.05, zorder=0)
        ax.axvline(best["t"], color="#1a9850", linestyle=(0, (3, 3)), linewidth=1.2)
        ax.text(best["t"] * 1.08, ymax * 1.0, f"shaded: slower and no more exact than {best['label']} (dominated)",
                fontsize=9, color="#1a7a3a", va="top")
    labels = []
    for p in sorted(points, key=lambda q: (q["err"], q["t"])):
        colour_, marker = GROUP_STYLE[p["group"]]
        hollow = p["impl"].endswith("-double")
        if p["hi"] > p["lo"]:
            ax.plot([p["lo"], p["hi"]], [p["err"]] * 2, color=colour_, linewidth=3, alpha=0.35,
                    solid_capstyle="round")
        ax.plot([p["t"]], [p["err"]], marker=marker, markersize=9, linestyle="none",
                markerfacecolor="white" if hollow else colour_, markeredgecolor=colour_ if hollow else "#222222",
                markeredgewidth=2.2 if hollow else 1)
        err = "0 (reference)" if p["impl"] == "exact-reference" else ("0" if p["err"] == 0 else f"{p['err']:.1f}%")
        text = f"{p['label']}\n{fmt_ns(p['t'])}, differs {err}"
        if p["tunnel"] > 0:
            text += f", tunnels {p['tunnel']:.1f}%"
        labels.append((p, text))
    # Labels placed greedily: the first of a few offsets around the point whose box meets no
    # label placed before, with a leader line.
    renderer = fig.canvas.get_renderer()
    placed = []
    offsets = [(12, 0, "left"), (-12, 0, "right"), (12, 22, "left"), (12, -22, "left"), (-12, 22, "right"),
               (-12, -22, "right"), (12, 44, "left"), (12, -44, "left"), (-12, 44, "right"), (-12, -44, "right"),
               (40, 66, "left"), (40, -66, "left")]
    for p, text in labels:
        for dx, dy, ha in offsets:
            note = ax.annotate(text, (p["t"], p["err"]), xytext=(dx, dy), textcoords="offset points", fontsize=8.5,
                               ha=ha, va="center",
                               bbox={"boxstyle": "round,pad=0.2", "fc": "white", "ec": "none", "alpha": 0.85},
                               arrowprops={"arrowstyle": "-", "color": "#777777", "linewidth": 0.8})
            box = note.get_window_extent(renderer)
            if not any(box.overlaps(other) for other in placed) or (dx, dy) == offsets[-1][:2]:
                placed.append(box)
                break
            note.remove()
    handles = [matplotlib.lines.Line2D([], [], marker=GROUP_STYLE[g][1], linestyle="none", markersize=8,
                                       markerfacecolor=GROUP_STYLE[g][0], markeredgecolor="#222222", label=text)
               for g, text in (("production", "production resolver (exact)"),
                               ("exact", "exact reference (GMP rationals)"),
                               ("seed", "seed algorithm (the article)"),
                               ("substep", "game-style float substeps"))]
    handles.append(matplotlib.lines.Line2D([], [], marker="o", linestyle="none", markersize=8,
                                           markerfacecolor="white", markeredgecolor="#666666",
                                           label="hollow: double (filled: float)"))
    handles.append(matplotlib.lines.Line2D([], [], color="#888888", linewidth=3, alpha=0.5,
                                           label="range: 0.5 to 32 tiles/frame"))
    ax.legend(handles=handles, loc="upper center", bbox_to_anchor=(0.5, -0.12), ncol=3, frameon=False, fontsize=9)
    fig.text(0.01, -0.06, "\n".join(footnotes), fontsize=8.5, color="#555555", va="top")
    fig.tight_layout()
    save(fig, path)


# ---- the engines' tolerances ---------------------------------------------------------------

TOLERANCE_PANELS = (("inside_depth", "deepest inside a tile"),
                    ("shortfall", "farthest short of touching"),
                    ("overshoot", "farthest past the exact end"))
ZERO_FLOOR = 1e-9  # where a tolerance of 0 (the claim held) is drawn on the log axis


def breach_quantile(histogram, q):
    """The upper edge of the binade holding the q-quantile of a breach histogram ({bin: count}; bin 0:
    no breach; bin k: [2^(k-42), 2^(k-41)) pixels), as audit/engine_rates.cpp computes it."""
    counts = {int(k): n for k, n in histogram.items()}
    total = sum(counts.values())
    if total == 0:
        return 0.0
    needed, seen = math.ceil(q * total), 0
    for k in sorted(counts):
        seen += counts[k]
        if seen >= needed:
            return 0.0 if k == 0 else 2.0 ** (k - 41)
    return 2.0 ** 41


def tolerance_vs_distance(rates):
    """Per claim, the largest breach (pixels) of every engine against the distance from the origin
    (the far families), with each engine's documented tolerance as a dashed line."""
    far = [(k, f["distance"]) for k, f in enumerate(rates["families"]) if f["name"].startswith("far-")]
    xs = [math.log2(d) if d > 0 else 0 for _, d in far]
    labels = ["0" if d == 0 else f"2^{int(round(math.log2(d)))}" for _, d in far]
    fig, axes = plt.subplots(1, len(TOLERANCE_PANELS), figsize=(13, 4.2), sharey=True)
    markers = ["o", "s", "^", "D", "v", "P", "X", "*"]
    top = max([ZERO_FLOOR] + [rates["cells"][e][k][key] for e in range(len(rates["engines"])) for k, _ in far
                              for key, _ in TOLERANCE_PANELS] + [e["documented_tolerance"] for e in rates["engines"]])
    for panel, (key, title) in enumerate(TOLERANCE_PANELS):
        ax = axes[panel]
        for e, engine in enumerate(rates["engines"]):
            values = [rates["cells"][e][k][key] for k, _ in far]
            # Engines that agree draw on top of each other: markers differ in shape and size.
            ax.plot(xs, [max(v, ZERO_FLOOR) for v in values], marker=markers[e % len(markers)], color=colour(e),
                    label=engine["name"], linewidth=1.4, markersize=9 - 1.2 * (e % 4), alpha=0.85)
            p99 = [breach_quantile(rates["cells"][e][k]["breach_histograms"][panel], 0.99) for k, _ in far]
            ax.plot(xs, [max(v, ZERO_FLOOR) for v in p99], color=colour(e), linestyle=":", linewidth=1.2)
            if engine["documented_tolerance"] > 0:
                ax.axhline(engine["documented_tolerance"], color=colour(e), linestyle="--", linewidth=1)
        ax.set_yscale("log")
        ax.set_ylim(ZERO_FLOOR / 3, top * 5)
        ax.set_xticks(xs, labels)
        ax.set_title(title, fontsize=10)
        ax.set_xlabel("distance from the origin (pixels)")
    axes[0].set_ylabel("largest breach (solid), pixels; bottom row: none")
    handles, names = axes[0].get_legend_handles_labels()
    handles.append(matplotlib.lines.Line2D([], [], color="#666666", linestyle=":", label="99% of scenes within"))
    handles.append(matplotlib.lines.Line2D([], [], color="#666666", linestyle="--", label="engine's documented tolerance"))
    fig.legend(handles=handles, loc="lower center", ncol=len(handles), frameon=False, bbox_to_anchor=(0.5, -0.06))
    fig.suptitle(f"The tolerance each claim would need, {rates['cases']} scenes per family", fontsize=11)
    fig.tight_layout()
    return fig


def main(argv):
    if len(argv) == 3 and argv[1] == "rates":
        with open(argv[2], encoding="utf-8") as f:
            rates = json.load(f)
        out = os.path.join(os.path.dirname(argv[2]) or ".", "tolerance_vs_distance.svg")
        save(tolerance_vs_distance(rates), out)
        print(f"plots: wrote {out}", file=sys.stderr)
        return 0
    if len(argv) == 3 and argv[1] == "audit":
        audit(argv[2])
        print(f"plots: wrote {argv[2]}/error_vs_magnitude.svg and failures_per_family.svg", file=sys.stderr)
        return 0
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv))

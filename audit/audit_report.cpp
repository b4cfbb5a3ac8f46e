// SPDX-License-Identifier: MIT
// The audit's output: report.md (a table per metric), report.json (every figure) and the worst
// scene of every failing cell as a replayable scene line. The charts are drawn from report.json
// by scripts/plots.py (matplotlib), the one way every chart is drawn; scripts/audit.sh runs both.
#include "tilesweep/audit/audit.h"
#include "tilesweep/scene/scalar_text.h"
#include "tilesweep/scene/scene.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace tilesweep::audit {
namespace {

using nlohmann::json;

// ---- figures --------------------------------------------------------------------------------

/// The upper bounds of the position-error histogram's buckets, in ulps (the last catches all).
struct Bucket {
    std::uint64_t upTo;
    const char* label;
};
const std::vector<Bucket> kHistogram = {
    {0, "0"},
    {1, "1"},
    {3, "2-3"},
    {15, "4-15"},
    {255, "16-255"},
    {65535, "256-65535"},
    {0xFFFFFFFFull, "2^16-2^32"},
    {kNonFiniteUlps - 1, ">2^32"},
    {kNonFiniteUlps, "non-finite"},
};

std::vector<std::uint64_t> histogramOf(const std::vector<std::uint64_t>& values) {
    std::vector<std::uint64_t> counts(kHistogram.size(), 0);
    for (const std::uint64_t v : values) {
        for (std::size_t b = 0; b < kHistogram.size(); ++b) {
            if (v <= kHistogram[b].upTo) {
                ++counts[b];
                break;
            }
        }
    }
    return counts;
}

/// The q-quantile (nearest rank) of sorted values.
template <class V>
V quantile(const std::vector<V>& sorted, double q) {
    if (sorted.empty()) return V{};
    const auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(sorted.size())));
    return sorted[std::min(sorted.size() - 1, rank == 0 ? 0 : rank - 1)];
}

std::string ulpsText(std::uint64_t u) {
    if (u == kNonFiniteUlps) return "inf";
    if (u < 1000000) return std::to_string(u);
    char text[32];
    std::snprintf(text, sizeof text, "%.2e", static_cast<double>(u));
    return text;
}

/// n of `of` in percent; "0%" of nothing.
std::string percent(std::uint64_t n, std::uint64_t of) {
    return detail::percentText(of == 0 ? 0.0 : static_cast<double>(n) / static_cast<double>(of));
}

std::string number(double x) {
    if (std::isinf(x)) return "inf";
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", x);
    return text;
}

json finiteOrString(double x) { return std::isfinite(x) ? json(x) : json(std::isnan(x) ? "nan" : "inf"); }
json ulpsJson(std::uint64_t u) { return u == kNonFiniteUlps ? json("non-finite") : json(u); }

std::string fileStem(const std::string& name) {
    std::string out;
    for (const char c : name) out += c == '^' ? 'p' : c;
    return out;
}

std::string worstFileName(const Implementation& impl, const Family& family) {
    return "worst/" + fileStem(impl.name) + "__" + fileStem(family.name) + ".jsonl";
}

bool runs(const Implementation& impl, const Family& family) { return impl.isDouble || family.floatToo; }

bool cellFailed(const CellStats& c) {
    for (std::size_t m = 0; m < kMetricCount; ++m)
        if (c.failures[m] > 0) return true;
    return false;
}

// ---- worst scenes ---------------------------------------------------------------------------

template <class T>
std::string worstLine(const Family& family, const Implementation& impl, Metric metric, const WorstCase& w,
                      std::uint64_t seed) {
    const Scene<T> scene = generateScene<T>(family, seed, w.caseIndex);
    std::string line = formatScene(scene);
    const json tags = {{"implementation", impl.name},
                       {"family", family.name},
                       {"metric", metricName(metric)},
                       {"score", finiteOrString(w.score)},
                       {"scalar", sizeof(T) == 4 ? "float" : "double"},
                       {"seed", seed},
                       {"case", w.caseIndex}};
    std::string fields = tags.dump();  // {"case":...,...}
    fields = fields.substr(1, fields.size() - 2);
    return "{" + fields + ", " + line.substr(1);
}

void writeText(const std::filesystem::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << text;
    out.close();
    if (!out) throw std::runtime_error("cannot write '" + path.string() + "'");
}

// ---- Markdown -------------------------------------------------------------------------------

std::string table(const AuditResult& r, const std::function<std::string(const CellStats&)>& text) {
    std::ostringstream s;
    s << "| implementation |";
    for (const Family& f : r.families) s << ' ' << f.name << " |";
    s << "\n|---|";
    for (std::size_t c = 0; c < r.families.size(); ++c) s << "---:|";
    s << '\n';
    for (std::size_t i = 0; i < r.implementations.size(); ++i) {
        s << "| " << r.implementations[i].name << " |";
        for (std::size_t c = 0; c < r.families.size(); ++c)
            s << ' ' << (runs(r.implementations[i], r.families[c]) ? text(r.cells[i][c]) : std::string("—"))
              << " |";
        s << '\n';
    }
    return s.str();
}

std::string countCell(const CellStats& c, Metric m) {
    return percent(c.failures[static_cast<std::size_t>(m)], c.scenes);
}

std::string eligibleCell(std::uint64_t n, std::uint64_t of) {
    if (of == 0) return "n/a";
    return std::to_string(n) + "/" + std::to_string(of);
}

bool productionClean(const AuditResult& r, std::string& problems) {
    bool clean = true;
    for (std::size_t i = 0; i < r.implementations.size(); ++i) {
        if (r.implementations[i].kind != ImplementationKind::Core) continue;
        for (std::size_t c = 0; c < r.families.size(); ++c) {
            const CellStats& cell = r.cells[i][c];
            for (std::size_t m = 0; m < kMetricCount; ++m) {
                if (cell.failures[m] == 0) continue;
                clean = false;
                problems += "- " + r.implementations[i].name + " on " + r.families[c].name + ": " +
                            std::to_string(cell.failures[m]) + " scene(s) fail `" +
                            metricName(static_cast<Metric>(m)) + "`; worst: `" +
                            worstFileName(r.implementations[i], r.families[c]) + "`\n";
            }
        }
    }
    return clean;
}

std::string markdown(const AuditResult& r) {
    std::ostringstream s;
    const AuditConfig& cfg = r.config;
    s << "# tilesweep audit\n\n";
    s << "Every implementation of the resolver held against the exact reference "
         "(`oracle/exact`, rational arithmetic), frame by frame.\n\n";
    s << "- command: `" << cfg.commandLine << "`\n";
    s << "- seed " << cfg.seed << ", " << cfg.cases << " scenes per family per scalar type ("
      << r.families.size() << " families), " << r.jobs << " thread" << (r.jobs == 1 ? "" : "s") << ", "
      << number(r.seconds) << " s\n";
    s << "- rerun exactly: `tilesweep audit --cases " << cfg.cases << " --seed " << cfg.seed
      << "` (the figures do not depend on `--jobs`)\n\n";

    std::string problems;
    if (productionClean(r, problems))
        s << "**Production rows (core-float, core-double): zero on every figure of every family** — no "
             "decision "
             "different, bit-for-bit the contract's rounded result (position within the rounding rule: 0 "
             "ulps), "
             "no tunnelling, never inside a tile.\n\n";
    else
        s << "**PRODUCTION ROWS ARE NOT ZERO** — a bug in the core:\n\n" << problems << "\n";

    s << "## What is measured\n\n"
         "A scene counts once in a figure whichever of its frames failed. Each frame of an implementation is "
         "judged "
         "against the exact frame that starts where *that implementation's* frame starts (the exact "
         "reference is "
         "re-run from its start when it has drifted), so one early error is not counted again on every later "
         "frame.\n\n"
         "| figure | a scene fails it when |\n|---|---|\n"
         "| decision | the multiset of (tile, normal) contacts of some frame differs from the exact one |\n"
         "| inexact | anything differs from the contract's result bit for bit: position (exact, rounded "
         "toward the start), "
         "contacts in order with their frame times (rounded to nearest), start overlaps |\n"
         "| tunnel | the box ends entirely beyond a tile the exact frame stops at, on that contact's axis "
         "(its trailing edge "
         "at or past the tile's far face) |\n"
         "| inside | the box ends strictly overlapping a solid tile it did not overlap at its frame's start "
         "|\n"
         "| clip-miss | the exact first step hits a tile by clipping its corner (it enters on one axis, not "
         "a tie, and the "
         "overlap window would close on the other axis before the frame ends: unstopped, it would pass the "
         "corner and "
         "come out) and the implementation reports no contact with that tile |\n"
         "| corner-hit | the straight move's swept bounds overlap a tile whose overlap set I is empty (the "
         "contract's corner "
         "miss, a path exactly through its corner point included), the exact frame never touches it, and the "
         "implementation reports a contact with it |\n"
         "| snag | the frame starts resting on a floor (bottom on the top of a solid tile it overlaps on x, "
         "the cell "
         "above empty) and the implementation reports an x contact on a tile of that floor row that the "
         "exact frame "
         "does not |\n"
         "| non-finite | an infinite or NaN position |\n"
         "| position | error of the final position against the contract's (exact, rounded toward the start), "
         "in ulps of "
         "the scalar type at the expected coordinate's magnitude, floored at the tile size: \\|got − want\\| "
         "/ "
         "ulp(max(\\|want\\|, tile)), rounded up (0 only when equal); largest axis and frame. Counting the "
         "representable "
         "values in between would call 1e-7 against 0 a billion ulps |\n"
         "| time | \\|t − t_contract\\| over contacts reported on the same tile, in fractions of the frame, "
         "t_contract being "
         "the exact time rounded to nearest (so a correct resolver reads 0). The seed reports "
         "its `time` as a fraction of that test's velocity and the substep loops k/N, as documented in "
         "oracle/README.md |\n\n";
    s << "Rates are % of scenes; `k/m` figures are failures over the scenes where the event can happen. "
         "`—`: not run (float cannot hold those magnitudes' tile maps at this tile size; the double rows go "
         "on).\n\n";

    s << "## Families and what they cover\n\n"
         "Counted on the exact first frame, float / double scenes. Every family of the property suite but "
         "extreme, then far-*: the random, corner-pass, corner-tie, seam-landing and one-way platform "
         "builders (in "
         "turn) with "
         "every map origin they draw at the magnitude, rounded down to whole tiles; case k of every far-* "
         "family is the same local scene, built there.\n\n"
         "The last two columns are the production resolver's own: the scenes where its fast path needed an "
         "exact "
         "refinement (filtered) and where it fell back to the exact lattice (exact), of all the scene's "
         "frames.\n\n"
         "| family | scenes | hit | two-step | tie | corner clip | corner miss | corner pass | start overlap "
         "| resting | filtered | exact |\n"
         "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (std::size_t c = 0; c < r.families.size(); ++c) {
        const auto& cv = r.coverage[c];
        auto both = [&](std::uint64_t Coverage::*field) {
            std::string out = cv[0].scenes > 0 ? percent(cv[0].*field, cv[0].scenes) : std::string("—");
            return out + " / " + percent(cv[1].*field, cv[1].scenes);
        };
        s << "| " << r.families[c].name << " | " << cv[0].scenes << " / " << cv[1].scenes << " | "
          << both(&Coverage::hit) << " | " << both(&Coverage::twoStep) << " | " << both(&Coverage::tie)
          << " | " << both(&Coverage::cornerClip) << " | " << both(&Coverage::cornerMiss) << " | "
          << both(&Coverage::cornerPass) << " | " << both(&Coverage::startOverlap) << " | "
          << both(&Coverage::resting) << " | " << both(&Coverage::filtered) << " | "
          << both(&Coverage::exactPath) << " |\n";
    }

    auto section = [&](const std::string& title, const std::string& note,
                       const std::function<std::string(const CellStats&)>& text) {
        s << "\n## " << title << "\n\n";
        if (!note.empty()) s << note << "\n\n";
        s << table(r, text);
    };
    section("Decisions differ (% of scenes)", "",
            [](const CellStats& c) { return countCell(c, Metric::Decision); });
    section("Not bit-for-bit the contract (% of scenes)", "",
            [](const CellStats& c) { return countCell(c, Metric::Inexact); });
    section("Tunnelling (% of scenes)", "", [](const CellStats& c) { return countCell(c, Metric::Tunnel); });
    section("Ends inside a tile (% of scenes)", "",
            [](const CellStats& c) { return countCell(c, Metric::Inside); });
    section("Misses a clipped corner (failures / scenes with a clipped corner)", "", [](const CellStats& c) {
        return eligibleCell(c.failures[static_cast<std::size_t>(Metric::ClipMiss)], c.clipEligible);
    });
    section("Hits a missed corner (failures / scenes with a corner-missed tile)", "", [](const CellStats& c) {
        return eligibleCell(c.failures[static_cast<std::size_t>(Metric::CornerHit)], c.cornerEligible);
    });
    section("Snags on a seam (failures / scenes resting on a floor)", "", [](const CellStats& c) {
        return eligibleCell(c.failures[static_cast<std::size_t>(Metric::Snag)], c.restingEligible);
    });
    section("Non-finite position (% of scenes)", "",
            [](const CellStats& c) { return countCell(c, Metric::NonFinite); });
    section("Position error, max (ulps)", "", [](const CellStats& c) {
        return c.positionUlps.empty() ? std::string("—") : ulpsText(c.positionUlps.back());
    });
    section("Position error, 99th percentile (ulps)", "",
            [](const CellStats& c) { return ulpsText(quantile(c.positionUlps, 0.99)); });
    section("Frame-time error, max (fraction of the frame)",
            "Over the contacts both report on the same tile.", [](const CellStats& c) {
                return c.timeErrors.empty() ? std::string("n/a") : number(c.timeErrors.back());
            });
    section("Frame-time error, 99th percentile", "", [](const CellStats& c) {
        return c.timeErrors.empty() ? std::string("n/a") : number(quantile(c.timeErrors, 0.99));
    });

    // Histogram over every family, one row per implementation.
    s << "\n## Position error histogram (ulps, scenes over all families)\n\n| implementation |";
    for (const Bucket& b : kHistogram) s << ' ' << b.label << " |";
    s << "\n|---|";
    for (std::size_t b = 0; b < kHistogram.size(); ++b) s << "---:|";
    s << '\n';
    for (std::size_t i = 0; i < r.implementations.size(); ++i) {
        std::vector<std::uint64_t> all;
        for (const CellStats& c : r.cells[i])
            all.insert(all.end(), c.positionUlps.begin(), c.positionUlps.end());
        const std::vector<std::uint64_t> h = histogramOf(all);
        s << "| " << r.implementations[i].name << " |";
        for (const std::uint64_t n : h) s << ' ' << n << " |";
        s << '\n';
    }

    // The epsilon question.
    s << "\n## Would a tolerance have fixed the naive variants?\n\n"
         "**Definition.** The seed algorithm compares times (`time > disjoint`, `timeX < 0`, `timeX > 1`). "
         "It is "
         "re-run with a tolerance ε, in fractions of the move, in each of those comparisons: "
         "`collided = !(time > disjoint + ε)`, rejected when `(timeX < −ε && timeY < −ε) || timeX > 1 + ε || "
         "timeY > 1 + ε` (`oracle/seed/seed_resolve.h`, default ε = 0 is the article). ε runs over "
         "{0, ±1e-7, ±1e-6, ±1e-5, ±1e-4, ±1e-3, ±1e-2} (+ accepts near misses, − rejects near hits). "
         "The cell gives the smallest |ε| at which its decisions (tiles and normals, every frame) match the "
         "exact "
         "ones on **every** scene of the family, or **none** when no ε in the list does; below it, the best "
         "ε and the "
         "share of scenes still wrong there. `none` means a tolerance cannot repair it: the flaws are not "
         "near-ties "
         "(the disjoint test compares a distance with a time, moving left or up never hits, a zero velocity "
         "component "
         "divides by zero, no slide) — and a tie decided wrongly at 1 ulp cannot be fixed by any ε either, "
         "since "
         "moving ε moves the wrong side of the tie with it. The substep loops have no tolerance in their "
         "comparisons: "
         "their errors come from sampling the path (a window shorter than a substep is missed, a hit is "
         "reported up "
         "to a substep late), which no ε repairs, so their cells read `n/a (sampling)` when they differ.\n\n";
    s << table(r, [&](const CellStats& c) -> std::string {
        if (c.epsilonMismatches.empty()) {
            return c.failures[static_cast<std::size_t>(Metric::Decision)] == 0
                       ? std::string("0 (exact)")
                       : std::string("n/a (sampling)");
        }
        std::size_t best = 0;
        for (std::size_t k = 1; k < c.epsilonMismatches.size(); ++k)
            if (c.epsilonMismatches[k] < c.epsilonMismatches[best]) best = k;
        char bestText[64];
        std::snprintf(bestText, sizeof bestText, "%g", kSeedEpsilons[best]);
        return smallestFixingEpsilon(c) + " (best ε=" + bestText + ": " +
               percent(c.epsilonMismatches[best], c.scenes) + " wrong)";
    });

    s << "\n## Worst scenes\n\n"
         "The worst scene of every failing cell, one line per failing figure (largest position error; "
         "largest time "
         "error for `time`), in `worst/<implementation>__<family>.jsonl` (`^` written as `p`). Each line is "
         "a scene "
         "with every number a hexfloat, plus `implementation`, `family`, `metric`, `score`, `scalar`, `seed` "
         "and "
         "`case`: replay it with `tilesweep resolve --scalar <scalar> FILE` (add `--resolver exact` for the "
         "exact "
         "answer, `--resolver seed` or `--resolver substep-float:N` for the naive ones) or draw it with "
         "`tilesweep render`.\n\n";
    for (std::size_t i = 0; i < r.implementations.size(); ++i) {
        std::vector<std::string> files;
        for (std::size_t c = 0; c < r.families.size(); ++c)
            if (runs(r.implementations[i], r.families[c]) && cellFailed(r.cells[i][c]))
                files.push_back(worstFileName(r.implementations[i], r.families[c]));
        s << "- " << r.implementations[i].name << ": "
          << (files.empty() ? std::string("none (no failure)") : std::to_string(files.size()) + " files")
          << '\n';
    }

    s << "\n## Plots\n\n![error against magnitude](error_vs_magnitude.svg)\n\n"
         "![failures per family](failures_per_family.svg)\n";
    return s.str();
}

// ---- JSON -----------------------------------------------------------------------------------

json reportJson(const AuditResult& r) {
    json j;
    j["command"] = r.config.commandLine;
    j["seed"] = r.config.seed;
    j["cases_per_family"] = r.config.cases;
    j["jobs"] = r.jobs;
    j["seconds"] = r.seconds;
    j["seed_epsilons"] = kSeedEpsilons;
    json buckets = json::array();
    for (const Bucket& b : kHistogram) buckets.push_back(b.label);
    j["histogram_buckets_ulps"] = buckets;
    std::string problems;
    j["production_clean"] = productionClean(r, problems);
    for (std::size_t c = 0; c < r.families.size(); ++c) {
        const Family& f = r.families[c];
        json fam = {{"name", f.name}, {"magnitude", f.magnitude}, {"float", f.floatToo}};
        for (std::size_t k = 0; k < 2; ++k) {
            const Coverage& cv = r.coverage[c][k];
            fam["coverage"][k == 0 ? "float" : "double"] = {
                {"scenes", cv.scenes},          {"hit", cv.hit},
                {"two_step", cv.twoStep},       {"tie", cv.tie},
                {"corner_clip", cv.cornerClip}, {"corner_miss", cv.cornerMiss},
                {"corner_pass", cv.cornerPass}, {"start_overlap", cv.startOverlap},
                {"resting", cv.resting},        {"filtered", cv.filtered},
                {"exact_path", cv.exactPath}};
        }
        j["families"].push_back(fam);
    }
    for (std::size_t i = 0; i < r.implementations.size(); ++i) {
        const Implementation& impl = r.implementations[i];
        json row = {
            {"name", impl.name}, {"scalar", impl.isDouble ? "double" : "float"}, {"substeps", impl.substeps}};
        for (std::size_t c = 0; c < r.families.size(); ++c) {
            if (!runs(impl, r.families[c])) continue;
            const CellStats& cell = r.cells[i][c];
            json cj;
            cj["scenes"] = cell.scenes;
            for (std::size_t m = 0; m < kMetricCount; ++m)
                cj["failures"][metricName(static_cast<Metric>(m))] = cell.failures[m];
            cj["eligible"] = {{"clip-miss", cell.clipEligible},
                              {"corner-hit", cell.cornerEligible},
                              {"snag", cell.restingEligible}};
            cj["position_ulps"] = {
                {"max", cell.positionUlps.empty() ? json(nullptr) : ulpsJson(cell.positionUlps.back())},
                {"p99", ulpsJson(quantile(cell.positionUlps, 0.99))},
                {"p50", ulpsJson(quantile(cell.positionUlps, 0.5))},
                {"histogram", histogramOf(cell.positionUlps)}};
            cj["time_error"] = {
                {"scenes", cell.timeErrors.size()},
                {"max", cell.timeErrors.empty() ? json(nullptr) : finiteOrString(cell.timeErrors.back())},
                {"p99",
                 cell.timeErrors.empty() ? json(nullptr) : finiteOrString(quantile(cell.timeErrors, 0.99))}};
            if (!cell.epsilonMismatches.empty()) {
                cj["epsilon_mismatches"] = cell.epsilonMismatches;
                cj["smallest_fixing_epsilon"] = smallestFixingEpsilon(cell);
            }
            for (std::size_t m = 0; m < kMetricCount; ++m) {
                const WorstCase& w = cell.worst[m];
                if (!w.found) continue;
                cj["worst"][metricName(static_cast<Metric>(m))] = {
                    {"case", w.caseIndex},
                    {"score", finiteOrString(w.score)},
                    {"file", worstFileName(impl, r.families[c])}};
            }
            row["families"][r.families[c].name] = cj;
        }
        j["implementations"].push_back(row);
    }
    return j;
}

}  // namespace

void writeAuditReport(const AuditResult& result, const std::string& directory) {
    const std::filesystem::path dir(directory);
    std::filesystem::create_directories(dir / "worst");
    // A rerun into the same directory must not leave the previous run's worst scenes behind.
    for (const auto& entry : std::filesystem::directory_iterator(dir / "worst"))
        if (entry.path().extension() == ".jsonl") std::filesystem::remove(entry.path());

    for (std::size_t i = 0; i < result.implementations.size(); ++i) {
        const Implementation& impl = result.implementations[i];
        for (std::size_t c = 0; c < result.families.size(); ++c) {
            const Family& family = result.families[c];
            if (!runs(impl, family)) continue;
            const CellStats& cell = result.cells[i][c];
            std::string lines;
            for (std::size_t m = 0; m < kMetricCount; ++m) {
                if (cell.failures[m] == 0 || !cell.worst[m].found) continue;
                lines += impl.isDouble ? worstLine<double>(family, impl, static_cast<Metric>(m),
                                                           cell.worst[m], result.config.seed)
                                       : worstLine<float>(family, impl, static_cast<Metric>(m), cell.worst[m],
                                                          result.config.seed);
                lines += '\n';
            }
            if (!lines.empty()) writeText(dir / worstFileName(impl, family), lines);
        }
    }
    writeText(dir / "report.md", markdown(result));
    writeText(dir / "report.json", reportJson(result).dump(1) + "\n");
}

}  // namespace tilesweep::audit

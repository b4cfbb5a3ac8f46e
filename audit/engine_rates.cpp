// SPDX-License-Identifier: MIT
// Engine rates (engine_rates.h): the scenes of each family drawn once per batch, judged once
// against the exact reference, and answered by every engine in turn; workers own their cells and
// their engines (one process each, for an outside resolver), merged at the end.
#include "tilesweep/audit/engine_rates.h"

#include "parallel_tasks.h"
#include "scene_judge.h"

#include "tilesweep/scene/scalar_text.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <memory>
#include <stdexcept>
#include <thread>
#include <type_traits>
#include <utility>

namespace tilesweep::audit {
namespace {

/// How many reasons for a missing answer a cell keeps, as samples for the report.
constexpr std::size_t kNoAnswerSamples = 3;

std::string distanceName(double distance) {
    if (distance == 0) return "0";
    char text[32];
    std::snprintf(text, sizeof text, "2^%d", static_cast<int>(std::lround(std::log2(distance))));
    return text;
}

void record(RateCell& cell, const judge::SceneVerdict& v, std::uint64_t caseIndex) {
    ++cell.scenes;
    for (std::size_t m = 0; m < kMetricCount; ++m) {
        if (!v.failed[m]) continue;
        ++cell.failures[m];
        cell.firstFailure[m] = std::min(cell.firstFailure[m], caseIndex);
    }
    if (v.restingEligible) ++cell.restingEligible;
    if (v.platformLandingEligible) ++cell.platformLandings;
    if (v.platformPassEligible) ++cell.platformPasses;
    if (v.platformRestingEligible) ++cell.platformResting;
    cell.insideDepth = std::max(cell.insideDepth, v.insideDepth);
    cell.shortfall = std::max(cell.shortfall, v.shortfall);
    cell.overshoot = std::max(cell.overshoot, v.overshoot);
    ++cell.breaches[static_cast<std::size_t>(Breach::InsideDepth)][breachBin(v.insideDepth)];
    ++cell.breaches[static_cast<std::size_t>(Breach::Shortfall)][breachBin(v.shortfall)];
    ++cell.breaches[static_cast<std::size_t>(Breach::Overshoot)][breachBin(v.overshoot)];
}

void recordNoAnswer(RateCell& cell, const std::string& why, std::uint64_t caseIndex) {
    judge::SceneVerdict v;
    v.failed[static_cast<std::size_t>(Metric::NoAnswer)] = true;
    record(cell, v, caseIndex);
    if (cell.noAnswerSamples.size() < kNoAnswerSamples) cell.noAnswerSamples.push_back(why.substr(0, 400));
}

/// One batch of one family: the case indices it covers.
struct Task {
    std::size_t family;
    std::vector<std::uint64_t> cases;
};

/// Draws the scenes of `cases` in `family`, judges each once against the exact reference, and
/// records every engine's answers in its cell (`cells[e]`); `resolverOf(e)` is the worker's own
/// resolver of engine e.
template <class T>
void judgeBatch(const Family& family, std::uint64_t seed, const std::vector<std::uint64_t>& cases,
                const std::function<resolvers::SceneResolver&(std::size_t)>& resolverOf,
                const std::vector<RateCell*>& cells) {
    std::vector<Scene<T>> scenes;
    std::vector<std::uint64_t> kept;
    scenes.reserve(cases.size());
    for (const std::uint64_t c : cases) {
        Scene<T> s = generateScene<T>(family, seed, c);
        // A far map whose edges T cannot hold is not a scene of the contract.
        if (validateTileMap(s.map.view()) != MapError::None) continue;
        scenes.push_back(std::move(s));
        kept.push_back(c);
    }
    std::vector<judge::SceneJudge<T>> judges;
    judges.reserve(scenes.size());
    for (const Scene<T>& s : scenes) judges.emplace_back(s);
    for (std::size_t e = 0; e < cells.size(); ++e) {
        const std::vector<resolvers::Answer<T>> answers = resolvers::resolveAll(resolverOf(e), scenes);
        RateCell& cell = *cells[e];
        for (std::size_t k = 0; k < scenes.size(); ++k) {
            if (k >= answers.size()) {
                recordNoAnswer(cell, "the resolver returned fewer answers than scenes", kept[k]);
            } else if (!answers[k].failure.empty()) {
                recordNoAnswer(cell, answers[k].failure, kept[k]);
            } else if (answers[k].frames.size() != scenes[k].moves.size()) {
                recordNoAnswer(cell,
                               "answered " + std::to_string(answers[k].frames.size()) +
                                   " frames for a scene of " + std::to_string(scenes[k].moves.size()),
                               kept[k]);
            } else {
                record(cell, judges[k].judge(answers[k].frames), kept[k]);
            }
        }
    }
}

}  // namespace

std::size_t breachBin(double pixels) noexcept {
    if (!(pixels > 0)) return 0;
    if (!std::isfinite(pixels)) return kBreachBins - 1;
    const int binade = std::ilogb(pixels);  // 2^binade <= pixels < 2^(binade+1)
    return static_cast<std::size_t>(std::clamp(binade + 42, 1, static_cast<int>(kBreachBins) - 1));
}

double breachQuantile(const BreachHistogram& histogram, double q) noexcept {
    std::uint64_t total = 0;
    for (const std::uint64_t n : histogram) total += n;
    if (total == 0) return 0;
    const auto needed = static_cast<std::uint64_t>(std::ceil(q * static_cast<double>(total)));
    std::uint64_t seen = 0;
    // The top bin gathers every breach from 2^kTopBreachBinade up, infinite ones too: its
    // nominal upper edge bounds nothing, so a quantile there has no finite bound.
    for (std::size_t k = 0; k + 1 < kBreachBins; ++k) {
        seen += histogram[k];
        if (seen >= needed) return k == 0 ? 0.0 : std::ldexp(1.0, static_cast<int>(k) - 41);
    }
    return std::numeric_limits<double>::infinity();
}

std::uint64_t RateCell::trials(Metric m) const noexcept {
    switch (m) {
        case Metric::Snag:
            return restingEligible;
        case Metric::PlatformFall:
            return platformLandings;
        case Metric::PlatformBlock:
            return platformPasses;
        case Metric::PlatformSnag:
            return platformResting;
        default:
            return scenes;
    }
}

void RateCell::merge(const RateCell& other) {
    scenes += other.scenes;
    restingEligible += other.restingEligible;
    platformLandings += other.platformLandings;
    platformPasses += other.platformPasses;
    platformResting += other.platformResting;
    for (std::size_t m = 0; m < kMetricCount; ++m) {
        failures[m] += other.failures[m];
        firstFailure[m] = std::min(firstFailure[m], other.firstFailure[m]);
    }
    insideDepth = std::max(insideDepth, other.insideDepth);
    shortfall = std::max(shortfall, other.shortfall);
    overshoot = std::max(overshoot, other.overshoot);
    for (std::size_t b = 0; b < kBreachCount; ++b)
        for (std::size_t k = 0; k < kBreachBins; ++k) breaches[b][k] += other.breaches[b][k];
    for (const std::string& s : other.noAnswerSamples)
        if (noAnswerSamples.size() < kNoAnswerSamples) noAnswerSamples.push_back(s);
}

std::vector<Family> rateFamilies(const std::string& scalar) {
    if (scalar != "float" && scalar != "double")
        throw std::invalid_argument("scalar '" + scalar + "' is neither float nor double");
    using Suite = scenarios::Family;
    std::vector<Family> f;
    for (const Suite suite : {Suite::Random, Suite::CornerPass, Suite::CornerTie, Suite::SeamLanding,
                              Suite::Resting, Suite::FarSubUlp, Suite::HighSpeed, Suite::PlatformLanding,
                              Suite::PlatformJump, Suite::PlatformWalk, Suite::Platforms})
        f.push_back(suiteFamily(suite));
    for (const double d : kRateDistances) f.push_back({"far-" + distanceName(d), FamilyKind::Far, d, true});
    if (scalar == "double")
        for (const double d : kDoubleRateDistances)
            f.push_back({"far-" + distanceName(d), FamilyKind::Far, d, false});
    return f;
}

RatesResult measureRates(const RatesConfig& config, const std::vector<EngineSpec>& engines) {
    if (config.shardCount < 1 || config.shardIndex < 0 || config.shardIndex >= config.shardCount)
        throw std::invalid_argument("shard " + std::to_string(config.shardIndex) + "/" +
                                    std::to_string(config.shardCount) + " is not K/N with 0 <= K < N");
    const auto started = std::chrono::steady_clock::now();
    RatesResult result;
    result.config = config;
    result.families = rateFamilies(config.scalar);
    result.shards = {config.shardIndex};
    for (const EngineSpec& e : engines) {
        result.engines.push_back(e.name);
        result.documentedTolerance.push_back(e.documentedTolerance);
        result.toleranceNotes.push_back(e.toleranceNote);
    }

    // Batches interleave the families, so that progress advances evenly across them.
    const std::uint64_t batch = std::max<std::uint64_t>(1, config.batch);
    std::vector<Task> tasks;
    std::uint64_t total = 0;
    for (std::uint64_t first = 0; first < config.cases;
         first += batch * static_cast<std::uint64_t>(config.shardCount))
        for (std::size_t f = 0; f < result.families.size(); ++f) {
            Task t{f, {}};
            for (std::uint64_t c = first; c < config.cases && t.cases.size() < batch; ++c)
                if (c % static_cast<std::uint64_t>(config.shardCount) ==
                    static_cast<std::uint64_t>(config.shardIndex))
                    t.cases.push_back(c);
            total += t.cases.size();
            if (!t.cases.empty()) tasks.push_back(std::move(t));
        }

    int jobs = config.jobs > 0 ? config.jobs : static_cast<int>(std::thread::hardware_concurrency());
    jobs = std::max(1, std::min<int>(jobs, static_cast<int>(std::max<std::size_t>(1, tasks.size()))));
    using Cells = std::vector<std::vector<RateCell>>;
    std::vector<Cells> shards(static_cast<std::size_t>(jobs),
                              Cells(engines.size(), std::vector<RateCell>(result.families.size())));
    // Each worker's engines (one process each, for an outside resolver), started at its first task.
    std::vector<std::vector<std::unique_ptr<resolvers::SceneResolver>>> made(static_cast<std::size_t>(jobs));
    for (auto& own : made) own.resize(engines.size());

    ParallelTasks parallel;
    parallel.workers = jobs;
    parallel.tasks = tasks.size();
    parallel.units = total;
    parallel.name = "rates";
    parallel.progress = config.progress;
    parallel.run = [&](std::size_t w, std::size_t t) -> std::uint64_t {
        const Task& task = tasks[t];
        const Family& family = result.families[task.family];
        std::vector<RateCell*> row;
        for (std::size_t e = 0; e < engines.size(); ++e) row.push_back(&shards[w][e][task.family]);
        const auto resolverOf = [&](std::size_t e) -> resolvers::SceneResolver& {
            if (!made[w][e]) made[w][e] = engines[e].make();
            return *made[w][e];
        };
        if (config.scalar == "double")
            judgeBatch<double>(family, config.seed, task.cases, resolverOf, row);
        else
            judgeBatch<float>(family, config.seed, task.cases, resolverOf, row);
        return task.cases.size();
    };
    runParallelTasks(parallel);
    made.clear();  // the outside resolvers' processes end here, as when each worker ended

    result.cells.assign(engines.size(), std::vector<RateCell>(result.families.size()));
    for (const Cells& s : shards)
        for (std::size_t e = 0; e < engines.size(); ++e)
            for (std::size_t f = 0; f < result.families.size(); ++f) result.cells[e][f].merge(s[e][f]);
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return result;
}

// ---- JSON -----------------------------------------------------------------------------------

namespace {

/// A largest breach as JSON: the number, or "inf" (JSON has no infinity; nlohmann would write
/// null, which reads back as no number at all).
nlohmann::ordered_json distanceJson(double pixels) {
    if (std::isinf(pixels) && pixels > 0) return "inf";
    return pixels;
}

double distanceOf(const nlohmann::json& j) {
    if (j.is_string() && j.get<std::string>() == "inf") return std::numeric_limits<double>::infinity();
    return j.get<double>();
}

}  // namespace

std::string ratesJson(const RatesResult& r) {
    nlohmann::ordered_json j;
    j["kind"] = "tilesweep-rates";
    j["seed"] = r.config.seed;
    j["cases"] = r.config.cases;
    j["scalar"] = r.config.scalar;
    j["shard_count"] = r.config.shardCount;
    j["shards"] = r.shards;
    j["seconds"] = r.seconds;
    j["distances"] = kRateDistances;
    if (r.config.scalar == "double") j["double_distances"] = kDoubleRateDistances;
    for (std::size_t e = 0; e < r.engines.size(); ++e)
        j["engines"].push_back({{"name", r.engines[e]},
                                {"documented_tolerance", r.documentedTolerance[e]},
                                {"tolerance_note", r.toleranceNotes[e]}});
    for (const Family& f : r.families) j["families"].push_back({{"name", f.name}, {"distance", f.magnitude}});
    for (std::size_t e = 0; e < r.engines.size(); ++e) {
        nlohmann::ordered_json row = nlohmann::ordered_json::array();
        for (const RateCell& c : r.cells[e]) {
            nlohmann::ordered_json cj;
            cj["scenes"] = c.scenes;
            cj["resting_eligible"] = c.restingEligible;
            cj["platform_landings"] = c.platformLandings;
            cj["platform_passes"] = c.platformPasses;
            cj["platform_resting"] = c.platformResting;
            for (std::size_t m = 0; m < kMetricCount; ++m) {
                const char* name = metricName(static_cast<Metric>(m));
                cj["failures"][name] = c.failures[m];
                if (c.firstFailure[m] != RateCell::kNoCase) cj["first_failure"][name] = c.firstFailure[m];
            }
            cj["inside_depth"] = distanceJson(c.insideDepth);
            cj["shortfall"] = distanceJson(c.shortfall);
            cj["overshoot"] = distanceJson(c.overshoot);
            // Histograms as {bin: count}, the bins that are not empty.
            for (std::size_t b = 0; b < kBreachCount; ++b) {
                nlohmann::ordered_json bins = nlohmann::ordered_json::object();
                for (std::size_t k = 0; k < kBreachBins; ++k)
                    if (c.breaches[b][k] != 0) bins[std::to_string(k)] = c.breaches[b][k];
                cj["breach_histograms"].push_back(bins);
            }
            cj["no_answer_samples"] = c.noAnswerSamples;
            row.push_back(cj);
        }
        j["cells"].push_back(row);
    }
    return j.dump(1) + "\n";
}

RatesResult readRatesJson(const std::string& text) {
    const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
    if (j.is_discarded() || !j.is_object() || j.value("kind", "") != "tilesweep-rates")
        throw std::runtime_error("not a rates file (tilesweep audit --rates-json writes one)");
    try {
        RatesResult r;
        r.config.seed = j.at("seed").get<std::uint64_t>();
        r.config.cases = j.at("cases").get<std::uint64_t>();
        r.config.scalar = j.value("scalar", std::string("float"));
        if (r.config.scalar != "float" && r.config.scalar != "double")
            throw std::runtime_error("scalar: '" + r.config.scalar + "' is neither float nor double");
        r.config.shardCount = j.at("shard_count").get<int>();
        r.shards = j.at("shards").get<std::vector<int>>();
        r.seconds = j.at("seconds").get<double>();
        const std::vector<Family> known = rateFamilies(r.config.scalar);
        for (const auto& f : j.at("families")) {
            const std::string name = f.at("name").get<std::string>();
            const auto it =
                std::find_if(known.begin(), known.end(), [&](const Family& k) { return k.name == name; });
            if (it == known.end()) throw std::runtime_error("families: unknown family '" + name + "'");
            r.families.push_back(*it);
        }
        for (const auto& e : j.at("engines")) {
            r.engines.push_back(e.at("name").get<std::string>());
            r.documentedTolerance.push_back(e.at("documented_tolerance").get<double>());
            r.toleranceNotes.push_back(e.at("tolerance_note").get<std::string>());
        }
        for (const auto& row : j.at("cells")) {
            std::vector<RateCell> cells;
            for (const auto& cj : row) {
                RateCell c;
                c.scenes = cj.at("scenes").get<std::uint64_t>();
                c.restingEligible = cj.at("resting_eligible").get<std::uint64_t>();
                c.platformLandings = cj.value("platform_landings", std::uint64_t{0});
                c.platformPasses = cj.value("platform_passes", std::uint64_t{0});
                c.platformResting = cj.value("platform_resting", std::uint64_t{0});
                for (std::size_t m = 0; m < kMetricCount; ++m) {
                    const char* name = metricName(static_cast<Metric>(m));
                    c.failures[m] = cj.at("failures").value(name, std::uint64_t{0});
                    if (cj.contains("first_failure") && cj["first_failure"].contains(name))
                        c.firstFailure[m] = cj["first_failure"][name].get<std::uint64_t>();
                }
                c.insideDepth = distanceOf(cj.at("inside_depth"));
                c.shortfall = distanceOf(cj.at("shortfall"));
                c.overshoot = distanceOf(cj.at("overshoot"));
                const auto& histograms = cj.at("breach_histograms");
                if (histograms.size() != kBreachCount)
                    throw std::runtime_error("breach_histograms: 3 expected");
                for (std::size_t b = 0; b < kBreachCount; ++b)
                    for (const auto& [bin, count] : histograms[b].items()) {
                        const std::size_t k = std::stoul(bin);
                        if (k >= kBreachBins)
                            throw std::runtime_error("breach_histograms: bin " + bin + " out of range");
                        c.breaches[b][k] = count.get<std::uint64_t>();
                    }
                c.noAnswerSamples = cj.at("no_answer_samples").get<std::vector<std::string>>();
                cells.push_back(std::move(c));
            }
            if (cells.size() != r.families.size())
                throw std::runtime_error("cells: a row per family expected");
            r.cells.push_back(std::move(cells));
        }
        if (r.cells.size() != r.engines.size()) throw std::runtime_error("cells: a row per engine expected");
        return r;
    } catch (const nlohmann::json::exception& e) {
        throw std::runtime_error(std::string("malformed rates file: ") + e.what());
    }
}

namespace {

std::string joined(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& n : names) text += (text.empty() ? "" : ", ") + n;
    return "[" + text + "]";
}

std::vector<std::string> familyNames(const RatesResult& r) {
    std::vector<std::string> names;
    for (const Family& f : r.families) names.push_back(f.name);
    return names;
}

}  // namespace

RatesResult mergeRates(const std::vector<RatesResult>& shards, const std::vector<std::string>& labels) {
    if (shards.empty()) throw std::invalid_argument("nothing to merge");
    const auto label = [&](std::size_t k) {
        return k < labels.size() ? labels[k] : "shard file " + std::to_string(k + 1);
    };
    RatesResult merged = shards.front();
    std::vector<std::size_t> from(merged.shards.size(), 0);  // which shard file gave each index
    for (std::size_t k = 1; k < shards.size(); ++k) {
        const RatesResult& s = shards[k];
        const auto differs = [&](const std::string& field, const std::string& got, const std::string& want) {
            return std::invalid_argument(label(k) + ": " + field + " " + got + " differs from " + label(0) +
                                         "'s " + want + " (a shard of another run)");
        };
        if (s.config.seed != merged.config.seed)
            throw differs("seed", std::to_string(s.config.seed), std::to_string(merged.config.seed));
        if (s.config.cases != merged.config.cases)
            throw differs("cases", std::to_string(s.config.cases), std::to_string(merged.config.cases));
        if (s.config.scalar != merged.config.scalar)
            throw differs("scalar", s.config.scalar, merged.config.scalar);
        if (s.config.shardCount != merged.config.shardCount)
            throw differs("shard count", std::to_string(s.config.shardCount),
                          std::to_string(merged.config.shardCount));
        if (s.engines != merged.engines) throw differs("engines", joined(s.engines), joined(merged.engines));
        if (familyNames(s) != familyNames(merged))
            throw differs("families", joined(familyNames(s)), joined(familyNames(merged)));
        for (const int index : s.shards) {
            const auto seen = std::find(merged.shards.begin(), merged.shards.end(), index);
            if (seen != merged.shards.end())
                throw std::invalid_argument(
                    label(k) + ": shard " + std::to_string(index) + "/" +
                    std::to_string(merged.config.shardCount) + " is given twice (also in " +
                    label(from[static_cast<std::size_t>(seen - merged.shards.begin())]) + ")");
            merged.shards.push_back(index);
            from.push_back(k);
        }
        for (std::size_t e = 0; e < merged.cells.size(); ++e)
            for (std::size_t f = 0; f < merged.cells[e].size(); ++f) merged.cells[e][f].merge(s.cells[e][f]);
        merged.seconds += s.seconds;
    }
    std::sort(merged.shards.begin(), merged.shards.end());
    return merged;
}

// ---- Markdown -------------------------------------------------------------------------------

namespace {

/// "1.2% [0.9, 1.6]": the share and its 95% Wilson interval, in percent; "–" with no trials.
std::string rateText(std::uint64_t failures, std::uint64_t trials) {
    if (trials == 0) return "–";
    const RateInterval ci = wilsonInterval(failures, trials);
    const std::string share =
        detail::percentText(static_cast<double>(failures) / static_cast<double>(trials));
    std::string low = detail::percentText(ci.low), high = detail::percentText(ci.high);
    if (!low.empty() && low.back() == '%') low.pop_back();
    return (failures > 0 ? "**" + share + "**" : share) + " [" + low + ", " + high + "]";
}

std::string pixels(double v) {
    if (v == 0) return "0";
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", v);
    return text;
}

const char* metricHeading(Metric m) {
    switch (m) {
        case Metric::Tunnel:
            return "tunnels";
        case Metric::Inside:
            return "ends inside";
        case Metric::Short:
            return "stops short";
        case Metric::Overshoot:
            return "passes the end";
        case Metric::Missed:
            return "misses a contact";
        case Metric::Extra:
            return "wrong tile/normal";
        case Metric::Snag:
            return "snags on a seam (of resting)";
        case Metric::PlatformFall:
            return "ends below a platform it lands on (of landings)";
        case Metric::PlatformBlock:
            return "blocked by a platform it passes (of passes)";
        case Metric::PlatformSnag:
            return "snags on a platform seam (of standing)";
        case Metric::Inexact:
            return "not bit-exact";
        case Metric::NoAnswer:
            return "no answer";
        default:
            return metricName(m);
    }
}

}  // namespace

std::string ratesMarkdown(const RatesResult& r) {
    std::string md;
    char text[1024];
    std::snprintf(
        text, sizeof text,
        "Seed %llu, %llu scenes per family (%s), shards %zu of %d; every engine answers the same "
        "scenes. A cell is the share of scenes that broke the claim, in bold when any did, with its "
        "95%% Wilson interval, \"–\" where no scene could break it. Snags are counted among the scenes "
        "that start resting on a floor; the platform columns among the scenes with a frame that lands "
        "on a one-way platform, passes one (jumping up through it, entering from the side, starting "
        "inside it), or starts standing on one.\n\n",
        static_cast<unsigned long long>(r.config.seed), static_cast<unsigned long long>(r.config.cases),
        r.config.scalar.c_str(), r.shards.size(), r.config.shardCount);
    md += text;

    // The headline: every engine, over all families.
    md += "| engine | scenes |";
    for (const Metric m : kRateMetrics) md += std::string(" ") + metricHeading(m) + " |";
    md += "\n|---|---:|";
    for (std::size_t k = 0; k < kRateMetrics.size(); ++k) md += "---|";
    md += "\n";
    for (std::size_t e = 0; e < r.engines.size(); ++e) {
        RateCell all;
        for (const RateCell& c : r.cells[e]) all.merge(c);
        md += "| " + r.engines[e] + " | " + std::to_string(all.scenes) + " |";
        for (const Metric m : kRateMetrics)
            md += " " + rateText(all.failures[static_cast<std::size_t>(m)], all.trials(m)) + " |";
        md += "\n";
    }

    for (std::size_t e = 0; e < r.engines.size(); ++e) {
        md += "\n### Rates: " + r.engines[e] + "\n\n| family | scenes |";
        for (const Metric m : kRateMetrics) md += std::string(" ") + metricHeading(m) + " |";
        md += "\n|---|---:|";
        for (std::size_t k = 0; k < kRateMetrics.size(); ++k) md += "---|";
        md += "\n";
        for (std::size_t f = 0; f < r.families.size(); ++f) {
            const RateCell& c = r.cells[e][f];
            md += "| " + r.families[f].name + " | " + std::to_string(c.scenes) + " |";
            for (const Metric m : kRateMetrics)
                md += " " + rateText(c.failures[static_cast<std::size_t>(m)], c.trials(m)) + " |";
            md += "\n";
        }

        // The tolerance each safety claim would need, by distance from the origin.
        md +=
            "\nTolerance under which each claim would hold (the largest breach, pixels), by distance from "
            "the origin (the far families: the same local scenes, translated)";
        if (r.documentedTolerance[e] > 0)
            md += "; the engine's own: " + r.toleranceNotes[e] + " = " + pixels(r.documentedTolerance[e]) +
                  " px";
        md +=
            ". Each cell: the largest breach, then the tolerance under which the claim holds on 99% of the "
            "scenes (an upper bound, a power of two: the breaches are counted in binades; \"≥ 2^" +
            std::to_string(kTopBreachBinade) +
            "\" when it lies in the top binade, which also holds every larger breach, infinite ones "
            "included):\n\n"
            "| distance | deepest inside a tile | farthest short of touching | farthest past the exact end "
            "|\n"
            "|---|---:|---:|---:|\n";
        for (std::size_t f = 0; f < r.families.size(); ++f) {
            if (r.families[f].kind != FamilyKind::Far) continue;
            const RateCell& c = r.cells[e][f];
            const double tol = r.documentedTolerance[e];
            // The largest as measured ("inf" when infinite); the 99% bound a bin's upper edge,
            // or, in the top bin, which has no upper edge, the bin's lower one as "≥ 2^39".
            auto cell = [&](double largest, Breach b) {
                const double p99 = breachQuantile(c.breaches[static_cast<std::size_t>(b)], 0.99);
                const std::string bound = p99 == 0          ? std::string("0")
                                          : std::isinf(p99) ? "≥ 2^" + std::to_string(kTopBreachBinade)
                                                            : "≤ " + pixels(p99);
                return pixels(largest) + (tol > 0 && largest > tol ? " (over)" : "") + "; 99%: " + bound;
            };
            md += "| " + distanceName(r.families[f].magnitude) + " | " +
                  cell(c.insideDepth, Breach::InsideDepth) + " | " + cell(c.shortfall, Breach::Shortfall) +
                  " | " + cell(c.overshoot, Breach::Overshoot) + " |\n";
        }

        // Where to look: the first failing case of each claim, and why answers were missing.
        std::string firsts;
        for (const Metric m : kRateMetrics) {
            for (std::size_t f = 0; f < r.families.size(); ++f) {
                const std::uint64_t c = r.cells[e][f].firstFailure[static_cast<std::size_t>(m)];
                if (c == RateCell::kNoCase) continue;
                const std::string line =
                    r.config.scalar == "double"
                        ? formatScene(generateScene<double>(r.families[f], r.config.seed, c))
                        : formatScene(generateScene<float>(r.families[f], r.config.seed, c));
                firsts += std::string("- ") + metricHeading(m) + ", " + r.families[f].name + " case " +
                          std::to_string(c) + ": `" + line + "`\n";
                break;
            }
        }
        if (!firsts.empty())
            md +=
                "\nFirst failing scene of each claim (replay with `tilesweep resolve --resolver-cmd`):\n\n" +
                firsts;
        std::string samples;
        for (std::size_t f = 0; f < r.families.size(); ++f)
            for (const std::string& s : r.cells[e][f].noAnswerSamples)
                samples += "- " + r.families[f].name + ": " + s + "\n";
        if (!samples.empty())
            md += "\nNo answer, some reasons (with the engine's output tail):\n\n" + samples;
    }
    return md;
}

}  // namespace tilesweep::audit

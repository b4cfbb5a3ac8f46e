// SPDX-License-Identifier: MIT
#pragma once

// Engine rates: how often, where and by how much a resolver breaks each claim. Every resolver
// (an engine behind `tilesweep resolve`'s protocol, or one of tilesweep's own implementations)
// answers the same scenes (float, or double for a double engine: RatesConfig::scalar), drawn per
// family from one seed, a batch at a time; each scene
// is judged frame by frame against the exact reference (scene_judge.h). The figures per
// (resolver, family): the share of scenes that break each claim, with a 95% Wilson interval,
// and the largest distance by which a safety claim broke (how deep inside a tile, how far
// short of touching, how far past the exact end): the tolerance under which it would hold.
// The far families are the same local scenes built at each distance of kRateDistances,
// so that the tolerance is a function of the distance from the origin.
//
//     RatesConfig config;  config.cases = 2000;
//     RatesResult r = measureRates(config, {{"godot", [] { return makeGodot(); }, 0.08, "safe margin"}});
//     writeRatesJson(r, "rates.json");  std::string md = ratesMarkdown(r);
//
// Shards: a run with `shardCount` N and `shardIndex` K takes the cases whose index is K mod N, so
// N machines cover the same cases as one; mergeRates adds their results up (rates.json files
// read back with readRatesJson).

#include "tilesweep/audit/audit.h"
#include "tilesweep/audit/scene_families.h"
#include "tilesweep/audit/wilson_interval.h"
#include "tilesweep/resolvers/scene_resolver.h"
#include "tilesweep/scene/scene.h"

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace tilesweep::audit {

/// A resolver to measure.
struct EngineSpec {
    std::string name;  ///< "godot", "rapier", "tilesweep", ...
    /// Makes the resolver (resolvers/scene_resolver.h); called once per worker thread.
    std::function<std::unique_ptr<resolvers::SceneResolver>()> make;
    double documentedTolerance = 0;  ///< the engine's own tolerance, in pixels (0: none stated)
    std::string toleranceNote;       ///< what that tolerance is ("safe margin 0.08 px")
};

/// The distances from the origin the far families are measured at, in pixels: in float, and the
/// further ones a double run adds (double holds whole tiles out to 2^52).
inline const std::vector<double> kRateDistances = {0, 0x1p10, 0x1p16, 0x1p20, 0x1p24};
inline const std::vector<double> kDoubleRateDistances = {0x1p32, 0x1p40, 0x1p52};

/// The metrics a rates table shows, in order: the claims a game developer asks about most
/// (tunnelling, ending inside a tile, snagging on seams, stopping short, one-way platforms), then
/// the rest.
inline const std::vector<Metric> kRateMetrics = {
    Metric::Tunnel,       Metric::Inside,        Metric::Snag,         Metric::Short,
    Metric::PlatformFall, Metric::PlatformBlock, Metric::PlatformSnag, Metric::Overshoot,
    Metric::Missed,       Metric::Extra,         Metric::Inexact,      Metric::NoAnswer};

/// The families of a rates run in `scalar` ("float" or "double"): seven property families
/// (random, corner-pass, corner-tie, seam-landing, resting, far-sub-ulp, high-speed), the four
/// one-way families (platform-landing, platform-jump, platform-walk, platforms), then far-<d> for
/// each distance (kRateDistances, and kDoubleRateDistances in double).
[[nodiscard]] std::vector<Family> rateFamilies(const std::string& scalar = "float");

/// A histogram of breach distances, in binades: bin 0 holds the scenes that did not break the
/// claim; bin k >= 1 those whose breach lay in [2^(k-42), 2^(k-41)) pixels, except at the ends:
/// bin 1 holds every breach below 2^-40 px, and the top bin every breach of 2^kTopBreachBinade px
/// or more, infinite ones included, so it has no upper edge. Mergeable, so that shards give the
/// quantiles one run would.
constexpr std::size_t kBreachBins = 82;
using BreachHistogram = std::array<std::uint64_t, kBreachBins>;
/// The top bin holds the breaches of 2^kTopBreachBinade px (2^39) or more.
constexpr int kTopBreachBinade = static_cast<int>(kBreachBins) - 43;

/// The bin of a breach of `pixels` (0 or less: no breach).
[[nodiscard]] std::size_t breachBin(double pixels) noexcept;
/// The smallest tolerance, as a bin's upper edge, under which the claim holds on at least the
/// share `q` (in [0, 1]) of the histogram's scenes: 0 when that many did not break it, and
/// +infinity when it lies in the top bin, which has no upper edge (a breach there may be any
/// size, or infinite).
[[nodiscard]] double breachQuantile(const BreachHistogram& histogram, double q) noexcept;

/// The breach distances measured per scene, in the order of RateCell::breaches.
enum class Breach : std::uint8_t { InsideDepth, Shortfall, Overshoot };
constexpr std::size_t kBreachCount = 3;

/// The figures of one resolver on one family.
struct RateCell {
    std::uint64_t scenes = 0;
    std::array<std::uint64_t, kMetricCount> failures{};
    std::uint64_t restingEligible = 0;   ///< scenes with a frame that starts resting on a floor (snag)
    std::uint64_t platformLandings = 0;  ///< scenes with a frame that lands on a platform (platform-fall)
    std::uint64_t platformPasses = 0;    ///< scenes with a frame that passes a platform (platform-block)
    std::uint64_t platformResting = 0;   ///< scenes with a frame that starts on a platform (platform-snag)
    double insideDepth = 0;              ///< the largest depth inside a tile, pixels (may be infinite)
    double shortfall = 0;                ///< the largest distance short of touching, pixels (likewise)
    double overshoot = 0;                ///< the largest distance past the exact end, pixels (likewise)
    std::array<BreachHistogram, kBreachCount> breaches{};  ///< per Breach, every scene's distance
    /// The lowest case index that broke each metric (regenerate it with generateScene), or none.
    std::array<std::uint64_t, kMetricCount> firstFailure;
    std::vector<std::string> noAnswerSamples;  ///< a few reasons the resolver gave no answer

    RateCell() { firstFailure.fill(kNoCase); }
    static constexpr std::uint64_t kNoCase = ~std::uint64_t{0};

    /// The scenes a metric's share is out of (the resting ones for snag, those with a frame that
    /// lands on, passes or starts on a platform for the platform metrics, else all).
    [[nodiscard]] std::uint64_t trials(Metric m) const noexcept;
    /// Adds another shard's figures.
    void merge(const RateCell& other);
};

/// What to run.
struct RatesConfig {
    std::uint64_t cases = 2000;     ///< scenes per family (before sharding)
    std::uint64_t seed = 20261122;  ///< every scene derives from it
    int jobs = 0;                   ///< worker threads; 0: all cores
    int shardIndex = 0;             ///< this run takes the cases whose index is shardIndex mod shardCount
    int shardCount = 1;
    std::uint64_t batch = 1000;    ///< scenes per batch sent to a resolver
    std::string scalar = "float";  ///< the scenes' and answers' scalar type: "float" or "double"
    /// Called from the coordinating thread now and then: (scenes judged, scenes in all).
    std::function<void(std::uint64_t, std::uint64_t)> progress;
};

/// Everything a rates run found.
struct RatesResult {
    RatesConfig config;
    std::vector<std::string> engines;
    std::vector<double> documentedTolerance;  ///< per engine
    std::vector<std::string> toleranceNotes;  ///< per engine
    std::vector<Family> families;
    std::vector<std::vector<RateCell>> cells;  ///< [engine][family]
    std::vector<int> shards;                   ///< the shard indices merged into this result
    double seconds = 0;
};

/// Runs every engine on every family. Deterministic for a given seed, case count and shard.
[[nodiscard]] RatesResult measureRates(const RatesConfig& config, const std::vector<EngineSpec>& engines);

/// A scalar's view of results in JSON text, and back; throws std::runtime_error on a malformed file.
/// An infinite largest breach is written as the string "inf" (JSON has no infinity).
[[nodiscard]] std::string ratesJson(const RatesResult& result);
[[nodiscard]] RatesResult readRatesJson(const std::string& text);

/// Adds up shards of the same run (same seed, cases, scalar, shard count, engines and families, names in
/// order); throws std::invalid_argument when they are not, or when a shard appears twice, naming
/// the shard by `labels[k]` (its file, say) when given, else as "shard file k+1", and the field
/// that differs.
[[nodiscard]] RatesResult mergeRates(const std::vector<RatesResult>& shards,
                                     const std::vector<std::string>& labels = {});

/// The Markdown section: per engine the rate table (families by metrics, share and interval)
/// and the tolerance table (distance by claim), with the first failing scene of each metric.
[[nodiscard]] std::string ratesMarkdown(const RatesResult& result);

}  // namespace tilesweep::audit

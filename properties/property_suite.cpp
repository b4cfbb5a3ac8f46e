// SPDX-License-Identifier: MIT
#include "property_suite.h"

#include "coverage_judgement.h"
#include "generators.h"
#include "scene_checks.h"
#include "scene_runner.h"

#include "tilesweep/oracle/exact/exact_resolve.h"
#include "tilesweep/scene/file_write.h"
#include "tilesweep/scene/render.h"
#include "tilesweep/scene/scalar_text.h"

#include <nlohmann/json.hpp>
#include <rapidcheck.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <stdexcept>

namespace tilesweep::properties {
namespace {

std::uint64_t fnv1a(const std::string& text) {
    std::uint64_t h = 1469598103934665603ull;
    for (const char c : text) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
    return h;
}

/// Writes `text` to `path` whole or not at all (writeFileWhole), its directory made first.
void writeAtomically(const std::filesystem::path& path, const std::string& text) {
    std::filesystem::create_directories(path.parent_path());
    std::string error;
    if (!writeFileWhole(path.string(), text, error)) throw std::runtime_error(error);
}

/// The seed of a run's coverage round `round` (> 0): far from the seeds `tilesweep check` gives
/// its own later rounds (seed + 1, seed + 2, ...).
std::uint64_t coverageRoundSeed(std::uint64_t seed, int round) {
    std::uint64_t h = seed ^ (0x9e3779b97f4a7c15ull * static_cast<std::uint64_t>(round));
    h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ull;
    h = (h ^ (h >> 27)) * 0x94d049bb133111ebull;
    return h ^ (h >> 31);
}

std::string percent(double share) {
    char text[32];
    std::snprintf(text, sizeof text, share < 0.01 ? "%.2f%%" : "%.1f%%", 100 * share);
    return text;
}

/// Judges every floor on the cases seen so far; fills the outcome's coverage fields when
/// `final`. Returns whether some floor is still undecided.
bool judgeFloors(const std::vector<CoverageFloor>& floors, PropertyOutcome& outcome, bool final) {
    bool undecided = false;
    for (const CoverageFloor& floor : floors) {
        const auto found = outcome.tagCounts.find(floor.tag);
        const long long hits = found == outcome.tagCounts.end() ? 0 : found->second;
        const FloorVerdict verdict = judgeFloor(hits, outcome.cases, floor.fraction);
        undecided = undecided || verdict == FloorVerdict::Undecided;
        if (!final || verdict == FloorVerdict::Met) continue;
        const ShareInterval share = wilsonInterval(hits, outcome.cases);
        const double seen = outcome.cases > 0 ? double(hits) / outcome.cases : 0.0;
        std::string& text =
            verdict == FloorVerdict::Short ? outcome.coverageShortfall : outcome.coverageUndecided;
        text += (text.empty() ? "" : "; ") + std::string("'") + floor.tag + "' in " + percent(seen) + " of " +
                std::to_string(outcome.cases) + " cases (between " + percent(share.low) + " and " +
                percent(share.high) + " at error rate 1e-9), " +
                (verdict == FloorVerdict::Short ? "below" : "not settled against") + " the floor of " +
                percent(floor.fraction);
    }
    return undecided;
}

/// One RapidCheck run of a claim: `cases` cases from `seed`.
template <class T>
PropertyOutcome runClaimOnce(const std::string& propertyName, const Claim<T>& claim, Family family,
                             const RunOptions& options) {
    PropertyOutcome outcome;
    GeneratedScene<T> lastFailure;
    std::string lastMessage;
    bool failed = false;
    int counted = 0;  // failing cases, when counting (!options.shrink)
    std::chrono::steady_clock::time_point firstFailure{};
    bool shrinkingStopped = false;
    const auto property = [&] {
        // Past the shrinking budget every further candidate counts as passing, unjudged, so that
        // RapidCheck ends with the smallest failing case found so far (with an outside resolver
        // each candidate is a request: an engine that starts slowly would shrink for minutes).
        if (failed && options.shrink && options.shrinkSeconds > 0 &&
            std::chrono::duration<double>(std::chrono::steady_clock::now() - firstFailure).count() >
                options.shrinkSeconds) {
            shrinkingStopped = true;
            return;
        }
        const GeneratedScene<T> g = *genScene<T>(family);
        // One RC_TAG per case (a second would replace the first): the classes, space-separated.
        std::string tags = std::string("family:") + familyName(g.family);
        for (const std::string& tag : classifyScene(g.scene)) {
            tags += " " + tag;
            // The rounding rule's exception per family, for the share each family reaches.
            if (tag == "rounded-down") tags += std::string(" rounded-down@") + familyName(g.family);
        }
        RC_TAG(tags);
        std::string message;
        try {
            message = checkClaim(claim, g.scene);
        } catch (const RehearsalDone&) {
            return;  // a rehearsal (scene_runner.h): the case's scenes are noted, not judged
        }
        if (!message.empty()) {
            if (!failed && options.onFirstFailure) options.onFirstFailure(message, formatScene(g.scene));
            if (!options.shrink) {  // counting: every case is judged; the first failure is kept
                if (!failed) {
                    lastFailure = g;
                    lastMessage = message;
                }
                failed = true;
                ++counted;
                return;
            }
            // RapidCheck shrinks by keeping failing cases, so the last failure seen is the
            // minimal one it reports.
            if (!failed) firstFailure = std::chrono::steady_clock::now();
            lastFailure = g;
            lastMessage = message;
            failed = true;
            RC_FAIL(message);
        }
    };
    rc::detail::TestParams params;
    params.seed = options.seed;
    params.maxSuccess = options.cases;
    params.disableShrinking = !options.shrink;
    rc::detail::TestMetadata metadata;
    metadata.id = propertyName;
    metadata.description = propertyName;
    const rc::detail::TestResult result = rc::detail::checkTestable(property, metadata, params);

    rc::detail::SuccessResult success{};
    if (result.template is<rc::detail::SuccessResult>()) {
        success = result.template get<rc::detail::SuccessResult>();
        outcome.cases = success.numSuccess;
        for (const auto& [tags, count] : success.distribution)
            for (const std::string& shown : tags) {
                // RC_TAG shows its value, so the string arrives in quotes.
                const bool quoted = shown.size() >= 2 && shown.front() == '"' && shown.back() == '"';
                std::istringstream words(quoted ? shown.substr(1, shown.size() - 2) : shown);
                std::string tag;
                while (words >> tag) outcome.tagCounts[tag] += count;
            }
        outcome.passed = counted == 0;
        if (counted > 0) {
            outcome.cases = success.numSuccess - counted;
            outcome.failedCases = counted;
            outcome.sceneLine = formatScene(lastFailure.scene);
            outcome.failure = lastMessage;
            outcome.message = lastMessage + "\n(" + std::to_string(counted) + " of " +
                              std::to_string(success.numSuccess) + " cases failed; the first, not shrunk) " +
                              familyName(lastFailure.family) + " scene: " + outcome.sceneLine;
        }
    } else if (result.template is<rc::detail::FailureResult>()) {
        const auto failure = result.template get<rc::detail::FailureResult>();
        outcome.cases = failure.numSuccess;
        outcome.failedCases = 1;
        if (shrinkingStopped) lastMessage += " (shrinking stopped after the --shrink-seconds budget)";
        outcome.message = lastMessage + "\n" +
                          (failed ? familyName(lastFailure.family) + std::string(" scene: ") +
                                        formatScene(lastFailure.scene)
                                  : std::string());
        if (failed) {
            outcome.sceneLine = formatScene(lastFailure.scene);
            outcome.failure = lastMessage;
        }
        if (failed && !options.corpusDir.empty()) {
            const std::string sceneLine = formatScene(lastFailure.scene);
            char hash[17];
            std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(fnv1a(sceneLine)));
            const std::filesystem::path file = std::filesystem::path(options.corpusDir) /
                                               (propertyName + "-" + std::string(hash, 8) + ".jsonl");
            // An outside resolver's failure carries its command and its answer beside the exact
            // one; the picture shows what it did, or the exact frames when it gave no answer.
            std::string extra;
            std::vector<FrameResult<T>> pictured;
            if (SceneRunner<T>* outside = currentSceneRunner<T>()) {
                nlohmann::ordered_json fields;
                fields["resolver_cmd"] = outside->name();
                const std::string answer = outside->answerText(lastFailure.scene);
                const nlohmann::ordered_json parsedAnswer =
                    nlohmann::ordered_json::parse(answer, nullptr, false);
                fields["resolver_answer"] =
                    parsedAnswer.is_discarded() ? nlohmann::ordered_json(answer) : parsedAnswer;
                const std::vector<FrameResult<T>> exact = oracle::resolveSceneExactRounded(lastFailure.scene);
                fields["exact_answer"] = nlohmann::ordered_json::parse(formatFrames(exact));
                extra = fields.dump();
                try {
                    pictured = resolveUnderTest(lastFailure.scene);
                } catch (const std::exception&) {
                    pictured = exact;
                }
            } else {
                pictured = runScene(lastFailure.scene);
            }
            writeAtomically(file, corpusLine(sceneLine, propertyName, options.seed, detail::scalarName<T>(),
                                             lastMessage, extra) +
                                      "\n");
            outcome.corpusFile = file.string();
            std::filesystem::path picture = file;
            picture.replace_extension(".svg");
            writeAtomically(picture, renderSceneSvg(lastFailure.scene, pictured));
            outcome.pictureFile = picture.string();
        }
    } else {
        outcome.message = "RapidCheck gave up";
    }
    return outcome;
}

/// A claim's run: `options.cases` cases, then, while some coverage floor is undecided (neither
/// certainly met nor certainly short: coverage_judgement.h), rounds of as many cases again as
/// have run, from seeds of their own, up to the cap. Every case of every round checks the claim.
/// The tags come from the scene's exact resolution and tilesweep's own decision path
/// (classifyScene), never from an outside resolver's answers, so a shortfall is the generator's.
template <class T>
PropertyOutcome runClaim(const std::string& propertyName, const Claim<T>& claim, Family family,
                         const std::vector<CoverageFloor>& floors, const RunOptions& options) {
    const auto started = std::chrono::steady_clock::now();
    const long long cap =
        options.maxCases > 0 ? options.maxCases : std::max(8LL * options.cases, kDefaultCoverageCases);
    PropertyOutcome outcome;
    RunOptions round = options;
    for (int r = 0;; ++r) {
        if (r > 0) {
            round.seed = coverageRoundSeed(options.seed, r);
            round.cases = static_cast<int>(std::min<long long>(outcome.cases, cap - outcome.cases));
        }
        PropertyOutcome part = runClaimOnce<T>(propertyName, claim, family, round);
        const int casesBefore = outcome.cases;
        outcome.cases += part.cases;
        for (const auto& [tag, count] : part.tagCounts) outcome.tagCounts[tag] += count;
        if (!part.passed) {
            part.cases = outcome.cases;
            part.tagCounts = outcome.tagCounts;
            if (r > 0)
                part.message += "\n(in coverage round " + std::to_string(r) + ": seed " +
                                std::to_string(round.seed) + ", " + std::to_string(round.cases) +
                                " cases, after " + std::to_string(casesBefore) + " that passed)";
            outcome = part;
            break;
        }
        outcome.passed = true;
        const bool undecided = judgeFloors(floors, outcome, false);
        if (!undecided || outcome.cases >= cap || part.cases == 0) {
            judgeFloors(floors, outcome, true);
            break;
        }
    }
    outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return outcome;
}

template <class T>
void addClaim(std::vector<Property>& out, const std::string& propertyName, const std::string& claimName,
              Family family, std::vector<CoverageFloor> floors) {
    const Claim<T>* claim = findClaim<T>(claimName);
    const std::string name = propertyName + "_" + detail::scalarName<T>();
    out.push_back({name, claimName, claim->scope, detail::scalarName<T>(), floors,
                   [name, claim, family, floors](const RunOptions& o) {
                       return runClaim<T>(name, *claim, family, floors, o);
                   }});
}

template <class T>
void addAll(std::vector<Property>& out) {
    // The floors say what a run must have seen for its pass to mean something.
    addClaim<T>(out, "matchesExactReferenceBitForBit", "matchesExactReferenceBitForBit", Family::Mixed,
                {{"hit", 0.2},
                 {"miss", 0.1},
                 {"tie", 0.03},
                 {"touch-at-0", 0.03},
                 {"two-step", 0.005},
                 {"family:corner-pass", 0.05},
                 {"seam", 0.02},
                 {"far-origin", 0.03}});
    // The corner, tie and far-origin families must reach the band where the resolver's fast path
    // cannot decide alone ("fallback": a filtered refinement or the exact lattice).
    addClaim<T>(out, "decidesCornerPassesExactly", "matchesExactReferenceBitForBit", Family::CornerPass,
                {{"hit", 0.1}, {"miss", 0.1}, {"fallback", 0.05}});
    addClaim<T>(out, "settlesCornerTiesByExposedFace", "matchesExactReferenceBitForBit", Family::CornerTie,
                {{"tie", 0.3}, {"fallback", 0.05}});
    addClaim<T>(
        out, "broadphaseOffersEveryBlockingTile", "matchesExactReferenceBitForBit", Family::Random,
        {{"hit", 0.10}, {"two-step", 0.02}});  // about 18.6% on average, 14.4% in the worst of 4,700 rounds
    addClaim<T>(out, "neverEndsInsideATileItDidNotStartIn", "neverEndsInsideATileItDidNotStartIn",
                Family::Mixed, {{"hit", 0.2}, {"rounded-down", 0.002}});
    addClaim<T>(out, "stopsJustTouching", "stopsJustTouching", Family::Mixed, {{"hit", 0.2}});
    addClaim<T>(out, "obeysTheSafetyRules", "obeysTheSafetyRules", Family::Mixed, {{"hit", 0.2}});
    // The rounding rule's family: the exception must change the result in a good share of it.
    addClaim<T>(out, "roundsFarEdgesByTheAmendedRule", "matchesExactReferenceBitForBit", Family::FarEdge,
                {{"rounded-down", 0.05}, {"hit", 0.2}});
    addClaim<T>(out, "neverGetsIntoAWall", "neverGetsIntoAWall", Family::FarEdge, {{"rounded-down", 0.05}});
    // Events the other families do not aim at: each has its floor.
    // In double, exact ties whose filter error lies in the band's upper half (filter_band_family.h):
    // what a halved bound decides wrongly.
    addClaim<T>(out, "decidesTiesInsideTheFilterBand", "matchesExactReferenceBitForBit", Family::FilterBand,
                std::is_same<T, double>::value
                    ? std::vector<CoverageFloor>{{"tie", 0.5}, {"fallback", 0.5}, {"filter-upper-half", 0.5}}
                    : std::vector<CoverageFloor>{{"tie", 0.5}, {"fallback", 0.5}});
    // In double, the code only double frames reach (productError's aLow * bLow term, the remainder
    // test of roundTimeToDouble) on purpose: refinements on inputs of full precision (35%).
    std::vector<CoverageFloor> fineBits = {
        {"time-tie", 0.05}, {"reaches-at-end", 0.05}, {"lattice-wide", 0.05}, {"lattice-192", 0.03}};
    if (std::is_same<T, double>::value) fineBits.push_back({"full-precision-refined", 0.15});
    addClaim<T>(out, "decidesFineBitsExactly", "matchesExactReferenceBitForBit", Family::FineBits, fineBits);
    // Float far edges all take the fast path, whose range test has no slack: the float range
    // test's edge has its own family and floor (decidesRangeEdgeScenesExactly).
    addClaim<T>(out, "farEdgesNeverEndInsideATile", "neverEndsInsideATileItDidNotStartIn", Family::FarEdge,
                std::is_same<T, double>::value
                    ? std::vector<CoverageFloor>{{"rounded-down", 0.05}, {"fallback", 0.05}}
                    : std::vector<CoverageFloor>{{"rounded-down", 0.05}});
    addClaim<T>(out, "farEdgesObeyTheSafetyRules", "obeysTheSafetyRules", Family::FarEdge,
                {{"rounded-down", 0.05}});
    addClaim<T>(out, "substepOracleFindsNoMissedContact", "substepOracleFindsNoMissedContact", Family::Mixed,
                {{"hit", 0.2}});
    // Contact positions: the one new number (a step-1 hit the box slides on from, after t = 0, at a
    // coordinate T cannot hold) must be reached: about 45%, 36% and 17% at 2,000 cases.
    addClaim<T>(out, "placesContactsLikeTheExactReference", "placesContactsLikeTheExactReference",
                Family::Mixed,
                {{"hit", 0.2},
                 {"hit-then-slide", 0.2},
                 {"late-hit-then-slide", 0.15},
                 {"hit-then-slide-rounded", 0.05}});
    addClaim<T>(out, "exactReferenceAgreesWithSubsteps", "exactReferenceAgreesWithSubsteps", Family::Mixed,
                {{"hit", 0.2}, {"touch-at-0", 0.03}});
    addClaim<T>(out, "zeroMoveChangesNothing", "zeroMoveChangesNothing", Family::Mixed, {});
    // Bad input, sweepBox, empty maps, huge moves: inputs the other families seldom make.
    addClaim<T>(out, "badInputIsRejected", "badInputIsRejected", Family::Mixed, {});
    addClaim<T>(out, "sweepBoxMatchesTheReference", "sweepBoxMatchesTheReference", Family::Mixed,
                {{"hit", 0.2}, {"tie", 0.03}});
    addClaim<T>(out, "handlesEmptyMapsAndHugeMovesExactly", "matchesExactReferenceBitForBit", Family::Extreme,
                {{"empty-map", 0.2}, {"huge-move", 0.3}});
    addClaim<T>(out, "extremeScenesObeyTheSafetyRules", "obeysTheSafetyRules", Family::Extreme,
                {{"empty-map", 0.2}, {"huge-move", 0.3}});
    addClaim<T>(out, "scalingByPowerOfTwoScalesTheResult", "scalingByPowerOfTwoScalesTheResult",
                Family::Mixed, {{"hit", 0.2}, {"tie", 0.02}});
    addClaim<T>(out, "mirroringXMirrorsTheResult", "mirroringXMirrorsTheResult", Family::Mixed,
                {{"hit", 0.2}});
    addClaim<T>(out, "mirroringYMirrorsTheResult", "mirroringYMirrorsTheResult", Family::Mixed,
                {{"hit", 0.2}});
    addClaim<T>(out, "translatingByWholeTilesKeepsDecisions", "translatingByWholeTilesKeepsDecisions",
                Family::Mixed, {{"hit", 0.2}});
    addClaim<T>(out, "roundingNearFarCornersStaysOutOfHitTiles", "neverEndsInsideATileItDidNotStartIn",
                Family::FarSubUlp, {{"far-origin", 0.9}, {"fallback", 0.05}});
    addClaim<T>(out, "neverTunnelsAtHighSpeed", "matchesExactReferenceBitForBit", Family::HighSpeed,
                {{"hit", 0.5}});
    addClaim<T>(out, "restingContactIsStable", "restingContactIsStable", Family::Resting,
                {{"touch-at-0", 0.3}});
    addClaim<T>(out, "slidingAlongFloorNeverSnags", "slidingAlongFloorNeverSnags", Family::SeamLanding,
                {{"seam", 0.1}, {"touch-at-0", 0.2}});
    // Four classes of inputs random scenes reach rarely, each with a family aimed at it (double
    // near-ties, the tiny end of the range, capacity boundaries, error codes). Corner entries one
    // ulp off a tie, whose products differ by less than the filter's bound: the refinement
    // decides a nonzero sign.
    // (Float frames hold every product exactly in double: no refinement there, the same claim.)
    const bool isDouble = std::is_same<T, double>::value;
    addClaim<T>(out, "decidesNearTiesInsideTheFilterBand", "matchesExactReferenceBitForBit", Family::NearTie,
                isDouble ? std::vector<CoverageFloor>{{"near-tie-refined", 0.1},
                                                      {"full-precision-refined", 0.1},
                                                      {"hit", 0.5}}
                         : std::vector<CoverageFloor>{{"hit", 0.5}});
    // The tiny end of the range: scenes scaled by powers of two near the least normal value.
    addClaim<T>(out, "decidesTinyScenesExactly", "matchesExactReferenceBitForBit", Family::TinyScale,
                {{"tiny", 0.5}, {"hit", 0.1}});
    // Capacity boundaries: buffers of exactly the count and the bound, the inline limit, the wide
    // path at its bound; and the same on every kind of scene.
    addClaim<T>(out, "storesContactsAtExactCapacity", "storesContactsAtExactCapacity", Family::Capacity,
                {{"bound-inline-limit", 0.15}, {"bound-wide", 0.15}, {"many-contacts", 0.3}});
    addClaim<T>(out, "storesEveryFramesContactsAtExactCapacity", "storesContactsAtExactCapacity",
                Family::Mixed, {{"hit", 0.2}, {"two-step", 0.005}});
    // The edge of the float range test (range-edge): spans 52 to 57 (range_edge_family.h), bit for
    // bit; the scenes four binades past it catch a test that much too generous.
    addClaim<T>(out, "decidesRangeEdgeScenesExactly", "matchesExactReferenceBitForBit", Family::RangeEdge,
                isDouble ? std::vector<CoverageFloor>{{"hit", 0.9}}
                         : std::vector<CoverageFloor>{{"range-boundary", 0.6}, {"hit", 0.9}});
    // One-way platforms (platform_family.h): landing on them at every speed and on exact
    // corners, jumping up through them, walking along them across seams, and platforms among
    // solid tiles; bit for bit, and by the rules a platformer relies on.
    addClaim<T>(out, "landsOnPlatformsExactly", "matchesExactReferenceBitForBit", Family::PlatformLanding,
                {{"one-way-hit", 0.3},
                 {"one-way-tie", 0.03},
                 {"one-way-fast", 0.1},
                 {"in-one-way", 0.1},
                 {"far-origin", 0.1}});
    addClaim<T>(out, "jumpsThroughPlatformsExactly", "matchesExactReferenceBitForBit", Family::PlatformJump,
                {{"in-one-way", 0.3}, {"one-way-hit", 0.15}, {"starts-in-one-way", 0.1}});
    addClaim<T>(out, "walksAlongPlatformsExactly", "matchesExactReferenceBitForBit", Family::PlatformWalk,
                {{"on-platform", 0.75}, {"one-way-seam", 0.1}});
    addClaim<T>(out, "decidesPlatformsAmongSolidTilesExactly", "matchesExactReferenceBitForBit",
                Family::Platforms, {{"one-way-hit", 0.05}, {"starts-in-one-way", 0.05}});
    addClaim<T>(out, "neverFallsThroughAPlatformItStoodOn", "neverFallsThroughAPlatformItStoodOn",
                Family::PlatformWalk, {{"on-platform", 0.75}});
    addClaim<T>(out, "neverBlockedByAPlatformFromBelow", "neverBlockedByAPlatformFromBelow",
                Family::PlatformJump, {{"in-one-way", 0.3}, {"one-way-hit", 0.15}});
    addClaim<T>(out, "neverSnagsOnAPlatformSeam", "slidingAlongFloorNeverSnags", Family::PlatformWalk,
                {{"on-platform", 0.75}, {"one-way-seam", 0.1}});
    addClaim<T>(out, "platformScenesObeyTheSafetyRules", "obeysTheSafetyRules", Family::Platforms,
                {{"one-way-hit", 0.05}, {"starts-in-one-way", 0.05}});
    addClaim<T>(out, "substepOracleSeesEveryPlatformLanding", "substepOracleFindsNoMissedContact",
                Family::PlatformLanding, {{"one-way-hit", 0.3}});
    // Every C error code from its own cause, through C.
    addClaim<T>(out, "reportsEachCErrorByItsCause", "reportsEachCErrorByItsCause", Family::Mixed,
                {{"edge-causes-built", 0.9}});
}

}  // namespace

const std::vector<Property>& allProperties() {
    static const std::vector<Property> properties = [] {
        std::vector<Property> out;
        addAll<float>(out);
        addAll<double>(out);
        return out;
    }();
    return properties;
}

Property makeProperty(const std::string& name, const std::string& claimName, const std::string& scalar,
                      const std::string& family, std::vector<CoverageFloor> floors) {
    Family chosen = Family::Mixed;
    bool known = family == familyName(Family::Mixed);
    for (const Family f : allFamilies())
        if (family == familyName(f)) {
            chosen = f;
            known = true;
        }
    if (!known) throw std::invalid_argument("no family '" + family + "'");
    if (scalar != "float" && scalar != "double") throw std::invalid_argument("no scalar '" + scalar + "'");
    const bool isFloat = scalar == "float";
    if (isFloat ? findClaim<float>(claimName) == nullptr : findClaim<double>(claimName) == nullptr)
        throw std::invalid_argument("no claim '" + claimName + "'");
    std::vector<Property> made;
    if (isFloat)
        addClaim<float>(made, name, claimName, chosen, std::move(floors));
    else
        addClaim<double>(made, name, claimName, chosen, std::move(floors));
    made.front().name = name;
    return made.front();
}

RunOptions optionsFromEnvironment() {
    RunOptions options;
    if (const char* seed = std::getenv("TILESWEEP_PROPERTY_DEFAULT_SEED"))
        options.seed = std::strtoull(seed, nullptr, 10);
    if (const char* seed = std::getenv("TILESWEEP_PROPERTY_SEED"))
        options.seed = std::strtoull(seed, nullptr, 10);
    if (const char* cases = std::getenv("TILESWEEP_PROPERTY_CASES")) options.cases = std::atoi(cases);
    if (const char* dir = std::getenv("TILESWEEP_CORPUS_DIR")) options.corpusDir = dir;
    return options;
}

std::string corpusLine(const std::string& sceneLine, const std::string& property, std::uint64_t seed,
                       const std::string& scalar, const std::string& failure, const std::string& extra) {
    nlohmann::ordered_json line = nlohmann::ordered_json::parse(sceneLine);
    line["property"] = property;
    line["seed"] = seed;
    line["scalar"] = scalar;
    line["failure"] = failure;
    if (!extra.empty()) line.update(nlohmann::ordered_json::parse(extra));
    return line.dump();
}

}  // namespace tilesweep::properties

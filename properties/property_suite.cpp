// SPDX-License-Identifier: MIT
#include "property_suite.h"

#include "generators.h"
#include "oracle/exact/exact_resolve.h"
#include "scene_checks.h"
#include "scene_runner.h"

#include "tilesweep/scene/render.h"

#include <nlohmann/json.hpp>
#include <rapidcheck.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace tilesweep::properties {
namespace {

std::uint64_t fnv1a(const std::string& text) {
    std::uint64_t h = 1469598103934665603ull;
    for (const char c : text) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
    return h;
}

/// Writes `text` to `path` whole or not at all (a temporary file, then a rename).
void writeAtomically(const std::filesystem::path& path, const std::string& text) {
    std::filesystem::create_directories(path.parent_path());
    const std::filesystem::path temporary = path.string() + ".tmp";
    {
        std::ofstream out(temporary, std::ios::binary);
        out << text;
        if (!out) throw std::runtime_error("cannot write " + temporary.string());
    }
    std::filesystem::rename(temporary, path);
}

template <class T>
const char* scalarName() {
    return std::is_same<T, float>::value ? "float" : "double";
}

template <class T>
PropertyOutcome runClaim(const std::string& propertyName, const Claim<T>& claim, Family family,
                         const std::vector<CoverageFloor>& floors, const RunOptions& options) {
    const auto started = std::chrono::steady_clock::now();
    PropertyOutcome outcome;
    GeneratedScene<T> lastFailure;
    std::string lastMessage;
    bool failed = false;
    const auto property = [&] {
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
            // RapidCheck shrinks by keeping failing cases, so the last failure seen is the
            // minimal one it reports.
            lastFailure = g;
            lastMessage = message;
            failed = true;
            RC_FAIL(message);
        }
    };
    rc::detail::TestParams params;
    params.seed = options.seed;
    params.maxSuccess = options.cases;
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
        outcome.passed = true;
        for (const CoverageFloor& floor : floors) {
            const double seen =
                outcome.cases > 0 ? double(outcome.tagCounts[floor.tag]) / outcome.cases : 0.0;
            if (seen < floor.fraction) {
                outcome.passed = false;
                char text[200];
                std::snprintf(text, sizeof text,
                              "coverage: '%s' in %.1f%% of cases, below the floor of %.1f%%; ",
                              floor.tag.c_str(), 100 * seen, 100 * floor.fraction);
                outcome.message += text;
            }
        }
    } else if (result.template is<rc::detail::FailureResult>()) {
        const auto failure = result.template get<rc::detail::FailureResult>();
        outcome.cases = failure.numSuccess;
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
            writeAtomically(
                file, corpusLine(sceneLine, propertyName, options.seed, scalarName<T>(), lastMessage, extra) +
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
    outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return outcome;
}

template <class T>
void addClaim(std::vector<Property>& out, const std::string& propertyName, const std::string& claimName,
              Family family, std::vector<CoverageFloor> floors) {
    const Claim<T>* claim = findClaim<T>(claimName);
    const std::string name = propertyName + "_" + scalarName<T>();
    out.push_back({name, claimName, claim->scope, scalarName<T>(), floors,
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
    addClaim<T>(out, "decidesTiesInsideTheFilterBand", "matchesExactReferenceBitForBit", Family::FilterBand,
                {{"tie", 0.5}, {"fallback", 0.5}});
    addClaim<T>(
        out, "decidesFineBitsExactly", "matchesExactReferenceBitForBit", Family::FineBits,
        {{"time-tie", 0.05}, {"reaches-at-end", 0.05}, {"lattice-wide", 0.05}, {"lattice-192", 0.03}});
    addClaim<T>(out, "farEdgesNeverEndInsideATile", "neverEndsInsideATileItDidNotStartIn", Family::FarEdge,
                {{"rounded-down", 0.05}, {"fallback", 0.05}});
    addClaim<T>(out, "farEdgesObeyTheSafetyRules", "obeysTheSafetyRules", Family::FarEdge,
                {{"rounded-down", 0.05}});
    addClaim<T>(out, "substepOracleFindsNoMissedContact", "substepOracleFindsNoMissedContact", Family::Mixed,
                {{"hit", 0.2}});
    addClaim<T>(out, "exactReferenceAgreesWithSubsteps", "exactReferenceAgreesWithSubsteps", Family::Mixed,
                {{"hit", 0.2}, {"touch-at-0", 0.03}});
    addClaim<T>(out, "zeroMoveChangesNothing", "zeroMoveChangesNothing", Family::Mixed, {});
    // What only the unit tests reached before: bad input, sweepBox, empty maps, huge moves.
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

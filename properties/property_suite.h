// SPDX-License-Identifier: MIT
#pragma once

// The property suite: one property for each (claim, family, floors) a claim declares (claim.h),
// in float and in double, with a runner. The GoogleTest suite (properties_test.cpp) and
// `tilesweep check` both run these; a failure shrinks along RapidCheck's shrinks, and the minimal
// scene is written to the regression corpus with the property and seed that found it.

#include "all_claims.h"

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace tilesweep::properties {

/// How to run a property.
struct RunOptions {
    std::uint64_t seed = 20261122;  ///< RapidCheck seed; the same seed gives the same cases
    /// The resolver the claims are held against; nullptr: tilesweep's own (the registry's core).
    SceneResolver* resolver = nullptr;
    int cases = 1000;       ///< successful cases before the property passes
    std::string corpusDir;  ///< where a shrunk counterexample is written; empty: nowhere
    /// Most cases a run may draw, in all, to settle its coverage floors (coverage_judgement.h);
    /// 0: the larger of 8 x cases and kDefaultCoverageCases.
    long long maxCases = 0;
    double shrinkSeconds = 0;  ///< stop shrinking this long after the first failure (keeping the
                               ///< smallest case found so far); 0: no limit
    bool shrink = true;        ///< false: count instead: every case is judged, the failures counted and the
                               ///< first one kept unshrunk (later rounds of a property already shrunk)
    /// Told the claim's message and the scene line of the run's first failing case as soon as it
    /// is found, before shrinking: a run stopped while it shrinks still has a counterexample.
    std::function<void(const std::string& message, const std::string& sceneLine)> onFirstFailure;
};

/// The least cap on a run's cases when its floors need more than `cases` to settle: enough for
/// a floor of 1% whose true share is 2% (about 6,000 cases) with room to spare.
inline constexpr long long kDefaultCoverageCases = 16000;

/// What one run of a property found. A claim that held can still have insufficient coverage:
/// that is the generator's shortfall, never the resolver's (coverage tags come from the scene and
/// the exact reference), so it is reported apart from `passed`.
struct PropertyOutcome {
    bool passed = false;  ///< no case falsified the claim
    int cases = 0;        ///< cases that passed, over every coverage round
    int failedCases = 0;  ///< cases that falsified the claim: 1 when a run stops at its first failure
                          ///< to shrink it, every failing case when it counts (RunOptions::shrink false)
    std::map<std::string, int> tagCounts;  ///< cases per coverage tag
    std::string message;                   ///< why the claim failed (the counterexample)
    /// The floors certainly missed (insufficient coverage), each with its share and interval;
    /// empty when every floor was met or left undecided at the cap.
    std::string coverageShortfall;
    /// The floors neither met nor missed when the cap on cases was reached (not a failure).
    std::string coverageUndecided;
    std::string corpusFile;   ///< the regression file written, if any
    std::string pictureFile;  ///< its picture (SVG), if any
    std::string sceneLine;    ///< the minimal failing scene (hexfloats), if any
    std::string failure;      ///< the claim's message on it, if any
    double seconds = 0;
};

/// One property: a claim, in one scalar type, over one scene family.
struct Property {
    std::string name;   ///< claim name and scalar, e.g. "matchesExactReferenceBitForBit_float"
    std::string claim;  ///< the claim it checks (all_claims.h), e.g. "matchesExactReferenceBitForBit"
    ClaimScope scope = ClaimScope::Internal;  ///< the claim's scope: which resolvers it applies to
    std::string scalar;                       ///< "float" or "double"
    std::vector<CoverageFloor> floors;
    std::function<PropertyOutcome(const RunOptions&)> run;
};

/// Every property of the suite.
[[nodiscard]] const std::vector<Property>& allProperties();

/// A property outside the suite's table, as addClaim builds them: `claimName` (all_claims.h) in
/// `scalar` ("float" or "double") over the family named `family` (familyName), with `floors`.
/// Throws std::invalid_argument for an unknown claim, scalar or family.
[[nodiscard]] Property makeProperty(const std::string& name, const std::string& claimName,
                                    const std::string& scalar, const std::string& family,
                                    std::vector<CoverageFloor> floors);

/// Options from the environment: TILESWEEP_PROPERTY_SEED (else TILESWEEP_PROPERTY_DEFAULT_SEED,
/// which ctest sets per discovered test), TILESWEEP_PROPERTY_CASES and TILESWEEP_CORPUS_DIR
/// (default: none, so test runs never write into the source tree).
[[nodiscard]] RunOptions optionsFromEnvironment();

/// The line written for a failing scene: the scene (hexfloats) with "property", "seed",
/// "scalar" and "failure" fields, which the scene reader ignores. `extra`, a JSON object's
/// text when not empty, adds its members (an outside resolver's "resolver_cmd",
/// "resolver_answer" and "exact_answer").
[[nodiscard]] std::string corpusLine(const std::string& sceneLine, const std::string& property,
                                     std::uint64_t seed, const std::string& scalar,
                                     const std::string& failure, const std::string& extra = {});

}  // namespace tilesweep::properties

// SPDX-License-Identifier: MIT
#pragma once

// The property suite: every claim of scene_checks.h paired with the scene family that exercises
// it, the coverage it must reach, and a runner. The GoogleTest suite (properties_test.cpp) and
// `tilesweep check` both run these; a failure shrinks (RapidCheck) and the minimal scene is
// written to the regression corpus with the property and seed that found it.

#include "scene_checks.h"

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
    int cases = 1000;               ///< successful cases before the property passes
    std::string corpusDir;          ///< where a shrunk counterexample is written; empty: nowhere
};

/// What one run of a property found.
struct PropertyOutcome {
    bool passed = false;
    int cases = 0;                         ///< cases that passed
    std::map<std::string, int> tagCounts;  ///< cases per coverage tag
    std::string message;                   ///< why it failed (counterexample, or coverage)
    std::string corpusFile;                ///< the regression file written, if any
    std::string pictureFile;               ///< its picture (SVG), if any
    std::string sceneLine;                 ///< the minimal failing scene (hexfloats), if any
    std::string failure;                   ///< the claim's message on it, if any
    double seconds = 0;
};

/// A coverage floor: at least `fraction` of the cases must carry `tag`.
struct CoverageFloor {
    std::string tag;
    double fraction;
};

/// One property: a claim, in one scalar type, over one scene family.
struct Property {
    std::string name;   ///< claim name and scalar, e.g. "matchesExactReferenceBitForBit_float"
    std::string claim;  ///< the claim it checks (scene_checks.h), e.g. "matchesExactReferenceBitForBit"
    ClaimScope scope = ClaimScope::Internal;  ///< the claim's scope: which resolvers it applies to
    std::string scalar;                       ///< "float" or "double"
    std::vector<CoverageFloor> floors;
    std::function<PropertyOutcome(const RunOptions&)> run;
};

/// Every property of the suite.
[[nodiscard]] const std::vector<Property>& allProperties();

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

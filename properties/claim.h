// SPDX-License-Identifier: MIT
#pragma once

// What a claim is: a check of one scene against the resolver under test, with everything the
// suite needs to know about it, declared once beside its definition (the group functions at the
// end of safety_claims.cpp, exact_reference_claims.cpp, metamorphic_claims.cpp,
// game_feel_claims.cpp and boundary_claims.cpp):
//
//     {"stopsJustTouching", &stopsJustTouching<T>, ClaimScope::Safety, nullptr,
//      {{"stopsJustTouching", Family::Mixed, {{"hit", 0.2}}}}},
//
// its name, its check, its scope (which resolvers it holds), the scenes it asks the resolver for,
// and its properties: each a family of generated scenes with the coverage floors a run of it must
// reach (the tags are classifyScene's, all_claims.h). all_claims.cpp gathers the groups; the
// property suite (property_suite.h) makes one property per entry and scalar type.

#include "generators.h"
#include "resolver_under_test.h"

#include "tilesweep/scene/scene.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tilesweep::properties {

/// What a claim is about, which says whether an outside resolver is held to it
/// (`tilesweep check --resolver-cmd`).
enum class ClaimScope : std::uint8_t {
    Safety,     ///< about results, under no particular rounding: any sound resolver holds it
    BitForBit,  ///< about results, bit for bit against the exact reference and the contract's rounding
    Internal,   ///< about tilesweep's internals, its C++ API or the oracles: built-in only
};

/// A coverage floor: at least `fraction` of the cases must carry `tag`, judged statistically
/// (coverage_judgement.h): a run draws more cases until the share is certainly above or below.
struct CoverageFloor {
    std::string tag;
    double fraction;
};

/// One property of a claim: the claim over one family of scenes, with its floors. Its name is
/// the property's in every report (with the scalar type appended: "_float", "_double").
struct PropertyOf {
    const char* name;
    Family family;
    std::vector<CoverageFloor> floors;
};

/// One claim, for scenes in T. A claim about results asks the resolver it is given; an Internal
/// claim is about tilesweep itself and ignores it (aboutTilesweep).
template <class T>
struct Claim {
    const char* name;                                       ///< the claim, camelCase
    std::string (*check)(const Scene<T>&, SceneResolver&);  ///< empty when it holds
    ClaimScope scope = ClaimScope::Internal;
    /// The scenes `check` asks the resolver for, so that a round can ask for all its cases' scenes
    /// in one batch before judging them; nullptr: the scene itself (none for an Internal claim).
    std::vector<Scene<T>> (*asks)(const Scene<T>&) = nullptr;
    std::vector<PropertyOf> properties;  ///< where the suite holds it
};

/// An Internal claim's check, about tilesweep itself: the resolver under test plays no part.
template <class T, std::string (*kCheck)(const Scene<T>&)>
std::string aboutTilesweep(const Scene<T>& scene, SceneResolver& /*unused*/) {
    return kCheck(scene);
}

/// The scenes a claim asks the resolver for on `scene` (Claim::asks).
template <class T>
[[nodiscard]] std::vector<Scene<T>> scenesAskedBy(const Claim<T>& claim, const Scene<T>& scene) {
    if (claim.scope == ClaimScope::Internal) return {};
    if (claim.asks != nullptr) return claim.asks(scene);
    return {scene};
}

/// Whether a claim applies to an outside resolver: every claim about results, or, with
/// `safetyOnly`, those that do not ask for the contract's rounding bit for bit.
[[nodiscard]] inline bool appliesToOutside(ClaimScope scope, bool safetyOnly) noexcept {
    return scope == ClaimScope::Safety || (scope == ClaimScope::BitForBit && !safetyOnly);
}

}  // namespace tilesweep::properties

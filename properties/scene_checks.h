// SPDX-License-Identifier: MIT
#pragma once

// The claims the property suite makes about the production resolver, each a plain function of
// one scene: it returns an empty string when the claim holds, otherwise what went wrong. The
// RapidCheck properties, the regression corpus replay and `tilesweep check` all call these, so a
// shrunk counterexample is replayed against every claim, for ever.

#include "tilesweep/scene/scene.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tilesweep::properties {

/// What a claim is about, which says whether an outside resolver is held to it
/// (`tilesweep check --resolver-cmd`, scene_runner.h).
enum class ClaimScope : std::uint8_t {
    Safety,     ///< about results, under no particular rounding: any sound resolver holds it
    BitForBit,  ///< about results, bit for bit against the exact reference and the contract's rounding
    Internal,   ///< about tilesweep's internals, its C++ API or the oracles: built-in only
};

/// One claim, for scenes in T. The claims about results run the scene through
/// resolveUnderTest (scene_runner.h): tilesweep's resolver, or the outside one installed.
template <class T>
struct Claim {
    const char* name;                       ///< the claim, camelCase (the property's name)
    std::string (*check)(const Scene<T>&);  ///< empty when it holds
    ClaimScope scope = ClaimScope::Internal;
};

/// Whether a claim applies to an outside resolver: every claim about results, or, with
/// `safetyOnly`, those that do not ask for the contract's rounding bit for bit.
[[nodiscard]] inline bool appliesToOutside(ClaimScope scope, bool safetyOnly) noexcept {
    return scope == ClaimScope::Safety || (scope == ClaimScope::BitForBit && !safetyOnly);
}

/// The claim's verdict on a scene: empty when it holds; otherwise what went wrong, including
/// "resolver failed: ..." when the resolver under test could not answer (ResolverFailure).
/// Never throws.
template <class T>
[[nodiscard]] std::string checkClaim(const Claim<T>& claim, const Scene<T>& scene);

/// Every claim, in the order `tilesweep check` lists them.
template <class T>
[[nodiscard]] const std::vector<Claim<T>>& allClaims();

/// The first claim of that name, or nullptr.
template <class T>
[[nodiscard]] const Claim<T>* findClaim(const std::string& name);

/// Coverage tags of a scene, from its exact resolution: "hit", "miss", "tie" (an exact corner
/// tie), "time-tie" (a frame time exactly halfway between two T values), "reaches-at-end" (a
/// tile first reached at exactly t = 1 with both axes moving), "rounded-down" (the rounding
/// rule's exception changed a position), "touch-at-0", "two-step", "seam" (several tiles hit at
/// once on one face), "start-overlap", "lattice-wide" and "lattice-192" (inputs spanning more
/// than 60 or 92 bits: the resolver's wide integer tiers), "empty-map" (no solid tile),
/// "huge-move" (a move of 2^40 or more), "far-origin"; "path:fast", "path:filtered" or
/// "path:exact" (which of the resolver's paths decided the frames: tilesweep/frame_stats.h), and
/// "fallback" when it was not the fast one; on maps with one-way tiles, "one-way-map" and
/// "one-way-hit", "one-way-tie", "one-way-fast", "one-way-seam", "on-platform", "in-one-way",
/// "starts-in-one-way" (scene_classification.cpp, addOneWayTags).
template <class T>
[[nodiscard]] std::vector<std::string> classifyScene(const Scene<T>& scene);

extern template const std::vector<Claim<float>>& allClaims<float>();
extern template const std::vector<Claim<double>>& allClaims<double>();
extern template const Claim<float>* findClaim<float>(const std::string&);
extern template const Claim<double>* findClaim<double>(const std::string&);
extern template std::string checkClaim<float>(const Claim<float>&, const Scene<float>&);
extern template std::string checkClaim<double>(const Claim<double>&, const Scene<double>&);
extern template std::vector<std::string> classifyScene<float>(const Scene<float>&);
extern template std::vector<std::string> classifyScene<double>(const Scene<double>&);

}  // namespace tilesweep::properties

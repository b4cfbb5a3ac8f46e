// SPDX-License-Identifier: MIT
#pragma once

// The claims the property suite makes, each a function of one scene and the resolver under test
// (resolver_under_test.h): it returns an empty string when the claim holds, otherwise what went
// wrong. The properties, the regression corpus replay and `tilesweep check` all call these, so a
// shrunk counterexample is replayed against every claim, for ever.

#include "claim.h"

#include "tilesweep/scene/scene.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tilesweep::properties {

/// The claim's verdict on a scene against `resolver`: empty when it holds; otherwise what went
/// wrong, including "resolver failed: ..." when the resolver could not answer. Never throws.
template <class T>
[[nodiscard]] std::string checkClaim(const Claim<T>& claim, const Scene<T>& scene, SceneResolver& resolver);

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
extern template std::string checkClaim<float>(const Claim<float>&, const Scene<float>&, SceneResolver&);
extern template std::string checkClaim<double>(const Claim<double>&, const Scene<double>&, SceneResolver&);
extern template std::vector<std::string> classifyScene<float>(const Scene<float>&);
extern template std::vector<std::string> classifyScene<double>(const Scene<double>&);

}  // namespace tilesweep::properties

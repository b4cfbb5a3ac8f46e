// SPDX-License-Identifier: MIT
#pragma once

// The claims about results and about the library, one function each, grouped by kind in the
// files named below; all_claims.cpp lists them (allClaims) with the boundary claims of
// boundary_claims.h. Each returns an empty string when the claim holds on the scene, otherwise
// what went wrong. Internal to the property suite.

#include "claim.h"

#include "tilesweep/math.h"
#include "tilesweep/scene/scene.h"

#include <string>
#include <vector>

namespace tilesweep::properties {

/// The claims of each file below, each with its scope and properties (claim.h); all_claims.cpp
/// gathers them.
template <class T>
[[nodiscard]] std::vector<Claim<T>> safetyClaims();
template <class T>
[[nodiscard]] std::vector<Claim<T>> exactReferenceClaims();
template <class T>
[[nodiscard]] std::vector<Claim<T>> metamorphicClaims();
template <class T>
[[nodiscard]] std::vector<Claim<T>> gameFeelClaims();

// ---- Safety (safety_claims.cpp) ----------------------------------------------------------------

/// At the end of every frame, the box overlaps no solid tile it did not overlap at the start.
template <class T>
[[nodiscard]] std::string neverEndsInsideATileItDidNotStartIn(const Scene<T>& scene, SceneResolver& resolver);

/// Every tile overlapped at a frame's start was overlapped at the first frame's start.
template <class T>
[[nodiscard]] std::string neverGetsIntoAWall(const Scene<T>& scene, SceneResolver& resolver);

/// After a hit on a face, the box ends touching it or short of it by less than one ulp.
template <class T>
[[nodiscard]] std::string stopsJustTouching(const Scene<T>& scene, SceneResolver& resolver);

/// Every frame obeys every safety rule of checks/frame_safety.h.
template <class T>
[[nodiscard]] std::string obeysTheSafetyRules(const Scene<T>& scene, SceneResolver& resolver);

/// No overlap the exact 64-substep oracle sees comes before the resolver's first contact.
template <class T>
[[nodiscard]] std::string substepOracleFindsNoMissedContact(const Scene<T>& scene, SceneResolver& resolver);

/// NaN, infinities and bad sizes are refused by the library and by the scene reader.
template <class T>
[[nodiscard]] std::string badInputIsRejected(const Scene<T>& scene);

// ---- The exact reference (exact_reference_claims.cpp) ------------------------------------------

/// Decisions, positions, times and start overlaps equal the exact reference's, bit for bit.
template <class T>
[[nodiscard]] std::string matchesExactReferenceBitForBit(const Scene<T>& scene, SceneResolver& resolver);

/// Every contact's position equals the exact reference's, bit for bit (tilesweep's resolver).
template <class T>
[[nodiscard]] std::string placesContactsLikeTheExactReference(const Scene<T>& scene);

/// The exact reference itself misses no contact the substep oracle sees.
template <class T>
[[nodiscard]] std::string exactReferenceAgreesWithSubsteps(const Scene<T>& scene);

/// sweepBox agrees with the exact single-tile test on every solid tile (up to 64).
template <class T>
[[nodiscard]] std::string sweepBoxMatchesTheReference(const Scene<T>& scene);

// ---- Metamorphic (metamorphic_claims.cpp) ------------------------------------------------------

/// A zero move changes nothing, touches nothing and reports the overlapped tiles.
template <class T>
[[nodiscard]] std::string zeroMoveChangesNothing(const Scene<T>& scene, SceneResolver& resolver);

/// Every length times 8: every position times 8, every decision and time unchanged.
template <class T>
[[nodiscard]] std::string scalingByPowerOfTwoScalesTheResult(const Scene<T>& scene, SceneResolver& resolver);

/// Map and box moved by whole tiles: every decision and time unchanged.
template <class T>
[[nodiscard]] std::string translatingByWholeTilesKeepsDecisions(const Scene<T>& scene,
                                                                SceneResolver& resolver);

/// Mirrored about x = 0 (or y = 0): every decision mirrored, the other axis's position unchanged.
template <class T, Axis kAxis>
[[nodiscard]] std::string mirroringMirrorsTheResult(const Scene<T>& scene, SceneResolver& resolver);

/// The scenes each metamorphic claim asks the resolver for (the scene and its transformed twin;
/// none when the claim makes no claim on the scene), so that a round can ask for its cases' scenes
/// in one batch before judging them (all_claims.h, Claim::asks).
template <class T>
[[nodiscard]] std::vector<Scene<T>> zeroMoveAsks(const Scene<T>& scene);
template <class T>
[[nodiscard]] std::vector<Scene<T>> scalingAsks(const Scene<T>& scene);
template <class T, Axis kAxis>
[[nodiscard]] std::vector<Scene<T>> mirroringAsks(const Scene<T>& scene);
template <class T>
[[nodiscard]] std::vector<Scene<T>> translatingAsks(const Scene<T>& scene);

// ---- Game feel (game_feel_claims.cpp) ----------------------------------------------------------

/// A box resting on a floor (a solid or one-way tile's top) under gravity lands at once and
/// keeps its height.
template <class T>
[[nodiscard]] std::string restingContactIsStable(const Scene<T>& scene, SceneResolver& resolver);

/// A box sliding along a floor (solid or one-way tiles) is never stopped on x by a tile of it.
template <class T>
[[nodiscard]] std::string slidingAlongFloorNeverSnags(const Scene<T>& scene, SceneResolver& resolver);

/// A box standing on a one-way tile and moving down, at any speed, stays on it.
template <class T>
[[nodiscard]] std::string neverFallsThroughAPlatformItStoodOn(const Scene<T>& scene, SceneResolver& resolver);

/// A one-way tile is hit only on its top, by a box whose bottom starts at or above that top.
template <class T>
[[nodiscard]] std::string neverBlockedByAPlatformFromBelow(const Scene<T>& scene, SceneResolver& resolver);

extern template std::vector<Claim<float>> safetyClaims<float>();
extern template std::vector<Claim<double>> safetyClaims<double>();
extern template std::vector<Claim<float>> exactReferenceClaims<float>();
extern template std::vector<Claim<double>> exactReferenceClaims<double>();
extern template std::vector<Claim<float>> metamorphicClaims<float>();
extern template std::vector<Claim<double>> metamorphicClaims<double>();
extern template std::vector<Claim<float>> gameFeelClaims<float>();
extern template std::vector<Claim<double>> gameFeelClaims<double>();
extern template std::string neverEndsInsideATileItDidNotStartIn<float>(const Scene<float>&, SceneResolver&);
extern template std::string neverEndsInsideATileItDidNotStartIn<double>(const Scene<double>&, SceneResolver&);
extern template std::string neverGetsIntoAWall<float>(const Scene<float>&, SceneResolver&);
extern template std::string neverGetsIntoAWall<double>(const Scene<double>&, SceneResolver&);
extern template std::string stopsJustTouching<float>(const Scene<float>&, SceneResolver&);
extern template std::string stopsJustTouching<double>(const Scene<double>&, SceneResolver&);
extern template std::string obeysTheSafetyRules<float>(const Scene<float>&, SceneResolver&);
extern template std::string obeysTheSafetyRules<double>(const Scene<double>&, SceneResolver&);
extern template std::string substepOracleFindsNoMissedContact<float>(const Scene<float>&, SceneResolver&);
extern template std::string substepOracleFindsNoMissedContact<double>(const Scene<double>&, SceneResolver&);
extern template std::string badInputIsRejected<float>(const Scene<float>&);
extern template std::string badInputIsRejected<double>(const Scene<double>&);
extern template std::string matchesExactReferenceBitForBit<float>(const Scene<float>&, SceneResolver&);
extern template std::string matchesExactReferenceBitForBit<double>(const Scene<double>&, SceneResolver&);
extern template std::string exactReferenceAgreesWithSubsteps<float>(const Scene<float>&);
extern template std::string exactReferenceAgreesWithSubsteps<double>(const Scene<double>&);
extern template std::string sweepBoxMatchesTheReference<float>(const Scene<float>&);
extern template std::string sweepBoxMatchesTheReference<double>(const Scene<double>&);
extern template std::string zeroMoveChangesNothing<float>(const Scene<float>&, SceneResolver&);
extern template std::string zeroMoveChangesNothing<double>(const Scene<double>&, SceneResolver&);
extern template std::string scalingByPowerOfTwoScalesTheResult<float>(const Scene<float>&, SceneResolver&);
extern template std::string scalingByPowerOfTwoScalesTheResult<double>(const Scene<double>&, SceneResolver&);
extern template std::string translatingByWholeTilesKeepsDecisions<float>(const Scene<float>&, SceneResolver&);
extern template std::string translatingByWholeTilesKeepsDecisions<double>(const Scene<double>&,
                                                                          SceneResolver&);
extern template std::string mirroringMirrorsTheResult<float, Axis::X>(const Scene<float>&, SceneResolver&);
extern template std::string mirroringMirrorsTheResult<float, Axis::Y>(const Scene<float>&, SceneResolver&);
extern template std::string mirroringMirrorsTheResult<double, Axis::X>(const Scene<double>&, SceneResolver&);
extern template std::string mirroringMirrorsTheResult<double, Axis::Y>(const Scene<double>&, SceneResolver&);
extern template std::vector<Scene<float>> zeroMoveAsks<float>(const Scene<float>&);
extern template std::vector<Scene<double>> zeroMoveAsks<double>(const Scene<double>&);
extern template std::vector<Scene<float>> scalingAsks<float>(const Scene<float>&);
extern template std::vector<Scene<double>> scalingAsks<double>(const Scene<double>&);
extern template std::vector<Scene<float>> mirroringAsks<float, Axis::X>(const Scene<float>&);
extern template std::vector<Scene<float>> mirroringAsks<float, Axis::Y>(const Scene<float>&);
extern template std::vector<Scene<double>> mirroringAsks<double, Axis::X>(const Scene<double>&);
extern template std::vector<Scene<double>> mirroringAsks<double, Axis::Y>(const Scene<double>&);
extern template std::vector<Scene<float>> translatingAsks<float>(const Scene<float>&);
extern template std::vector<Scene<double>> translatingAsks<double>(const Scene<double>&);
extern template std::string restingContactIsStable<float>(const Scene<float>&, SceneResolver&);
extern template std::string restingContactIsStable<double>(const Scene<double>&, SceneResolver&);
extern template std::string slidingAlongFloorNeverSnags<float>(const Scene<float>&, SceneResolver&);
extern template std::string slidingAlongFloorNeverSnags<double>(const Scene<double>&, SceneResolver&);
extern template std::string neverFallsThroughAPlatformItStoodOn<float>(const Scene<float>&, SceneResolver&);
extern template std::string neverFallsThroughAPlatformItStoodOn<double>(const Scene<double>&, SceneResolver&);
extern template std::string neverBlockedByAPlatformFromBelow<float>(const Scene<float>&, SceneResolver&);
extern template std::string neverBlockedByAPlatformFromBelow<double>(const Scene<double>&, SceneResolver&);

}  // namespace tilesweep::properties

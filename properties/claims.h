// SPDX-License-Identifier: MIT
#pragma once

// The claims about results and about the library, one function each, grouped by kind in the
// files named below; scene_checks.cpp lists them (allClaims) with the boundary claims of
// boundary_checks.h. Each returns an empty string when the claim holds on the scene, otherwise
// what went wrong. Internal to the property suite.

#include "tilesweep/math.h"
#include "tilesweep/scene/scene.h"

#include <string>

namespace tilesweep::properties {

// ---- Safety (safety_claims.cpp) ----------------------------------------------------------------

/// At the end of every frame, the box overlaps no solid tile it did not overlap at the start.
template <class T>
[[nodiscard]] std::string neverEndsInsideATileItDidNotStartIn(const Scene<T>& scene);

/// Every tile overlapped at a frame's start was overlapped at the first frame's start.
template <class T>
[[nodiscard]] std::string neverGetsIntoAWall(const Scene<T>& scene);

/// After a hit on a face, the box ends touching it or short of it by less than one ulp.
template <class T>
[[nodiscard]] std::string stopsJustTouching(const Scene<T>& scene);

/// Every frame obeys every safety rule of checks/frame_safety.h.
template <class T>
[[nodiscard]] std::string obeysTheSafetyRules(const Scene<T>& scene);

/// No overlap the exact 64-substep oracle sees comes before the resolver's first contact.
template <class T>
[[nodiscard]] std::string substepOracleFindsNoMissedContact(const Scene<T>& scene);

/// NaN, infinities and bad sizes are refused by the library and by the scene reader.
template <class T>
[[nodiscard]] std::string badInputIsRejected(const Scene<T>& scene);

// ---- The exact reference (exact_reference_claims.cpp) ------------------------------------------

/// Decisions, positions, times and start overlaps equal the exact reference's, bit for bit.
template <class T>
[[nodiscard]] std::string matchesExactReferenceBitForBit(const Scene<T>& scene);

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
[[nodiscard]] std::string zeroMoveChangesNothing(const Scene<T>& scene);

/// Every length times 8: every position times 8, every decision and time unchanged.
template <class T>
[[nodiscard]] std::string scalingByPowerOfTwoScalesTheResult(const Scene<T>& scene);

/// Map and box moved by whole tiles: every decision and time unchanged.
template <class T>
[[nodiscard]] std::string translatingByWholeTilesKeepsDecisions(const Scene<T>& scene);

/// Mirrored about x = 0 (or y = 0): every decision mirrored, the other axis's position unchanged.
template <class T, Axis kAxis>
[[nodiscard]] std::string mirroringMirrorsTheResult(const Scene<T>& scene);

// ---- Game feel (game_feel_claims.cpp) ----------------------------------------------------------

/// A box resting on a floor (a solid or one-way tile's top) under gravity lands at once and
/// keeps its height.
template <class T>
[[nodiscard]] std::string restingContactIsStable(const Scene<T>& scene);

/// A box sliding along a floor (solid or one-way tiles) is never stopped on x by a tile of it.
template <class T>
[[nodiscard]] std::string slidingAlongFloorNeverSnags(const Scene<T>& scene);

/// A box standing on a one-way tile and moving down, at any speed, stays on it.
template <class T>
[[nodiscard]] std::string neverFallsThroughAPlatformItStoodOn(const Scene<T>& scene);

/// A one-way tile is hit only on its top, by a box whose bottom starts at or above that top.
template <class T>
[[nodiscard]] std::string neverBlockedByAPlatformFromBelow(const Scene<T>& scene);

extern template std::string neverEndsInsideATileItDidNotStartIn<float>(const Scene<float>&);
extern template std::string neverEndsInsideATileItDidNotStartIn<double>(const Scene<double>&);
extern template std::string neverGetsIntoAWall<float>(const Scene<float>&);
extern template std::string neverGetsIntoAWall<double>(const Scene<double>&);
extern template std::string stopsJustTouching<float>(const Scene<float>&);
extern template std::string stopsJustTouching<double>(const Scene<double>&);
extern template std::string obeysTheSafetyRules<float>(const Scene<float>&);
extern template std::string obeysTheSafetyRules<double>(const Scene<double>&);
extern template std::string substepOracleFindsNoMissedContact<float>(const Scene<float>&);
extern template std::string substepOracleFindsNoMissedContact<double>(const Scene<double>&);
extern template std::string badInputIsRejected<float>(const Scene<float>&);
extern template std::string badInputIsRejected<double>(const Scene<double>&);
extern template std::string matchesExactReferenceBitForBit<float>(const Scene<float>&);
extern template std::string matchesExactReferenceBitForBit<double>(const Scene<double>&);
extern template std::string exactReferenceAgreesWithSubsteps<float>(const Scene<float>&);
extern template std::string exactReferenceAgreesWithSubsteps<double>(const Scene<double>&);
extern template std::string sweepBoxMatchesTheReference<float>(const Scene<float>&);
extern template std::string sweepBoxMatchesTheReference<double>(const Scene<double>&);
extern template std::string zeroMoveChangesNothing<float>(const Scene<float>&);
extern template std::string zeroMoveChangesNothing<double>(const Scene<double>&);
extern template std::string scalingByPowerOfTwoScalesTheResult<float>(const Scene<float>&);
extern template std::string scalingByPowerOfTwoScalesTheResult<double>(const Scene<double>&);
extern template std::string translatingByWholeTilesKeepsDecisions<float>(const Scene<float>&);
extern template std::string translatingByWholeTilesKeepsDecisions<double>(const Scene<double>&);
extern template std::string mirroringMirrorsTheResult<float, Axis::X>(const Scene<float>&);
extern template std::string mirroringMirrorsTheResult<float, Axis::Y>(const Scene<float>&);
extern template std::string mirroringMirrorsTheResult<double, Axis::X>(const Scene<double>&);
extern template std::string mirroringMirrorsTheResult<double, Axis::Y>(const Scene<double>&);
extern template std::string restingContactIsStable<float>(const Scene<float>&);
extern template std::string restingContactIsStable<double>(const Scene<double>&);
extern template std::string slidingAlongFloorNeverSnags<float>(const Scene<float>&);
extern template std::string slidingAlongFloorNeverSnags<double>(const Scene<double>&);
extern template std::string neverFallsThroughAPlatformItStoodOn<float>(const Scene<float>&);
extern template std::string neverFallsThroughAPlatformItStoodOn<double>(const Scene<double>&);
extern template std::string neverBlockedByAPlatformFromBelow<float>(const Scene<float>&);
extern template std::string neverBlockedByAPlatformFromBelow<double>(const Scene<double>&);

}  // namespace tilesweep::properties

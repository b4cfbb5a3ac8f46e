// SPDX-License-Identifier: MIT
#pragma once

#include "tilesweep/scene/scene.h"

#include <cstdint>

// The drawn families: plain std::mt19937_64 builders, one scene per seed, with real-valued
// (not only lattice) boxes and moves. They are the audit's reference population, measured
// against the exact reference with error figures in ulps. (The audit's high-speed column is the
// property family's builder, high_speed_family.h: the same scenes, built once.) Every scene has integer tile
// sizes and an origin that is a whole number of tiles, so that its map is representable in the scalar type at
// every magnitude used.

namespace tilesweep::scenarios {

/// A drawn family.
enum class DrawnFamily : std::uint8_t {
    Uniform,     ///< random maps (30% solid), boxes and moves, a share snapped to the lattice, 1 to 3 frames
    NearCorner,  ///< a corner grazed exactly, or clipped or missed by 1 to 4 ulps
    Tie,         ///< both axes enter at the same time (an exact corner hit), sometimes 1 ulp off
    Seam,        ///< landings across floor seams and long slides resting on a floor
    Tiny,        ///< displacements below one ulp of the position, free or against a face
};

/// The scene of `family` drawn from `seed`, its map's origin moved to `magnitude` (rounded down
/// to whole tiles); the same three values always give the same scene.
template <class T>
[[nodiscard]] Scene<T> drawScene(DrawnFamily family, std::uint64_t seed, double magnitude = 0);

extern template Scene<float> drawScene<float>(DrawnFamily, std::uint64_t, double);
extern template Scene<double> drawScene<double>(DrawnFamily, std::uint64_t, double);

}  // namespace tilesweep::scenarios

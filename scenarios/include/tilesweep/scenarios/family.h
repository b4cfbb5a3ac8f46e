// SPDX-License-Identifier: MIT
#pragma once

// The scenario families by name (families.h builds them): every kind of scene the suite, the
// audit, the benchmarks and the soak generate, and the scene a family built.

#include "tilesweep/scene/scene.h"

#include <cstdint>
#include <vector>

namespace tilesweep::scenarios {

/// The families of scenes; each is reachable on its own, and `Mixed` draws from all.
enum class Family : std::uint8_t {
    Random,       ///< random density, any box and motion
    Floor,        ///< flat floors and ceilings, walls one tile thick, corridors
    Stairs,       ///< a staircase
    SingleTile,   ///< one solid tile
    CornerTie,    ///< the box's leading corner aimed exactly at a tile corner; random exposed faces
    CornerPass,   ///< a path exactly through a corner point, or off it by one ulp either way
    SeamLanding,  ///< landing straddling the seam between two floor tiles
    Gap,          ///< a box exactly as wide as a one-tile gap, or one ulp wider
    Resting,      ///< resting on a floor under gravity for many frames, possibly sliding
    FarSubUlp,    ///< far from the origin, moves of a few ulps past a tile corner: rounding at work
    FarEdge,      ///< far edge a few ulps past a grid line, a tiny move away, then back: the rounding rule
    FineBits,     ///< frame times exactly halfway between two values, tiles reached at t = 1, wide lattices
    Extreme,      ///< empty maps (0 x 0, or no solid cell), huge moves, huge coordinates
    FilterBand,   ///< exact corner ties whose rounded time comparison lands deep in the filter's band
    HighSpeed,    ///< 1 to 100 tiles a frame along a corridor with thin walls: no tunnelling
    NearTie,      ///< the filter band's corner ties nudged one ulp off: nonzero signs its refinement decides
    TinyScale,    ///< a mixed scene scaled by a power of two near the bottom of T's normal range
    Capacity,     ///< boxes whose contact bound is the inline limit or just past it, into a corner
    RangeEdge,    ///< float frames at the range test's edge: a fine width and move just past a grid line
    Platforms,    ///< one-way platforms among solid tiles; any box (sometimes inside one) and motion
    PlatformLanding,  ///< falling onto thin platforms at 1/8 to 100 tiles a frame; exact corners; sides
    PlatformJump,     ///< jumping up through a platform, then landing on it over the following frames
    PlatformWalk,     ///< walking along a row of platforms across its seams under gravity
    Mixed,
};

[[nodiscard]] inline const char* familyName(Family f) {
    switch (f) {
        case Family::Random:
            return "random";
        case Family::Floor:
            return "floor";
        case Family::Stairs:
            return "stairs";
        case Family::SingleTile:
            return "single-tile";
        case Family::CornerTie:
            return "corner-tie";
        case Family::CornerPass:
            return "corner-pass";
        case Family::SeamLanding:
            return "seam-landing";
        case Family::Gap:
            return "gap";
        case Family::Resting:
            return "resting";
        case Family::FarSubUlp:
            return "far-sub-ulp";
        case Family::FarEdge:
            return "far-edge";
        case Family::FineBits:
            return "fine-bits";
        case Family::Extreme:
            return "extreme";
        case Family::FilterBand:
            return "filter-band";
        case Family::HighSpeed:
            return "high-speed";
        case Family::NearTie:
            return "near-tie";
        case Family::TinyScale:
            return "tiny-scale";
        case Family::Capacity:
            return "capacity";
        case Family::RangeEdge:
            return "range-edge";
        case Family::Platforms:
            return "platforms";
        case Family::PlatformLanding:
            return "platform-landing";
        case Family::PlatformJump:
            return "platform-jump";
        case Family::PlatformWalk:
            return "platform-walk";
        case Family::Mixed:
            return "mixed";
    }
    return "?";
}

/// A generated scene and the family that built it.
template <class T>
struct GeneratedScene {
    Scene<T> scene;
    Family family = Family::Random;
    bool farOrigin = false;
};

/// Every family but `Mixed`, in declaration order.
[[nodiscard]] inline std::vector<Family> allFamilies() {
    std::vector<Family> out;
    for (int f = 0; f < static_cast<int>(Family::Mixed); ++f) out.push_back(static_cast<Family>(f));
    return out;
}

}  // namespace tilesweep::scenarios

// SPDX-License-Identifier: MIT
#pragma once

// The scenario families: every kind of scene the suite, the audit, the benchmarks and the soak
// generate, defined once (tilesweep_scenarios, scenarios/README.md).
//
// Each family is a RapidCheck generator built from shared parameterised pieces (genTileSize,
// genOrigin, genLength, genDisplacement, clearUnder, ...), so the property suite draws it and
// shrinks a counterexample to a small scene; `buildScene(family, seed)` runs the same generator
// once from a seed, deterministically, for the tools that are not properties (the audit's
// property-family columns, tools that want "the scene of family F, number N").
//
// One file per family (or per builder that draws several related families): layout_family.h,
// corner_family.h, floor_family.h, far_sub_ulp_family.h, far_edge_family.h, fine_bits_family.h,
// extreme_family.h, filter_band_family.h, high_speed_family.h, tiny_scale_family.h,
// capacity_family.h, range_edge_family.h and platform_family.h (the one-way families), over the shared pieces
// of scene_pieces.h; family.h names them. This header includes them all and draws any of them (genScene,
// buildScene).
//
// RapidCheck's own float generator never yields -0, subnormals or tile-edge values and shrinks
// poorly, so every number here is an integer on a grid mapped to T (a multiple of tile/8, say),
// which keeps shrinking on clean values; adversarial builders then place boxes exactly on
// corners, seams and gaps, and perturb them by one ulp. Scenes are built valid directly (the
// cells under the box's start are cleared when a start without overlap is wanted) rather than
// filtered with RC_PRE. Every function is inline (RapidCheck's example Generators.h is an ODR
// trap otherwise).

#include "tilesweep/scenarios/capacity_family.h"
#include "tilesweep/scenarios/corner_family.h"
#include "tilesweep/scenarios/extreme_family.h"
#include "tilesweep/scenarios/family.h"
#include "tilesweep/scenarios/far_edge_family.h"
#include "tilesweep/scenarios/far_sub_ulp_family.h"
#include "tilesweep/scenarios/filter_band_family.h"
#include "tilesweep/scenarios/fine_bits_family.h"
#include "tilesweep/scenarios/floor_family.h"
#include "tilesweep/scenarios/high_speed_family.h"
#include "tilesweep/scenarios/layout_family.h"
#include "tilesweep/scenarios/platform_family.h"
#include "tilesweep/scenarios/range_edge_family.h"
#include "tilesweep/scenarios/tiny_scale_family.h"
#include "tilesweep/scene/scene.h"

#include <rapidcheck.h>

#include <cstdint>
#include <mutex>
#include <ostream>

namespace tilesweep::scenarios {

/// Scenes of one family, or of all of them (`Mixed`).
template <class T>
rc::Gen<GeneratedScene<T>> genScene(Family family) {
    using detail::genCornerScene;
    using detail::genExtremeScene;
    using detail::genFarEdgeScene;
    using detail::genFarSubUlpScene;
    using detail::genFilterBandScene;
    using detail::genFineBitsScene;
    using detail::genFloorScene;
    using detail::genHighSpeedScene;
    using detail::genLayoutScene;
    switch (family) {
        case Family::Random:
        case Family::Floor:
        case Family::Stairs:
        case Family::SingleTile:
            return genLayoutScene<T>(family);
        case Family::CornerTie:
        case Family::CornerPass:
            return genCornerScene<T>(family);
        case Family::SeamLanding:
        case Family::Gap:
        case Family::Resting:
            return genFloorScene<T>(family);
        case Family::FarSubUlp:
            return genFarSubUlpScene<T>();
        case Family::FarEdge:
            return genFarEdgeScene<T>();
        case Family::FineBits:
            return genFineBitsScene<T>();
        case Family::Extreme:
            return genExtremeScene<T>();
        case Family::FilterBand:
            return genFilterBandScene<T>();
        case Family::NearTie:
            return genFilterBandScene<T>(true);
        case Family::HighSpeed:
            return genHighSpeedScene<T>();
        case Family::TinyScale:
            return detail::genTinyScaleScene<T>(genScene<T>(Family::Mixed));
        case Family::Capacity:
            return detail::genCapacityScene<T>();
        case Family::RangeEdge:
            return detail::genRangeEdgeScene<T>();
        case Family::Platforms:
        case Family::PlatformLanding:
        case Family::PlatformJump:
        case Family::PlatformWalk:
            return detail::genPlatformScene<T>(family);
        case Family::Mixed:
            break;
    }
    return rc::gen::weightedOneOf<GeneratedScene<T>>({
        {4, genLayoutScene<T>(Family::Random)},
        {2, genLayoutScene<T>(Family::Floor)},
        {1, genLayoutScene<T>(Family::Stairs)},
        {1, genLayoutScene<T>(Family::SingleTile)},
        {2, genCornerScene<T>(Family::CornerTie)},
        {3, genCornerScene<T>(Family::CornerPass)},
        {2, genFloorScene<T>(Family::SeamLanding)},
        {1, genFloorScene<T>(Family::Gap)},
        {2, genFloorScene<T>(Family::Resting)},
        {1, genFarSubUlpScene<T>()},
        {1, genFarEdgeScene<T>()},
        {1, genFineBitsScene<T>()},
        {1, detail::genPlatformScene<T>(Family::Platforms)},
    });
}

/// RapidCheck keeps the generator being run in process-wide state (rc::detail::ImplicitParam), so
/// two threads must not run generators at once; buildScene takes this lock.
[[nodiscard]] inline std::mutex& generatorMutex() {
    static std::mutex mutex;
    return mutex;
}

/// The scene that `genScene<T>(family)` draws from `seed` at RapidCheck's size `size`: the same
/// builders, run once outside any property, so the same (family, seed, size) always gives the
/// same scene, on every machine with the same standard library. Thread-safe.
template <class T>
[[nodiscard]] GeneratedScene<T> buildScene(Family family, std::uint64_t seed, int size = rc::kNominalSize) {
    const std::lock_guard<std::mutex> lock(generatorMutex());
    return genScene<T>(family)(rc::Random(seed), size).value();
}

/// buildScene with every map origin the family draws (genOrigin) at `magnitude`, rounded down to
/// whole tiles: the same (family, seed) gives the same local scene at every magnitude, built in
/// T there. The families whose builders draw their origin that way: random, floor, stairs,
/// single-tile, corner-tie, corner-pass, seam-landing, gap, resting, high-speed and the four
/// one-way families (the others place
/// their own origins and ignore it). The audit's far columns are these.
template <class T>
[[nodiscard]] GeneratedScene<T> buildSceneAt(Family family, std::uint64_t seed, double magnitude) {
    detail::placedOriginMagnitude() = magnitude;
    struct Clear {
        ~Clear() { detail::placedOriginMagnitude().reset(); }
    } clear;
    return buildScene<T>(family, seed);
}

/// Prints a generated scene as the scene line it is (every number a hexfloat), so a
/// counterexample reads back bit for bit.
template <class T>
void showValue(const GeneratedScene<T>& g, std::ostream& os) {
    os << familyName(g.family) << ": " << formatScene(g.scene);
}

}  // namespace tilesweep::scenarios

// SPDX-License-Identifier: MIT
#pragma once

// The resolvers the side-by-side comparisons run on the same frames: tilesweep, the lean twin,
// the lean grid, and the dividing and libm twins (baselines/), behind one call, so that the timed benchmarks
// (resolve_bench.cpp) and the instruction counts (frame_instructions.cpp) run the same code.
// Each gets what it keeps per map, made once as a game keeps it beside its map: tilesweep its
// PreparedMap (prepareMap), the baselines the tile size's reciprocal. TilesweepView is tilesweep
// on the bare map view (resolveMove(input, output)), which redoes the map's checks every frame.

#include "tilesweep/baselines/grid_resolve.h"
#include "tilesweep/baselines/twin_resolve.h"
#include "tilesweep/mover.h"
#include "tilesweep/resolve.h"

namespace tilesweep::bench {

enum class Impl { Tilesweep, TilesweepView, Twin, Grid, TwinDividing, TwinLibm };

/// What each resolver keeps per map (see the top of this file).
template <class T>
struct PerMap {
    explicit PerMap(const TileMapView<T>& view) noexcept
        : prepared(prepareMap(view)), reciprocal(baselines::reciprocalOf(view)) {}
    PreparedMap<T> prepared;
    baselines::TileReciprocal<T> reciprocal;
};

/// One frame through `I`, with what it keeps for the frame's map.
template <class T, Impl I>
[[gnu::always_inline]] inline ResolveResult<T> resolveWith(const ResolveInput<T>& in,
                                                           const ResolveOutput<T>& out,
                                                           const PerMap<T>& perMap) noexcept {
    if constexpr (I == Impl::Tilesweep) {
        return resolveMove(perMap.prepared, {in.box, in.displacement}, out);
    } else if constexpr (I == Impl::TilesweepView) {
        return resolveMove<T>(in, out);
    } else if constexpr (I == Impl::Twin) {
        return baselines::resolveMoveTwin<T>(in, out, perMap.reciprocal);
    } else if constexpr (I == Impl::Grid) {
        return baselines::resolveMoveGrid<T>(in, out, perMap.reciprocal);
    } else if constexpr (I == Impl::TwinDividing) {
        return baselines::resolveMoveTwinDividing<T>(in, out, perMap.reciprocal);
    } else {
        return baselines::resolveMoveTwinLibm<T>(in, out);
    }
}

}  // namespace tilesweep::bench

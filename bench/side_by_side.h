// SPDX-License-Identifier: MIT
#pragma once

// The resolvers the side-by-side comparisons run on the same frames: tilesweep, the lean twin,
// the lean grid and the libm twin (baselines/), behind one call, so that the timed benchmarks
// (resolve_bench.cpp) and the instruction counts (frame_instructions.cpp) run the same code.

#include "tilesweep/baselines/grid_resolve.h"
#include "tilesweep/baselines/twin_resolve.h"
#include "tilesweep/resolve.h"

namespace tilesweep::bench {

enum class Impl { Tilesweep, Twin, Grid, TwinLibm };

/// One frame through `I`; `reciprocal` is the map's, prepared once as a game keeps it.
template <class T, Impl I>
[[gnu::always_inline]] inline ResolveResult<T> resolveWith(
    const ResolveInput<T>& in, const ResolveOutput<T>& out,
    const baselines::TileReciprocal<T>& reciprocal) noexcept {
    if constexpr (I == Impl::Tilesweep) {
        return resolveMove<T>(in, out);
    } else if constexpr (I == Impl::Twin) {
        return baselines::resolveMoveTwin<T>(in, out, reciprocal);
    } else if constexpr (I == Impl::Grid) {
        return baselines::resolveMoveGrid<T>(in, out, reciprocal);
    } else {
        return baselines::resolveMoveTwinLibm<T>(in, out);
    }
}

}  // namespace tilesweep::bench

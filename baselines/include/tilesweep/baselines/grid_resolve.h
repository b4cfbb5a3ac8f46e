// SPDX-License-Identifier: MIT
#pragma once

#include "tilesweep/baselines/twin_resolve.h"

#include <algorithm>
#include <cstdint>

// The swept-bounds grid resolver: the inexact twin's tile test and frame loop (twin_resolve.h),
// with the broadphase most tile-game tutorials use instead of a path walk: every cell of the
// step's swept bounds (the union of the box at the start and at the end of the step), row by
// row, with no early exit. The cost grows with the area of the bounds, so with speed squared on
// a diagonal move, where the path walk grows linearly.

namespace tilesweep::baselines {

namespace detail {

/// Every solid cell of the step's swept bounds, row by row.
struct FindHitsInSweptBounds {
    template <class T, Arithmetic A>
    void operator()(const TileMapView<T>& map, const StepFrame<T, A>& f, StepHits<T>& hits) const noexcept {
        std::int64_t first[2];
        std::int64_t last[2];
        for (int a = 0; a < 2; ++a) {
            const T lo = std::min(f.lo[a], f.lo[a] + f.r[a]);
            const T hi = std::max(f.hi[a], f.hi[a] + f.r[a]);
            first[a] = std::max<std::int64_t>(f.cellBefore(a, lo), 0);
            last[a] = std::min<std::int64_t>(f.cellOf(a, hi), f.cells[a] - 1);
        }
        for (std::int64_t j = first[1]; j <= last[1]; ++j)
            for (std::int64_t i = first[0]; i <= last[0]; ++i)
                if (map.isSolid(i, j)) testTile(map, f, i, j, hits);
    }
};

}  // namespace detail

/// Resolves one frame with the swept-bounds broadphase, with the reciprocal of the map's tile
/// size computed once per map by the caller; otherwise as resolveMoveTwin (lean).
template <class T>
[[nodiscard]] inline ResolveResult<T> resolveMoveGrid(const ResolveInput<T>& input,
                                                      const ResolveOutput<T>& output,
                                                      TileReciprocal<T> reciprocal) noexcept {
    return detail::resolveFrame<T, detail::Arithmetic::Lean>(input, output, reciprocal,
                                                             detail::FindHitsInSweptBounds{});
}

/// As above, the reciprocal computed for this frame (resolveMove's signature shape).
template <class T>
[[nodiscard]] inline ResolveResult<T> resolveMoveGrid(const ResolveInput<T>& input,
                                                      const ResolveOutput<T>& output) noexcept {
    return resolveMoveGrid(input, output, reciprocalOf(input.map));
}

}  // namespace tilesweep::baselines

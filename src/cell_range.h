// SPDX-License-Identifier: MIT
#pragma once

// The one cell-range estimator: which cells of one axis an interval may touch, from estimates
// of its ends in cell coordinates ((v - origin) / tile) and a certified bound on their error.
// The frame loop's start overlaps, swept bounds and walk (fast_frame.h) and the free move
// (free_move.h) use it; each caller derives its margin (proof_constants.h). The range it gives
// is a superset of the exact one; the callers test every cell in it exactly, or, for the free
// move, need only that no solid cell lies in it.

#include <cstdint>

// The functions here run a few times a frame on the fast path: always inlined (gnu::always_inline;
// other compilers ignore it), so that their callers keep the ends and margins in registers.

namespace tilesweep::detail {

/// The cells [first, last] of one axis; empty when first > last.
struct CellRange {
    std::int64_t first;
    std::int64_t last;
};

/// floor(v) for |v| < 2^62, without a libm call (x86-64's baseline has no rounding instruction).
[[nodiscard, gnu::always_inline]] inline std::int64_t floorToInt(double v) noexcept {
    auto k = static_cast<std::int64_t>(v);  // toward zero
    if (static_cast<double>(k) > v) --k;
    return k;
}

/// floor(v) clamped to [-1, cells], for an estimate v of a cell coordinate (a NaN gives -1).
[[nodiscard, gnu::always_inline]] inline std::int64_t clampCell(double v, std::int64_t cells) noexcept {
    if (!(v > -1)) return -1;
    if (v >= static_cast<double>(cells)) return cells;
    return floorToInt(v);
}

/// The cells of [0, cells) that an interval may touch whose ends lie in cell coordinates within
/// `margin` of `low` and `high`: floor(low - margin) to floor(high + margin), clamped to the map
/// (empty when the interval lies off it).
[[nodiscard, gnu::always_inline]] inline CellRange estimateCells(double low, double high, double margin,
                                                                 std::int64_t cells) noexcept {
    const std::int64_t first = clampCell(low - margin, cells);
    const std::int64_t last = clampCell(high + margin, cells);
    return {first < 0 ? 0 : first, last > cells - 1 ? cells - 1 : last};
}

}  // namespace tilesweep::detail

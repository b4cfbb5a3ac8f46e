// SPDX-License-Identifier: MIT
#pragma once

// The one cell-range estimator: which cells of one axis an interval may touch, from estimates
// of its ends in cell coordinates ((v - origin) / tile) and a certified bound on their error.
// The frame loop's start overlaps, swept bounds and walk (fast_frame.h) use it; each caller
// derives its margin (proof_constants.h). The range it gives is a superset of the exact one; the
// callers test every cell in it exactly.

#include <cstdint>

#if defined(__SSE2__) && !defined(TILESWEEP_PORTABLE_INTEGERS)
#include <emmintrin.h>
#define TILESWEEP_CELL_RANGE_SSE2 1
#endif

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
/// `margin` of `low` and `high`: from floor(low - margin) to floor(high + margin), or one cell
/// more at the high end (see below), clamped to the map (empty when the interval lies off it).
///
/// Branch-free: each end is clamped as a double, then truncated. The low end, clamped to
/// [0, cells], truncates to its floor (truncation is the floor of a nonnegative value), which
/// is already the clamp of floor(low - margin) to [0, cells]: cells gives an empty range. The
/// high end v = high + margin is taken as trunc(clamp(v + 1, 0, cells)) - 1, which is
/// min(floor(v), cells - 1) or one more, and -1 (empty) when v < -1 (v + 1 < 0): for v >= -1,
/// v + 1 >= floor(v) + 1 exactly, so fl(v + 1) >= floor(v) + 1 as well (rounding is monotonic and
/// the integer is a double: |v| < 2^53 wherever the clamp does not decide), and it can exceed it
/// only by rounding up onto the next integer: a cell too many, which the callers' exact tests
/// reject (the range is a superset either way). A NaN end gives an empty range.
[[nodiscard, gnu::always_inline]] inline CellRange estimateCells(double low, double high, double margin,
                                                                 std::int64_t cells) noexcept {
    const auto limit = static_cast<double>(cells);
    double from = low - margin;
    from = from > 0 ? from : 0;  // NaN: 0, and the high end makes the range empty
    from = from < limit ? from : limit;
    double to = (high + margin) + 1;
    to = to > 0 ? to : 0;  // NaN: 0, an empty range
    to = to < limit ? to : limit;
    return {static_cast<std::int64_t>(from), static_cast<std::int64_t>(to) - 1};
}

#if defined(TILESWEEP_CELL_RANGE_SSE2)
/// estimateCells of two axes at once, lane 0 into out[0] and lane 1 into out[1]: the same
/// operations on the same values in each SSE2 lane (a lane's max(v, 0) is v > 0 ? v : 0 and its
/// min(v, limit) is v < limit ? v : limit, NaN included), so the same ranges bit for bit.
/// `limit` holds each axis's cell count (below 2^31: a map's columns and rows are 32-bit), so
/// each clamped end truncates exactly in a 32-bit lane.
[[gnu::always_inline]] inline void estimateCellsOfBoth(__m128d low, __m128d high, __m128d margin,
                                                       __m128d limit, CellRange (&out)[2]) noexcept {
    const __m128d zero = _mm_setzero_pd();
    const __m128d from = _mm_min_pd(_mm_max_pd(_mm_sub_pd(low, margin), zero), limit);
    const __m128d to =
        _mm_min_pd(_mm_max_pd(_mm_add_pd(_mm_add_pd(high, margin), _mm_set1_pd(1)), zero), limit);
    // Both ends are integers in [0, 2^31) once truncated: zero-extended to 64 bits.
    const __m128i zeroBits = _mm_setzero_si128();
    const __m128i first = _mm_unpacklo_epi32(_mm_cvttpd_epi32(from), zeroBits);
    const __m128i last =
        _mm_sub_epi64(_mm_unpacklo_epi32(_mm_cvttpd_epi32(to), zeroBits), _mm_set1_epi64x(1));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(&out[0]), _mm_unpacklo_epi64(first, last));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(&out[1]), _mm_unpackhi_epi64(first, last));
}
#endif

}  // namespace tilesweep::detail

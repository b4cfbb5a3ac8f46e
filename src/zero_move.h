// SPDX-License-Identifier: MIT
#pragma once

// The early exit of resolveMove for a zero displacement (both components +0 or -0): nothing
// moves, nothing is hit, and the frame's whole answer is the start position (bit for bit, so
// -0 stays -0) and the solid cells the box overlaps at the start. Those are found from the cells
// under the box, byte first, without forming a tile edge.
//
// On one axis, with x the box's low edge, w its size, o the map origin and t the tile size, cell
// i overlaps the open interval (x, x + w) iff o + (i+1)t > x and o + i*t < x + w, that is iff
// floor(Ql) <= i <= ceil(Qh) - 1 with Ql = (x - o) / t and Qh = (x + w - o) / t (exact
// rationals; the tile edges need not be representable for this, so the answer is the exact
// reference's whatever the map). In double (float inputs widen exactly), with u = 2^-53:
//   a = fl(x - o), b = fl(a + w), ql = fl(a / t), qh = fl(b / t).
// Each rounding errs by at most u times its result (an addition that underflows is exact; a
// division that underflows errs by at most 2^-1075 more), so, while |ql|, |qh| < 2^31
// (kZeroMoveReach), ql is within (2u + u^2)|Ql| and qh within u(1 + u)^2|Ql| + (2u + u^2)|Qh| of
// the exact values: under 3.01u * 2^31 < kZeroMoveBand = 2^-20 (proof_constants.h).
//
// The estimate (estimateZeroMoveRange, every frame): when 0 < ql and qh < 2^31 and both lie more
// than the band from every integer, truncation gives k = floor(ql) and m = floor(qh), the
// fractions ql - k and qh - m are exact (Sterbenz), ql in (k + band, k + 1 - band) puts Ql in
// (k, k + 1), so floor(Ql) = k, and likewise ceil(Qh) - 1 = m. A box away from grid lines (the
// frames a game sees most) is settled there with no exact arithmetic.
//
// The settlement (settleZeroMoveRanges, out of line, both axes again when the estimate leaves one): on a line
// (a rounded quotient that is an integer k: a box resting on a floor or snapped to a wall) the band puts the
// exact quotient in (k - 1, k + 1), and one exact comparison decides: x - o >= k*t for the low end, x + w - o
// > k*t for the high one, made with the rounded a, b and p = fl(k*t) when all three are exact (TwoSum and
// TwoProduct say so). Two ends need no band at all, by monotonic rounding alone: ql < 1 implies Ql < 1 (Ql >=
// 1 means x - o >= t, so a >= t and ql >= 1), so the first cell is 0 or before the map; qh < 0 implies Qh < 0
// (x + w - o >= 0 means x - o >= -w, so a >= -w, b >= 0 and qh >= 0), so no cell of the map is overlapped.
// Anything else (a box edge within 2^-20 cells of a line but not on it, inexact a, b or p there, quotients
// past 2^31) takes the ordinary path, which settles it exactly.
//
// Validity is folded in, so that invalid input always returns false (the ordinary path then
// reports it): the map's header and the signs of the sizes (one minimum: a size <= 0 makes it
// <= 0; a NaN may hide in it but fails below) are tested first; an infinite or NaN x, o or w
// makes ql or qh infinite or NaN, which fails the estimate's range test and the settlement's; an
// infinite t makes ql zero, which fails the estimate, and the settlement tests it; a NaN t makes
// both quotients NaN. The displacement is zero.

#include "cell_range.h"
#include "exact_double.h"
#include "frame_input.h"
#include "proof_constants.h"

#include "tilesweep/resolve.h"
#include "tilesweep/tile_map.h"

#include <algorithm>
#include <cstdint>
#include <limits>

namespace tilesweep::detail {

/// Whether the fraction f = q - floor(q) of an estimated cell coordinate q puts the exact one
/// strictly inside the same cell: more than the band (the estimate's error bound) from both of
/// its lines.
[[nodiscard, gnu::always_inline]] inline bool isInsideCell(double f) noexcept {
    return f > kZeroMoveBand && f < 1 - kZeroMoveBand;
}

/// One axis of a zero move, estimated (see the top of this file): the cells [first, last] whose
/// open interior meets the box's, first >= 0, last not yet clamped to the map, from a = fl(x -
/// o), ql = fl(a / t) and qh = fl(fl(a + w) / t); false when an end lies within the band of a
/// line, or outside (0, 2^31), or a value is not finite. The test 0 < ql and qh < 2^31 covers
/// both quotients: w > 0 gives b >= a and qh >= ql.
[[nodiscard, gnu::always_inline]] inline bool estimateZeroMoveRange(double ql, double qh,
                                                                    CellRange& range) noexcept {
    if (!(ql > 0 && qh < kZeroMoveReach)) return false;  // NaN fails too
    range.first = static_cast<std::int64_t>(ql);         // truncation: floor, as ql > 0
    range.last = static_cast<std::int64_t>(qh);
    return isInsideCell(ql - static_cast<double>(range.first)) &&
           isInsideCell(qh - static_cast<double>(range.last));
}

/// p = fl(k * t) for a cell index 0 <= k < 2^31, and whether it is k * t exactly (TwoProduct's
/// error is zero; the guard keeps TwoProduct exact).
[[nodiscard]] inline bool isExactMultiple(std::int64_t k, double t, double& p) noexcept {
    const auto kd = static_cast<double>(k);
    p = kd * t;
    if (k == 0) return true;
    return t > kZeroMoveProductGuard && t < 1 / kZeroMoveProductGuard && productError(kd, t, p) == 0;
}

/// One axis of a zero move the estimate left undecided, settled exactly (see the top of this
/// file): first clamped at 0, last possibly -1 or past the map; false when an end is undecided
/// or a value of the axis is not finite. The caller has checked that w and t are > 0 or NaN.
[[nodiscard]] inline bool settleZeroMoveRange(double x, double w, double o, double t,
                                              CellRange& range) noexcept {
    const double a = x - o;
    const double b = a + w;
    const double ql = a / t;
    const double qh = b / t;
    // Finite values: an infinite or NaN x, o or w makes ql or qh infinite or NaN; an infinite t
    // makes them zero, so it is tested; a NaN t makes them NaN.
    if (!(ql > -kZeroMoveReach && qh < kZeroMoveReach && t < std::numeric_limits<double>::infinity()))
        return false;  // and, with qh >= ql, both in reach
    double p = 0;
    if (ql < 1) {
        range.first = 0;  // Ql < 1 by monotonic rounding: the map's first cell or one before it
    } else {
        const auto k = static_cast<std::int64_t>(ql);
        const double f = ql - static_cast<double>(k);
        if (isInsideCell(f)) {
            range.first = k;
        } else if (f == 0 && twoSum(x, -o).lo == 0 && isExactMultiple(k, t, p)) {
            range.first = a >= p ? k : k - 1;  // Ql in (k - 1, k + 1): the sign of Ql - k decides
        } else {
            return false;
        }
    }
    if (qh < 0) {
        range.last = -1;  // Qh < 0 by monotonic rounding: the box ends before the map
        return true;
    }
    const auto m = static_cast<std::int64_t>(qh);
    const double f = qh - static_cast<double>(m);
    if (isInsideCell(f)) {
        range.last = m;
    } else if (f == 0 && twoSum(x, -o).lo == 0 && twoSum(a, w).lo == 0 && isExactMultiple(m, t, p)) {
        range.last = b > p ? m : m - 1;  // Qh in (m - 1, m + 1): the sign of Qh - m decides
    } else {
        return false;
    }
    return true;
}

/// The cells of both axes a zero move overlaps, and whether they were decided.
struct ZeroMoveRanges {
    bool decided = false;
    CellRange x{};
    CellRange y{};
};

/// Both axes of a zero move the estimate left undecided, settled exactly; not decided when an
/// end is undecided or the input invalid (the caller has checked the map's header and that the
/// sizes are > 0 or NaN). Out of line, and returned by value, so that the early exit stays
/// small and keeps its own ranges in registers.
template <class T>
[[nodiscard, gnu::noinline]] ZeroMoveRanges settleZeroMoveRanges(FrameInput<T> in) noexcept {
    const TileMapView<T>& map = in.map;
    ZeroMoveRanges r;
    r.decided =
        settleZeroMoveRange(static_cast<double>(in.box.pos.x), static_cast<double>(in.box.size.x),
                            static_cast<double>(map.origin.x), static_cast<double>(map.tileSize.x), r.x) &&
        settleZeroMoveRange(static_cast<double>(in.box.pos.y), static_cast<double>(in.box.size.y),
                            static_cast<double>(map.origin.y), static_cast<double>(map.tileSize.y), r.y);
    return r;
}

/// One axis of a zero move, estimated from its coordinates (estimateZeroMoveRange).
[[nodiscard, gnu::always_inline]] inline bool estimateZeroMoveAxis(double x, double w, double o, double t,
                                                                   CellRange& range) noexcept {
    const double a = x - o;
    return estimateZeroMoveRange(a / t, (a + w) / t, range);
}

/// The zero-move frame (see the top of this file); false when it must take the ordinary path
/// (invalid input, or a box edge the settlement cannot decide). Only for a displacement of
/// zeros. `mapValidated` when the map passed validateTileMap (a PreparedMap that isValid()):
/// its header and tile sizes are then known good (cells present whenever there are any) and
/// are not tested again.
template <class T>
[[nodiscard]] inline bool resolveZeroMove(FrameInput<T> in, const ResolveOutput<T>& out,
                                          ResolveResult<T>& result, bool mapValidated = false) noexcept {
    const TileMapView<T>& map = in.map;
    const std::int64_t columns = map.columns;
    const std::int64_t rows = map.rows;
    // The part of validity the estimates do not imply (see the top of this file). A size <= 0
    // makes the minimum <= 0; a NaN among them may hide in it, but fails the estimate.
    if (mapValidated) {
        if (!(std::min(in.box.size.x, in.box.size.y) > 0)) return false;
    } else {
        if ((columns | rows) < 0 || columns * rows > kMaxCells || map.solid == nullptr) return false;
        if (!(std::min(std::min(in.box.size.x, map.tileSize.x), std::min(in.box.size.y, map.tileSize.y)) > 0))
            return false;
    }
    CellRange x{};
    CellRange y{};
    if (!(estimateZeroMoveAxis(static_cast<double>(in.box.pos.x), static_cast<double>(in.box.size.x),
                               static_cast<double>(map.origin.x), static_cast<double>(map.tileSize.x), x) &&
          estimateZeroMoveAxis(static_cast<double>(in.box.pos.y), static_cast<double>(in.box.size.y),
                               static_cast<double>(map.origin.y), static_cast<double>(map.tileSize.y), y))) {
        const ZeroMoveRanges settled = settleZeroMoveRanges(in);
        if (!settled.decided) return false;
        x = settled.x;
        y = settled.y;
    }
    const std::int64_t lastColumn = std::min(x.last, columns - 1);
    const std::int64_t lastRow = std::min(y.last, rows - 1);
    std::int32_t count = 0;
    for (std::int64_t j = y.first; j <= lastRow; ++j) {
        const std::uint8_t* row = map.solid + j * columns;
        for (std::int64_t i = x.first; i <= lastColumn; ++i) {
            if (row[i] == 0) continue;  // the byte is all it takes: the range is exact
            if (count < out.startOverlapCapacity)
                out.startOverlaps[count] = {static_cast<std::int32_t>(i), static_cast<std::int32_t>(j)};
            ++count;
        }
    }
    result.status = ResolveStatus::Moved;
    result.position = in.box.pos;
    result.contactCount = 0;
    result.startOverlapCount = count;
    return true;
}

}  // namespace tilesweep::detail

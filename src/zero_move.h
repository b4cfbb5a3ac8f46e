// SPDX-License-Identifier: MIT
#pragma once

// The early exit of resolveMove for a zero displacement (both components +0 or -0): nothing
// moves, nothing is hit, and the frame's whole answer is the start position (bit for bit, so
// -0 stays -0) and the solid cells the box overlaps at the start. Those are found from the cells
// under the box, byte first, without forming a tile edge:
//
// On one axis, with x the box's low edge, w its size, o the map origin and t the tile size, cell
// i overlaps the open interval (x, x + w) iff o + (i+1)t > x and o + i*t < x + w, that is iff
// floor(Ql) <= i <= ceil(Qh) - 1 with Ql = (x - o) / t and Qh = (x + w - o) / t (exact
// rationals; the tile edges need not be representable for this, so the answer is the exact
// reference's whatever the map). The two ends are estimated in double:
//   ql = fl(fl(x - o) / t), within (2u + u^2)|Ql| of Ql (two roundings, u = 2^-53; an
//        underflowing difference is exact; a quotient below 2^-900 that is not an exact zero is
//        left to the ordinary path, where underflow would break the relative bound);
//   qh = fl(fl(fl(x - o) + w) / t), within u|x - o| / t of Qh from the first rounding, and
//        (2u + u^2)|Qh| + O(u^2) from the other two: under 1.01u|Ql| + 2.01u|Qh|.
// When ql and qh lie far enough from an integer (margins below, at zeroMoveCells), floor(Ql) =
// floor(ql) and ceil(Qh) - 1 = floor(qh). When either is undecided (a box edge within a few ulps
// of a grid line, or on one: a box resting on a floor), the frame takes the ordinary path, which
// settles it exactly. Float inputs are widened to double (exactly) and take the
// same test. Inputs must be valid (finite, sizes > 0); estimates beyond +-2^52 are undecided.

#include "cell_range.h"
#include "exact_double.h"
#include "proof_constants.h"
#include "validity.h"

#include "tilesweep/resolve.h"

#include <cmath>
#include <cstdint>
#include <limits>

namespace tilesweep::detail {

/// Whether num = n * t exactly, for a double integer n = fl(num / t): the product rounds to num
/// and its rounding error (TwoProduct, exact_double.h) is zero. Away from underflow only.
[[nodiscard]] inline bool isExactQuotient(double num, double t, double n) noexcept {
    if (num == 0) return true;  // n = fl(0 / t) = 0
    if (!(std::fabs(num) > kZeroMoveUnderflowGuard && std::fabs(num) < 1 / kZeroMoveUnderflowGuard))
        return false;
    const double p = n * t;
    return p == num && productError(n, t, p) == 0;
}

/// zeroMoveCells outside its bands: a box edge exactly on a grid line (a box resting on a floor,
/// snapped to a tile) is settled when the rounded quotient is an integer n and x - o, x - o + w
/// and n*t are exact, so that Q = n; false otherwise. Out of line: the early exit stays small.
#if defined(__GNUC__)
__attribute__((noinline, cold))
#endif
inline bool
settleOnLine(double x, double w, double o, double t, double a, double b, double ql, double qh, double rl,
             double rh, double el, double eh, std::int64_t& last) noexcept {
    const bool exactA = twoSum(x, -o).lo == 0;
    if (!(rl > el && rl < 1 - el) && !(rl == 0 && exactA && isExactQuotient(a, t, ql))) return false;
    // x on line n: cell n = floor(ql) is the first whose interior meets the box's, as found.
    if (rh > eh && rh < 1 - eh) return true;
    if (!(rh == 0 && exactA && twoSum(a, w).lo == 0 && isExactQuotient(b, t, qh))) return false;
    last -= 1;  // x + w on line n: cell n - 1 is the last
    return true;
}

/// The cells [from, to] (clamped to the map; empty when from > to) whose open interior meets
/// the box's on one axis; false when a bound is too close to a grid line to be sure.
///
/// With f = floor(ql) (exact: |ql| < 2^52) and r = fl(ql - f) (exact but when ql lies in
/// (-1, 0), then within 2^-54), Ql - f lies within r -+ (2^-54 + 2.02u|ql|). So r > el and
/// r < fl(1 - el), with el = fl(2^-50|ql| + 2^-52) >= (8u|ql| + 2^-52)(1 - u), put Ql strictly
/// inside (f, f + 1): floor(Ql) = f. The same with eh = fl(2^-50(|ql| + |qh|) + 2^-52) puts Qh
/// strictly inside (g, g + 1), g = floor(qh), so that ceil(Qh) - 1 = g. Outside those bands the
/// one case settled here is an exact one: Q an integer (isExactQuotient).
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
inline bool
zeroMoveCells(double x, double w, double o, double t, std::int64_t cells, std::int64_t& from,
              std::int64_t& to) noexcept {
    const double a = x - o;
    const double b = a + w;
    const double ql = a / t;
    const double qh = b / t;
    // NaN (an overflowing x - o) fails this too.
    if (!(std::fabs(ql) < kZeroMoveReach && std::fabs(qh) < kZeroMoveReach)) return false;
    // A quotient near underflow loses its relative error bound (0 for a nonzero Ql, say).
    if ((std::fabs(ql) < kZeroMoveUnderflowGuard && a != 0) ||
        (std::fabs(qh) < kZeroMoveUnderflowGuard && b != 0))
        return false;
    const std::int64_t i0 = floorToInt(ql);
    const std::int64_t i1 = floorToInt(qh);
    constexpr double kBand = kZeroMoveBandUlps * kUnitRoundoff;  // 2^-50 (proof_constants.h)
    const double el = kBand * std::fabs(ql) + kZeroMoveBandFloor;
    const double eh = kBand * (std::fabs(ql) + std::fabs(qh)) + kZeroMoveBandFloor;
    const double rl = ql - static_cast<double>(i0);
    const double rh = qh - static_cast<double>(i1);
    std::int64_t last = i1;
    if (!(rl > el && rl < 1 - el && rh > eh && rh < 1 - eh) &&
        !settleOnLine(x, w, o, t, a, b, ql, qh, rl, rh, el, eh, last))
        return false;
    from = i0 < 0 ? 0 : i0;
    to = last >= cells ? cells - 1 : last;
    return true;
}

/// The zero-move frame (see the top of this file); false when it must take the ordinary path
/// (invalid input, or a box edge too close to a grid line). Only for a displacement of zeros.
template <class T>
[[nodiscard]] inline bool resolveZeroMove(const ResolveInput<T>& in, const ResolveOutput<T>& out,
                                          ResolveResult<T>& result) noexcept {
    if (!isValidInput(in)) return false;
    const TileMapView<T>& map = in.map;
    std::int64_t i0 = 0;
    std::int64_t i1 = 0;
    std::int64_t j0 = 0;
    std::int64_t j1 = 0;
    if (!zeroMoveCells(static_cast<double>(in.box.pos.x), static_cast<double>(in.box.size.x),
                       static_cast<double>(map.origin.x), static_cast<double>(map.tileSize.x), map.columns,
                       i0, i1) ||
        !zeroMoveCells(static_cast<double>(in.box.pos.y), static_cast<double>(in.box.size.y),
                       static_cast<double>(map.origin.y), static_cast<double>(map.tileSize.y), map.rows, j0,
                       j1))
        return false;
    std::int32_t count = 0;
    for (std::int64_t j = j0; j <= j1; ++j) {
        const std::uint8_t* row = map.solid + j * map.columns;
        for (std::int64_t i = i0; i <= i1; ++i) {
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

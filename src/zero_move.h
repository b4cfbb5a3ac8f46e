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
// The margins el = 4u|ql| and eh = 4u(|ql| + |qh|) exceed those by more than the rounding of
// ql -+ el and qh -+ eh (one more u|q| each); so when floor(ql - el) == floor(ql + el), that is
// floor(Ql), and likewise for the ceiling of Qh. When either is undecided (a box edge within a
// few ulps of a grid line, or on one: a box resting on a floor), the frame takes the ordinary
// path, which settles it exactly. Float inputs are widened to double (exactly) and take the
// same test. Inputs must be valid (finite, sizes > 0); estimates beyond +-2^62 are undecided.

#include <cmath>
#include <cstdint>
#include <limits>

#include "tilesweep/resolve.h"

namespace tilesweep::detail {

/// floor(v) for a finite |v| < 2^62 (no libm call: x86-64's baseline has no rounding instruction).
[[nodiscard]] inline std::int64_t zeroMoveFloor(double v) noexcept {
    auto k = static_cast<std::int64_t>(v);  // toward zero
    if (static_cast<double>(k) > v) --k;
    return k;
}

/// The cells [from, to] (clamped to the map; empty when from > to) whose open interior meets
/// the box's on one axis; false when a bound is too close to a grid line to be sure.
[[nodiscard]] inline bool zeroMoveCells(double x, double w, double o, double t, std::int64_t cells,
                                        std::int64_t& from, std::int64_t& to) noexcept {
    const double a = x - o;
    const double b = a + w;
    const double ql = a / t;
    const double qh = b / t;
    // A quotient near underflow loses its relative error bound (0 for a nonzero Ql, say).
    if ((std::fabs(ql) < 0x1p-900 && a != 0) || (std::fabs(qh) < 0x1p-900 && b != 0)) return false;
    const double el = 0x1p-51 * std::fabs(ql);
    const double eh = 0x1p-51 * (std::fabs(ql) + std::fabs(qh));
    const double lowA = ql - el;
    const double lowB = ql + el;
    const double highA = qh - eh;
    const double highB = qh + eh;
    constexpr double kReach = 0x1p62;
    // NaN (an overflowing x - o) fails these too.
    if (!(lowA > -kReach && lowB < kReach && highA > -kReach && highB < kReach)) return false;
    const std::int64_t i0 = zeroMoveFloor(lowA);
    if (zeroMoveFloor(lowB) != i0) return false;
    // ceil(v) - 1 = -floor(-v) - 1.
    const std::int64_t i1 = -zeroMoveFloor(-highB) - 1;
    if (-zeroMoveFloor(-highA) - 1 != i1) return false;
    from = i0 < 0 ? 0 : i0;
    to = i1 >= cells ? cells - 1 : i1;
    return true;
}

/// Whether in's values are all finite and its sizes positive, and its map header sane: isValid
/// (validate.cpp) inline, for the early exit.
template <class T>
[[nodiscard]] inline bool isValidInline(const SweepInput<T>& in) noexcept {
    const TileMapView<T>& map = in.map;
    const std::int64_t cells = static_cast<std::int64_t>(map.columns) * map.rows;
    constexpr T kMax = std::numeric_limits<T>::max();
    // |v| <= max is false for NaN and infinities; v > 0 && v <= max for positive finite sizes.
    return std::fabs(in.box.pos.x) <= kMax && std::fabs(in.box.pos.y) <= kMax && in.box.size.x > 0 &&
           in.box.size.x <= kMax && in.box.size.y > 0 && in.box.size.y <= kMax &&
           std::fabs(map.origin.x) <= kMax && std::fabs(map.origin.y) <= kMax && map.tileSize.x > 0 &&
           map.tileSize.x <= kMax && map.tileSize.y > 0 && map.tileSize.y <= kMax && map.columns >= 0 &&
           map.rows >= 0 && cells <= kMaxCells && (cells == 0 || map.solid != nullptr);
}

/// The zero-move frame (see the top of this file); false when it must take the ordinary path
/// (invalid input, or a box edge too close to a grid line). Only for a displacement of zeros.
template <class T>
[[nodiscard]] inline bool resolveZeroMove(const SweepInput<T>& in, const ResolveOutput<T>& out,
                                          SweepResult<T>& result) noexcept {
    if (!isValidInline(in)) return false;
    const TileMapView<T>& map = in.map;
    std::int64_t i0 = 0;
    std::int64_t i1 = 0;
    std::int64_t j0 = 0;
    std::int64_t j1 = 0;
    if (!zeroMoveCells(static_cast<double>(in.box.pos.x), static_cast<double>(in.box.size.x),
                       static_cast<double>(map.origin.x), static_cast<double>(map.tileSize.x), map.columns, i0, i1) ||
        !zeroMoveCells(static_cast<double>(in.box.pos.y), static_cast<double>(in.box.size.y),
                       static_cast<double>(map.origin.y), static_cast<double>(map.tileSize.y), map.rows, j0, j1))
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
    result.status = Status::Moved;
    result.position = in.box.pos;
    result.contactCount = 0;
    result.startOverlapCount = count;
    return true;
}

}  // namespace tilesweep::detail

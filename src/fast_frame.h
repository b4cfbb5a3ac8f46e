// SPDX-License-Identifier: MIT
#pragma once

// The fast path of resolveMove for float frames: the same frame loop, walk and tile test as
// the lattice solver (resolve.cpp), on doubles that hold every coordinate exactly.
//
// Why exact. Every finite float is a multiple of its ulp. Let G be the lowest ulp exponent
// among the frame's nonzero inputs, and 2^C a bound on the magnitude of every coordinate the
// frame forms (box edges at the start, the end and every touch position, tile edges from one
// cell before the map to two past it, grid lines next to them). Every such coordinate, and every
// difference of two of them, is a multiple of 2^G below 2^(C+2) in magnitude; when
// C + 2 - G <= 53 (the range test, admitFloatFrame) it is a double exactly, and so is every sum
// and difference the solver takes. What is left:
//   - times are ratios of exact doubles and are compared as cross products, exactly, by
//     compareProducts (exact_double.h: monotonic rounding, then TwoProduct on a tie);
//   - cell indices are estimated by a rounded quotient and settled by one exact comparison with
//     a tile edge (cellOf); the secondary range of the walk, which is a rational, is widened by
//     a certified error bound, which can only add cells for the exact tile test to reject;
//   - a contact time num/den is rounded to double, then to float: that is the correct rounding
//     unless the double lands exactly on a float rounding midpoint, which is then settled
//     exactly by the sign of num - q*den (TwoProduct again);
//   - final positions are exact doubles, rounded to float with the direction the contract asks.
// Every deliberate fault of the lattice solver (fault_injection.h) has its twin here, so the
// fault table proves the suite has teeth on both paths.
//
// Double frames (FastFrame<double>) take the same solver with a filter in place of the exact
// range. The range test (admitDoubleFrame) asks that every nonzero input lie in [2^-250, 2^251),
// that every tile edge origin + k*tile the walk forms be a double computed exactly (all of them
// multiples of the lowest set bit of origin and tile, below 2^53 of it), that the origin be
// within 2^47 tiles of zero, and that the inputs of each axis span at most 104 bits. Then every
// coordinate the solver forms is a double or an exact pair (ExactPair, exact_double.h): a
// difference of two doubles by TwoSum, or a distance between the far box edge x + w (itself a
// TwoSum pair) and a tile edge, a three-term sum that one more TwoSum turns into an exact
// normalized pair (FastAxis::farEdgeMinus, where the span condition is derived). So:
//   - a pair against a double (a distance against a speed, a coordinate against a tile edge)
//     compares exactly by monotonic rounding of its high part;
//   - a time against a time (a pair times a speed against a pair times a speed) is decided by a
//     semi-static filter with a certified bound (compareProducts on pairs), refined exactly
//     by expansion arithmetic inside it (Filtered);
//   - a contact time pair / speed is rounded to double by division and checked against the two
//     rounding midpoints with a TwoProduct remainder (roundTimeToDouble);
//   - a final position pair is rounded by the direction of its low part, and the amended rule's
//     grid-line test is filtered; when the filter cannot decide, the frame goes to the lattice.

#include "axis_sweep.h"
#include "bit_ops.h"
#include "exact_double.h"
#include "fault_injection.h"

#include "tilesweep/resolve.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace tilesweep::detail {

/// Certified bound on the error of the walk's secondary range estimate, in units of
/// u = 2^-53 times A / tile cells, A = |low| + |high| + |disp| + |origin| of the secondary axis.
/// The estimate v = (low + (disp / speed) * t - origin) * fl(1 / tile) takes six rounded
/// operations. With t / speed in [0, 1] and every intermediate below A(1 + 3u) in magnitude,
/// their errors are at most 2.01u|disp| (the slope and its product with t), + 1.01uA (sum),
/// + 1.01uA (difference), all scaled by 1/tile (1 + 2.01u), then + 2.01uA/tile (the rounded
/// reciprocal and the product): under 6.05 uA/tile in all. Adding or subtracting the margin
/// rounds once more, by at most 1.01 uA/tile, and the margin itself is computed 5u low at
/// worst: 10 covers the 7.07 needed (and half of it does not). Double frames estimate the
/// distances t as well (the high part of an exact pair, within u|t|): 1.01u|disp| more; and
/// `high` is the far edge rounded to nearest (|highLow| <= u|high|): 1.01u|high| more, 9.09 in
/// all, which 10, computed at most 5u low, still covers.
inline constexpr double kSecondaryRangeErrorUlps = 10;

/// The most bits the fast path's exact doubles may need: a double's 53.
inline constexpr int kFastSpanBits = 53;

/// The parts of isValid (validate.cpp) that the range tests below do not imply: sizes and tile
/// sizes > 0, map dimensions sane, cells present. (A NaN or an infinity fails the range tests:
/// its exponent field is all ones.) So a frame the fast path admits is a valid one.
template <class T>
[[nodiscard]] inline bool hasValidShape(const SweepInput<T>& in) noexcept {
    const TileMapView<T>& map = in.map;
    const std::int64_t cells = static_cast<std::int64_t>(map.columns) * map.rows;
    return in.box.size.x > 0 && in.box.size.y > 0 && map.tileSize.x > 0 && map.tileSize.y > 0 &&
           map.columns >= 0 && map.rows >= 0 && cells <= kMaxCells && (cells == 0 || map.solid != nullptr);
}

/// Whether the fast path holds every value of this float frame exactly (see the top of this
/// file), which must be valid (hasValidShape): all nonzero inputs normal, C + 2 - G <= 53, and no coordinate
/// near the top of float's range. A few integer operations on the inputs' exponent fields.
[[nodiscard]] inline bool admitFloatFrame(const SweepInput<float>& in) noexcept {
    const float values[10] = {in.box.pos.x,      in.box.pos.y,      in.box.size.x,   in.box.size.y,
                              in.displacement.x, in.displacement.y, in.map.origin.x, in.map.origin.y,
                              in.map.tileSize.x, in.map.tileSize.y};
    int field[10];
    int lowest = 255;
    bool subnormal = false;
    for (int k = 0; k < 10; ++k) {
        std::uint32_t bits = 0;
        std::memcpy(&bits, &values[k], sizeof bits);
        const int f = static_cast<int>((bits >> 23) & 0xff);
        const bool zero = (bits & 0x7fffffff) == 0;
        subnormal |= f == 0 && !zero;
        field[k] = zero ? -1000 : f;  // biased exponent: |v| in [2^(f-127), 2^(f-126))
        if (!zero) lowest = std::min(lowest, f);
    }
    if (subnormal || !hasValidShape(in)) return false;
    if (in.map.columns >= (1 << 24) || in.map.rows >= (1 << 24)) return false;
    // G = lowest - 127 - 23 (the ulp of the smallest input); magnitudes below 2^(f - 126).
    int boxTop = -1000;  // |box input| < 2^(boxTop - 126)
    for (int k = 0; k < 6; ++k) boxTop = std::max(boxTop, field[k]);
    const int cellBits[2] = {32 - countLeadingZeros32(static_cast<std::uint32_t>(in.map.columns) + 2),
                             32 - countLeadingZeros32(static_cast<std::uint32_t>(in.map.rows) + 2)};
    // |origin + k*tile| < 2^(fo - 126) + 2^(ft - 126 + cellBits) <= 2^(edgeTop - 126)
    int edgeTop = -1000;
    for (int a = 0; a < 2; ++a)
        edgeTop = std::max(edgeTop, std::max(field[6 + a], field[8 + a] + cellBits[a]) + 1);
    // Coordinates: |x| + |w| + |dx| < 2^(boxTop + 2 - 126); an edge minus a size, a grid line
    // next to a box edge: one bit more than the larger.
    const int top = std::max(boxTop + 2, edgeTop) + 1;  // all coordinates below 2^(top - 126)
    // Span in bits: (C + 2) - G = (top - 126 + 2) - (lowest - 150).
    int span = top - lowest + 26;
#if defined(TILESWEEP_FAULT_FAST_RANGE_TOO_WIDE)
    --span;  // deliberate fault: the range test one binade too generous
#endif
#if defined(TILESWEEP_FAULT_FAST_RANGE_FAR_TOO_WIDE)
    span -= 6;  // deliberate fault: six binades too generous, past the test's slack
#endif
    return span <= kFastSpanBits && top - 126 <= 120;
}

/// Whether the double fast path holds every value of this double frame (see the top of this
/// file), which must be valid (hasValidShape): nonzero inputs in [2^-250, 2^251), so that no product,
/// TwoProduct error term or filter bound comes near overflow or underflow; every tile edge origin + k*tile
/// with 0 <= k <= cells + 2 a multiple of 2^g (g the lowest set bit of origin and tile) below 2^(g + 53), so
/// that k*tile and the sum are exact doubles; |origin| < 2^47 tile, so that a cell estimate from a rounded
/// quotient is off by less than one cell; and a span of at most 104 bits between the largest coordinate and
/// the lowest set bit of the box and grid inputs, so that the far box edge's distances to tile edges come out
/// as exact pairs (farEdgeMinus).
[[nodiscard]] inline bool admitDoubleFrame(const SweepInput<double>& in) noexcept {
    const double values[10] = {in.box.pos.x,      in.box.pos.y,      in.box.size.x,   in.box.size.y,
                               in.displacement.x, in.displacement.y, in.map.origin.x, in.map.origin.y,
                               in.map.tileSize.x, in.map.tileSize.y};
    int field[10];
    int lsb[10];
    for (int k = 0; k < 10; ++k) {
        std::uint64_t bits = 0;
        std::memcpy(&bits, &values[k], sizeof bits);
        const int f = static_cast<int>((bits >> 52) & 0x7ff);  // |v| in [2^(f-1023), 2^(f-1022))
        const std::uint64_t fraction = bits & ((std::uint64_t{1} << 52) - 1);
        if (f == 0 && fraction == 0) {
            field[k] = -100000;
            lsb[k] = 100000;
            continue;
        }
#if defined(TILESWEEP_FAULT_RANGE_NO_LOWER_BOUND)
        if (f > 1023 + 250) return false;  // deliberate fault: the lower bound 2^-250 forgotten
#else
        if (f < 1023 - 250 || f > 1023 + 250) return false;
#endif
        field[k] = f - 1023;
        lsb[k] = f - 1023 - 52 + countTrailingZeros64(fraction | (std::uint64_t{1} << 52));
    }
    if (!hasValidShape(in)) return false;
    const std::int32_t cells[2] = {in.map.columns, in.map.rows};
    for (int a = 0; a < 2; ++a) {
        const int o = 6 + a;
        const int t = 8 + a;
        const int cellBits = 64 - countLeadingZeros64(static_cast<std::uint64_t>(cells[a]) + 3);
        // |origin| + (cells + 2) * tile < 2^(max(eo + 1, et + 1 + cellBits) + 1).
        const int top = std::max(field[o] + 1, field[t] + 1 + cellBits) + 1;
        if (top > std::min(lsb[o], lsb[t]) + 53) return false;
        if (field[o] - field[t] > 46) return false;  // |origin| / tile < 2^(eo + 1 - et) <= 2^47
        // The far edge's distances to tile edges (FastAxis::farEdgeMinus). With x, w the box's
        // position and size, h = fl(x + w) and h + l = x + w: |h| <= |x| + |w| < 2^boxTop; for an
        // edge e (|e| < 2^top), fl(h - e) = a with h - e = a + b, |a| < 2^(m + 1), m = max(top,
        // boxTop), so |b| <= 2^(m - 52) and |l| <= 2^(boxTop - 53): |b + l| < 2^(m - 51). All of
        // e, x, w, h, a, b, l are multiples of 2^lowest (the least set bit of x, w, origin and
        // tile), so b + l is a double, exactly, when m - 51 <= lowest + 53.
        const int boxTop = std::max(field[a], field[2 + a]) + 2;
        const int lowest = std::min(std::min(lsb[a], lsb[2 + a]), std::min(lsb[o], lsb[t]));
        if (std::max(top, boxTop) > lowest + 104) return false;
    }
    return true;
}

/// floor(v) for |v| < 2^62, without a libm call (x86-64's baseline has no rounding instruction).
[[nodiscard]] inline std::int64_t floorToInt(double v) noexcept {
    auto k = static_cast<std::int64_t>(v);  // toward zero
    if (static_cast<double>(k) > v) --k;
    return k;
}

// The arithmetic of a coordinate, by type: an exact double (float frames) or an exact pair
// (double frames). The double versions are the plain operations, so the float path compiles
// to what it was.

template <class Coord>
[[nodiscard]] Coord differenceOf(double a, double b) noexcept;
template <>
[[nodiscard]] inline double differenceOf<double>(double a, double b) noexcept {
    return a - b;
}
template <>
[[nodiscard]] inline ExactPair differenceOf<ExactPair>(double a, double b) noexcept {
    return twoSum(a, -b);
}

template <class Coord>
[[nodiscard]] Coord sumOf(double a, double b) noexcept;
template <>
[[nodiscard]] inline double sumOf<double>(double a, double b) noexcept {
    return a + b;
}
template <>
[[nodiscard]] inline ExactPair sumOf<ExactPair>(double a, double b) noexcept {
    return twoSum(a, b);
}

template <class Coord>
[[nodiscard]] Coord coordOf(double a) noexcept;
template <>
[[nodiscard]] inline double coordOf<double>(double a) noexcept {
    return a;
}
template <>
[[nodiscard]] inline ExactPair coordOf<ExactPair>(double a) noexcept {
    return {a, 0};
}

/// -1, 0 or 1 as v compares with d, exactly.
[[nodiscard]] inline int compare(double v, double d) noexcept { return v < d ? -1 : (v > d ? 1 : 0); }
/// The sign of v, exactly (a pair's high part is zero only when the pair is).
[[nodiscard]] inline int signOf(double v) noexcept { return v < 0 ? -1 : (v > 0 ? 1 : 0); }
[[nodiscard]] inline int signOf(ExactPair v) noexcept { return signOf(v.hi); }
/// A double near v, for estimates only: within u|v| of it.
[[nodiscard]] inline double approximate(double v) noexcept { return v; }
[[nodiscard]] inline double approximate(ExactPair v) noexcept { return v.hi; }
/// Whether two coordinates are the same value represented the same way (a sufficient test of
/// equality, for the shortcut in compareTimes).
[[nodiscard]] inline bool identical(double a, double b) noexcept { return a == b; }
[[nodiscard]] inline bool identical(ExactPair a, ExactPair b) noexcept {
    return a.hi == b.hi && a.lo == b.lo;
}

/// Whether a*s > b*t for certain (a, b coordinates, s, t >= 0): false may also mean "equal or
/// could not tell". The walk's early exit; walking on is always harmless.
[[nodiscard]] inline bool certainlyGreater(double a, double s, double b, double t) noexcept {
    return a * s > b * t;  // monotonic rounding: a strictly greater rounded product is exact
}
[[nodiscard]] inline bool certainlyGreater(ExactPair a, double s, ExactPair b, double t) noexcept {
    const double p = a.hi * s;
    const double q = b.hi * t;
    return p - q > kPairProductErrorBound * (std::fabs(p) + std::fabs(q));  // compareProducts' filter
}

/// One axis of a fast frame: the box's motion and the grid, as exact doubles. The far box edge
/// low + size is held as high + highLow: on float frames it is a double (highLow = 0); on double
/// frames it is the TwoSum pair of low and size, and the distances from it to a tile edge are
/// three-term sums (farEdgeMinus), made exact pairs again by one more TwoSum.
struct FastAxis {
    double low;     ///< box edge with the smaller coordinate, at t = 0
    double high;    ///< fl(low + size): the far edge, rounded to nearest (exact on float frames)
    double disp;    ///< displacement over the frame
    double speed;   ///< |disp|
    int dir;        ///< sign of disp
    double origin;  ///< map origin
    double tile;    ///< tile size
    std::int64_t cells;
    double invTile;      ///< 1 / tile, rounded: for estimates only
    double size;         ///< the box size: low + size is the far edge, exactly
    double highLow = 0;  ///< low + size - high, exactly (|highLow| <= ulp(high) / 2)

    [[nodiscard]] double edge(std::int64_t k) const noexcept {
        return origin + static_cast<double>(k) * tile;
    }

    /// The far edge minus the tile edge e, exactly: (high - e) + highLow. For double frames,
    /// TwoSum gives high - e = a + b exactly, and then b + highLow is exact too: both are
    /// multiples of 2^L (L the lowest set bit among the box, origin and tile inputs of this axis)
    /// below 2^(L+53) in magnitude, which admitDoubleFrame checks (|b| <= u|a|, |highLow| <=
    /// u|high|, and |a|, |high| < 2^(L+105)). A last TwoSum of a and b + highLow returns a
    /// normalized pair (hi = fl(value)), exact for any doubles: the form compare,
    /// compareProducts and roundTimeToDouble ask for.
    template <class Coord>
    [[nodiscard]] Coord farEdgeMinus(double e) const noexcept {
        if constexpr (std::is_same<Coord, ExactPair>::value) {
            const ExactPair s = twoSum(high, -e);
            if (highLow == 0) return s;
            return twoSum(s.hi, s.lo + highLow);
        } else {
            return high - e;  // float frames: exact in double (admitFloatFrame)
        }
    }
    /// The tile edge e minus the far edge, exactly: the negation of farEdgeMinus (negation is
    /// exact and keeps a pair normalized).
    template <class Coord>
    [[nodiscard]] Coord minusFarEdge(double e) const noexcept {
        if constexpr (std::is_same<Coord, ExactPair>::value) {
            const ExactPair s = farEdgeMinus<ExactPair>(e);
            return {-s.hi, -s.lo};
        } else {
            return e - high;
        }
    }
    /// The far edge at t = 0 as a coordinate (exact).
    template <class Coord>
    [[nodiscard]] Coord farEdge() const noexcept {
        if constexpr (std::is_same<Coord, ExactPair>::value) {
            return {high, highLow};
        } else {
            return high;
        }
    }
    /// Whether the far edge lies above the double v, exactly: when high != v the rounded far
    /// edge is on the same side of v as the exact one (monotonic rounding); when equal, highLow
    /// decides.
    [[nodiscard]] bool farEdgeAbove(double v) const noexcept {
        return high > v || (high == v && highLow > 0);
    }
    [[nodiscard]] bool farEdgeAtLeast(double v) const noexcept {
        return high > v || (high == v && highLow >= 0);
    }

    template <class Coord = double>
    [[nodiscard]] Coord entryDistance(double lo, double hi) const noexcept {
        return dir > 0 ? minusFarEdge<Coord>(lo) : differenceOf<Coord>(low, hi);
    }
    template <class Coord = double>
    [[nodiscard]] Coord exitDistance(double lo, double hi) const noexcept {
        return dir > 0 ? differenceOf<Coord>(hi, low) : farEdgeMinus<Coord>(lo);
    }
    [[nodiscard]] bool overlapsAtStart(double lo, double hi) const noexcept {
#if defined(TILESWEEP_FAULT_TOUCH_OVERLAPS)
        return low <= hi && farEdgeAtLeast(lo);  // deliberate fault: touching counted as overlap
#else
        return low < hi && farEdgeAbove(lo);
#endif
    }

    /// clamp(floor((c - origin) / tile), -1, cells), exactly. The estimate is off by less than
    /// one cell where the clamp does not decide: for an exact double c, (c - origin) * invTile
    /// is within 2.01u of the quotient, relatively (float frames: the difference is exact); for
    /// a pair, the difference of its high part and the origin adds u(|c| + |origin|) / tile,
    /// under 0.2 cells where |quotient| < 2^32 since |origin| < 2^47 tile (admitDoubleFrame).
    /// One exact comparison with a tile edge, either way, settles it.
    template <class Coord>
    [[nodiscard]] std::int64_t cellOf(Coord c) const noexcept {
        std::int64_t k = clampCell((approximate(c) - origin) * invTile);
        if (k > -1 && compare(c, edge(k)) < 0) {
            --k;
        } else if (k < cells && compare(c, edge(k + 1)) >= 0) {
            ++k;
        }
        return k;
    }

    /// floor(v) clamped to [-1, cells], for an estimate v of a cell coordinate.
    [[nodiscard]] std::int64_t clampCell(double v) const noexcept {
        if (!(v > -1)) return -1;
        if (v >= static_cast<double>(cells)) return cells;
        return floorToInt(v);
    }

    /// Whether a grid line origin + k*tile (any integer k) lies in [lo, hi): the least k with
    /// origin + k*tile >= lo from a rounded quotient (off by at most one: the quotient is below
    /// 2^53), settled by exact comparisons. Float frames only (every value an exact double).
    [[nodiscard]] bool hasLineIn(double lo, double hi) const noexcept {
        if (!(lo < hi)) return false;
        if (hi - lo >= tile) return true;
        // |(lo - origin) / tile| < 2^53 (the range test): the ceiling fits, and k * tile is exact.
        auto k = static_cast<double>(-floorToInt(-((lo - origin) / tile)));
        if (origin + k * tile < lo) {
            k += 1;
        } else if (origin + (k - 1) * tile >= lo) {
            k -= 1;
        }
        return origin + k * tile < hi;
    }
};

/// A time num / den (den > 0): num an exact coordinate, den an exact double.
template <class Coord = double>
struct FastTime {
    Coord num;
    double den;
};

/// The verdict on one tile and, when it blocks, its time of impact (TileTest, axis_sweep.h).
template <class Coord = double>
struct FastTileTest {
    TileVerdict verdict;
    FastTime<Coord> time;
};

/// testTile (axis_sweep.h) on exact coordinates: the same branches, every comparison of two
/// times made by compareProducts. Only the motion fields of mx and my are read.
template <class Coord = double>
[[nodiscard]] FastTileTest<Coord> testTileFast(const FastAxis& mx, const FastAxis& my, double xlo, double xhi,
                                               double ylo, double yhi, bool& refined) noexcept {
    FastTileTest<Coord> miss{TileVerdict::Misses, {coordOf<Coord>(0), 1}};
    if (mx.dir == 0 || my.dir == 0) {
        if (mx.dir == 0 && my.dir == 0) {
            if (mx.overlapsAtStart(xlo, xhi) && my.overlapsAtStart(ylo, yhi))
                miss.verdict = TileVerdict::StartsOverlapping;
            return miss;
        }
        const bool xMoves = mx.dir != 0;
        const FastAxis& moving = xMoves ? mx : my;
        const FastAxis& still = xMoves ? my : mx;
        const double lo = xMoves ? xlo : ylo;
        const double hi = xMoves ? xhi : yhi;
        if (!(xMoves ? still.overlapsAtStart(ylo, yhi) : still.overlapsAtStart(xlo, xhi))) return miss;
        const Coord entry = moving.entryDistance<Coord>(lo, hi);
        if (signOf(entry) < 0) {
            if (signOf(moving.exitDistance<Coord>(lo, hi)) > 0) miss.verdict = TileVerdict::StartsOverlapping;
            return miss;
        }
        if (compare(entry, moving.speed) >= 0) return miss;
        return {xMoves ? TileVerdict::BlocksOnX : TileVerdict::BlocksOnY, {entry, moving.speed}};
    }
    const Coord ex = mx.entryDistance<Coord>(xlo, xhi);
    const Coord ey = my.entryDistance<Coord>(ylo, yhi);
    const Coord xx = mx.exitDistance<Coord>(xlo, xhi);
    const Coord xy = my.exitDistance<Coord>(ylo, yhi);
    if (signOf(ex) < 0 && signOf(ey) < 0) {
        if (signOf(xx) > 0 && signOf(xy) > 0) miss.verdict = TileVerdict::StartsOverlapping;
        return miss;
    }
#if defined(TILESWEEP_FAULT_END_INCLUSIVE)
    if (compare(ex, mx.speed) > 0 || compare(ey, my.speed) > 0)
        return miss;  // deliberate fault: t = 1 blocks
#else
    if (compare(ex, mx.speed) >= 0 || compare(ey, my.speed) >= 0) return miss;  // E >= 1
#endif
#if !defined(TILESWEEP_FAULT_NO_CORNER_MISS)
    // E < X: each axis enters before the other exits.
    if (compareProducts(ex, my.speed, xy, mx.speed, refined) >= 0) return miss;
    if (compareProducts(ey, mx.speed, xx, my.speed, refined) >= 0) return miss;
#endif
#if defined(TILESWEEP_FAULT_DOUBLE_PREDICATE)
    // Deliberate fault: the entry comparison in plain double arithmetic.
    const double pa = approximate(ex) * my.speed;
    const double pb = approximate(ey) * mx.speed;
    const int order = pa > pb ? 1 : (pa < pb ? -1 : 0);
#else
    const int order = compareProducts(ex, my.speed, ey, mx.speed, refined);
#endif
    if (order > 0) return {TileVerdict::BlocksOnX, {ex, mx.speed}};
    if (order < 0) return {TileVerdict::BlocksOnY, {ey, my.speed}};
    return {TileVerdict::Tie, {ey, my.speed}};
}

/// The exact time num / den (0 <= num <= den, exact doubles) rounded to the nearest float,
/// ties to even; false for a time in float's subnormal range (the lattice rounds those).
/// `refined` is set when the rounded quotient landed on a float rounding midpoint.
[[nodiscard]] inline bool roundTimeToFloat(const FastTime<double>& t, bool& refined, float& out) noexcept {
    const double q = t.num / t.den + 0.0;  // -0 (from -0 - +0) reads +0, as the lattice's does
    if (q != 0 && q < 0x1p-126) return false;
    std::uint64_t bits = 0;
    std::memcpy(&bits, &q, sizeof bits);
    // The 29 bits of q below float's 24 (q is a normal double in float's normal range).
    // Rounding q to float is the correct rounding of num/den unless q is a float rounding
    // midpoint: q = fl(num/den) lies on the same side of every float and every midpoint as
    // num/den does (monotonic rounding, and floats and their midpoints are doubles).
    if ((bits & 0x1fffffffu) != 0x10000000u) {
        out = static_cast<float>(q);
        return true;
    }
    // q is a midpoint: the sign of num - q*den decides. q*den = p + e exactly (TwoProduct),
    // and num - p is exact (Sterbenz: p is within a factor 2 of num).
    refined = true;
    const double p = q * t.den;
    const double e = productError(q, t.den, p);
    const double r = t.num - p;
    if (r > e) {
        out = roundToFloat(q, true);
    } else if (r < e) {
        out = roundToFloat(q, false);
    } else {
#if defined(TILESWEEP_FAULT_TIME_TIES_AWAY)
        out = roundToFloat(q, true);  // deliberate fault: an exact halfway time rounded away
#else
        out = static_cast<float>(q);                      // exactly the midpoint: ties to even
#endif
    }
    return true;
}

/// The exact time num / den (num an exact pair, 0 <= num <= den, den a double) rounded to the
/// nearest double, ties to even; false when it cannot settle it (the lattice then rounds).
///
/// A pair with a zero low part is a double, and IEEE division rounds correctly. Otherwise take
/// q = fl(hi / den) and R = num - q*den = (hi - p) - e + lo exactly, where q*den = p + e
/// (TwoProduct) and hi - p is exact (Sterbenz: p is within a factor 2 of hi). q is the correct
/// rounding iff -down < R < up, with up = den*ulp(q)/2 and down the same below q (a quarter
/// ulp when q is a power of two), both exact; R = up or R = -down is a tie. The filter computes
/// R~ = fl(fl(d - e) + lo), d = hi - p, within (2u + u^2)(|d| + |e| + |lo|) of R; the bound,
/// computed as fl(3u fl(fl(|d| + |e|) + |lo|)), exceeds that. Inside it the sign of the exact
/// five-term sum decides (Filtered). q moves by one ulp at a time (it starts within two).
[[nodiscard]] inline bool roundTimeToDouble(const FastTime<ExactPair>& t, bool& refined,
                                            double& out) noexcept {
    double q = t.num.hi / t.den + 0.0;  // -0 reads +0
    if (t.num.lo == 0) {
        out = q;
        return true;
    }
    for (int step = 0; step < 4; ++step) {
        const double p = q * t.den;
        const double e = productError(q, t.den, p);
        const double d = t.num.hi - p;
        const double r = (d - e) + t.num.lo;
        const double bound = 3 * 0x1p-53 * ((std::fabs(d) + std::fabs(e)) + std::fabs(t.num.lo));
        const double ulp = ulpAbove(q);
        const double up = 0.5 * ulp * t.den;
        std::uint64_t bits = 0;
        std::memcpy(&bits, &q, sizeof bits);
        const bool powerOfTwo = (bits & ((std::uint64_t{1} << 52) - 1)) == 0;
        const double down = (powerOfTwo ? 0.25 : 0.5) * ulp * t.den;
        int above = 0;  // sign of R - up
        if (r - bound > up) {
            above = 1;
        } else if (r + bound < up) {
            above = -1;
        } else {
            refined = true;
            const double terms[4] = {-up, t.num.lo, -e, d};
            above = signOfSum(terms, 4);
        }
        if (above > 0) {
            q = stepDouble(q, true);
            continue;
        }
        int below = 0;  // sign of R + down
        if (r + bound < -down) {
            below = -1;
        } else if (r - bound > -down) {
            below = 1;
        } else {
            refined = true;
            const double terms[4] = {down, t.num.lo, -e, d};
            below = signOfSum(terms, 4);
        }
        if (below < 0) {
            q = stepDouble(q, false);
            continue;
        }
        const bool odd = (bits & 1) != 0;
#if defined(TILESWEEP_FAULT_TIME_TIES_AWAY)
        if (above == 0) q = stepDouble(q, true);  // deliberate fault: an exact halfway time rounded away
        (void)odd;
#else
        if (above == 0 && odd) q = stepDouble(q, true);   // halfway to the even one above
        if (below == 0 && odd) q = stepDouble(q, false);  // halfway to the even one below
#endif
        out = q;
        return true;
    }
    return false;
}

/// The fast path's frame solver: FrameSolver (resolve.cpp) step for step, on exact doubles
/// (T = float) or exact pairs under a filter (T = double).
template <class T>
class FastFrame {
public:
    /// A coordinate the solver forms from two values: exact in double for float frames, an
    /// exact pair for double frames.
    using Coord = std::conditional_t<std::is_same<T, float>::value, double, ExactPair>;

    explicit FastFrame(const SweepInput<T>& in) noexcept : map_(in.map) {
        axis_[0] = makeAxis(in.box.pos.x, in.box.size.x, in.displacement.x, in.map.origin.x,
                            in.map.tileSize.x, in.map.columns);
        axis_[1] = makeAxis(in.box.pos.y, in.box.size.y, in.displacement.y, in.map.origin.y,
                            in.map.tileSize.y, in.map.rows);
        start_[0] = in.box.pos.x;
        start_[1] = in.box.pos.y;
    }

    /// Solves the frame into `result`; false when it meets a case it hands to the lattice.
    bool run(const ResolveOutput<T>& out, SweepResult<T>& result) noexcept {
        // A short move: the solid cells of the swept bounds, listed once, serve the start
        // overlaps and both steps (collectNear); otherwise the walk.
        const bool nearOnly = collectNear(std::max<std::int32_t>(out.contactCapacity, 0));
        result.startOverlapCount = nearOnly ? startOverlapsOfNear(out.startOverlaps, out.startOverlapCapacity)
                                            : listStartOverlaps(out.startOverlaps, out.startOverlapCapacity);
        result.position = {start_[0], start_[1]};
        if (axis_[0].dir == 0 && axis_[1].dir == 0) {
            result.status = Status::Moved;
            return true;
        }
        Coord finalPos[2] = {sumOf<Coord>(axis_[0].low, axis_[0].disp),
                             sumOf<Coord>(axis_[1].low, axis_[1].disp)};
        Hits first{out.contacts, std::max<std::int32_t>(out.contactCapacity, 0)};
        if (axis_[0].dir != 0 && axis_[1].dir != 0) {
            if (nearOnly) {
                for (std::int32_t n = 0; n < nearCount_; ++n) testAndRecord(near_[n].i, near_[n].j, first);
            } else {
                sweepBothAxes(first);
            }
        } else {
            const int a = axis_[0].dir != 0 ? 0 : 1;
            const Coord heldLow = coordOf<Coord>(axis_[1 - a].low);
            const Coord heldHigh = axis_[1 - a].template farEdge<Coord>();
            if (nearOnly) {
                sweepOneAxisNear(a, heldLow, heldHigh, {coordOf<Coord>(0), 1}, first);
            } else {
                sweepOneAxis(a, heldLow, heldHigh, {coordOf<Coord>(0), 1}, first);
            }
        }
        std::int32_t total = 0;
        if (first.any) {
            if (!finishStep(first)) return false;
            total = first.count;
            for (int a = 0; a < 2; ++a)
                if (first.axisHit[a]) finalPos[a] = touchLow(a, first.touch[a]);
            const int free = first.axisHit[0] ? 1 : 0;
            if (first.axisHit[0] != first.axisHit[1] && axis_[free].dir != 0) {
                const int held = 1 - free;
                const std::int32_t used = std::min(first.count, first.capacity);
                Hits second{out.contacts + used, first.capacity - used};
                if (nearOnly) {
                    sweepOneAxisNear(free, touchLow(held, first.touch[held]),
                                     touchHigh(held, first.touch[held]), first.time, second);
                } else {
                    sweepOneAxis(free, touchLow(held, first.touch[held]), touchHigh(held, first.touch[held]),
                                 first.time, second);
                }
                if (second.any) {
                    if (!finishStep(second)) return false;
                    total += second.count;
                    finalPos[free] = touchLow(free, second.touch[free]);
                }
            }
        }
        result.contactCount = total;
        result.status = total > 0 ? Status::Blocked : Status::Moved;
        if (!roundFinal(finalPos[0], 0, result.position.x) || !roundFinal(finalPos[1], 1, result.position.y))
            return false;
        return true;
    }

    /// Whether some predicate needed its exact refinement (DecisionPath::Filtered).
    [[nodiscard]] bool refined() const noexcept { return refined_; }

private:
    /// The hits of one step (StepHits in resolve.cpp). `touch` is the tile edge the box touches
    /// on each contact axis: its near edge for a move toward minus infinity, its far edge else.
    struct Hits {
        Contact<T>* store;
        std::int32_t capacity;
        std::int32_t count = 0;
        bool any = false;
        FastTime<Coord> time{coordOf<Coord>(0), 1};
        bool axisHit[2] = {false, false};
        double touch[2] = {0, 0};
    };

    FastAxis makeAxis(T pos, T size, T disp, T origin, T tile, std::int32_t cells) noexcept {
        const auto p = static_cast<double>(pos);
        const auto d = static_cast<double>(disp);
        const int dir = d > 0 ? 1 : (d < 0 ? -1 : 0);
        const auto t = static_cast<double>(tile);
        const auto w = static_cast<double>(size);
        const auto o = static_cast<double>(origin);
        const Coord high = sumOf<Coord>(p, w);
        if constexpr (std::is_same<Coord, ExactPair>::value) {
            return {p, high.hi, d, std::fabs(d), dir, o, t, cells, 1 / t, w, high.lo};
        } else {
            return {p, high, d, std::fabs(d), dir, o, t, cells, 1 / t, w, 0};
        }
    }

    /// The box's low edge when it touches the tile edge `e` on `axis`.
    Coord touchLow(int axis, double e) const noexcept {
        const FastAxis& g = axis_[axis];
        return g.dir > 0 ? differenceOf<Coord>(e, g.size) : coordOf<Coord>(e);
    }
    /// The box's high edge when it touches the tile edge `e` on `axis`.
    Coord touchHigh(int axis, double e) const noexcept {
        const FastAxis& g = axis_[axis];
        return g.dir > 0 ? coordOf<Coord>(e) : sumOf<Coord>(e, g.size);
    }

    int compareTimes(const FastTime<Coord>& a, const FastTime<Coord>& b) noexcept {
        // The same fraction (tiles entered across one face line): equal without arithmetic.
        if (identical(a.num, b.num) && a.den == b.den) return 0;
        return compareProducts(a.num, b.den, b.num, a.den, refined_);
    }

    void add(Hits& hits, Cell cell, Axis axis, const FastTime<Coord>& t, double touchEdge) noexcept {
        if (hits.any) {
            const int order = compareTimes(t, hits.time);
            if (order > 0) return;
            if (order < 0) {
                hits.count = 0;
                hits.axisHit[0] = hits.axisHit[1] = false;
            }
        }
        hits.any = true;
        hits.time = t;
        const int a = axis == Axis::X ? 0 : 1;
        hits.axisHit[a] = true;
        hits.touch[a] = touchEdge;
        if (hits.count < hits.capacity) hits.store[hits.count] = {cell, normalOn(a), T(0)};
        ++hits.count;
    }

    /// Sorts a step's stored hits by row, then column, and writes its frame time.
    bool finishStep(Hits& hits) noexcept {
        const std::int32_t stored = std::min(hits.count, hits.capacity);
        T time = 0;
        if constexpr (std::is_same<T, float>::value) {
            if (!roundTimeToFloat(hits.time, refined_, time)) return false;
        } else {
            if (!roundTimeToDouble(hits.time, refined_, time)) return false;
        }
        for (std::int32_t k = 0; k < stored; ++k) hits.store[k].time = time;
        if (stored > 1)
            std::sort(hits.store, hits.store + stored, [](const Contact<T>& a, const Contact<T>& b) {
                return a.tile.j != b.tile.j ? a.tile.j < b.tile.j : a.tile.i < b.tile.i;
            });
        return true;
    }

    /// FrameSolver::roundFinal: toward the start, or toward minus infinity on an axis moving
    /// that way when rounding back would carry the far edge over a grid line. `exact` is the
    /// exact final coordinate; false when the grid-line test cannot be settled here.
    bool roundFinal(double exact, int axis, float& out) const noexcept {
        // Float frames: the rounded value is a float between the exact one and the start, so a
        // multiple of 2^G below 2^C, and its far edge is exact too.
        exact += 0.0;  // -0 reads +0, as the lattice's zero does
        const float start = start_[axis];
        if (exact == static_cast<double>(start)) {
            out = start;
            return true;
        }
#if defined(TILESWEEP_FAULT_ROUND_NEAREST)
        const float towardStart = static_cast<float>(exact);  // deliberate fault
#else
        const float towardStart = roundToFloat(exact, exact < static_cast<double>(start));
#endif
        out = towardStart;
#if !defined(TILESWEEP_FAULT_OLD_ROUNDING_RULE)  // the fault keeps the rule before the amendment
        const FastAxis& m = axis_[axis];
        if (!(exact < m.low)) return true;
        const auto rounded = static_cast<double>(towardStart);
        if (rounded == exact) return true;
        if (!m.hasLineIn(exact + m.size, rounded + m.size)) return true;
        out = roundToFloat(exact, false);
#endif
        return true;
    }

    /// The same on an exact pair (double frames). The pair's high part is the exact value
    /// rounded to nearest; its low part says which side of it the exact value lies on, so the
    /// directed roundings are hi or its neighbour. The grid-line test is filtered: the grid
    /// coordinate of the far edge, z = (exact + size - origin) / tile, is estimated from
    /// fl(fl(fl(hi + size) - origin) * fl(1 / tile)) within 4.1u(|hi| + size + |origin|) / tile
    /// + |lo| / tile (two rounded sums, the reciprocal and the product; lo left out), and the
    /// interval [exact, rounded) + size spans (rounded - exact) / tile <= (|rounded - hi| + |lo|)
    /// / tile of it. The reach below is 16u and twice those, which also covers its own rounding
    /// and that of z -+ reach; when the widened interval holds no integer there is no line
    /// (decided); otherwise the lattice settles it.
    bool roundFinal(ExactPair exact, int axis, double& out) const noexcept {
        const double start = start_[axis];
        const int side = compare(exact, start);
        if (side == 0) {
            out = start;
            return true;
        }
        const double hi = exact.hi + 0.0;  // -0 reads +0, as the lattice's zero does
        const double down = exact.lo < 0 ? stepDouble(hi, false) : hi;  // toward minus infinity
        const double up = exact.lo > 0 ? stepDouble(hi, true) : hi;
#if defined(TILESWEEP_FAULT_ROUND_NEAREST)
        const double towardStart = hi;  // deliberate fault
        (void)up;
        (void)down;
#else
        const double towardStart = side > 0 ? down : up;
#endif
        out = towardStart;
#if !defined(TILESWEEP_FAULT_OLD_ROUNDING_RULE)  // the fault keeps the rule before the amendment
        const FastAxis& m = axis_[axis];
        if (side > 0 || exact.lo == 0) return true;  // not toward minus infinity, or exact
        // Some k with exact + size <= origin + k*tile < towardStart + size?
        constexpr double u = 0x1p-53;
        const double z = ((hi + m.size) - m.origin) * m.invTile;
        const double reach = 16 * u * ((std::fabs(hi) + m.size) + std::fabs(m.origin)) * m.invTile +
                             2 * (std::fabs(towardStart - hi) + std::fabs(exact.lo)) * m.invTile;
        if (!(std::fabs(z) < 0x1p40)) return false;
        const double from = z - reach;
        const double to = z + reach;
        const std::int64_t k = floorToInt(from);
        if (static_cast<double>(k) == from || floorToInt(to) != k) return false;  // may hold a line
#endif
        return true;
    }

    /// Solid cells the box overlaps (open) at the start, by row then column. The candidate
    /// range comes from the cell estimates (low - origin) * invTile, widened by a certified
    /// bound. Float frames: low and high are exact doubles and so is their difference with the
    /// origin, so the estimate is within 2.01u of the quotient, relatively; 8u of its magnitude
    /// covers it. Double frames: fl(v - origin) adds u|v - origin| and the far edge's rounding
    /// |highLow| <= u|high|, so the estimate is off by at most (4.02u(|v| + |origin|)) / tile;
    /// the margin 8u(|v| + |origin|) * invTile, computed at most 4u low, covers it. No exact
    /// settle: a solid byte in the range is the only thing that costs an exact test, the open
    /// overlap of the tile with the box on each axis.
    std::int32_t listStartOverlaps(Cell* store, std::int32_t capacity) const noexcept {
        std::int64_t from[2];
        std::int64_t to[2];
        for (int a = 0; a < 2; ++a) {
            const FastAxis& g = axis_[a];
            const double low = (g.low - g.origin) * g.invTile;
            const double high = (g.high - g.origin) * g.invTile;
            double lowMargin = 0x1p-50 * std::fabs(low);
            double highMargin = 0x1p-50 * std::fabs(high);
            if constexpr (std::is_same<T, double>::value) {
                lowMargin = 0x1p-50 * (std::fabs(g.low) + std::fabs(g.origin)) * g.invTile;
                highMargin = 0x1p-50 * (std::fabs(g.high) + std::fabs(g.origin)) * g.invTile;
            }
            from[a] = std::max<std::int64_t>(g.clampCell(low - lowMargin), 0);
            to[a] = std::min<std::int64_t>(g.clampCell(high + highMargin), g.cells - 1);
        }
        const FastAxis& gx = axis_[0];
        const FastAxis& gy = axis_[1];
        std::int32_t count = 0;
        for (std::int64_t j = from[1]; j <= to[1]; ++j) {
            const std::uint8_t* row = map_.solid + j * map_.columns;
            bool rowChecked = false;
            for (std::int64_t i = from[0]; i <= to[0]; ++i) {
                if (row[i] == 0) continue;  // the byte first
                if (!rowChecked) {
                    if (!gy.overlapsAtStart(gy.edge(j), gy.edge(j + 1))) break;
                    rowChecked = true;
                }
                if (!gx.overlapsAtStart(gx.edge(i), gx.edge(i + 1))) continue;
                if (count < capacity)
                    store[count] = {static_cast<std::int32_t>(i), static_cast<std::int32_t>(j)};
                ++count;
            }
        }
        return count;
    }

    std::int64_t firstCellAhead(int axis) const noexcept {
        const FastAxis& g = axis_[axis];
        if (g.dir > 0) return std::max<std::int64_t>(g.cellOf(g.low), 0);
        std::int64_t k = g.cellOf(g.template farEdge<Coord>());
        if (k >= 0 && k < g.cells && compare(g.template farEdge<Coord>(), g.edge(k)) == 0) --k;
        return std::min<std::int64_t>(k, g.cells - 1);
    }

    /// The tile edge the box touches when it hits cell k on `axis`.
    double touchEdge(int axis, std::int64_t k) const noexcept {
        const FastAxis& g = axis_[axis];
        return g.dir > 0 ? g.edge(k) : g.edge(k + 1);
    }

    void sweepBothAxes(Hits& hits) noexcept {
        // The primary axis: any choice is correct; this one only keeps the walk short (for float
        // frames the products are exact, for double frames nearly so).
        const int p = axis_[0].speed * axis_[1].tile >= axis_[1].speed * axis_[0].tile ? 0 : 1;
        const int s = 1 - p;
        const FastAxis& mp = axis_[p];
        const FastAxis& ms = axis_[s];
        const bool forward = ms.dir > 0;
        // The secondary range's certified error bound, in cells (kSecondaryRangeErrorUlps).
#if defined(TILESWEEP_FAULT_FILTER_BOUND_HALVED)
        const double bound = kSecondaryRangeErrorUlps / 2;  // deliberate fault: the bound halved
#else
        const double bound = kSecondaryRangeErrorUlps;
#endif
        const double margin = bound * 0x1p-53 *
                              (std::fabs(ms.low) + std::fabs(ms.high) + ms.speed + std::fabs(ms.origin)) *
                              ms.invTile;
        const double slope = ms.disp / mp.speed;  // secondary motion per unit of primary distance
        for (std::int64_t k = firstCellAhead(p); k >= 0 && k < mp.cells; k += mp.dir) {
            const double lo = mp.edge(k);
            const double hi = mp.edge(k + 1);
            const Coord entry = mp.entryDistance<Coord>(lo, hi);
            if (compare(entry, mp.speed) >= 0) break;  // entered at t >= 1
            // Entered after the hits found so far, for certain; on a near tie walking on is harmless.
            if (hits.any && certainlyGreater(entry, hits.time.den, hits.time.num, mp.speed)) break;
            const double entryNear = approximate(entry);
            const double exitNear = approximate(mp.exitDistance<Coord>(lo, hi));
            const double t0 = entryNear < 0 ? 0.0 : entryNear;
            const double t1 = exitNear < mp.speed ? exitNear : mp.speed;
            // The secondary span while the box is in this primary cell, estimated, then widened
            // by the bound so that it holds the exact range (extra cells are tested and rejected).
            const double lowAt = (ms.low + slope * (forward ? t0 : t1) - ms.origin) * ms.invTile;
            const double highAt = (ms.high + slope * (forward ? t1 : t0) - ms.origin) * ms.invTile;
            const std::int64_t j0 = std::max<std::int64_t>(ms.clampCell(lowAt - margin), 0);
            std::int64_t j1 = std::min<std::int64_t>(ms.clampCell(highAt + margin), ms.cells - 1);
#if defined(TILESWEEP_FAULT_BROADPHASE_SHORT)
            --j1;  // deliberate fault: the secondary range one cell short
#endif
            for (std::int64_t j = j0; j <= j1; ++j) {
                const std::int64_t ci = p == 0 ? k : j;
                const std::int64_t cj = p == 0 ? j : k;
                if (!map_.isSolid(ci, cj)) continue;
                testAndRecord(ci, cj, hits);
            }
        }
    }

    void testAndRecord(std::int64_t i, std::int64_t j, Hits& hits) noexcept {
        const FastAxis& mx = axis_[0];
        const FastAxis& my = axis_[1];
        const FastTileTest<Coord> test =
            testTileFast<Coord>(mx, my, mx.edge(i), mx.edge(i + 1), my.edge(j), my.edge(j + 1), refined_);
        Axis axis = Axis::Y;
        switch (test.verdict) {
            case TileVerdict::Misses:
            case TileVerdict::StartsOverlapping:
                return;
            case TileVerdict::BlocksOnX:
                axis = Axis::X;
                break;
            case TileVerdict::BlocksOnY:
                axis = Axis::Y;
                break;
            case TileVerdict::Tie: {
                const bool xExposed = !map_.isSolid(i - mx.dir, j);
                const bool yExposed = !map_.isSolid(i, j - my.dir);
                axis = settleTie(xExposed, yExposed);
                break;
            }
        }
        const int a = axis == Axis::X ? 0 : 1;
        add(hits, {static_cast<std::int32_t>(i), static_cast<std::int32_t>(j)}, axis, test.time,
            touchEdge(a, a == 0 ? i : j));
    }

    /// FrameSolver::sweepOneAxis on exact coordinates.
    void sweepOneAxis(int axis, Coord heldLow, Coord heldHigh, const FastTime<Coord>& from,
                      Hits& hits) noexcept {
        const FastAxis& ga = axis_[axis];
        const FastAxis& go = axis_[1 - axis];
        const std::int64_t j0 = std::max<std::int64_t>(go.cellOf(heldLow), 0);
        const std::int64_t j1 = std::min<std::int64_t>(go.cellOf(heldHigh), go.cells - 1);
        if (j0 > j1) return;
        for (std::int64_t k = firstCellAhead(axis); k >= 0 && k < ga.cells; k += ga.dir) {
            const Coord entry = ga.entryDistance<Coord>(ga.edge(k), ga.edge(k + 1));
            if (compare(entry, ga.speed) >= 0) return;  // entered at t >= 1
            const FastTime<Coord> at{entry, ga.speed};
            if (compareTimes(at, from) < 0) continue;  // overlapping already at `from`
            for (std::int64_t j = j0; j <= j1; ++j) {
                const std::int64_t ci = axis == 0 ? k : j;
                const std::int64_t cj = axis == 0 ? j : k;
                if (!map_.isSolid(ci, cj)) continue;
                if (!(compare(heldLow, go.edge(j + 1)) < 0 && compare(heldHigh, go.edge(j)) > 0)) continue;
                add(hits, {static_cast<std::int32_t>(ci), static_cast<std::int32_t>(cj)},
                    axis == 0 ? Axis::X : Axis::Y, at, touchEdge(axis, k));
            }
            if (hits.any) return;
        }
    }

    Normal normalOn(int axis) const noexcept {
        const auto against = static_cast<std::int8_t>(-axis_[axis].dir);
        return axis == 0 ? Normal{against, 0} : Normal{0, against};
    }

    /// The most cells of swept bounds that collectNear scans, and the most solid ones it keeps.
    static constexpr std::int64_t kNearArea = 12;

    /// Lists the solid cells of the frame's swept bounds, row by row, when those bounds hold at
    /// most kNearArea cells and at most `contactCapacity` of them are solid; false otherwise
    /// (the walk then runs). Every tile that can block either step, or that the box overlaps at
    /// the start, lies in them: on each axis the box covers [min(low, low + disp), max(high,
    /// high + disp)] over the frame, and step 2 stays inside that (its held axis is at a touch
    /// position between the start and the end, its free axis on the rest of its own motion). The
    /// cell range is estimated from (v - origin) * invTile with a margin of 8u(|low| + |high| +
    /// |disp| + |origin|) * invTile: the coordinates (low + disp, rounded on double frames, and
    /// high, rounded on double frames) are within 2u of that sum of magnitudes, the difference,
    /// the reciprocal and the product add 3.02u of it, all over tile: 5.03u < 8u(1 - 4u), the
    /// margin with its own roundings, and the rounding of the widened estimate adds u more. So
    /// the range is a superset; extra cells are tested exactly and rejected. With every tile
    /// tested, the earliest hits are the same set as the walk's, and none is cut short
    /// (solid cells <= capacity), so the stored contacts match too.
    bool collectNear(std::int32_t contactCapacity) noexcept {
        std::int64_t from[2];
        std::int64_t to[2];
        for (int a = 0; a < 2; ++a) {
            const FastAxis& g = axis_[a];
            const double lowEnd = std::min(g.low, g.low + g.disp);
            const double highEnd = std::max(g.high, g.high + g.disp);
            const double margin = 0x1p-50 *
                                  (((std::fabs(g.low) + std::fabs(g.high)) + g.speed) + std::fabs(g.origin)) *
                                  g.invTile;
            from[a] = std::max<std::int64_t>(g.clampCell((lowEnd - g.origin) * g.invTile - margin), 0);
            to[a] =
                std::min<std::int64_t>(g.clampCell((highEnd - g.origin) * g.invTile + margin), g.cells - 1);
            if (from[a] > to[a]) {
                nearCount_ = 0;  // the swept bounds miss the map: nothing to find
                return true;
            }
        }
        if ((to[0] - from[0] + 1) * (to[1] - from[1] + 1) > kNearArea) return false;
#if defined(TILESWEEP_FAULT_BROADPHASE_SHORT)
        --to[1];  // deliberate fault: the swept bounds one row short (the walk's twin)
#endif
        std::int32_t count = 0;
        for (std::int64_t j = from[1]; j <= to[1]; ++j) {
            const std::uint8_t* row = map_.solid + j * map_.columns;
            for (std::int64_t i = from[0]; i <= to[0]; ++i) {
                if (row[i] == 0) continue;
                if (count >= contactCapacity) return false;
                near_[count++] = {static_cast<std::int32_t>(i), static_cast<std::int32_t>(j)};
            }
        }
        nearCount_ = count;
        return true;
    }

    /// The start overlaps among the listed cells (collectNear), which hold all of them, in the
    /// same row-then-column order.
    std::int32_t startOverlapsOfNear(Cell* store, std::int32_t capacity) const noexcept {
        std::int32_t count = 0;
        for (std::int32_t n = 0; n < nearCount_; ++n) {
            const Cell c = near_[n];
            if (!axis_[1].overlapsAtStart(axis_[1].edge(c.j), axis_[1].edge(c.j + 1)) ||
                !axis_[0].overlapsAtStart(axis_[0].edge(c.i), axis_[0].edge(c.i + 1)))
                continue;
            if (count < capacity) store[count] = c;
            ++count;
        }
        return count;
    }

    /// sweepOneAxis over the listed cells: the tiles overlapping the held span whose entry time
    /// on `axis` lies in [from, 1), at the earliest such time (the walk's first column that has
    /// any: entry times grow strictly along the motion).
    void sweepOneAxisNear(int axis, Coord heldLow, Coord heldHigh, const FastTime<Coord>& from,
                          Hits& hits) noexcept {
        const FastAxis& ga = axis_[axis];
        const FastAxis& go = axis_[1 - axis];
        for (std::int32_t n = 0; n < nearCount_; ++n) {
            const std::int64_t k = axis == 0 ? near_[n].i : near_[n].j;
            const std::int64_t o = axis == 0 ? near_[n].j : near_[n].i;
            if (!(compare(heldLow, go.edge(o + 1)) < 0 && compare(heldHigh, go.edge(o)) > 0)) continue;
            const Coord entry = ga.entryDistance<Coord>(ga.edge(k), ga.edge(k + 1));
            if (compare(entry, ga.speed) >= 0) continue;  // entered at t >= 1
            const FastTime<Coord> at{entry, ga.speed};
            if (compareTimes(at, from) < 0) continue;  // overlapping already at `from`
            add(hits, near_[n], axis == 0 ? Axis::X : Axis::Y, at, touchEdge(axis, k));
        }
    }

    const TileMapView<T>& map_;
    FastAxis axis_[2];
    T start_[2];
    bool refined_ = false;
    std::int32_t nearCount_ = 0;
    Cell near_[kNearArea];
};

}  // namespace tilesweep::detail

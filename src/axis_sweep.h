// SPDX-License-Identifier: MIT
#pragma once

// The contract's test of one box against one tile, written once for every arithmetic: the
// lattice integers (lattice.h), and the exact doubles or exact pairs of the fast path
// (pair_arithmetic.h). The resolver applies it to every candidate tile (frame_loop.h), and
// sweepBox to its one tile (box_sweep.cpp).
//
// On one axis the box [low, high] moves by disp; a tile spans [lo, hi]. With dir = sign(disp)
// and speed = |disp|, the projections overlap (open) for t in (entry, exit), where
//     entry = entryDistance / speed,  exit = exitDistance / speed,
//     dir > 0: entryDistance = lo - high,  exitDistance = hi - low
//     dir < 0: entryDistance = low - hi,   exitDistance = high - lo.
// A static axis overlaps for all t or for none. With E = max entry and X = min exit over both
// axes, the tile blocks iff 0 <= E < 1 and E < X (0 not in I and I meets (0, 1), docs/contract.md).
// Every comparison of two times n1/s1 and n2/s2 is made as n1*s2 against n2*s1 (s1, s2 > 0),
// exactly (compareProducts: integers on the lattice; monotonic rounding and TwoProduct, or a
// certified filter with an exact refinement, on doubles). That settles corner misses (E >= X,
// including a path exactly through a corner, E == X) and exact ties (equal entries) without any
// tolerance.

#include "fault_injection.h"
#include "pair_arithmetic.h"

#include "tilesweep/math.h"

#include <cmath>
#include <cstdint>
#include <utility>

namespace tilesweep::detail {

/// A time num / den with den > 0, as a fraction of the frame: a coordinate (a distance) over a
/// speed.
template <class Coord, class Speed>
struct TimeRatio {
    Coord num;
    Speed den;
};

/// A time on the lattice: both parts integers.
template <class Num>
using Fraction = TimeRatio<Num, Num>;

// The lattice integers' operations under the names the double arithmetic uses
// (pair_arithmetic.h), so that the test below and the frame loop read the same on both.

/// The sign of an integer.
template <class Num>
[[nodiscard]] inline auto signOf(const Num& v) noexcept -> decltype(v.sign()) {
    return v.sign();
}
/// -1, 0 or 1 as a*s compares with b*t, exactly (integers).
template <class Num>
[[nodiscard]] inline auto compareProducts(const Num& a, const Num& s, const Num& b, const Num& t,
                                          bool&) noexcept -> decltype(compare(a * s, b* t)) {
    return compare(a * s, b * t);
}
/// An integer as a double, for estimates only.
template <class Num>
[[nodiscard]] inline auto approximate(const Num& v) noexcept
    -> decltype(v.approximate(std::declval<int&>())) {
    int e = 0;
    const double m = v.approximate(e);
    return std::ldexp(m, e);
}

/// Whether two closed intervals [low, high] and [lo, hi] overlap, given the signs of low - hi
/// and high - lo as two callables (the second is evaluated only when the first leaves the answer
/// open, which matters for pairs and wide integers): their interiors must meet, so touching is
/// not overlapping (docs/contract.md). The one statement of that rule: the start overlaps, the tile
/// test and the held axis of a one-axis move all ask it.
template <class LowMinusHi, class HighMinusLo>
[[nodiscard, gnu::always_inline]] inline bool overlapsOpen(const LowMinusHi& lowMinusHi,
                                                           const HighMinusLo& highMinusLo) noexcept {
#if defined(TILESWEEP_FAULT_TOUCH_OVERLAPS)
    return lowMinusHi() <= 0 && highMinusLo() >= 0;  // deliberate fault: touching counted as overlap
#else
    return lowMinusHi() < 0 && highMinusLo() > 0;
#endif
}

/// -1, 0 or 1 as a/b compares with c/d (denominators positive).
template <class Num>
[[nodiscard]] inline int compareFractions(const Fraction<Num>& a, const Fraction<Num>& b) noexcept {
    return compare(a.num * b.den, b.num * a.den);
}

/// One axis of a box's motion, in lattice integers.
template <class Num>
struct AxisMotion {
    using Coord = Num;  ///< a coordinate or a distance
    using Speed = Num;  ///< the denominator of a time
    using Edge = Num;   ///< a tile edge

    Num low;    ///< box edge with the smaller coordinate, at t = 0
    Num high;   ///< low + size
    Num disp;   ///< displacement over the frame
    Num speed;  ///< |disp|
    int dir;    ///< sign of disp

    [[nodiscard]] Num entryDistance(const Num& lo, const Num& hi) const noexcept {
        return dir > 0 ? lo - high : low - hi;
    }
    [[nodiscard]] Num exitDistance(const Num& lo, const Num& hi) const noexcept {
        return dir > 0 ? hi - low : high - lo;
    }
    /// The walks' distances (frame_loop.h): here the exact ones.
    [[nodiscard]] Num walkEntry(const Num& lo, const Num& hi) const noexcept { return entryDistance(lo, hi); }
    [[nodiscard]] Num walkExit(const Num& lo, const Num& hi) const noexcept { return exitDistance(lo, hi); }
    /// Whether the cell [lo, hi] is entered at t >= 1, given walkEntry(lo, hi).
    [[nodiscard]] bool enteredByEnd(const Num& entry, const Num&, const Num&) const noexcept {
        return compare(entry, speed) >= 0;
    }
    /// Open overlap of the box's projection at t = 0 with [lo, hi].
    [[nodiscard]] bool overlapsAtStart(const Num& lo, const Num& hi) const noexcept {
        return overlapsOpen([&] { return compare(low, hi); }, [&] { return compare(high, lo); });
    }
};

template <class Num>
[[nodiscard]] inline AxisMotion<Num> makeAxisMotion(const Num& pos, const Num& size,
                                                    const Num& disp) noexcept {
    const int dir = disp.sign();
    return {pos, pos + size, disp, dir < 0 ? -disp : disp, dir};
}

/// What a tile does; `Tie` is a block whose contact axis the exposed-face rule must settle.
enum class TileVerdict : std::uint8_t { Misses, StartsOverlapping, BlocksOnX, BlocksOnY, Tie };

/// The verdict on one tile and, when it blocks, its time of impact.
template <class Coord, class Speed>
struct TileTest {
    TileVerdict verdict;
    TimeRatio<Coord, Speed> time;  ///< set when the tile blocks (or ties)
};

/// The contract's test of one tile [xlo, xhi] x [ylo, yhi] against a box moving on both axes
/// or on one; a box that moves on neither never blocks. `Motion` is an axis of the arithmetic
/// in use (AxisMotion on the lattice, FastAxis on doubles); `refined` is set when a comparison
/// of products needed its exact refinement (frame_stats.h, DecisionPath::Filtered).
/// Always inlined: float frames test every tile with it (fast_frame.h); testTile below is the
/// same test left to the compiler, for the lattice and for double frames' rare fallback.
template <class Motion, class Coord = typename Motion::Coord, class Speed = typename Motion::Speed,
          class Edge = typename Motion::Edge>
[[nodiscard, gnu::always_inline]] inline TileTest<Coord, Speed> testTileInline(
    const Motion& mx, const Motion& my, const Edge& xlo, const Edge& xhi, const Edge& ylo, const Edge& yhi,
    bool& refined) noexcept {
    TileTest<Coord, Speed> miss{TileVerdict::Misses, {}};
    if (mx.dir == 0 || my.dir == 0) {
        if (mx.dir == 0 && my.dir == 0) {
            if (mx.overlapsAtStart(xlo, xhi) && my.overlapsAtStart(ylo, yhi))
                miss.verdict = TileVerdict::StartsOverlapping;
            return miss;
        }
        // One static axis: it overlaps at all times or never; the moving axis alone decides.
        const bool xMoves = mx.dir != 0;
        const Motion& moving = xMoves ? mx : my;
        const Motion& still = xMoves ? my : mx;
        const Edge& lo = xMoves ? xlo : ylo;
        const Edge& hi = xMoves ? xhi : yhi;
        if (!(xMoves ? still.overlapsAtStart(ylo, yhi) : still.overlapsAtStart(xlo, xhi))) return miss;
        const Coord entry = moving.entryDistance(lo, hi);
        if (signOf(entry) < 0) {
            if (signOf(moving.exitDistance(lo, hi)) > 0) miss.verdict = TileVerdict::StartsOverlapping;
            return miss;
        }
        if (compare(entry, moving.speed) >= 0) return miss;  // entry >= 1
        return {xMoves ? TileVerdict::BlocksOnX : TileVerdict::BlocksOnY, {entry, moving.speed}};
    }
    const Coord ex = mx.entryDistance(xlo, xhi);
    const Coord ey = my.entryDistance(ylo, yhi);
    const Coord xx = mx.exitDistance(xlo, xhi);
    const Coord xy = my.exitDistance(ylo, yhi);
    if (signOf(ex) < 0 && signOf(ey) < 0) {
        // E < 0: either the box overlaps the tile now (0 in I), or I lies before t = 0.
        if (signOf(xx) > 0 && signOf(xy) > 0) miss.verdict = TileVerdict::StartsOverlapping;
        return miss;
    }
#if defined(TILESWEEP_FAULT_END_INCLUSIVE)
    if (compare(ex, mx.speed) > 0 || compare(ey, my.speed) > 0)
        return miss;  // deliberate fault: a tile reached at t = 1 blocks
#else
    if (compare(ex, mx.speed) >= 0 || compare(ey, my.speed) >= 0) return miss;  // E >= 1
#endif
#if !defined(TILESWEEP_FAULT_NO_CORNER_MISS)
    // E < X: each axis enters before the other exits (an axis's own entry precedes its exit).
    if (compareProducts(ex, my.speed, xy, mx.speed, refined) >= 0) return miss;
    if (compareProducts(ey, mx.speed, xx, my.speed, refined) >= 0) return miss;
#endif
#if defined(TILESWEEP_FAULT_DOUBLE_PREDICATE)
    // Deliberate fault: the entry comparison in plain double arithmetic.
    const double pa = approximate(ex) * approximate(my.speed);
    const double pb = approximate(ey) * approximate(mx.speed);
    const int order = pa > pb ? 1 : (pa < pb ? -1 : 0);
#else
    const int order = compareProducts(ex, my.speed, ey, mx.speed, refined);
#endif
    if (order > 0) return {TileVerdict::BlocksOnX, {ex, mx.speed}};
    if (order < 0) return {TileVerdict::BlocksOnY, {ey, my.speed}};
    return {TileVerdict::Tie, {ey, my.speed}};
}

/// testTileInline, inlined or not as the compiler decides.
template <class Motion, class Coord = typename Motion::Coord, class Speed = typename Motion::Speed,
          class Edge = typename Motion::Edge>
[[nodiscard]] TileTest<Coord, Speed> testTile(const Motion& mx, const Motion& my, const Edge& xlo,
                                              const Edge& xhi, const Edge& ylo, const Edge& yhi,
                                              bool& refined) noexcept {
    return testTileInline(mx, my, xlo, xhi, ylo, yhi, refined);
}

/// The contact axis of an exact corner tie: the face that is exposed when exactly one is,
/// otherwise y (docs/contract.md; it decides whether a character snags on a corner).
[[nodiscard]] inline Axis settleTie(bool xFaceExposed, bool yFaceExposed) noexcept {
#if defined(TILESWEEP_FAULT_TIE_REVERSED)
    return (yFaceExposed && !xFaceExposed) ? Axis::Y : Axis::X;  // deliberate fault
#else
    return (xFaceExposed && !yFaceExposed) ? Axis::X : Axis::Y;
#endif
}

}  // namespace tilesweep::detail

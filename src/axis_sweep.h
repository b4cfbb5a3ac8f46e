// SPDX-License-Identifier: MIT
#pragma once

// The exact single-tile test of the contract, on lattice integers (lattice.h).
//
// On one axis the box [low, high] moves by disp; a tile spans [lo, hi]. With dir = sign(disp)
// and speed = |disp|, the projections overlap (open) for t in (entry, exit), where
//     entry = entryDistance / speed,  exit = exitDistance / speed,
//     dir > 0: entryDistance = lo - high,  exitDistance = hi - low
//     dir < 0: entryDistance = low - hi,   exitDistance = high - lo.
// A static axis overlaps for all t or for none. With E = max entry and X = min exit over both
// axes, the tile blocks iff 0 <= E < 1 and E < X (0 not in I and I meets (0, 1), CONTRACT.md).
// Every comparison of two times n1/s1 and n2/s2 is made as n1*s2 against n2*s1 (s1, s2 > 0):
// integers, so exact. That settles corner misses (E >= X, including a path exactly through a
// corner, E == X) and exact ties (equal entries) without any tolerance.

#include "fault_injection.h"

#include "tilesweep/math.h"

#include <cmath>
#include <cstdint>

namespace tilesweep::detail {

/// A time n / d with d > 0, as a fraction of the frame.
template <class Num>
struct Fraction {
    Num num;
    Num den;
};

/// -1, 0 or 1 as a/b compares with c/d (denominators positive).
template <class Num>
[[nodiscard]] inline int compareFractions(const Fraction<Num>& a, const Fraction<Num>& b) noexcept {
    return compare(a.num * b.den, b.num * a.den);
}

/// One axis of a box's motion, in lattice integers.
template <class Num>
struct AxisMotion {
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
    /// Open overlap of the box's projection at t = 0 with [lo, hi].
    [[nodiscard]] bool overlapsAtStart(const Num& lo, const Num& hi) const noexcept {
#if defined(TILESWEEP_FAULT_TOUCH_OVERLAPS)
        return low <= hi && high >= lo;  // deliberate fault: touching counted as overlap
#else
        return low < hi && high > lo;
#endif
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
template <class Num>
struct TileTest {
    TileVerdict verdict;
    Fraction<Num> time;  ///< set when the tile blocks (or ties)
};

/// The contract's test of one tile [xlo, xhi] x [ylo, yhi] against a box moving on both axes
/// or on one; a box that moves on neither never blocks.
template <class Num>
[[nodiscard]] TileTest<Num> testTile(const AxisMotion<Num>& mx, const AxisMotion<Num>& my, const Num& xlo,
                                     const Num& xhi, const Num& ylo, const Num& yhi) noexcept {
    const Num zero = Num::fromInt(0);
    TileTest<Num> miss{TileVerdict::Misses, {zero, Num::fromInt(1)}};
    if (mx.dir == 0 || my.dir == 0) {
        if (mx.dir == 0 && my.dir == 0) {
            if (mx.overlapsAtStart(xlo, xhi) && my.overlapsAtStart(ylo, yhi))
                miss.verdict = TileVerdict::StartsOverlapping;
            return miss;
        }
        // One static axis: it overlaps at all times or never; the moving axis alone decides.
        const bool xMoves = mx.dir != 0;
        const AxisMotion<Num>& moving = xMoves ? mx : my;
        const AxisMotion<Num>& still = xMoves ? my : mx;
        const Num& lo = xMoves ? xlo : ylo;
        const Num& hi = xMoves ? xhi : yhi;
        if (!(xMoves ? still.overlapsAtStart(ylo, yhi) : still.overlapsAtStart(xlo, xhi))) return miss;
        const Num entry = moving.entryDistance(lo, hi);
        if (entry.isNegative()) {
            if (moving.exitDistance(lo, hi).sign() > 0) miss.verdict = TileVerdict::StartsOverlapping;
            return miss;
        }
        if (entry >= moving.speed) return miss;  // entry >= 1
        return {xMoves ? TileVerdict::BlocksOnX : TileVerdict::BlocksOnY, {entry, moving.speed}};
    }
    const Num ex = mx.entryDistance(xlo, xhi);
    const Num ey = my.entryDistance(ylo, yhi);
    const Num xx = mx.exitDistance(xlo, xhi);
    const Num xy = my.exitDistance(ylo, yhi);
    if (ex.isNegative() && ey.isNegative()) {
        // E < 0: either the box overlaps the tile now (0 in I), or I lies before t = 0.
        if (xx.sign() > 0 && xy.sign() > 0) miss.verdict = TileVerdict::StartsOverlapping;
        return miss;
    }
#if defined(TILESWEEP_FAULT_END_INCLUSIVE)
    if (ex > mx.speed || ey > my.speed) return miss;  // deliberate fault: a tile reached at t = 1 blocks
#else
    if (ex >= mx.speed || ey >= my.speed) return miss;  // E >= 1
#endif
#if !defined(TILESWEEP_FAULT_NO_CORNER_MISS)
    // E < X: each axis enters before the other exits (an axis's own entry precedes its exit).
    if (!(ex * my.speed < xy * mx.speed)) return miss;
    if (!(ey * mx.speed < xx * my.speed)) return miss;
#endif
#if defined(TILESWEEP_FAULT_DOUBLE_PREDICATE)
    // Deliberate fault: the entry comparison in plain double arithmetic.
    int ea = 0, eb = 0, ec = 0, ed = 0;
    const double pa = std::ldexp(ex.approximate(ea), ea) * std::ldexp(my.speed.approximate(eb), eb);
    const double pb = std::ldexp(ey.approximate(ec), ec) * std::ldexp(mx.speed.approximate(ed), ed);
    const int order = pa > pb ? 1 : (pa < pb ? -1 : 0);
#else
    const int order = compare(ex * my.speed, ey * mx.speed);
#endif
    if (order > 0) return {TileVerdict::BlocksOnX, {ex, mx.speed}};
    if (order < 0) return {TileVerdict::BlocksOnY, {ey, my.speed}};
    return {TileVerdict::Tie, {ey, my.speed}};
}

/// The contact axis of an exact corner tie: the face that is exposed when exactly one is,
/// otherwise y (CONTRACT.md; it decides whether a character snags on a corner).
[[nodiscard]] inline Axis settleTie(bool xFaceExposed, bool yFaceExposed) noexcept {
#if defined(TILESWEEP_FAULT_TIE_REVERSED)
    return (yFaceExposed && !xFaceExposed) ? Axis::Y : Axis::X;  // deliberate fault
#else
    return (xFaceExposed && !yFaceExposed) ? Axis::X : Axis::Y;
#endif
}

}  // namespace tilesweep::detail

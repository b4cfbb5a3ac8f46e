// SPDX-License-Identifier: MIT
#pragma once

// The axis test of the fast path: one axis of a frame (the box's motion and the grid) as exact
// doubles, with the distances the tile test (axis_sweep.h) and the frame loop (frame_loop.h)
// take, as exact doubles (float frames) or exact pairs (double frames).

#include "axis_sweep.h"
#include "cell_range.h"
#include "exact_double.h"
#include "fault_injection.h"
#include "pair_arithmetic.h"

#include <cstdint>
#include <type_traits>

namespace tilesweep::detail {

// The members below run in the solver's innermost loops, from many call sites: always inlined
// (gnu::always_inline; other compilers ignore it), so that a call costs nothing there.

/// One axis of a fast frame: the box's motion and the grid, as exact doubles. The far box edge
/// low + size is held as high + highLow: on float frames it is a double (highLow = 0); on double
/// frames it is the TwoSum pair of low and size, and the distances from it to a tile edge are
/// three-term sums (farEdgeMinus), made exact pairs again by one more TwoSum.
template <class C>
struct FastAxis {
    using Coord = C;       ///< a coordinate or a distance: double (float frames) or ExactPair
    using Speed = double;  ///< the denominator of a time
    using Edge = double;   ///< a tile edge

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

    [[nodiscard, gnu::always_inline]] double edge(std::int64_t k) const noexcept {
        return origin + static_cast<double>(k) * tile;
    }

    /// The far edge minus the tile edge e, exactly: (high - e) + highLow. For double frames,
    /// TwoSum gives high - e = a + b exactly, and then b + highLow is exact too: both are
    /// multiples of 2^L (L the lowest set bit among the box, origin and tile inputs of this axis)
    /// below 2^(L+53) in magnitude, which admitDoubleFrame checks (|b| <= u|a|, |highLow| <=
    /// u|high|, and |a|, |high| < 2^(L+105)). A last TwoSum of a and b + highLow returns a
    /// normalized pair (hi = fl(value)), exact for any doubles: the form compare,
    /// compareProducts and roundTimeToDouble ask for.
    [[nodiscard, gnu::always_inline]] Coord farEdgeMinus(double e) const noexcept {
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
    [[nodiscard, gnu::always_inline]] Coord minusFarEdge(double e) const noexcept {
        if constexpr (std::is_same<Coord, ExactPair>::value) {
            const ExactPair s = farEdgeMinus(e);
            return {-s.hi, -s.lo};
        } else {
            return e - high;
        }
    }
    /// The far edge at t = 0 as a coordinate (exact).
    [[nodiscard, gnu::always_inline]] Coord farEdge() const noexcept {
        if constexpr (std::is_same<Coord, ExactPair>::value) {
            return {high, highLow};
        } else {
            return high;
        }
    }
    [[nodiscard, gnu::always_inline]] Coord entryDistance(double lo, double hi) const noexcept {
        return dir > 0 ? minusFarEdge(lo) : differenceOf<Coord>(low, hi);
    }
    [[nodiscard, gnu::always_inline]] Coord exitDistance(double lo, double hi) const noexcept {
        return dir > 0 ? differenceOf<Coord>(hi, low) : farEdgeMinus(lo);
    }
    /// The high parts of the pairs entryDistance and exitDistance return, bit for bit, without
    /// their low parts (double frames; the tile screen of fast_frame.h). A pair's high part is
    /// the last TwoSum's sum: fl(a - b) for a difference of doubles, and for the far edge
    /// fl(high - e) when highLow == 0, otherwise fl(s.hi + (s.lo + highLow)) with s the TwoSum of
    /// high and -e: the same operations on the same operands as farEdgeMinus, minus the error
    /// terms. Negation is exact, so the sign flip of minusFarEdge commutes with it.
    /// kFarEdgeDouble: the caller knows highLow == 0 (FastFrame::distancesExact).
    template <bool kFarEdgeDouble = false>
    [[nodiscard, gnu::always_inline]] double farEdgeMinusHigh(double e) const noexcept {
        if (kFarEdgeDouble || highLow == 0) return high - e;
        const ExactPair s = twoSum(high, -e);
        return s.hi + (s.lo + highLow);
    }
    template <bool kFarEdgeDouble = false>
    [[nodiscard, gnu::always_inline]] double entryDistanceHigh(double lo, double hi) const noexcept {
        return dir > 0 ? -farEdgeMinusHigh<kFarEdgeDouble>(lo) : low - hi;
    }
    template <bool kFarEdgeDouble = false>
    [[nodiscard, gnu::always_inline]] double exitDistanceHigh(double lo, double hi) const noexcept {
        return dir > 0 ? hi - low : farEdgeMinusHigh<kFarEdgeDouble>(lo);
    }
    /// The walks' distances (frame_loop.h): what a walk reads of a cell's entry and exit
    /// distances before it tests the cell's tiles, which is their estimate for the secondary
    /// range and the entry's order against the speed. Float frames take the exact doubles;
    /// double frames the pairs' high parts alone (entryDistanceHigh, exitDistanceHigh: bit for
    /// bit the high parts the pairs would have, so the same estimates as from the pairs), and
    /// the order against the speed from the high part, exactly, unless it equals the speed.
    [[nodiscard, gnu::always_inline]] double walkEntry(double lo, double hi) const noexcept {
        if constexpr (std::is_same<Coord, ExactPair>::value) {
            return entryDistanceHigh(lo, hi);
        } else {
            return entryDistance(lo, hi);
        }
    }
    [[nodiscard, gnu::always_inline]] double walkExit(double lo, double hi) const noexcept {
        if constexpr (std::is_same<Coord, ExactPair>::value) {
            return exitDistanceHigh(lo, hi);
        } else {
            return exitDistance(lo, hi);
        }
    }
    /// Whether the cell [lo, hi] is entered at t >= 1 (its entry distance at least the speed),
    /// given walkEntry(lo, hi). For a pair, hi = fl(value) is on the value's side of the speed (a
    /// double) when it differs from it (monotonic rounding); on equality the low part decides.
    [[nodiscard, gnu::always_inline]] bool enteredByEnd(double entry, double lo, double hi) const noexcept {
        if constexpr (std::is_same<Coord, ExactPair>::value) {
#if defined(TILESWEEP_FAULT_WALK_ENTRY_TIE_BY_HIGH_PART)
            static_cast<void>(lo);
            static_cast<void>(hi);
            return entry >= speed;  // deliberate fault: a tie with the speed read from the high part
#else
            if (entry < speed) return false;  // the common answer, from one comparison
            return entry > speed ||
                   compare(entryDistance(lo, hi), speed) >= 0;  // on a tie the low part decides
#endif
        } else {
            static_cast<void>(lo);
            static_cast<void>(hi);
            return entry >= speed;
        }
    }
    /// Open overlap of the box's projection at t = 0 with [lo, hi] (overlapsOpen, axis_sweep.h).
    [[nodiscard, gnu::always_inline]] bool overlapsAtStart(double lo, double hi) const noexcept {
        return overlapsOpen([&] { return compare(low, hi); }, [&] { return compare(farEdge(), lo); });
    }

    /// clamp(floor((c - origin) / tile), -1, cells), exactly, for an exact double or a Coord. The estimate is
    /// off by less than one cell where the clamp does not decide: for an exact double c, (c - origin) *
    /// invTile is within 2.01u of the quotient, relatively (float frames: the difference is exact); for a
    /// pair, the difference of its high part and the origin adds u(|c| + |origin|) / tile, under 0.2 cells
    /// where |quotient| < 2^32 since |origin| < 2^47 tile (admitDoubleFrame). One exact comparison with a
    /// tile edge, either way, settles it.
    template <class Value>
    [[nodiscard, gnu::always_inline]] std::int64_t cellOf(const Value& c) const noexcept {
        std::int64_t k = clampCell((approximate(c) - origin) * invTile, cells);
        if (k > -1 && compare(c, edge(k)) < 0) {
            --k;
        } else if (k < cells && compare(c, edge(k + 1)) >= 0) {
            ++k;
        }
        return k;
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

}  // namespace tilesweep::detail

// SPDX-License-Identifier: MIT
#pragma once

// The fast path's arithmetic for the frame loop (frame_loop.h): float frames on doubles that
// hold every coordinate exactly, double frames on exact pairs under a certified filter. The
// loop, the tile test and the rounding rule are the lattice's (frame_loop.h, axis_sweep.h,
// final_rounding.h); what this file adds is how each is computed here, and where it may answer
// "undecided", so that the frame goes to the lattice.
//
// Float frames (admitFloatFrame, range_admission.h): every coordinate, and every difference of
// two, is an exact double, and so is every sum and difference the solver takes. What is left:
//   - times are ratios of exact doubles and are compared as cross products, exactly, by
//     compareProducts (exact_double.h: monotonic rounding, then TwoProduct on a tie);
//   - cell indices are estimated by a rounded quotient and settled by one exact comparison with
//     a tile edge (FastAxis::cellOf); cell ranges (start overlaps, swept bounds, the walk's
//     secondary range) are estimated and widened by a certified bound (proof_constants.h),
//     which can only add cells for the exact tile test to reject (cell_range.h);
//   - a contact time is rounded by roundTimeToFloat (time_rounding.h), and a contact's
//     coordinate on the axis it slides on by roundPositionAtTime (contact_position.h);
//   - final positions are exact doubles, rounded to float with the direction the contract asks.
//
// Double frames (admitDoubleFrame): every coordinate the solver forms is a double or an exact
// pair (ExactPair, exact_double.h): a difference of two doubles by TwoSum, or a distance between
// the far box edge x + w and a tile edge (FastAxis::farEdgeMinus). So:
//   - a pair against a double compares exactly by monotonic rounding of its high part;
//   - a time against a time is decided by a semi-static filter with a certified bound
//     (compareProducts on pairs), refined exactly by expansion arithmetic inside it (Filtered);
//   - a contact time is rounded by roundTimeToDouble (time_rounding.h), a contact's coordinate
//     on the axis it slides on by roundPositionAtTime (contact_position.h);
//   - a final position pair is rounded by the direction of its low part, and the amended rule's
//     grid-line test is filtered; when the filter cannot decide, the frame goes to the lattice.

#include "axis_sweep.h"
#include "cell_range.h"
#include "contact_position.h"
#include "exact_double.h"
#include "fast_axis.h"
#include "fault_injection.h"
#include "final_rounding.h"
#include "frame_input.h"
#include "pair_arithmetic.h"
#include "proof_constants.h"
#include "range_admission.h"
#include "time_rounding.h"

#include "tilesweep/resolve.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>

namespace tilesweep::detail {

/// A frame admitted to the fast path: the arithmetic the frame loop asks for, on exact doubles
/// (T = float) or exact pairs under a filter (T = double).
template <class T>
class FastFrame {
public:
    using Scalar = T;
    /// A coordinate the solver forms from two values: exact in double for float frames, an
    /// exact pair for double frames.
    using Coord = std::conditional_t<std::is_same<T, float>::value, double, ExactPair>;
    using Edge = double;
    using Time = TimeRatio<Coord, double>;
    using Motion = FastAxis<Coord>;
    /// What the walk's secondary range needs, computed once a frame.
    struct Walk {
        int primary;
        double margin;  ///< the certified error bound of the range, in cells
        double slope;   ///< secondary motion per unit of primary distance
    };

    /// The frame `in`, with its map's range (range_admission.h: the reciprocals of the tile size
    /// and the grid lines' lowest bit, computed once per map when it was prepared). `inWindow`:
    /// the range test's short form admitted the frame, so the map's windowMagnitude bounds its
    /// cell estimates' magnitudes (magnitude()).
    FastFrame(FrameInput<T> in, const MapRange& range, bool inWindow = false) noexcept
        : map_(in.map), range_(range), inWindow_(inWindow) {
#if defined(TILESWEEP_CELL_RANGE_SSE2)
        setUpOnLanes(in);
#else
        axis_[0] = makeAxis(in.box.pos.x, in.box.size.x, in.displacement.x, in.map.origin.x,
                            in.map.tileSize.x, in.map.columns, range.inverseTile[0]);
        axis_[1] = makeAxis(in.box.pos.y, in.box.size.y, in.displacement.y, in.map.origin.y,
                            in.map.tileSize.y, in.map.rows, range.inverseTile[1]);
        for (int a = 0; a < 2; ++a) {
            end_[a] = sumOf<Coord>(axis_[a].low, axis_[a].disp);
            swept_[a] = sweptCells(a);
        }
        if (inWindow_)
            windowLinesClearBits_ = static_cast<int>(linesClear(0)) | (static_cast<int>(linesClear(1)) << 1);
        if constexpr (std::is_same<Coord, ExactPair>::value)
            distancesExact_ = distancesExactOn(0) && distancesExactOn(1);
#endif
        start_[0] = in.box.pos.x;
        start_[1] = in.box.pos.y;
    }

    /// Whether no grid line can fall between an end on axis `a` and the value above it
    /// (linesClearOf): the amended rule's test is then skipped. A frame in the map's window takes
    /// the window's bound on its ends (setWindowLinesClear, range_admission.h): the grid's half
    /// read from the map, the size's by one addition and one subtraction.
    bool linesClear(int a) const noexcept {
        const Motion& m = axis_[a];
        if (inWindow_) {
            const double shift = range_.sizeGrainShift;
            return ((range_.windowLinesClearBits >> a) & 1) != 0 && (m.size + shift) - shift == m.size;
        }
        return linesClearOf(m.low, m.disp, m.size, range_.lineBit[a]);
    }
    /// linesClear of both axes, as bits 0 (x) and 1 (y). A frame in the window has them from its
    /// set-up (windowLinesClearBits_: on two lanes where SSE2 is at hand); the final rounding asks
    /// for them on most frames that are not free (an end with a nonzero low part).
    [[gnu::always_inline]] int linesClearBits() const noexcept {
        if (inWindow_) return windowLinesClearBits_;
        return static_cast<int>(linesClear(0)) | (static_cast<int>(linesClear(1)) << 1);
    }
    /// Whether some predicate needed its exact refinement (DecisionPath::Filtered).
    [[nodiscard]] bool refined() const noexcept { return refined_; }
    /// Double frames: whether every distance between the box at t = 0 and a tile the frame tests
    /// (testTile, called by the frame loop's listing and walks) is an exact double, so that the
    /// tile screen needs no filter (screenTile). Computed with the frame (distancesExactOn).
    [[nodiscard]] bool distancesExact() const noexcept { return distancesExact_; }
    /// distancesExact's test on axis `a`: the far edge a double, 2 L - H at least
    /// kExactDistanceSpanTiles tiles, L and H the swept bounds' ends as sweptCells forms them,
    /// and the swept cells' margin at most kExactDistanceMarginLimit; proof_constants.h says
    /// why every tile the frame tests then lies where Sterbenz's lemma makes its distances exact.
    [[nodiscard]] bool distancesExactOn(int a) const noexcept {
        const Motion& g = axis_[a];
        const double lowEnd = std::min(g.low, g.low + g.disp);
        const double highEnd = std::max(g.high, g.high + g.disp);
        const double margin = cellMargin(kCellEstimateErrorUlps, magnitude(a), g.invTile);
#if defined(TILESWEEP_FAULT_EXACT_DISTANCES_FAR_PAIR)
        const bool farDouble = true;  // deliberate fault: a far edge that is a pair taken as a double
#else
        const bool farDouble = g.highLow == 0;
#endif
        return farDouble && (lowEnd + lowEnd) - highEnd >= kExactDistanceSpanTiles * g.tile &&
               margin <= kExactDistanceMarginLimit;
    }

    const TileMapView<T>& map() const noexcept { return map_; }
    const Motion& axis(int a) const noexcept { return axis_[a]; }
    T start(int a) const noexcept { return start_[a]; }
    double edge(int a, std::int64_t k) const noexcept { return axis_[a].edge(k); }
    /// e + tile or e - tile as the motion on `a` goes, for a tile edge e: exact, since both edges
    /// are exact doubles (the range test). (Both are representable in T as well, which a valid map
    /// guarantees, docs/contract.md: a step rounded to T would change nothing.)
    [[gnu::always_inline]] double nextEdge(int a, double e) const noexcept {
        return axis_[a].dir > 0 ? e + axis_[a].tile : e - axis_[a].tile;
    }
    std::int64_t cells(int a) const noexcept { return axis_[a].cells; }
    [[gnu::always_inline]] std::int64_t cellOf(int a, const Coord& c) const noexcept {
        return axis_[a].cellOf(c);
    }
    /// The low edge is an exact double on either kind of frame: its cell without a pair.
    [[gnu::always_inline]] std::int64_t nearEdgeCell(int a) const noexcept {
        return axis_[a].cellOf(axis_[a].low);
    }

    /// The magnitude the cell estimates' margins take on axis `a` (proof_constants.h): |low| +
    /// |high| + |disp| + |origin|, formed in that order, or for a frame in the map's window the
    /// map's bound on it (MapRange::windowMagnitude, windowMagnitudeOf), at least as large. A
    /// larger margin only adds cells for the exact tile test to reject.
    [[gnu::always_inline]] double magnitude(int a) const noexcept {
        if (inWindow_) return range_.windowMagnitude[a];  // one branch, which a game predicts
        const Motion& g = axis_[a];
        return ((std::fabs(g.low) + std::fabs(g.high)) + g.speed) + std::fabs(g.origin);
    }

    /// The cells the box's span covers at the start, estimated (kCellEstimateErrorUlps).
    CellRange startCells(int a) const noexcept {
        const Motion& g = axis_[a];
        return estimateCells((g.low - g.origin) * g.invTile, (g.high - g.origin) * g.invTile,
                             cellMargin(kCellEstimateErrorUlps, magnitude(a), g.invTile), g.cells);
    }
    /// The cells the box's span covers over the frame, [min(low, low + disp), max(high, high +
    /// disp)], estimated (kCellEstimateErrorUlps).
    CellRange sweptCells(int a) const noexcept {
        const Motion& g = axis_[a];
        const double lowEnd = std::min(g.low, g.low + g.disp);
        const double highEnd = std::max(g.high, g.high + g.disp);
        return estimateCells((lowEnd - g.origin) * g.invTile, (highEnd - g.origin) * g.invTile,
                             cellMargin(kCellEstimateErrorUlps, magnitude(a), g.invTile), g.cells);
    }

    /// sweptCells of both axes, computed with the frame (setUpOnLanes: on two lanes).
    [[gnu::always_inline]] void sweptCellsOfBoth(CellRange (&out)[2]) const noexcept {
        out[0] = swept_[0];
        out[1] = swept_[1];
    }

    Coord nearEdge(int a) const noexcept { return coordOf<Coord>(axis_[a].low); }
    Coord farEdge(int a) const noexcept { return axis_[a].farEdge(); }
    /// low + disp, exactly: computed with the frame.
    Coord endOf(int a) const noexcept { return end_[a]; }
    /// The box's low edge when it touches the tile edge `e` on `a`.
    Coord touchLow(int a, double e) const noexcept {
        const Motion& g = axis_[a];
        return g.dir > 0 ? differenceOf<Coord>(e, g.size) : coordOf<Coord>(e);
    }
    /// The box's high edge when it touches the tile edge `e` on `a`.
    Coord touchHigh(int a, double e) const noexcept {
        const Motion& g = axis_[a];
        return g.dir > 0 ? coordOf<Coord>(e) : sumOf<Coord>(e, g.size);
    }

    /// An estimate of the first cell along `a` that the box enters at or after time t (the cell
    /// its leading edge is in at t), for walkOneAxis to start from (skipCellsEnteredBefore, which
    /// checks it exactly). At t = 0 there is nothing to skip: a cell before every walk's start.
    std::int64_t firstCellNotBefore(int a, const Time& t) const noexcept {
        const Motion& g = axis_[a];
        const double s = approximate(t.num) / t.den;
        if (!(s > 0)) return g.dir > 0 ? -2 : g.cells + 2;
        const double lead = (g.dir > 0 ? g.high : g.low) + s * g.disp;
        return clampCell((lead - g.origin) * g.invTile, g.cells);
    }

    static Time zeroTime() noexcept { return {coordOf<Coord>(0), 1}; }
    [[gnu::always_inline]] int compareTimes(const Time& a, const Time& b) noexcept {
        // The same fraction (tiles entered across one face line), or two zero times (a box
        // touching a tile at the start, against the zero time: the denominators are positive, and a
        // pair's high part is zero only when the pair is): equal without arithmetic.
        if (identical(a.num, b.num) && (a.den == b.den || approximate(a.num) == 0)) return 0;
        return compareProducts(a.num, b.den, b.num, a.den, refined_);
    }
    bool certainlyLater(const Time& a, const Time& b) const noexcept {
        return certainlyGreater(a.num, b.den, b.num, a.den);
    }

    /// The primary axis: any choice is correct; this one only keeps the walk short (for float
    /// frames the products are exact, for double frames nearly so).
    int primaryAxis() const noexcept {
        return axis_[0].speed * axis_[1].tile >= axis_[1].speed * axis_[0].tile ? 0 : 1;
    }
    Walk prepareWalk(int p) const noexcept {
        const Motion& mp = axis_[p];
        const Motion& ms = axis_[1 - p];
#if defined(TILESWEEP_FAULT_FILTER_BOUND_HALVED)
        const double bound = kSecondaryRangeErrorUlps / 2;  // deliberate fault: the bound halved
#else
        const double bound = kSecondaryRangeErrorUlps;
#endif
        return {p, cellMargin(bound, magnitude(1 - p), ms.invTile), ms.disp / mp.speed};
    }
    /// The secondary span while the box is in the primary cell entered at entry / speed and
    /// left at exit / speed, estimated, then widened by the walk's bound so that it holds the
    /// exact range (extra cells are tested and rejected). The distances come as the walk reads
    /// them (FastAxis::walkEntry, walkExit): exact doubles, or the pairs' high parts, which is
    /// all the estimate ever read of them.
    CellRange secondaryCells(const Walk& w, double entryNear, double exitNear) const noexcept {
        const Motion& mp = axis_[w.primary];
        const Motion& ms = axis_[1 - w.primary];
        const double t0 = entryNear < 0 ? 0.0 : entryNear;
        const double t1 = exitNear < mp.speed ? exitNear : mp.speed;
        const bool forward = ms.dir > 0;
        const double lowAt = (ms.low + w.slope * (forward ? t0 : t1) - ms.origin) * ms.invTile;
        const double highAt = (ms.high + w.slope * (forward ? t1 : t0) - ms.origin) * ms.invTile;
        return estimateCells(lowAt, highAt, w.margin, ms.cells);
    }

    /// axis_sweep.h's test of tile (i, j). On double frames whose box moves on both axes the
    /// screen below answers first, from the distances' high parts alone; it builds an exact
    /// pair only for the entry of a tile that blocks (its time is compared with other hits).
    TileTest<Coord, double> testTile(std::int64_t i, std::int64_t j) noexcept {
        const Motion& mx = axis_[0];
        const Motion& my = axis_[1];
        const double xlo = mx.edge(i);
        const double xhi = mx.edge(i + 1);
        const double ylo = my.edge(j);
        const double yhi = my.edge(j + 1);
        if constexpr (std::is_same<Coord, ExactPair>::value) {
            TileVerdict verdict = TileVerdict::Misses;
            ExactPair entry{};
            if (mx.dir != 0 && my.dir != 0 &&
                (distancesExact_ ? screenTile<true>(mx, my, xlo, xhi, ylo, yhi, verdict, entry)
                                 : screenTile<false>(mx, my, xlo, xhi, ylo, yhi, verdict, entry))) {
                if (verdict == TileVerdict::BlocksOnX) return {verdict, {entry, mx.speed}};
                if (verdict == TileVerdict::BlocksOnY) return {verdict, {entry, my.speed}};
                return {verdict, {}};
            }
            return detail::testTile(mx, my, xlo, xhi, ylo, yhi, refined_);  // the screen's rare fallback
        } else {
            // Float frames: every tile test, inlined (a call costs a frame that tests many tiles
            // more instructions than the inlined code: scripts/instructions.sh, FloorAndWalls).
            return detail::testTileInline(mx, my, xlo, xhi, ylo, yhi, refined_);
        }
    }

    bool roundTime(const Time& t, T& out) noexcept {
        if constexpr (std::is_same<T, float>::value) {
            return roundTimeToFloat(t, refined_, out);
        } else {
            return roundTimeToDouble(t, refined_, out);
        }
    }

    /// The box's coordinate on `a` at time t, start + t * displacement, rounded to nearest
    /// (contact_position.h); the start itself at t = 0. `frameTime` is t rounded to T (roundTime's,
    /// as the contacts carry it): on a double frame that is t rounded to the nearest double, the
    /// estimate's quotient, so the position costs no division of its own; a float frame divides.
    /// False when the lattice must settle it.
    bool positionAt(int a, const Time& t, T frameTime, T& out) noexcept {
        if (highPartOf(t.num) == 0) {
            out = start_[a];
            return true;
        }
        auto q = static_cast<double>(frameTime);
#if !defined(TILESWEEP_FAULT_POSITION_FROM_FLOAT_TIME)  // the fault: a float frame's float time taken
        if constexpr (std::is_same<T, float>::value) q = t.num / t.den;  // num a double: one rounding
#endif
        return roundPositionAtTime<T>(axis_[a].low, axis_[a].disp, t.num, t.den, q, refined_, out);
    }

    // The final rounding (final_rounding.h), without a branch on the data in its common case. A
    // zero reads +0 (exact + 0.0), as the lattice's zero does.
    int compareWithStart(const Coord& exact, int a) const noexcept {
        const auto start = static_cast<double>(start_[a]);
        if constexpr (std::is_same<T, float>::value) {
            return compare(exact, start);
        } else {
            // The high parts first (monotonic rounding, the start representable); on a tie, the low part.
            const int byHigh = compare(exact.hi, start);
            return byHigh != 0 ? byHigh : signOf(exact.lo);
        }
    }
    /// Both ends' final rounding at once (roundFloatEndsTogether, roundDoubleEndsTogether:
    /// final_rounding.h); false, writing nothing, when roundFinal must run on each axis.
    [[gnu::always_inline]] bool roundEndsTogether(const Coord& x, const Coord& y, T& outX,
                                                  T& outY) const noexcept {
        if constexpr (std::is_same<T, float>::value) {
            return roundFloatEndsTogether(
                x, y, start_[0], start_[1], [this] { return linesClearBits(); }, outX, outY);
        } else {
            return roundDoubleEndsTogether(
                x, y, start_[0], start_[1], [this] { return linesClearBits(); }, outX, outY);
        }
    }
    /// Float frames: whether the exact double survives the trip to float and back; double frames:
    /// whether the pair's low part is zero.
    bool isRepresentable(const Coord& exact) const noexcept {
        if constexpr (std::is_same<T, float>::value) {
            return static_cast<double>(static_cast<float>(exact)) == exact;
        } else {
            return exact.lo == 0;
        }
    }
    /// Float frames: roundToFloat (exact_double.h), on the bits of the exact double. Double frames:
    /// the high part (fl(value), to nearest), moved one step down when `down` and the low part is
    /// negative, up when rounding up and it is positive (the high part is then nonzero).
    [[gnu::always_inline]] T roundToward(const Coord& exact, bool down) const noexcept {
        if constexpr (std::is_same<T, float>::value) {
            return roundToFloat(exact + 0.0, !down);
        } else {
            const int downward = static_cast<int>(down);
            const int steps = (static_cast<int>(exact.lo > 0) & (1 - downward)) -
                              (static_cast<int>(exact.lo < 0) & downward);
            return stepFromNonzero(exact.hi + 0.0, steps);
        }
    }
    T roundNearest(const Coord& exact) const noexcept {
        if constexpr (std::is_same<T, float>::value) {
            return static_cast<float>(exact + 0.0);
        } else {
            return exact.hi + 0.0;
        }
    }
    /// Whether a grid line lies in [exact + size, up + size), up the value just above exact, read
    /// only when `needed`. A filter answers first, on every axis: z, the far edge's grid
    /// coordinate, estimated, and the reach of that estimate plus the interval's width (in
    /// cells); when the nearest integer to z lies beyond the reach, no line is in the interval.
    /// Otherwise, when needed (rarely: the far edge ends within the reach of a line), float
    /// frames take FastAxis::hasLineIn, exact on their exact doubles, and double frames go to the
    /// lattice (Undecided).
    ///   Float frames: exact + size and its difference with the origin are exact doubles, so z
    ///   errs by the reciprocal's and the product's roundings alone (kFloatLineReachRelative).
    ///   Double frames: the pair's low part is left out (kGridLineReachUlps).
    [[gnu::always_inline]] LineTest gridLineAhead(const Coord& exact, int a, bool needed) const noexcept {
        // One branch, which a game predicts: its boxes' sizes and its map stay the same. Asked
        // here, of inexact ends alone: a frame whose ends are floats (moves by whole pixels) pays
        // nothing for it.
        if (linesClear(a)) return LineTest::No;
        const Motion& m = axis_[a];
        if constexpr (std::is_same<T, float>::value) {
            const double far = exact + m.size;
            const double fromOrigin = far - m.origin;
            const double z = fromOrigin * m.invTile;
            const double reach =
                (kFloatLineReachRelative * ((std::fabs(far) + m.size) + std::fabs(fromOrigin)) +
                 kFloatLineReachLeast) *
                m.invTile;
            const bool clear = lineFree(z, reach);
            if (needed & !clear) {
                const auto up = static_cast<double>(roundToFloat(exact + 0.0, true));
                return m.hasLineIn(far, up + m.size) ? LineTest::Yes : LineTest::No;
            }
            return LineTest::No;
        } else {
            const double hi = exact.hi + 0.0;
            const double z = ((hi + m.size) - m.origin) * m.invTile;
            const double reach = kGridLineReachUlps * kUnitRoundoff *
                                 ((std::fabs(hi) + m.size) + std::fabs(m.origin)) * m.invTile;
            const bool clear = lineFree(z, reach);
            return (needed & !clear) ? LineTest::Undecided : LineTest::No;
        }
    }

private:
    /// The tile test of a double frame on a box that moves on both axes, screened: axis_sweep.h's
    /// testTile evaluated on the high parts of its four distances (FastAxis::entryDistanceHigh,
    /// exitDistanceHigh: bit for bit the high parts of the pairs it builds), up to the first
    /// step where that test would read a low part; there the screen returns false and the exact
    /// test runs from the start. Where it returns true, `verdict` is the exact test's, because
    /// every step before is one the exact test decides from the same high parts:
    ///   - signOf of a pair is the sign of its high part (hi = fl(value), which is zero only for
    ///     a zero value);
    ///   - compare(pair, speed) reads the low part only when hi == speed: hi > speed or
    ///     hi < speed is the exact order (monotonic rounding), equality goes to the exact test;
    ///   - compareProducts on pairs first runs pairProductFilter on fl(hi * speed), which reads
    ///     no low part; its 0 (the band, where the exact refinement would run) goes to the exact
    ///     test, so an exact tie (the Tie verdict) is never screened.
    /// `refined` is untouched: the exact test sets it only beyond a step the screen defers.
    /// No bound of its own: the only filter is compareProducts', derived in proof_constants.h.
    /// On a frame whose tile distances are all exact doubles (kExact: distancesExact()) it skips
    /// that filter too: rounded products in strict order are in that order exactly (monotonic
    /// rounding, as compareProducts on doubles has it), and equal ones defer; the entry is then the
    /// pair {distance, 0}, the value entryDistance would build.
    /// Every fault of the tile test (axis_sweep.h) defers here, so that it reaches double frames.
    /// A verdict that blocks comes with its entry distance in `entry`.
    template <bool kExact>
    [[gnu::always_inline]] static bool screenTile(const Motion& mx, const Motion& my, double xlo, double xhi,
                                                  double ylo, double yhi, TileVerdict& verdict,
                                                  ExactPair& entry) noexcept {
#if defined(TILESWEEP_FAULT_END_INCLUSIVE) || defined(TILESWEEP_FAULT_NO_CORNER_MISS) || \
    defined(TILESWEEP_FAULT_DOUBLE_PREDICATE)
        return false;
#endif
        const double ex = mx.template entryDistanceHigh<kExact>(xlo, xhi);
        const double ey = my.template entryDistanceHigh<kExact>(ylo, yhi);
        const double xx = mx.template exitDistanceHigh<kExact>(xlo, xhi);
        const double xy = my.template exitDistanceHigh<kExact>(ylo, yhi);
        if (ex < 0 && ey < 0) {
            if (xx > 0 && xy > 0) verdict = TileVerdict::StartsOverlapping;
            return true;
        }
        if (!(ex < mx.speed && ey < my.speed)) {    // rarely: an entry at or after the end
            return ex > mx.speed || ey > my.speed;  // E > 1; on a tie, false: the low part decides
        }
        // E < X on each axis (corner misses), then which axis enters later.
        const double exSy = ex * my.speed;
        const double eySx = ey * mx.speed;
        const double xySx = xy * mx.speed;
        const double xxSy = xx * my.speed;
        if constexpr (kExact) {
            if (!(exSy < xySx)) return exSy > xySx;
            if (!(eySx < xxSy)) return eySx > xxSy;
            if (exSy == eySx) return false;
            const bool onX = exSy > eySx;
            verdict = onX ? TileVerdict::BlocksOnX : TileVerdict::BlocksOnY;
            entry = {onX ? ex : ey, 0};
            return true;
        }
        const int xAfterYExits = pairProductFilter(exSy, xySx);
        if (xAfterYExits >= 0) return xAfterYExits > 0;
        const int yAfterXExits = pairProductFilter(eySx, xxSy);
        if (yAfterXExits >= 0) return yAfterXExits > 0;
        const int order = pairProductFilter(exSy, eySx);
        if (order == 0) return false;
        verdict = order > 0 ? TileVerdict::BlocksOnX : TileVerdict::BlocksOnY;
        entry = order > 0 ? mx.entryDistance(xlo, xhi) : my.entryDistance(ylo, yhi);
        return true;
    }

    /// Whether [z - reach, z + reach] holds no integer, for |z| below kGridLineReachLimit (false
    /// beyond it, and for a NaN): the integer nearest z, by the shift that rounds |z| < 2^51 to
    /// an integer (kNearestIntegerShift), lies farther than reach from z. Exact comparisons of
    /// exact values (z - nearest is exact: they are within half a unit of each other).
    [[gnu::always_inline]] static bool lineFree(double z, double reach) noexcept {
        const double nearest = (z + kNearestIntegerShift) - kNearestIntegerShift;
        const bool inLimit = std::fabs(z) < kGridLineReachLimit;
        const bool beyondReach = std::fabs(z - nearest) > reach;
        return inLimit & beyondReach;
    }

    /// Whether no grid line can lie in [exact + size, up + size) for any end `exact` of this axis
    /// (up: exact rounded toward plus infinity), so that the amended rule never applies on it.
    /// Every grid line g = origin + k*tile is a multiple of 2^lineBit (MapRange), the size one of
    /// its lowest set bit, so g - size is a multiple of 2^q, q the lesser of the two. A line in
    /// the interval has exact <= g - size < up, and as up is the least T at or above exact,
    /// g - size is then no T. But a multiple of 2^q at most 2^(q + p) in magnitude is a T (p = 24
    /// for float, 53 for double; q is at least the least input's ulp exponent: -149 or above in
    /// float frames, -302 or above in double frames by the range test), and
    /// |g - size| <= max(|exact|, |up|) <= 2^E when every end is below 2^E in magnitude (2^E is a
    /// T, so |up| <= 2^E too). Ends lie between the start and the start plus the displacement
    /// (final_rounding.h), so |exact| <= |x| + |dx| < 2^E with E one above the larger one's
    /// binade. So E <= q + p suffices. It holds for the boxes of a pixel game (sizes of whole or
    /// half pixels, maps of whole tiles), and for them the grid-line filter costs one predicted
    /// branch. The inputs come as doubles, which hold a float's value and binade exactly.
    [[gnu::always_inline]] static bool linesClearOf(double pos, double disp, double size,
                                                    int lineBit) noexcept {
        constexpr int p = std::numeric_limits<T>::digits;  // 24 or 53
        const std::uint64_t larger = std::max(magnitudeBits(pos), magnitudeBits(disp));
        const int ends = static_cast<int>(larger >> 52) - 1021;  // |x|, |dx| < 2^(field - 1022)
#if defined(TILESWEEP_FAULT_LINES_CLEAR_SIZE_IGNORED)
        static_cast<void>(size);
        return ends <= lineBit + p;  // deliberate fault: the size's bits left out
#else
        return ends <= std::min(lineBit, lowestBitOf(magnitudeBits(size))) + p;
#endif
    }

    /// A margin of `ulps` units of u times `magnitude`, in cells (proof_constants.h).
    static double cellMargin(double ulps, double magnitude, double invTile) noexcept {
        return ulps * kUnitRoundoff * magnitude * invTile;
    }

#if defined(TILESWEEP_CELL_RANGE_SSE2)
    /// A Vec2's x and y as the two lanes of a vector of doubles (exact: a float converts exactly).
    [[gnu::always_inline]] static __m128d lanesOf(const Vec2<T>& v) noexcept {
        if constexpr (std::is_same<T, float>::value) {
            return _mm_cvtps_pd(_mm_castsi128_ps(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(&v))));
        } else {
            return _mm_loadu_pd(&v.x);
        }
    }
    /// Lane 0 into axis x's field, lane 1 into axis y's.
    [[gnu::always_inline]] void storeLanes(double Motion::*field, __m128d v) noexcept {
        _mm_storel_pd(&(axis_[0].*field), v);
        _mm_storeh_pd(&(axis_[1].*field), v);
    }

    /// The frame's set-up, both axes on two SSE2 lanes: makeAxis, endOf's sums and sweptCells
    /// (cell_range.h: estimateCellsOfBoth), with the same operations on the same values as the
    /// per-axis definitions, lane by lane, so the same numbers bit for bit
    /// (FastFrameLanes.* in tests/exact_primitives_test.cpp). A lane's min(w, v) is w < v ? w : v,
    /// which is std::min(v, w); its max(w, v) is w > v ? w : v, which is std::max(v, w).
    [[gnu::always_inline]] void setUpOnLanes(FrameInput<T> in) noexcept {
        const __m128d pos = lanesOf(in.box.pos);
        const __m128d size = lanesOf(in.box.size);
        const __m128d disp = lanesOf(in.displacement);
        const __m128d origin = lanesOf(in.map.origin);
        const __m128d invTile = _mm_loadu_pd(range_.inverseTile);
        const __m128d zero = _mm_setzero_pd();
        const __m128d sign = _mm_set1_pd(-0.0);
        const __m128d speed = _mm_andnot_pd(sign, disp);
        const int positive = _mm_movemask_pd(_mm_cmpgt_pd(disp, zero));
        const int negative = _mm_movemask_pd(_mm_cmplt_pd(disp, zero));
        const __m128d tile = lanesOf(in.map.tileSize);
        __m128d high;
        __m128d highLow = zero;
        if constexpr (std::is_same<Coord, ExactPair>::value) {
            const PairLanes far = twoSumOnLanes(pos, size);
            const PairLanes end = twoSumOnLanes(pos, disp);
            high = far.hi;
            highLow = far.lo;
            storeLanes(&Motion::highLow, far.lo);
            end_[0] = {_mm_cvtsd_f64(end.hi), _mm_cvtsd_f64(end.lo)};
            end_[1] = {_mm_cvtsd_f64(_mm_unpackhi_pd(end.hi, end.hi)),
                       _mm_cvtsd_f64(_mm_unpackhi_pd(end.lo, end.lo))};
        } else {
            high = _mm_add_pd(pos, size);  // exact (admitFloatFrame), as the end
            storeLanes(&Motion::highLow, zero);
            const __m128d end = _mm_add_pd(pos, disp);
            _mm_storel_pd(&end_[0], end);
            _mm_storeh_pd(&end_[1], end);
        }
        storeLanes(&Motion::low, pos);
        storeLanes(&Motion::high, high);
        storeLanes(&Motion::disp, disp);
        storeLanes(&Motion::speed, speed);
        storeLanes(&Motion::origin, origin);
        storeLanes(&Motion::tile, tile);
        storeLanes(&Motion::invTile, invTile);
        storeLanes(&Motion::size, size);
        axis_[0].dir = (positive & 1) - (negative & 1);
        axis_[1].dir = (positive >> 1) - (negative >> 1);
        axis_[0].cells = in.map.columns;
        axis_[1].cells = in.map.rows;

        const __m128d lowEnd = _mm_min_pd(_mm_add_pd(pos, disp), pos);
        const __m128d highEnd = _mm_max_pd(_mm_add_pd(high, disp), high);
        __m128d magnitude;
        if (inWindow_) {
            magnitude = _mm_loadu_pd(range_.windowMagnitude);
            // linesClear of both axes: the grid's half from the map, the sizes' on the lanes.
            const __m128d shift = _mm_set1_pd(range_.sizeGrainShift);
            const int grained =
                _mm_movemask_pd(_mm_cmpeq_pd(_mm_sub_pd(_mm_add_pd(size, shift), shift), size));
            windowLinesClearBits_ = grained & range_.windowLinesClearBits;
        } else {
            magnitude =
                _mm_add_pd(_mm_add_pd(_mm_add_pd(_mm_andnot_pd(sign, pos), _mm_andnot_pd(sign, high)), speed),
                           _mm_andnot_pd(sign, origin));
        }
        const __m128d margin =
            _mm_mul_pd(_mm_mul_pd(_mm_set1_pd(kCellEstimateErrorUlps * kUnitRoundoff), magnitude), invTile);
        estimateCellsOfBoth(_mm_mul_pd(_mm_sub_pd(lowEnd, origin), invTile),
                            _mm_mul_pd(_mm_sub_pd(highEnd, origin), invTile), margin,
                            _mm_set_pd(static_cast<double>(in.map.rows), static_cast<double>(in.map.columns)),
                            swept_);
        if constexpr (std::is_same<Coord, ExactPair>::value) {
            // distancesExactOn of both axes.
            const __m128d span = _mm_sub_pd(_mm_add_pd(lowEnd, lowEnd), highEnd);
            const __m128d spanNeeded = _mm_mul_pd(_mm_set1_pd(kExactDistanceSpanTiles), tile);
            const __m128d marginSmall = _mm_cmple_pd(margin, _mm_set1_pd(kExactDistanceMarginLimit));
#if defined(TILESWEEP_FAULT_EXACT_DISTANCES_FAR_PAIR)
            const __m128d farDouble = _mm_cmpeq_pd(zero, zero);  // deliberate fault (distancesExactOn)
            static_cast<void>(highLow);
#else
            const __m128d farDouble = _mm_cmpeq_pd(highLow, zero);
#endif
            const __m128d exact =
                _mm_and_pd(_mm_and_pd(_mm_cmpge_pd(span, spanNeeded), marginSmall), farDouble);
            distancesExact_ = _mm_movemask_pd(exact) == 3;
        }
    }
#endif

    static Motion makeAxis(T pos, T size, T disp, T origin, T tile, std::int32_t cells,
                           double inverseTile) noexcept {
        const auto p = static_cast<double>(pos);
        const auto d = static_cast<double>(disp);
        const int dir = (d > 0) - (d < 0);  // without a branch: the sign is the data's
        const auto t = static_cast<double>(tile);
        const auto w = static_cast<double>(size);
        const auto o = static_cast<double>(origin);
        const Coord high = sumOf<Coord>(p, w);
        if constexpr (std::is_same<Coord, ExactPair>::value) {
            return {p, high.hi, d, std::fabs(d), dir, o, t, cells, inverseTile, w, high.lo};
        } else {
            return {p, high, d, std::fabs(d), dir, o, t, cells, inverseTile, w, 0};
        }
    }

    const TileMapView<T>& map_;
    const MapRange& range_;  ///< the map's range test; outlives the frame
    Motion axis_[2];
    Coord end_[2];        ///< low + disp, exactly
    CellRange swept_[2];  ///< sweptCells(0), sweptCells(1)
    T start_[2];
    bool inWindow_;
    bool refined_ = false;
    bool distancesExact_ = false;   ///< distancesExact(), from the set-up
    int windowLinesClearBits_ = 0;  ///< linesClearBits of a frame in the window, from the set-up
};

}  // namespace tilesweep::detail

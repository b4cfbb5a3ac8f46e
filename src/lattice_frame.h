// SPDX-License-Identifier: MIT
#pragma once

// The lattice arithmetic of the frame loop (frame_loop.h): a frame scaled onto an integer
// lattice (lattice.h) and solved there exactly, then the final position and the frame times
// rounded back to T: positions by the contract's rule (final_rounding.h), times and a contact's
// coordinate on the axis it slides on (positionAt) to nearest.
// It never answers "undecided": it is the fallback of the fast path (fast_frame.h) and the
// solver of every frame the fast path does not admit.

#include "axis_sweep.h"
#include "cell_range.h"
#include "final_rounding.h"
#include "lattice.h"
#include "wide_int.h"

#include "tilesweep/resolve.h"

#include <cmath>
#include <cstdint>

namespace tilesweep::detail {

/// Per-axis grid of a frame, in lattice integers.
template <class Num>
struct GridAxis {
    Num origin;
    Num tile;
    std::int64_t cells;  ///< columns (x) or rows (y)

    [[nodiscard]] Num edge(std::int64_t k) const noexcept { return origin + tile * k; }

    /// clamp(floor((coordNum / coordDen - origin) / tile), -1, cells): the cell holding a
    /// coordinate, or -1 / cells when it lies before / past the map. Estimated in floating
    /// point, then settled exactly.
    [[nodiscard]] std::int64_t cellOf(const Num& coordNum, const Num& coordDen) const noexcept {
        const Num a = coordNum - origin * coordDen;
        const Num b = tile * coordDen;
        const double estimate = estimateQuotient(a, b);
        std::int64_t q = -1;
        if (estimate >= static_cast<double>(cells)) {
            q = cells;
        } else if (estimate > -1) {
            q = static_cast<std::int64_t>(std::floor(estimate));
        }
        while (q > -1 && b * q > a) --q;
        while (q < cells && b * (q + 1) <= a) ++q;
        return q;
    }
    [[nodiscard]] std::int64_t cellOf(const Num& coord) const noexcept {
        return cellOf(coord, Num::fromInt(1));
    }

    /// Whether a grid line origin + k*tile (k any integer, on the map or off it) lies in
    /// [low, high). One exact remainder; the map is not scanned.
    [[nodiscard]] bool hasLineIn(const Num& low, const Num& high) const noexcept {
        if (!(low < high)) return false;
        const Num width = high - low;
        if (width >= tile) return true;
        // The last line below high lies `back` below it.
        const Num r = floorModulo(high - origin, tile);
        const Num back = r.isZero() ? tile : r;
        return back <= width;
    }
};

/// A frame on its lattice: the arithmetic the frame loop asks for (frame_loop.h), in integers.
template <class T, class Num>
class LatticeFrame {
public:
    using Scalar = T;
    using Coord = Num;
    using Edge = Num;
    using Time = Fraction<Num>;
    using Motion = AxisMotion<Num>;
    struct Walk {
        int primary;
    };

    /// `d` holds the inputs' dyadic forms: box position x, y, size x, y, displacement x, y, map
    /// origin x, y, tile size x, y (solveOnLattice).
    LatticeFrame(const ResolveInput<T>& input, const Dyadic* d, int latticeExponent) noexcept
        : map_(input.map), exponent_(latticeExponent) {
        grid_[0] = {lattice(d[6]), lattice(d[8]), input.map.columns};
        grid_[1] = {lattice(d[7]), lattice(d[9]), input.map.rows};
        motion_[0] = makeAxisMotion(lattice(d[0]), lattice(d[2]), lattice(d[4]));
        motion_[1] = makeAxisMotion(lattice(d[1]), lattice(d[3]), lattice(d[5]));
        start_[0] = input.box.pos.x;
        start_[1] = input.box.pos.y;
    }

    const TileMapView<T>& map() const noexcept { return map_; }
    const Motion& axis(int a) const noexcept { return motion_[a]; }
    T start(int a) const noexcept { return start_[a]; }
    Num edge(int a, std::int64_t k) const noexcept { return grid_[a].edge(k); }
    Num nextEdge(int a, const Num& e) const noexcept {
        return motion_[a].dir > 0 ? e + grid_[a].tile : e - grid_[a].tile;
    }
    std::int64_t cells(int a) const noexcept { return grid_[a].cells; }
    std::int64_t cellOf(int a, const Num& c) const noexcept { return grid_[a].cellOf(c); }
    std::int64_t nearEdgeCell(int a) const noexcept { return grid_[a].cellOf(motion_[a].low); }

    /// The cells the box's span [low, high] covers at the start, exactly (closed, so a superset
    /// of the open overlaps).
    CellRange startCells(int a) const noexcept { return clamped(a, motion_[a].low, motion_[a].high); }
    /// The cells the box's span covers over the frame, exactly (closed).
    CellRange sweptCells(int a) const noexcept {
        const Motion& m = motion_[a];
        const Num end = m.low + m.disp;
        return m.dir < 0 ? clamped(a, end, m.high) : clamped(a, m.low, m.dir > 0 ? m.high + m.disp : m.high);
    }

    void sweptCellsOfBoth(CellRange (&out)[2]) const noexcept {
        out[0] = sweptCells(0);
        out[1] = sweptCells(1);
    }

    Num nearEdge(int a) const noexcept { return motion_[a].low; }
    Num farEdge(int a) const noexcept { return motion_[a].high; }
    Num endOf(int a) const noexcept { return motion_[a].low + motion_[a].disp; }
    /// The box's low and high edges when it touches the tile edge `e` on `a`.
    Num touchLow(int a, const Num& e) const noexcept {
        const Motion& m = motion_[a];
        return m.dir > 0 ? e - (m.high - m.low) : e;
    }
    Num touchHigh(int a, const Num& e) const noexcept {
        const Motion& m = motion_[a];
        return m.dir > 0 ? e : e + (m.high - m.low);
    }

    /// No estimate (frame_loop.h, skipCellsEnteredBefore): a cell before every walk's start, so
    /// that the lattice's walks visit every cell from the first ahead.
    std::int64_t firstCellNotBefore(int a, const Time& /*t*/) const noexcept {
        return motion_[a].dir > 0 ? -2 : grid_[a].cells + 2;
    }
    static Time zeroTime() noexcept { return {Num::fromInt(0), Num::fromInt(1)}; }
    int compareTimes(const Time& a, const Time& b) const noexcept { return compareFractions(a, b); }
    bool certainlyLater(const Time& a, const Time& b) const noexcept { return compareFractions(a, b) > 0; }

    /// The axis whose motion crosses more cells, |d_x| / tile_x > |d_y| / tile_y, so that each
    /// primary cell is crossed in a short time and spans few secondary cells.
    int primaryAxis() const noexcept {
        return compare(motion_[0].speed * grid_[1].tile, motion_[1].speed * grid_[0].tile) >= 0 ? 0 : 1;
    }
    Walk prepareWalk(int p) const noexcept { return {p}; }
    /// The secondary cells the box covers while it is inside the primary cell entered at
    /// entry / speed and left at exit / speed (within [0, 1]), exactly.
    CellRange secondaryCells(const Walk& w, const Num& entry, const Num& exit) const noexcept {
        const Motion& mp = motion_[w.primary];
        const Motion& ms = motion_[1 - w.primary];
        const GridAxis<Num>& gs = grid_[1 - w.primary];
        const Num t0 = entry.isNegative() ? Num::fromInt(0) : entry;
        const Num t1 = exit < mp.speed ? exit : mp.speed;
        // The secondary span over that window, in coordinates scaled by mp.speed.
        const bool forward = ms.dir > 0;
        const Num atT0 = ms.disp * t0;
        const Num atT1 = ms.disp * t1;
        const std::int64_t j0 = gs.cellOf(ms.low * mp.speed + (forward ? atT0 : atT1), mp.speed);
        const std::int64_t j1 = gs.cellOf(ms.high * mp.speed + (forward ? atT1 : atT0), mp.speed);
        return {j0 < 0 ? 0 : j0, j1 > gs.cells - 1 ? gs.cells - 1 : j1};
    }

    TileTest<Num, Num> testTile(std::int64_t i, std::int64_t j) const noexcept {
        bool refined = false;  // integers need no refinement
        return detail::testTile(motion_[0], motion_[1], grid_[0].edge(i), grid_[0].edge(i + 1),
                                grid_[1].edge(j), grid_[1].edge(j + 1), refined);
    }

    /// Both ends at once: never here (roundFinal runs on each axis).
    bool roundEndsTogether(const Num&, const Num&, T&, T&) const noexcept { return false; }

    bool roundTime(const Time& t, T& out) const noexcept {
        out = roundRatioToNearest<T>(t.num, t.den);
        return true;
    }

    /// The box's coordinate on `a` at time t, (low * den + num * disp) / den on the lattice,
    /// rounded to nearest, ties to even (a negative value that rounds to zero gives -0, as IEEE
    /// rounding does); the start itself at t = 0. The frame time (t rounded) is not needed here.
    bool positionAt(int a, const Time& t, T /*frameTime*/, T& out) const noexcept {
        if (t.num.isZero()) {
            out = start_[a];
            return true;
        }
        const Motion& m = motion_[a];
        const Num exact = m.low * t.den + t.num * m.disp;
        const T magnitude = roundRatioToNearest<T>(exact.magnitude(), t.den, exponent_);
        out = exact.isNegative() ? -magnitude : magnitude;
        return true;
    }

    // The final rounding (final_rounding.h).
    int compareWithStart(const Num& exact, int a) const noexcept { return compare(exact, motion_[a].low); }
    bool isRepresentable(const Num& exact) const noexcept {
        return roundLattice<T>(exact, exponent_, MagnitudeRounding::TowardZero) ==
               roundLattice<T>(exact, exponent_, MagnitudeRounding::AwayFromZero);
    }
    T roundToward(const Num& exact, bool down) const noexcept { return roundDirected(exact, !down); }
    T roundNearest(const Num& exact) const noexcept {
        return roundLattice<T>(exact, exponent_, MagnitudeRounding::NearestEven);
    }
    LineTest gridLineAhead(const Num& exact, int a, bool needed) const noexcept {
        if (!needed) return LineTest::No;
        const Num size = motion_[a].high - motion_[a].low;
        const Num up = lattice(decompose(roundDirected(exact, true)));
        return grid_[a].hasLineIn(exact + size, up + size) ? LineTest::Yes : LineTest::No;
    }

private:
    T roundDirected(const Num& exact, bool up) const noexcept {
        return roundLattice<T>(
            exact, exponent_,
            up != exact.isNegative() ? MagnitudeRounding::AwayFromZero : MagnitudeRounding::TowardZero);
    }
    Num lattice(Dyadic v) const noexcept { return toLattice<Num>(v, exponent_); }
    CellRange clamped(int a, const Num& low, const Num& high) const noexcept {
        const GridAxis<Num>& g = grid_[a];
        const std::int64_t first = g.cellOf(low);
        const std::int64_t last = g.cellOf(high);
        return {first < 0 ? 0 : first, last > g.cells - 1 ? g.cells - 1 : last};
    }

    const TileMapView<T>& map_;
    int exponent_;
    GridAxis<Num> grid_[2];
    Motion motion_[2];
    T start_[2];
};

}  // namespace tilesweep::detail

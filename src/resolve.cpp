// SPDX-License-Identifier: MIT
#include "tilesweep/resolve.h"

#include "axis_sweep.h"
#include "fast_frame.h"
#include "fault_injection.h"
#include "lattice.h"
#include "wide_int.h"
#include "zero_move.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <type_traits>

// Move-and-slide over the tile grid: the frame loop of CONTRACT.md ("One frame through a map").
//
// Structure. A frame is scaled onto an integer lattice (lattice.h) and solved there exactly by
// FrameSolver, then the final position and the frame times are rounded back to T: positions
// toward the start (or down, where the far edge would cross a grid line: roundFinal), times to
// nearest. The contract's loop runs at most two steps, and the
// second is always a one-axis move: after the first contact at time s, the motion on the
// contact axes is zeroed; if both were contact axes nothing moves, otherwise only the free axis
// moves on, from where it was at s, while the contact axis stays exactly touching. In the
// frame's own time the free axis is still moving at its original speed, so a tile blocks the
// second step iff it overlaps the (static) contact-axis span and its entry time on the free axis
// lies in [s, 1); its frame time is that entry time. Solving step 2 in frame time avoids the
// rational position at s altogether.
//
// Broadphase. Candidate tiles come from the grid, never from a scan of the map. The walk goes
// along the primary axis (the one whose motion crosses more cells), cell by cell in the order
// the box enters them; for each primary cell it takes the secondary cells the box's span covers
// while it is inside that primary cell, and it stops at the first primary cell entered after the
// earliest time of impact found so far, or at time 1. Cells entered at exactly that time are
// still visited: they may be hit at the same time, and the contract takes all of them at once.
// The cost is the number of cells the path touches, independent of the map's size.

namespace tilesweep {
namespace {

/// Records the path that decided the frame when the caller asked for it (frame_stats.h).
template <class T>
void recordPath(const ResolveOutput<T>& output, DecisionPath path) noexcept {
    if (output.stats != nullptr) output.stats->path = path;
}

using detail::AxisMotion;
using detail::Fraction;
using detail::MagnitudeRounding;
using detail::TileVerdict;

/// Per-axis grid and box data of a frame, in lattice integers.
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
        const double estimate = detail::estimateQuotient(a, b);
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
        const Num r = detail::floorModulo(high - origin, tile);
        const Num back = r.isZero() ? tile : r;
        return back <= width;
    }
};

/// The hits of one step: all tiles at the earliest time of impact found so far.
template <class T, class Num>
struct StepHits {
    Contact<T>* store;       ///< caller's buffer, from the first slot this step may use
    std::int32_t capacity;   ///< slots available from `store`
    std::int32_t count = 0;  ///< hits at `time`, stored or not
    bool any = false;
    Fraction<Num> time{};
    bool axisHit[2] = {false, false};
    Num touch[2]{};  ///< box position that touches the hit face, per contact axis

    /// Whether a tile entered at `t` could still be among the hits (not later than them).
    [[nodiscard]] bool mayHitAt(const Fraction<Num>& t) const noexcept {
        return !any || detail::compareFractions(t, time) <= 0;
    }

    /// Records a hit at `t`; a hit earlier than the current ones replaces them all. The frame
    /// time is filled in when the step ends.
    void add(Cell cell, Axis axis, Normal normal, const Fraction<Num>& t, const Num& touchPosition) noexcept {
        if (any) {
            const int order = detail::compareFractions(t, time);
            if (order > 0) return;
            if (order < 0) {
                count = 0;
                axisHit[0] = axisHit[1] = false;
            }
        }
        any = true;
        time = t;
        const int a = axis == Axis::X ? 0 : 1;
        axisHit[a] = true;
        touch[a] = touchPosition;
        if (count < capacity) store[count] = {cell, normal, T(0)};
        ++count;
    }
};

template <class T, class Num>
class FrameSolver {
public:
    /// `d` holds the inputs' dyadic forms: box position x, y, size x, y, displacement x, y, map
    /// origin x, y, tile size x, y (solveOnLattice).
    FrameSolver(const SweepInput<T>& input, const detail::Dyadic* d, int latticeExponent) noexcept
        : map_(input.map), exponent_(latticeExponent) {
        grid_[0] = {lattice(d[6]), lattice(d[8]), input.map.columns};
        grid_[1] = {lattice(d[7]), lattice(d[9]), input.map.rows};
        motion_[0] = detail::makeAxisMotion(lattice(d[0]), lattice(d[2]), lattice(d[4]));
        motion_[1] = detail::makeAxisMotion(lattice(d[1]), lattice(d[3]), lattice(d[5]));
        start_[0] = input.box.pos.x;
        start_[1] = input.box.pos.y;
    }

    SweepResult<T> run(const ResolveOutput<T>& out) noexcept {
        SweepResult<T> result;
        result.startOverlapCount = listStartOverlaps(out.startOverlaps, out.startOverlapCapacity);
        result.position = {start_[0], start_[1]};
        if (motion_[0].dir == 0 && motion_[1].dir == 0) {
            result.status = Status::Moved;
            return result;
        }

        Num finalPos[2] = {motion_[0].low + motion_[0].disp, motion_[1].low + motion_[1].disp};
        StepHits<T, Num> first{out.contacts, std::max<std::int32_t>(out.contactCapacity, 0)};
        if (motion_[0].dir != 0 && motion_[1].dir != 0) {
            sweepBothAxes(first);
        } else {
            const int a = motion_[0].dir != 0 ? 0 : 1;
            sweepOneAxis(a, motion_[1 - a].low, motion_[1 - a].high, zeroTime(), first);
        }
        std::int32_t total = 0;
        if (first.any) {
            finishStep(first);
            total = first.count;
            result.blockedX = first.axisHit[0];
            result.blockedY = first.axisHit[1];
            for (int a = 0; a < 2; ++a)
                if (first.axisHit[a]) finalPos[a] = first.touch[a];
            const int free = first.axisHit[0] ? 1 : 0;
            if (first.axisHit[0] != first.axisHit[1] && motion_[free].dir != 0) {
                const int held = 1 - free;
                const std::int32_t used = std::min(first.count, first.capacity);
                StepHits<T, Num> second{out.contacts + used, first.capacity - used};
                const Num low = first.touch[held];
                sweepOneAxis(free, low, low + (motion_[held].high - motion_[held].low), first.time, second);
                if (second.any) {
                    finishStep(second);
                    total += second.count;
                    finalPos[free] = second.touch[free];
                    (free == 0 ? result.blockedX : result.blockedY) =
                        true;  // a second step moves on `free` alone
                }
            }
        }
        result.contactCount = total;
        result.status = total > 0 ? Status::Blocked : Status::Moved;
        result.position = {roundFinal(finalPos[0], 0), roundFinal(finalPos[1], 1)};
        return result;
    }

private:
    Num lattice(detail::Dyadic v) const noexcept { return detail::toLattice<Num>(v, exponent_); }
    static Fraction<Num> zeroTime() noexcept { return {Num::fromInt(0), Num::fromInt(1)}; }

    /// The exact final coordinate, rounded to the T between the start and it that is nearest
    /// to it: toward -inf when it lies after the start, toward +inf before.
    T roundTowardStart(const Num& exact, int axis) const noexcept {
        const int side = compare(exact, motion_[axis].low);
        if (side == 0) return start_[axis];
        const bool towardMinusInf = side > 0;
        const bool negative = exact.isNegative();
#if defined(TILESWEEP_FAULT_ROUND_NEAREST)
        const MagnitudeRounding mode = MagnitudeRounding::NearestEven;  // deliberate fault
        (void)towardMinusInf;
        (void)negative;
#else
        const MagnitudeRounding mode =
            towardMinusInf != negative ? MagnitudeRounding::TowardZero : MagnitudeRounding::AwayFromZero;
#endif
        return detail::roundLattice<T>(exact, exponent_, mode);
    }

    /// The contract's rounding of a final coordinate ("Positions"): toward the start, except on
    /// an axis that moved toward minus infinity when that would carry the far edge (x + w) over
    /// a grid line the exact far edge had not passed; then toward minus infinity. Rounding down
    /// never carries the near edge over a tile edge (edges are representable), and the far edge
    /// then stays short of every line the exact one had not reached, so the rounded box overlaps
    /// no tile the exact one does not. When nothing finite lies at or below the exact value, the
    /// rounding toward the start stands.
    T roundFinal(const Num& exact, int axis) const noexcept {
        const T towardStart = roundTowardStart(exact, axis);
#if defined(TILESWEEP_FAULT_OLD_ROUNDING_RULE)
        return towardStart;  // deliberate fault: the contract's rule before the amendment
#else
        const AxisMotion<Num>& m = motion_[axis];
        if (!(exact < m.low)) return towardStart;  // not a move toward minus infinity
        // The rounded value is a T between the exact value and the start: on the lattice.
        const Num rounded = lattice(detail::decompose(towardStart));
        if (rounded == exact) return towardStart;
        const Num size = m.high - m.low;
        if (!grid_[axis].hasLineIn(exact + size, rounded + size)) return towardStart;
        const bool negative = exact.isNegative();
        const T down = detail::roundLattice<T>(
            exact, exponent_, negative ? MagnitudeRounding::AwayFromZero : MagnitudeRounding::TowardZero);
        return std::isfinite(down) ? down : towardStart;
#endif
    }

    /// Solid cells the box overlaps (open) at the start, by row then column.
    std::int32_t listStartOverlaps(Cell* store, std::int32_t capacity) const noexcept {
        const GridAxis<Num>& gx = grid_[0];
        const GridAxis<Num>& gy = grid_[1];
        const std::int64_t i0 = std::max<std::int64_t>(gx.cellOf(motion_[0].low), 0);
        const std::int64_t i1 = std::min<std::int64_t>(gx.cellOf(motion_[0].high), gx.cells - 1);
        const std::int64_t j0 = std::max<std::int64_t>(gy.cellOf(motion_[1].low), 0);
        const std::int64_t j1 = std::min<std::int64_t>(gy.cellOf(motion_[1].high), gy.cells - 1);
        std::int32_t count = 0;
        for (std::int64_t j = j0; j <= j1; ++j) {
            if (!motion_[1].overlapsAtStart(gy.edge(j), gy.edge(j + 1))) continue;
            for (std::int64_t i = i0; i <= i1; ++i) {
                if (!map_.isSolid(i, j) || !motion_[0].overlapsAtStart(gx.edge(i), gx.edge(i + 1))) continue;
                if (count < capacity)
                    store[count] = {static_cast<std::int32_t>(i), static_cast<std::int32_t>(j)};
                ++count;
            }
        }
        return count;
    }

    /// First cell along `axis` (in the direction of motion) whose far side the trailing edge
    /// has not passed at t = 0, clamped into the map; -1 or cells when no map cell qualifies.
    std::int64_t firstCellAhead(int axis) const noexcept {
        const GridAxis<Num>& g = grid_[axis];
        const AxisMotion<Num>& m = motion_[axis];
        if (m.dir > 0) {
            // The cell holding the trailing (low) edge: its high edge lies beyond it.
            return std::max<std::int64_t>(g.cellOf(m.low), 0);
        }
        // Largest k with edge(k) < high edge.
        std::int64_t k = g.cellOf(m.high);
        if (k >= 0 && k < g.cells && g.edge(k) == m.high) --k;
        return std::min<std::int64_t>(k, g.cells - 1);
    }

    Num touchPosition(int axis, std::int64_t k) const noexcept {
        const GridAxis<Num>& g = grid_[axis];
        const AxisMotion<Num>& m = motion_[axis];
        return m.dir > 0 ? g.edge(k) - (m.high - m.low) : g.edge(k + 1);
    }

    /// Step 1 when both axes move: walk the primary axis in time order.
    void sweepBothAxes(StepHits<T, Num>& hits) const noexcept {
        // Primary: the axis whose motion crosses more cells, |d_x| / tile_x > |d_y| / tile_y,
        // so that each primary cell is crossed in a short time and spans few secondary cells.
        const int p =
            compare(motion_[0].speed * grid_[1].tile, motion_[1].speed * grid_[0].tile) >= 0 ? 0 : 1;
        const int s = 1 - p;
        const GridAxis<Num>& gp = grid_[p];
        const GridAxis<Num>& gs = grid_[s];
        const AxisMotion<Num>& mp = motion_[p];
        const AxisMotion<Num>& ms = motion_[s];
        const Num zero = Num::fromInt(0);
        for (std::int64_t k = firstCellAhead(p); k >= 0 && k < gp.cells; k += mp.dir) {
            const Num lo = gp.edge(k);
            const Num hi = gp.edge(k + 1);
            const Num entry = mp.entryDistance(lo, hi);
            if (entry >= mp.speed) break;  // entered at t >= 1
            if (!hits.mayHitAt({entry, mp.speed})) break;
            const Num exit = mp.exitDistance(lo, hi);
            // The box is inside this primary cell for t in (entry, exit) / speed, within [0, 1].
            const Num t0 = entry.isNegative() ? zero : entry;
            const Num t1 = exit < mp.speed ? exit : mp.speed;
            // The secondary span over that window, in coordinates scaled by mp.speed.
            const Num atT0 = ms.disp * t0;
            const Num atT1 = ms.disp * t1;
            const Num lowScaled = ms.low * mp.speed;
            const Num highScaled = ms.high * mp.speed;
            const bool forward = ms.dir > 0;
            std::int64_t j0 = gs.cellOf(lowScaled + (forward ? atT0 : atT1), mp.speed);
            std::int64_t j1 = gs.cellOf(highScaled + (forward ? atT1 : atT0), mp.speed);
            j0 = std::max<std::int64_t>(j0, 0);
            j1 = std::min<std::int64_t>(j1, gs.cells - 1);
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

    void testAndRecord(std::int64_t i, std::int64_t j, StepHits<T, Num>& hits) const noexcept {
        const GridAxis<Num>& gx = grid_[0];
        const GridAxis<Num>& gy = grid_[1];
        const auto test =
            detail::testTile(motion_[0], motion_[1], gx.edge(i), gx.edge(i + 1), gy.edge(j), gy.edge(j + 1));
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
                // The cell across the face approached on each axis.
                const bool xExposed = !map_.isSolid(i - motion_[0].dir, j);
                const bool yExposed = !map_.isSolid(i, j - motion_[1].dir);
                axis = detail::settleTie(xExposed, yExposed);
                break;
            }
        }
        const int a = axis == Axis::X ? 0 : 1;
        hits.add({static_cast<std::int32_t>(i), static_cast<std::int32_t>(j)}, axis, normalOn(a), test.time,
                 touchPosition(a, a == 0 ? i : j));
    }

    /// A move along `axis` alone while the other axis stays at [heldLow, heldHigh]: step 1 with
    /// a static axis (from = 0), or step 2 (from = s). Only tiles entered in [from, 1) block;
    /// they are found in the first cell along `axis` that has any, and all share its time.
    void sweepOneAxis(int axis, const Num& heldLow, const Num& heldHigh, const Fraction<Num>& from,
                      StepHits<T, Num>& hits) const noexcept {
        const int other = 1 - axis;
        const GridAxis<Num>& ga = grid_[axis];
        const GridAxis<Num>& go = grid_[other];
        const AxisMotion<Num>& m = motion_[axis];
        const std::int64_t j0 = std::max<std::int64_t>(go.cellOf(heldLow), 0);
        const std::int64_t j1 = std::min<std::int64_t>(go.cellOf(heldHigh), go.cells - 1);
        if (j0 > j1) return;
        for (std::int64_t k = firstCellAhead(axis); k >= 0 && k < ga.cells; k += m.dir) {
            const Num entry = m.entryDistance(ga.edge(k), ga.edge(k + 1));
            if (entry >= m.speed) return;  // entered at t >= 1
            const Fraction<Num> at{entry, m.speed};
            if (detail::compareFractions(at, from) < 0) continue;  // overlapping already at `from`
            for (std::int64_t j = j0; j <= j1; ++j) {
                const std::int64_t ci = axis == 0 ? k : j;
                const std::int64_t cj = axis == 0 ? j : k;
                if (!map_.isSolid(ci, cj)) continue;
                // Open overlap on the held axis; touching is not overlapping.
                if (!(heldLow < go.edge(j + 1) && heldHigh > go.edge(j))) continue;
                hits.add({static_cast<std::int32_t>(ci), static_cast<std::int32_t>(cj)},
                         axis == 0 ? Axis::X : Axis::Y, normalOn(axis), at, touchPosition(axis, k));
            }
            if (hits.any) return;
        }
    }

    /// The normal of a hit on `axis`: against the motion, (-sign(r_x), 0) or (0, -sign(r_y)).
    Normal normalOn(int axis) const noexcept {
        const auto against = static_cast<std::int8_t>(-motion_[axis].dir);
        return axis == 0 ? Normal{against, 0} : Normal{0, against};
    }

    /// Sorts the stored hits of a step by row, then column, and fills in the frame time (the
    /// same for every hit of the step).
    void finishStep(StepHits<T, Num>& hits) const noexcept {
        const std::int32_t stored = std::min(hits.count, hits.capacity);
        const T time = detail::roundRatioToNearest<T>(hits.time.num, hits.time.den);
        for (std::int32_t k = 0; k < stored; ++k) hits.store[k].time = time;
        std::sort(hits.store, hits.store + stored, [](const Contact<T>& a, const Contact<T>& b) {
            return a.tile.j != b.tile.j ? a.tile.j < b.tile.j : a.tile.i < b.tile.i;
        });
    }

    const TileMapView<T>& map_;
    int exponent_;
    GridAxis<Num> grid_[2];
    AxisMotion<Num> motion_[2];
    T start_[2];
};

/// Scales the frame onto its lattice and solves it with integers wide enough for it.
template <class T>
SweepResult<T> solveOnLattice(const SweepInput<T>& in, const ResolveOutput<T>& out) noexcept {
    using detail::decompose;
    using detail::exponentAbove;
    const detail::Dyadic d[10] = {decompose(in.box.pos.x),      decompose(in.box.pos.y),
                                  decompose(in.box.size.x),     decompose(in.box.size.y),
                                  decompose(in.displacement.x), decompose(in.displacement.y),
                                  decompose(in.map.origin.x),   decompose(in.map.origin.y),
                                  decompose(in.map.tileSize.x), decompose(in.map.tileSize.y)};
    // Every coordinate the frame forms is below 2^top: box edges at the start and the end (a sum
    // of three inputs, so 2 bits above the largest) and tile edges from one cell before the map
    // to one past it (origin + k*tile with |k| <= cells + 2).
    int top = 0;
    for (int k = 0; k < 6; ++k) top = std::max(top, exponentAbove(d[k]) + 2);
    const int cellBits[2] = {detail::bitLength(static_cast<std::uint64_t>(in.map.columns) + 2),
                             detail::bitLength(static_cast<std::uint64_t>(in.map.rows) + 2)};
    for (int a = 0; a < 2; ++a)
        top = std::max(top, std::max(exponentAbove(d[6 + a]), exponentAbove(d[8 + a]) + cellBits[a]) + 1);
    const detail::LatticeShape shape = detail::shapeLattice(d, 10, top);
    return detail::withWidth(detail::bitsNeeded(shape), [&](auto tag) {
        return FrameSolver<T, decltype(tag)>(in, d, shape.exponent).run(out);
    });
}

/// Every frame but the zero moves resolveZeroMove settles: out of line, so that the early exit
/// pays for none of its stack frame.
template <class T>
#if defined(__GNUC__)
__attribute__((noinline))
#endif
SweepResult<T>
resolveMoving(const SweepInput<T>& input, const ResolveOutput<T>& output) noexcept {
    // The fast path, when the range test admits the frame (fast_frame.h): float frames on exact
    // doubles, double frames on exact pairs under a certified filter. The range test implies
    // the frame is valid, so isValid only runs for the frames it turns away.
    bool admitted = false;
    if constexpr (std::is_same<T, float>::value) {
        admitted = detail::admitFloatFrame(input);
    } else {
        admitted = detail::admitDoubleFrame(input);
    }
    if (admitted) {
        detail::FastFrame<T> frame(input);
        SweepResult<T> result;
        if (frame.run(output, result)) {
            recordPath(output, frame.refined() ? DecisionPath::Filtered : DecisionPath::Fast);
            return result;
        }
    } else if (!isValid(input)) {
        SweepResult<T> invalid;
        invalid.status = Status::InvalidInput;
        invalid.position = input.box.pos;
        if (!std::isfinite(invalid.position.x) || !std::isfinite(invalid.position.y))
            invalid.position = {0, 0};
        recordPath(output, DecisionPath::Exact);
        return invalid;
    }
    recordPath(output, DecisionPath::Exact);
    return solveOnLattice(input, output);
}

}  // namespace

template <class T>
SweepResult<T> resolveMove(const SweepInput<T>& input, const ResolveOutput<T>& output) noexcept {
    // A zero move: the start overlaps alone, from the cells under the box (zero_move.h).
    if (input.displacement.x == 0 && input.displacement.y == 0) {
        SweepResult<T> result;
        if (detail::resolveZeroMove(input, output, result)) {
            recordPath(output, DecisionPath::Fast);
            return result;
        }
    }
    return resolveMoving(input, output);
}

template SweepResult<float> resolveMove<float>(const SweepInput<float>&,
                                               const ResolveOutput<float>&) noexcept;
template SweepResult<double> resolveMove<double>(const SweepInput<double>&,
                                                 const ResolveOutput<double>&) noexcept;

SweepResult<float> resolveMove(const SweepInput<float>& input, const ResolveOutput<float>& output) noexcept {
    return resolveMove<float>(input, output);
}
SweepResult<double> resolveMove(const SweepInput<double>& input,
                                const ResolveOutput<double>& output) noexcept {
    return resolveMove<double>(input, output);
}

}  // namespace tilesweep

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

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "axis_sweep.h"
#include "exact_double.h"
#include "fault_injection.h"
#include "tilesweep/resolve.h"

namespace tilesweep::detail {

/// Certified bound on the error of the walk's secondary range estimate, in units of
/// u = 2^-53 times A / tile cells, A = |low| + |high| + |disp| + |origin| of the secondary axis.
/// The estimate v = (low + (disp / speed) * t - origin) * fl(1 / tile) takes six rounded
/// operations. With t / speed in [0, 1] and every intermediate below A(1 + 3u) in magnitude,
/// their errors are at most 2.01u|disp| (the slope and its product with t), + 1.01uA (sum),
/// + 1.01uA (difference), all scaled by 1/tile (1 + 2.01u), then + 2.01uA/tile (the rounded
/// reciprocal and the product): under 6.05 uA/tile in all. Adding or subtracting the margin
/// rounds once more, by at most 1.01 uA/tile, and the margin itself is computed 5u low at
/// worst: 10 covers the 7.07 needed (and half of it does not).
inline constexpr double kSecondaryRangeErrorUlps = 10;

/// The most bits the fast path's exact doubles may need: a double's 53.
inline constexpr int kFastSpanBits = 53;

/// Whether the fast path holds every value of this float frame exactly (see the top of this
/// file): all nonzero inputs normal, C + 2 - G <= 53, and no coordinate near the top of
/// float's range. A few integer operations on the inputs' exponent fields.
[[nodiscard]] inline bool admitFloatFrame(const SweepInput<float>& in) noexcept {
    const float values[10] = {in.box.pos.x,     in.box.pos.y,     in.box.size.x,   in.box.size.y,
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
    if (subnormal) return false;
    if (in.map.columns >= (1 << 24) || in.map.rows >= (1 << 24)) return false;
    // G = lowest - 127 - 23 (the ulp of the smallest input); magnitudes below 2^(f - 126).
    int boxTop = -1000;  // |box input| < 2^(boxTop - 126)
    for (int k = 0; k < 6; ++k) boxTop = std::max(boxTop, field[k]);
    const int cellBits[2] = {32 - __builtin_clz(static_cast<std::uint32_t>(in.map.columns) + 2),
                             32 - __builtin_clz(static_cast<std::uint32_t>(in.map.rows) + 2)};
    // |origin + k*tile| < 2^(fo - 126) + 2^(ft - 126 + cellBits) <= 2^(edgeTop - 126)
    int edgeTop = -1000;
    for (int a = 0; a < 2; ++a) edgeTop = std::max(edgeTop, std::max(field[6 + a], field[8 + a] + cellBits[a]) + 1);
    // Coordinates: |x| + |w| + |dx| < 2^(boxTop + 2 - 126); an edge minus a size, a grid line
    // next to a box edge: one bit more than the larger.
    const int top = std::max(boxTop + 2, edgeTop) + 1;  // all coordinates below 2^(top - 126)
    // Span in bits: (C + 2) - G = (top - 126 + 2) - (lowest - 150).
    int span = top - lowest + 26;
#if defined(TILESWEEP_FAULT_FAST_RANGE_TOO_WIDE)
    --span;  // deliberate fault: the range test one binade too generous
#endif
    return span <= kFastSpanBits && top - 126 <= 120;
}

/// floor(v) for |v| < 2^62, without a libm call (x86-64's baseline has no rounding instruction).
[[nodiscard]] inline std::int64_t floorToInt(double v) noexcept {
    auto k = static_cast<std::int64_t>(v);  // toward zero
    if (static_cast<double>(k) > v) --k;
    return k;
}

/// One axis of a fast frame: the box's motion and the grid, as exact doubles.
struct FastAxis {
    double low;     ///< box edge with the smaller coordinate, at t = 0
    double high;    ///< low + size
    double disp;    ///< displacement over the frame
    double speed;   ///< |disp|
    int dir;        ///< sign of disp
    double origin;  ///< map origin
    double tile;    ///< tile size
    std::int64_t cells;
    double invTile; ///< 1 / tile, rounded: for estimates only

    [[nodiscard]] double edge(std::int64_t k) const noexcept { return origin + static_cast<double>(k) * tile; }
    [[nodiscard]] double entryDistance(double lo, double hi) const noexcept { return dir > 0 ? lo - high : low - hi; }
    [[nodiscard]] double exitDistance(double lo, double hi) const noexcept { return dir > 0 ? hi - low : high - lo; }
    [[nodiscard]] bool overlapsAtStart(double lo, double hi) const noexcept {
#if defined(TILESWEEP_FAULT_TOUCH_OVERLAPS)
        return low <= hi && high >= lo;  // deliberate fault: touching counted as overlap
#else
        return low < hi && high > lo;
#endif
    }

    /// clamp(floor((c - origin) / tile), -1, cells), exactly. The estimate (c - origin) * invTile
    /// is within 2.01u of the quotient, relatively: off by far less than one where the clamp
    /// does not decide (|quotient| < 2^25), so one exact comparison with a tile edge, either
    /// way, settles it.
    [[nodiscard]] std::int64_t cellOf(double c) const noexcept {
        std::int64_t k = clampCell((c - origin) * invTile);
        if (k > -1 && edge(k) > c) {
            --k;
        } else if (k < cells && edge(k + 1) <= c) {
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
    /// 2^53), settled by exact comparisons.
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

/// A time num / den (den > 0) as exact doubles.
struct FastTime {
    double num;
    double den;
};

/// The verdict on one tile and, when it blocks, its time of impact (TileTest, axis_sweep.h).
struct FastTileTest {
    TileVerdict verdict;
    FastTime time;
};

/// testTile (axis_sweep.h) on exact doubles: the same branches, every comparison of two times
/// made by compareProducts. Only the motion fields of mx and my are read.
[[nodiscard]] inline FastTileTest testTileFast(const FastAxis& mx, const FastAxis& my, double xlo, double xhi,
                                               double ylo, double yhi, bool& refined) noexcept {
    FastTileTest miss{TileVerdict::Misses, {0, 1}};
    if (mx.dir == 0 || my.dir == 0) {
        if (mx.dir == 0 && my.dir == 0) {
            if (mx.overlapsAtStart(xlo, xhi) && my.overlapsAtStart(ylo, yhi)) miss.verdict = TileVerdict::StartsOverlapping;
            return miss;
        }
        const bool xMoves = mx.dir != 0;
        const FastAxis& moving = xMoves ? mx : my;
        const FastAxis& still = xMoves ? my : mx;
        const double lo = xMoves ? xlo : ylo;
        const double hi = xMoves ? xhi : yhi;
        if (!(xMoves ? still.overlapsAtStart(ylo, yhi) : still.overlapsAtStart(xlo, xhi))) return miss;
        const double entry = moving.entryDistance(lo, hi);
        if (entry < 0) {
            if (moving.exitDistance(lo, hi) > 0) miss.verdict = TileVerdict::StartsOverlapping;
            return miss;
        }
        if (entry >= moving.speed) return miss;
        return {xMoves ? TileVerdict::BlocksOnX : TileVerdict::BlocksOnY, {entry, moving.speed}};
    }
    const double ex = mx.entryDistance(xlo, xhi);
    const double ey = my.entryDistance(ylo, yhi);
    const double xx = mx.exitDistance(xlo, xhi);
    const double xy = my.exitDistance(ylo, yhi);
    if (ex < 0 && ey < 0) {
        if (xx > 0 && xy > 0) miss.verdict = TileVerdict::StartsOverlapping;
        return miss;
    }
    if (ex >= mx.speed || ey >= my.speed) return miss;  // E >= 1
#if !defined(TILESWEEP_FAULT_NO_CORNER_MISS)
    // E < X: each axis enters before the other exits.
    if (compareProducts(ex, my.speed, xy, mx.speed, refined) >= 0) return miss;
    if (compareProducts(ey, mx.speed, xx, my.speed, refined) >= 0) return miss;
#endif
#if defined(TILESWEEP_FAULT_DOUBLE_PREDICATE)
    // Deliberate fault: the entry comparison in plain double arithmetic.
    const double pa = ex * my.speed;
    const double pb = ey * mx.speed;
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
[[nodiscard]] inline bool roundTimeToFloat(const FastTime& t, bool& refined, float& out) noexcept {
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
        out = static_cast<float>(q);  // exactly the midpoint: ties to even
    }
    return true;
}

/// The fast path's frame solver: FrameSolver (resolve.cpp) step for step, on exact doubles.
class FastFrame {
public:
    explicit FastFrame(const SweepInput<float>& in) noexcept : map_(in.map) {
        axis_[0] = makeAxis(in.box.pos.x, in.box.size.x, in.displacement.x, in.map.origin.x, in.map.tileSize.x,
                            in.map.columns);
        axis_[1] = makeAxis(in.box.pos.y, in.box.size.y, in.displacement.y, in.map.origin.y, in.map.tileSize.y,
                            in.map.rows);
        start_[0] = in.box.pos.x;
        start_[1] = in.box.pos.y;
    }

    /// Solves the frame into `result`; false when it meets a case it hands to the lattice.
    bool run(const ResolveOutput<float>& out, SweepResult<float>& result) noexcept {
        result.startOverlapCount = listStartOverlaps(out.startOverlaps, out.startOverlapCapacity);
        result.position = {start_[0], start_[1]};
        if (axis_[0].dir == 0 && axis_[1].dir == 0) {
            result.status = Status::Moved;
            return true;
        }
        double finalPos[2] = {axis_[0].low + axis_[0].disp, axis_[1].low + axis_[1].disp};
        Hits first{out.contacts, std::max<std::int32_t>(out.contactCapacity, 0)};
        if (axis_[0].dir != 0 && axis_[1].dir != 0) {
            sweepBothAxes(first);
        } else {
            const int a = axis_[0].dir != 0 ? 0 : 1;
            sweepOneAxis(a, axis_[1 - a].low, axis_[1 - a].high, {0, 1}, first);
        }
        std::int32_t total = 0;
        if (first.any) {
            if (!finishStep(first)) return false;
            total = first.count;
            for (int a = 0; a < 2; ++a)
                if (first.axisHit[a]) finalPos[a] = first.touch[a];
            const int free = first.axisHit[0] ? 1 : 0;
            if (first.axisHit[0] != first.axisHit[1] && axis_[free].dir != 0) {
                const int held = 1 - free;
                const std::int32_t used = std::min(first.count, first.capacity);
                Hits second{out.contacts + used, first.capacity - used};
                const double low = first.touch[held];
                sweepOneAxis(free, low, low + (axis_[held].high - axis_[held].low), first.time, second);
                if (second.any) {
                    if (!finishStep(second)) return false;
                    total += second.count;
                    finalPos[free] = second.touch[free];
                }
            }
        }
        result.contactCount = total;
        result.status = total > 0 ? Status::Blocked : Status::Moved;
        result.position = {roundFinal(finalPos[0], 0), roundFinal(finalPos[1], 1)};
        return true;
    }

    /// Whether some predicate needed its exact refinement (DecisionPath::Filtered).
    [[nodiscard]] bool refined() const noexcept { return refined_; }

private:
    /// The hits of one step (StepHits in resolve.cpp).
    struct Hits {
        Contact<float>* store;
        std::int32_t capacity;
        std::int32_t count = 0;
        bool any = false;
        FastTime time{0, 1};
        bool axisHit[2] = {false, false};
        double touch[2] = {0, 0};
    };

    static FastAxis makeAxis(float pos, float size, float disp, float origin, float tile,
                             std::int32_t cells) noexcept {
        const double p = pos;
        const double d = disp;
        const int dir = d > 0 ? 1 : (d < 0 ? -1 : 0);
        const double t = tile;
        return {p, p + static_cast<double>(size), d, std::fabs(d), dir, origin, t, cells, 1 / t};
    }

    int compareTimes(const FastTime& a, const FastTime& b) noexcept {
        // The same fraction (tiles entered across one face line): equal without arithmetic.
        if (a.num == b.num && a.den == b.den) return 0;
        return compareProducts(a.num, b.den, b.num, a.den, refined_);
    }

    void add(Hits& hits, Cell cell, Axis axis, const FastTime& t, double touchPosition) noexcept {
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
        hits.touch[a] = touchPosition;
        if (hits.count < hits.capacity) hits.store[hits.count] = {cell, normalOn(a), 0.0f};
        ++hits.count;
    }

    /// Sorts a step's stored hits by row, then column, and writes its frame time.
    bool finishStep(Hits& hits) noexcept {
        const std::int32_t stored = std::min(hits.count, hits.capacity);
        float time = 0;
        if (!roundTimeToFloat(hits.time, refined_, time)) return false;
        for (std::int32_t k = 0; k < stored; ++k) hits.store[k].time = time;
        if (stored > 1)
            std::sort(hits.store, hits.store + stored, [](const Contact<float>& a, const Contact<float>& b) {
                return a.tile.j != b.tile.j ? a.tile.j < b.tile.j : a.tile.i < b.tile.i;
            });
        return true;
    }

    /// FrameSolver::roundFinal: toward the start, or toward minus infinity on an axis moving
    /// that way when rounding back would carry the far edge over a grid line. `exact` is the
    /// exact final coordinate; the rounded one is a float between it and the start, so a
    /// multiple of 2^G below 2^C, and its far edge is exact too.
    float roundFinal(double exact, int axis) const noexcept {
        exact += 0.0;  // -0 reads +0, as the lattice's zero does
        const float start = start_[axis];
        if (exact == static_cast<double>(start)) return start;
#if defined(TILESWEEP_FAULT_ROUND_NEAREST)
        const float towardStart = static_cast<float>(exact);  // deliberate fault
#else
        const float towardStart = roundToFloat(exact, exact < static_cast<double>(start));
#endif
#if defined(TILESWEEP_FAULT_OLD_ROUNDING_RULE)
        return towardStart;  // deliberate fault: the contract's rule before the amendment
#else
        const FastAxis& m = axis_[axis];
        if (!(exact < m.low)) return towardStart;
        const double rounded = towardStart;
        if (rounded == exact) return towardStart;
        const double size = m.high - m.low;
        if (!m.hasLineIn(exact + size, rounded + size)) return towardStart;
        return roundToFloat(exact, false);
#endif
    }

    std::int32_t listStartOverlaps(Cell* store, std::int32_t capacity) const noexcept {
        const FastAxis& gx = axis_[0];
        const FastAxis& gy = axis_[1];
        const std::int64_t i0 = std::max<std::int64_t>(gx.cellOf(gx.low), 0);
        const std::int64_t i1 = std::min<std::int64_t>(gx.cellOf(gx.high), gx.cells - 1);
        const std::int64_t j0 = std::max<std::int64_t>(gy.cellOf(gy.low), 0);
        const std::int64_t j1 = std::min<std::int64_t>(gy.cellOf(gy.high), gy.cells - 1);
        std::int32_t count = 0;
        for (std::int64_t j = j0; j <= j1; ++j) {
            const std::uint8_t* row = map_.solid + j * map_.columns;
            bool rowChecked = false;
            for (std::int64_t i = i0; i <= i1; ++i) {
                if (row[i] == 0) continue;  // the byte first
                if (!rowChecked) {
                    if (!gy.overlapsAtStart(gy.edge(j), gy.edge(j + 1))) break;
                    rowChecked = true;
                }
                if (!gx.overlapsAtStart(gx.edge(i), gx.edge(i + 1))) continue;
                if (count < capacity) store[count] = {static_cast<std::int32_t>(i), static_cast<std::int32_t>(j)};
                ++count;
            }
        }
        return count;
    }

    std::int64_t firstCellAhead(int axis) const noexcept {
        const FastAxis& g = axis_[axis];
        if (g.dir > 0) return std::max<std::int64_t>(g.cellOf(g.low), 0);
        std::int64_t k = g.cellOf(g.high);
        if (k >= 0 && k < g.cells && g.edge(k) == g.high) --k;
        return std::min<std::int64_t>(k, g.cells - 1);
    }

    double touchPosition(int axis, std::int64_t k) const noexcept {
        const FastAxis& g = axis_[axis];
        return g.dir > 0 ? g.edge(k) - (g.high - g.low) : g.edge(k + 1);
    }

    void sweepBothAxes(Hits& hits) noexcept {
        // The primary axis: products of two floats, exact in double. (Either choice is correct;
        // this one only keeps the walk short.)
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
                              (std::fabs(ms.low) + std::fabs(ms.high) + ms.speed + std::fabs(ms.origin)) * ms.invTile;
        const double slope = ms.disp / mp.speed;  // secondary motion per unit of primary distance
        for (std::int64_t k = firstCellAhead(p); k >= 0 && k < mp.cells; k += mp.dir) {
            const double lo = mp.edge(k);
            const double hi = mp.edge(k + 1);
            const double entry = mp.entryDistance(lo, hi);
            if (entry >= mp.speed) break;  // entered at t >= 1
            // Entered after the hits found so far: a rounded product strictly greater is an
            // exactly greater one (monotonic rounding); on a rounded tie walking on is harmless.
            if (hits.any && entry * hits.time.den > hits.time.num * mp.speed) break;
            const double exit = mp.exitDistance(lo, hi);
            const double t0 = entry < 0 ? 0.0 : entry;
            const double t1 = exit < mp.speed ? exit : mp.speed;
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
        const FastTileTest test = testTileFast(mx, my, mx.edge(i), mx.edge(i + 1), my.edge(j), my.edge(j + 1), refined_);
        Axis axis = Axis::Y;
        switch (test.verdict) {
            case TileVerdict::Misses:
            case TileVerdict::StartsOverlapping: return;
            case TileVerdict::BlocksOnX: axis = Axis::X; break;
            case TileVerdict::BlocksOnY: axis = Axis::Y; break;
            case TileVerdict::Tie: {
                const bool xExposed = !map_.isSolid(i - mx.dir, j);
                const bool yExposed = !map_.isSolid(i, j - my.dir);
                axis = settleTie(xExposed, yExposed);
                break;
            }
        }
        const int a = axis == Axis::X ? 0 : 1;
        add(hits, {static_cast<std::int32_t>(i), static_cast<std::int32_t>(j)}, axis, test.time,
            touchPosition(a, a == 0 ? i : j));
    }

    /// FrameSolver::sweepOneAxis on exact doubles.
    void sweepOneAxis(int axis, double heldLow, double heldHigh, const FastTime& from, Hits& hits) noexcept {
        const FastAxis& ga = axis_[axis];
        const FastAxis& go = axis_[1 - axis];
        const std::int64_t j0 = std::max<std::int64_t>(go.cellOf(heldLow), 0);
        const std::int64_t j1 = std::min<std::int64_t>(go.cellOf(heldHigh), go.cells - 1);
        if (j0 > j1) return;
        for (std::int64_t k = firstCellAhead(axis); k >= 0 && k < ga.cells; k += ga.dir) {
            const double entry = ga.entryDistance(ga.edge(k), ga.edge(k + 1));
            if (entry >= ga.speed) return;  // entered at t >= 1
            const FastTime at{entry, ga.speed};
            if (compareTimes(at, from) < 0) continue;  // overlapping already at `from`
            for (std::int64_t j = j0; j <= j1; ++j) {
                const std::int64_t ci = axis == 0 ? k : j;
                const std::int64_t cj = axis == 0 ? j : k;
                if (!map_.isSolid(ci, cj)) continue;
                if (!(heldLow < go.edge(j + 1) && heldHigh > go.edge(j))) continue;
                add(hits, {static_cast<std::int32_t>(ci), static_cast<std::int32_t>(cj)},
                    axis == 0 ? Axis::X : Axis::Y, at, touchPosition(axis, k));
            }
            if (hits.any) return;
        }
    }

    Normal normalOn(int axis) const noexcept {
        const auto against = static_cast<std::int8_t>(-axis_[axis].dir);
        return axis == 0 ? Normal{against, 0} : Normal{0, against};
    }

    const TileMapView<float>& map_;
    FastAxis axis_[2];
    float start_[2];
    bool refined_ = false;
};

}  // namespace tilesweep::detail

// SPDX-License-Identifier: MIT
#pragma once

#include "tilesweep/resolve.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

// The inexact twin: the move-and-slide a competent game developer writes, in plain T arithmetic,
// as the baseline tilesweep::resolveMove is measured against: exact has to cost no more than
// this. It is NOT exact and is not meant to be: it exists for the benchmarks and
// for counting how often plain arithmetic decides differently (tilesweep_twin_agreement).
//
// What it does, per frame (the contract's loop in spirit, docs/contract.md "One frame through a
// map"):
//   - at most two steps; each finds the earliest time of impact over the cells the step's path
//     covers, takes every tile hit at exactly that time (T equality), snaps the box to the face
//     on each contact axis, zeroes that axis of the remaining motion and slides on;
//   - per tile, the slab method (Ericson, RTCD 5.3.3) with the inverse of the step's displacement:
//     an axis that does not move overlaps at all times or at none; touching is not overlapping
//     (open intervals, entry == exit misses); a tile the box overlaps at the step's start never
//     blocks; the later entry is the contact axis, and an exact tie takes y unless only the x
//     face is exposed;
//   - the broadphase walks cells in path order along the primary axis (the one that crosses more
//     cells) and stops at the first cell entered later than the earliest hit found, as
//     tilesweep's does, but every time and span is a rounded T.
// The final position is the rounded sum p + s*r + (1-s)*r, not the contract's rounding, and the
// free axis after a snap starts from a rounded point, so a box can end an ulp inside a tile; the
// next frame then lets it walk out. No validation: the input is assumed valid (tilesweep's
// resolveMove checks it every frame; a NaN here just propagates). No allocation.
//
// Lean, as a careful game developer writes it, so that the comparison is honest:
//   - a time is a distance times the inverse of the step's displacement, 1 / r per moving axis,
//     computed once per step (the ray/box slab trick): no division per tile or per walked cell;
//   - a coordinate becomes a cell index with one multiplication by the tile size's reciprocal,
//     computed once per map (TileReciprocal; the two-argument overload computes it once per
//     frame), and a floor or ceiling by truncation and a one-step correction, with no libm call.
// Both reciprocals round. Where the tile size is not a power of two a coordinate within an ulp or
// so of a tile edge may land in the neighbouring cell's index; the ranges keep the touching cells
// at both ends, and the slab test decides. A time from the rounded inverse can differ from the
// rounded quotient by an ulp, so the lean twin decides a near tie now and then otherwise than the
// dividing one; neither is exact.
//
// Two heavier twins are kept for one benchmark row each, so that what each trick saves stays
// visible: resolveMoveTwinDividing divides every distance by the displacement (four divisions
// per tile tested, one or two per walked cell), and resolveMoveTwinLibm does that and takes each
// cell index as std::floor or std::ceil of a quotient by the tile size.
//
// The frame loop and the tile test are shared with grid_resolve.h (the swept-bounds
// variant); only the broadphase differs.

namespace tilesweep::baselines {

/// 1 / tile size per axis: what the lean twin multiplies by instead of dividing per cell.
template <class T>
struct TileReciprocal {
    T x;
    T y;
};

/// The reciprocal of `map`'s tile size, once per map (or per frame).
template <class T>
[[nodiscard]] inline TileReciprocal<T> reciprocalOf(const TileMapView<T>& map) noexcept {
    return {T(1) / map.tileSize.x, T(1) / map.tileSize.y};
}

namespace detail {

/// How the twin turns numbers into cells and times (see the header comment):
///   Lean      cell index: (v - origin) * (1 / tile), truncated; time: distance * (1 / r), the
///             inverse taken once per step;
///   Dividing  cell index as Lean; time: distance / r at every use;
///   Libm      cell index: std::floor or std::ceil of (v - origin) / tile; time as Dividing.
enum class Arithmetic { Lean, Dividing, Libm };

/// The times at which a box's projection on one axis overlaps a tile's: the open interval
/// (entry, exit); all times when `ever` and the axis does not move; none when !ever.
template <class T>
struct Slab {
    bool ever;
    T entry;
    T exit;
};

/// One step's geometry, per axis (0 = x, 1 = y), computed once per step.
template <class T, Arithmetic A = Arithmetic::Lean>
struct StepFrame {
    T lo[2];                       ///< box min edge at the step's start
    T hi[2];                       ///< box max edge at the step's start (lo + size, rounded)
    T r[2];                        ///< the step's motion
    T origin[2];                   ///< map origin
    T tile[2];                     ///< tile size
    std::int64_t cells[2];         ///< columns, rows
    T inverseTile[2];              ///< 1 / tile, rounded (the cell indexing's, but Libm's)
    T inverseR[2] = {T(0), T(0)};  ///< 1 / r, rounded, on a moving axis (Lean's times); see startStep

    /// Takes the inverse of the step's motion, once per step (Lean; the others divide).
    void startStep() noexcept {
        if constexpr (A == Arithmetic::Lean)
            for (int a = 0; a < 2; ++a) inverseR[a] = r[a] != T(0) ? T(1) / r[a] : T(0);
    }

    /// The time at which the box has moved `distance` on axis a (r[a] != 0), in T.
    [[nodiscard]] T timeOf(int a, T distance) const noexcept {
        if constexpr (A == Arithmetic::Lean) {
            return distance * inverseR[a];
        } else {
            return distance / r[a];
        }
    }

    /// The times at which the box's span on axis a overlaps [tileLo, tileHi] (the slab).
    [[nodiscard]] Slab<T> slab(int a, T tileLo, T tileHi) const noexcept {
        constexpr T inf = std::numeric_limits<T>::infinity();
        if (r[a] == T(0)) return {lo[a] < tileHi && hi[a] > tileLo, -inf, inf};
        if (r[a] > T(0)) return {true, timeOf(a, tileLo - hi[a]), timeOf(a, tileHi - lo[a])};
        return {true, timeOf(a, tileHi - lo[a]), timeOf(a, tileLo - hi[a])};
    }

    /// floor((v - origin) / tile), clamped to [-1, cells]: the cell holding v on axis a.
    [[nodiscard]] std::int64_t cellOf(int a, T v) const noexcept {
        if constexpr (A == Arithmetic::Libm) {
            const T q = std::floor((v - origin[a]) / tile[a]);
            if (!(q > T(-1))) return -1;
            if (q >= static_cast<T>(cells[a])) return cells[a];
            return static_cast<std::int64_t>(q);
        } else {
            const T q = (v - origin[a]) * inverseTile[a];
            if (!(q > T(-1))) return -1;
            if (q >= static_cast<T>(cells[a])) return cells[a];
            // q in (-1, cells), so the conversion is defined; it truncates toward zero, one
            // above the floor for a negative q that is not a whole number.
            const auto k = static_cast<std::int64_t>(q);
            return static_cast<T>(k) > q ? k - 1 : k;
        }
    }
    /// ceil((v - origin) / tile) - 1, clamped likewise: the lowest cell that v lies in or
    /// touches from above. Used for the low end of a range whose bound is a rounded sum: the
    /// rounding can land such a bound on a tile edge (edges are representable) but not carry it
    /// over, so a range that keeps the touching cells at both ends loses no tile to it.
    [[nodiscard]] std::int64_t cellBefore(int a, T v) const noexcept {
        if constexpr (A == Arithmetic::Libm) {
            const T q = std::ceil((v - origin[a]) / tile[a]) - T(1);
            if (!(q > T(-1))) return -1;
            if (q >= static_cast<T>(cells[a])) return cells[a];
            return static_cast<std::int64_t>(q);
        } else {
            // ceil(q) - 1 > -1 exactly when q > 0, and ceil(q) - 1 >= cells when q > cells.
            const T q = (v - origin[a]) * inverseTile[a];
            if (!(q > T(0))) return -1;
            if (q > static_cast<T>(cells[a])) return cells[a];
            // q in (0, cells]: truncation is the floor, and the ceiling one more unless q is whole.
            const auto k = static_cast<std::int64_t>(q);
            return static_cast<T>(k) < q ? k : k - 1;
        }
    }
    [[nodiscard]] T edge(int a, std::int64_t k) const noexcept {
        return origin[a] + static_cast<T>(k) * tile[a];
    }
};

/// The hits of one step, kept in the caller's buffer: all tiles at the earliest time so far.
template <class T>
struct StepHits {
    Contact<T>* store;
    std::int32_t capacity;
    std::int32_t count = 0;  ///< hits at `time`, stored or not
    bool any = false;
    T time = T(0);  ///< the step's time of impact, fraction of the step
    bool axisHit[2] = {false, false};
    T face[2] = {T(0), T(0)};  ///< the box position touching the hit face, per contact axis

    void add(Cell cell, int axis, Normal normal, T t, T touch) noexcept {
        if (any) {
            if (t > time) return;
            if (t < time) {
                count = 0;
                axisHit[0] = axisHit[1] = false;
            }
        }
        any = true;
        time = t;
        if (!axisHit[axis]) face[axis] = touch;
        axisHit[axis] = true;
        if (count < capacity) store[count] = {cell, normal, t, {}};  // the twin places no contact
        ++count;
    }
};

/// Tests solid tile (i, j) against the step and records a hit. The slab method; see the header.
template <class T, Arithmetic A>
inline void testTile(const TileMapView<T>& map, const StepFrame<T, A>& f, std::int64_t i, std::int64_t j,
                     StepHits<T>& hits) noexcept {
    const T x0 = f.edge(0, i), x1 = f.edge(0, i + 1);
    const T y0 = f.edge(1, j), y1 = f.edge(1, j + 1);
    // A tile the box overlaps at the step's start never blocks.
    if (f.lo[0] < x1 && f.hi[0] > x0 && f.lo[1] < y1 && f.hi[1] > y0) return;
    const Slab<T> sx = f.slab(0, x0, x1);
    if (!sx.ever) return;
    const Slab<T> sy = f.slab(1, y0, y1);
    if (!sy.ever) return;
    const T entry = std::max(sx.entry, sy.entry);
    const T exit = std::min(sx.exit, sy.exit);
    // Open intervals: entry == exit is a corner touch, not a hit.
    if (!(entry < exit) || !(entry < T(1)) || !(exit > T(0))) return;
    int axis = 1;
    if (sx.entry > sy.entry) {
        axis = 0;
    } else if (sx.entry == sy.entry) {
        const std::int64_t sxDir = f.r[0] > T(0) ? 1 : -1;
        const std::int64_t syDir = f.r[1] > T(0) ? 1 : -1;
        const bool xExposed = !map.isSolid(i - sxDir, j);
        const bool yExposed = !map.isSolid(i, j - syDir);
        axis = xExposed && !yExposed ? 0 : 1;
    }
    const T size = f.hi[axis] - f.lo[axis];
    const T lo = axis == 0 ? x0 : y0;
    const T hi = axis == 0 ? x1 : y1;
    const bool forward = f.r[axis] > T(0);
    const auto against = static_cast<std::int8_t>(forward ? -1 : 1);
    const Normal normal = axis == 0 ? Normal{against, 0} : Normal{0, against};
    hits.add({static_cast<std::int32_t>(i), static_cast<std::int32_t>(j)}, axis, normal,
             std::max(entry, T(0)), forward ? lo - size : hi);
}

/// Solid cells the box overlaps (open) at the frame's start, by row then column.
template <class T, Arithmetic A>
inline std::int32_t listStartOverlaps(const TileMapView<T>& map, const StepFrame<T, A>& f, Cell* store,
                                      std::int32_t capacity) noexcept {
    const std::int64_t i0 = std::max<std::int64_t>(f.cellOf(0, f.lo[0]), 0);
    const std::int64_t i1 = std::min<std::int64_t>(f.cellOf(0, f.hi[0]), f.cells[0] - 1);
    const std::int64_t j0 = std::max<std::int64_t>(f.cellOf(1, f.lo[1]), 0);
    const std::int64_t j1 = std::min<std::int64_t>(f.cellOf(1, f.hi[1]), f.cells[1] - 1);
    std::int32_t count = 0;
    for (std::int64_t j = j0; j <= j1; ++j)
        for (std::int64_t i = i0; i <= i1; ++i) {
            if (!map.isSolid(i, j)) continue;
            if (!(f.lo[0] < f.edge(0, i + 1) && f.hi[0] > f.edge(0, i) && f.lo[1] < f.edge(1, j + 1) &&
                  f.hi[1] > f.edge(1, j)))
                continue;
            if (count < capacity) store[count] = {static_cast<std::int32_t>(i), static_cast<std::int32_t>(j)};
            ++count;
        }
    return count;
}

/// The frame loop (at most two steps), with the broadphase `findHits(map, frame, hits)`.
template <class T, Arithmetic A, class FindHits>
[[nodiscard]] inline ResolveResult<T> resolveFrame(const ResolveInput<T>& in, const ResolveOutput<T>& out,
                                                   TileReciprocal<T> reciprocal, FindHits findHits) noexcept {
    const TileMapView<T>& map = in.map;
    StepFrame<T, A> f{{in.box.pos.x, in.box.pos.y},
                      {in.box.pos.x + in.box.size.x, in.box.pos.y + in.box.size.y},
                      {in.displacement.x, in.displacement.y},
                      {map.origin.x, map.origin.y},
                      {map.tileSize.x, map.tileSize.y},
                      {map.columns, map.rows},
                      {reciprocal.x, reciprocal.y}};
    const T size[2] = {in.box.size.x, in.box.size.y};
    ResolveResult<T> result;
    result.status = ResolveStatus::Moved;
    result.startOverlapCount = listStartOverlaps(map, f, out.startOverlaps, out.startOverlapCapacity);
    std::int32_t used = 0;
    std::int32_t total = 0;
    T elapsed = T(0);  // frame time at the step's start
    for (int step = 0; step < 2; ++step) {
        if (f.r[0] == T(0) && f.r[1] == T(0)) break;
        StepHits<T> hits{out.contacts + used, std::max<std::int32_t>(out.contactCapacity - used, 0)};
        f.startStep();
        findHits(map, f, hits);
        if (!hits.any) {
            f.lo[0] += f.r[0];
            f.lo[1] += f.r[1];
            f.r[0] = f.r[1] = T(0);
            break;
        }
        const T s = hits.time;
        const T frameTime = elapsed + (T(1) - elapsed) * s;
        const std::int32_t stored = std::min(hits.count, hits.capacity);
        for (std::int32_t k = 0; k < stored; ++k) hits.store[k].time = frameTime;
        // Within a step, by row then column (insertion sort: a step has a handful of hits).
        for (std::int32_t k = 1; k < stored; ++k)
            for (std::int32_t m = k; m > 0; --m) {
                const Cell a = hits.store[m - 1].tile, b = hits.store[m].tile;
                if (a.j < b.j || (a.j == b.j && a.i <= b.i)) break;
                std::swap(hits.store[m - 1], hits.store[m]);
            }
        used += stored;
        total += hits.count;
        for (int a = 0; a < 2; ++a) {
            if (hits.axisHit[a]) {
                f.lo[a] = hits.face[a];
                f.r[a] = T(0);
            } else {
                f.lo[a] += s * f.r[a];
                f.r[a] *= T(1) - s;
            }
            f.hi[a] = f.lo[a] + size[a];
        }
        elapsed = frameTime;
    }
    // A second step that was not resolved (two contacts already) leaves its motion unapplied.
    result.position = {f.lo[0], f.lo[1]};
    result.contactCount = total;
    if (total > 0) result.status = ResolveStatus::Blocked;
    return result;
}

/// The twin's broadphase: cells in path order along the primary axis, with the early exit.
struct FindHitsInPathOrder {
    template <class T, Arithmetic A>
    void operator()(const TileMapView<T>& map, const StepFrame<T, A>& f, StepHits<T>& hits) const noexcept {
        // Primary: the axis whose motion crosses more cells, |r_x| / tile_x >= |r_y| / tile_y.
        const int p = std::abs(f.r[0]) * f.tile[1] >= std::abs(f.r[1]) * f.tile[0] ? 0 : 1;
        const int s = 1 - p;
        const T rp = f.r[p];
        const bool forward = rp > T(0);
        // From the cell holding the trailing edge to the one holding the leading edge at the end.
        std::int64_t k = forward ? f.cellBefore(p, f.lo[p]) : f.cellOf(p, f.hi[p]);
        std::int64_t last = forward ? f.cellOf(p, f.hi[p] + rp) : f.cellBefore(p, f.lo[p] + rp);
        const std::int64_t dir = forward ? 1 : -1;
        if (forward) {
            k = std::max<std::int64_t>(k, 0);
            last = std::min<std::int64_t>(last, f.cells[p] - 1);
        } else {
            k = std::min<std::int64_t>(k, f.cells[p] - 1);
            last = std::max<std::int64_t>(last, 0);
        }
        for (; forward ? k <= last : k >= last; k += dir) {
            const T lo = f.edge(p, k);
            const T hi = f.edge(p, k + 1);
            // The box is inside this primary cell for t in (enter, leave), clamped to [0, 1].
            T enter = f.timeOf(p, forward ? lo - f.hi[p] : hi - f.lo[p]);
            T leave = f.timeOf(p, forward ? hi - f.lo[p] : lo - f.hi[p]);
            enter = std::max(enter, T(0));
            leave = std::min(leave, T(1));
            if (enter >= T(1)) break;
            if (hits.any && enter > hits.time) break;  // later than the earliest hit: done
            // The secondary span over that window.
            const T a = f.r[s] * enter;
            const T b = f.r[s] * leave;
            const std::int64_t j0 = std::max<std::int64_t>(f.cellBefore(s, f.lo[s] + std::min(a, b)), 0);
            const std::int64_t j1 =
                std::min<std::int64_t>(f.cellOf(s, f.hi[s] + std::max(a, b)), f.cells[s] - 1);
            for (std::int64_t j = j0; j <= j1; ++j) {
                const std::int64_t ci = p == 0 ? k : j;
                const std::int64_t cj = p == 0 ? j : k;
                if (map.isSolid(ci, cj)) testTile(map, f, ci, cj, hits);
            }
        }
    }
};

}  // namespace detail

/// Resolves one frame the inexact way (see the header comment), with the reciprocal of the
/// map's tile size computed once per map by the caller (reciprocalOf). Contacts step by step,
/// within a step by row then column; a count above capacity means truncated. Input assumed valid.
template <class T>
[[nodiscard]] inline ResolveResult<T> resolveMoveTwin(const ResolveInput<T>& input,
                                                      const ResolveOutput<T>& output,
                                                      TileReciprocal<T> reciprocal) noexcept {
    return detail::resolveFrame<T, detail::Arithmetic::Lean>(input, output, reciprocal,
                                                             detail::FindHitsInPathOrder{});
}

/// As above, the reciprocal computed for this frame: the same signature shape as
/// tilesweep::resolveMove, so it can be swapped in.
template <class T>
[[nodiscard]] inline ResolveResult<T> resolveMoveTwin(const ResolveInput<T>& input,
                                                      const ResolveOutput<T>& output) noexcept {
    return resolveMoveTwin(input, output, reciprocalOf(input.map));
}

/// The twin that divides by the displacement wherever it needs a time (four divisions per tile
/// tested), kept for one benchmark row (BM_TwinDividing_*); otherwise as resolveMoveTwin.
template <class T>
[[nodiscard]] inline ResolveResult<T> resolveMoveTwinDividing(const ResolveInput<T>& input,
                                                              const ResolveOutput<T>& output,
                                                              TileReciprocal<T> reciprocal) noexcept {
    return detail::resolveFrame<T, detail::Arithmetic::Dividing>(input, output, reciprocal,
                                                                 detail::FindHitsInPathOrder{});
}

/// The first twin, kept for one benchmark row (BM_TwinLibm_*): as resolveMoveTwinDividing, with
/// every cell index a std::floor or std::ceil of a quotient by the tile size (a division and a
/// libm call per cell on the x86-64 baseline). It decides as resolveMoveTwinDividing does
/// wherever the tile size is a power of two.
template <class T>
[[nodiscard]] inline ResolveResult<T> resolveMoveTwinLibm(const ResolveInput<T>& input,
                                                          const ResolveOutput<T>& output) noexcept {
    return detail::resolveFrame<T, detail::Arithmetic::Libm>(input, output, TileReciprocal<T>{T(0), T(0)},
                                                             detail::FindHitsInPathOrder{});
}

}  // namespace tilesweep::baselines

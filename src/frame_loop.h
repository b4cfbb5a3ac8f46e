// SPDX-License-Identifier: MIT
#pragma once

// The contract's frame loop ("One frame through a map", docs/contract.md), written once for every
// arithmetic the resolver uses: the exact lattice integers (lattice_frame.h), and the exact
// doubles or exact pairs of the fast path (fast_frame.h), which may answer "undecided", so that
// the frame falls back to the lattice.
//
// Structure. The contract's loop runs at most two steps, and the second is always a one-axis
// move: after the first contact at time s, the motion on the contact axes is zeroed; if both
// were contact axes nothing moves, otherwise only the free axis moves on, from where it was at
// s, while the contact axis stays exactly touching. In the frame's own time the free axis is
// still moving at its original speed, so a tile blocks the second step iff it overlaps the
// (static) contact-axis span and its entry time on the free axis lies in [s, 1); its frame time
// is that entry time. Solving step 2 in frame time avoids the rational position at s altogether.
//
// Broadphase. Candidate tiles come from the grid, never from a scan of the map. A short move
// lists the solid cells of its swept bounds once (at most kNearArea cells, or up to kSparseArea
// with few solid ones), and those serve the start overlaps and both steps. Otherwise the walk
// goes along the primary axis (the one whose motion crosses more cells), cell by cell in the
// order the box enters them; for each primary cell it takes the secondary cells the box's span
// covers while it is inside that primary cell, and it stops at the first primary cell entered
// after the earliest time of impact found so far, or at time 1. Cells entered at exactly that
// time are still visited: they may be hit at the same time, and the contract takes all of them
// at once. The cost is the number of cells the path touches, independent of the map's size.
// Cell ranges may be supersets (the fast path estimates them with a certified margin): every
// cell in them gets the exact tile test.
//
// One-way tiles (docs/contract.md, "One-way tiles"). They can block only when the box moves down,
// so such a frame, on a map that has them (oneWayCellsMayBlock, frame_solve.h), runs on
// FrameLoop<Arith, true> (kOneWayDown), and every other frame on the loop compiled without a test
// of them: the caller chooses before it builds the frame's arithmetic. They block only on y: in
// step 1 when the tile test says BlocksOnY or Tie (testOneWayAndRecord), in a step 2 sliding down
// exactly as a solid tile would, and never in a move or slide along x. Otherwise they are empty
// cells: start overlaps, the exposed-face rule and every other read of `solid` ignore them.
//
// What an arithmetic `Arith` provides (LatticeFrame, FastFrame):
//   types   Scalar (float or double), Coord (a box coordinate or a distance), Edge (a tile
//           edge), Time (a ratio {Coord num, Speed den}), Motion (one axis of the box's
//           motion: dir, speed, entryDistance, exitDistance, overlapsAtStart, and what the
//           walks read first, walkEntry, walkExit and enteredByEnd; axis_sweep.h, fast_axis.h),
//           Walk (what the walk's secondary range needs, computed once a frame)
//   grid    axis(a) (the Motion), edge(a, k), nextEdge(a, e) (the edge one tile from e along
//           the motion on a, exactly), cells(a), cellOf(a, c) and nearEdgeCell(a) (the cell of a
//           coordinate, of the box's low edge at the start: exact, clamped to [-1, cells]),
//           startCells(a), sweptCells(a) and sweptCellsOfBoth(ranges) (supersets), map()
//   times   zeroTime(), compareTimes(a, b), certainlyLater(a, b) (a > b for certain; false may
//           be a tie), firstCellNotBefore(a, t) (an estimate of the first cell along a entered
//           at or after t, checked exactly by its user)
//   walk    primaryAxis(), prepareWalk(p), secondaryCells(walk, entry, exit)
//   box     start(a), nearEdge(a), farEdge(a), endOf(a), touchLow(a, e), touchHigh(a, e)
//   tile    testTile(i, j) (axis_sweep.h's test on its numbers)
//   result  roundTime(time, out), positionAt(a, time, frameTime, out) (the box's coordinate on
//           `a` at that time, rounded to nearest; frameTime is roundTime's result for it),
//           roundEndsTogether(x, y, outX, outY) (both final coordinates at once, or false), and for
//           roundFinal (final_rounding.h): false = undecided.

#include "axis_sweep.h"
#include "cell_range.h"
#include "fault_injection.h"
#include "final_rounding.h"
#include "proof_constants.h"

#include "tilesweep/resolve.h"

#include <algorithm>
#include <cassert>
#include <cstdint>

namespace tilesweep::detail {

// The small steps of the loop (add, firstCellAhead, the overlap and edge helpers) are always
// inlined (gnu::always_inline; other compilers ignore it): one loop over two arithmetics runs as
// fast as a solver of each arithmetic's own would (bench/).
template <class Arith, bool kOneWayDown = false>
class FrameLoop {
public:
    using T = typename Arith::Scalar;
    using Coord = typename Arith::Coord;
    using Edge = typename Arith::Edge;
    using Time = typename Arith::Time;

    explicit FrameLoop(Arith& arith) noexcept : m_(arith) {}

    /// Solves the frame into `result`; false when the arithmetic could not decide something
    /// (the caller then solves the frame on the lattice). `placeContactPositions` false leaves
    /// the stored contacts' positions unwritten (frame_solve.h, ContactPositions).
    bool run(const ResolveOutput<T>& out, ResolveResult<T>& result, bool placeContactPositions) noexcept {
        // A short move: the solid cells of the swept bounds, listed once, serve the start
        // overlaps and both steps (collectNear); otherwise the walk.
        const bool nearOnly = collectNear();
        const bool bothMove = m_.axis(0).dir != 0 && m_.axis(1).dir != 0;
        Hits first{out.contacts, std::max<std::int32_t>(out.contactCapacity, 0)};
        if (nearOnly && bothMove) {
            result.startOverlapCount = testNear(out.startOverlaps, out.startOverlapCapacity, first);
        } else {
            result.startOverlapCount = nearOnly
                                           ? startOverlapsOfNear(out.startOverlaps, out.startOverlapCapacity)
                                           : listStartOverlaps(out.startOverlaps, out.startOverlapCapacity);
        }
        result.position = {m_.start(0), m_.start(1)};
        if (m_.axis(0).dir == 0 && m_.axis(1).dir == 0) {
            result.status = ResolveStatus::Moved;
            return true;
        }
        Coord finalPos[2] = {m_.endOf(0), m_.endOf(1)};
        if (bothMove) {
            if (!nearOnly) sweepBothAxes(first);
        } else {
            const int a = m_.axis(0).dir != 0 ? 0 : 1;
            sweepOneAxis(a, m_.nearEdge(1 - a), m_.farEdge(1 - a), m_.zeroTime(), nearOnly, first);
        }
        std::int32_t total = 0;
        bool slides = false;  // step 1 hit one axis and the box moves on along the other
        if (first.any) {
            if (!finishStep(first)) return false;
            total = first.count;
            result.blockedX = first.axisHit[0];
            result.blockedY = first.axisHit[1];
            for (int a = 0; a < 2; ++a)
                if (first.axisHit[a]) finalPos[a] = m_.touchLow(a, first.touch[a]);
            const int free = first.axisHit[0] ? 1 : 0;
            // Step 2 of a short move tests the listed cells, and a cell hit in step 1 cannot
            // block it (slideMeetsOnlyStepOneHits): when step 1 hit every listed cell, the slide
            // is decided without a test.
            slides = first.axisHit[0] != first.axisHit[1] && m_.axis(free).dir != 0;
            if (slides && !(nearOnly && slideMeetsOnlyStepOneHits(first))) {
                const int held = 1 - free;
                const std::int32_t used = std::min(first.count, first.capacity);
                Hits second{out.contacts + used, first.capacity - used};
                sweepOneAxis(free, m_.touchLow(held, first.touch[held]),
                             m_.touchHigh(held, first.touch[held]), first.time, nearOnly, second);
                if (second.any) {
                    if (!finishStep(second)) return false;
                    total += second.count;
                    finalPos[free] = m_.touchLow(free, second.touch[free]);
                    (free == 0 ? result.blockedX : result.blockedY) = true;  // step 2 moves on `free` alone
                }
            }
        }
        result.contactCount = total;
        result.status = total > 0 ? ResolveStatus::Blocked : ResolveStatus::Moved;
        return roundEnds(finalPos, result.position) &&
               (!placeContactPositions || placeContacts(out, first, slides, result));
    }

private:
    /// The hits of one step: all tiles at the earliest time of impact found so far. `touch` is
    /// the tile edge the box touches on each contact axis.
    struct Hits {
        Contact<T>* store;       ///< caller's buffer, from the first slot this step may use
        std::int32_t capacity;   ///< slots available from `store`
        std::int32_t count = 0;  ///< hits at `time`, stored or not
        bool any = false;
        Time time{};
        bool axisHit[2] = {false, false};
        Edge touch[2]{};
    };

    /// Records a hit at `t`; a hit earlier than the current ones replaces them all. The frame
    /// time is filled in when the step ends.
    [[gnu::always_inline]] void add(Hits& hits, Cell cell, int a, const Time& t,
                                    const Edge& touchEdge) noexcept {
        if (hits.any) {
            const int order = m_.compareTimes(t, hits.time);
            if (order > 0) return;
            if (order < 0) {
                hits.count = 0;
                hits.axisHit[0] = hits.axisHit[1] = false;
            }
        }
        hits.any = true;
        hits.time = t;
        hits.axisHit[a] = true;
        hits.touch[a] = touchEdge;
        if (hits.count < hits.capacity) hits.store[hits.count] = {cell, normalOn(a), T(0), {}};
        ++hits.count;
    }

    /// Whether step 1 of a short move hit every listed cell (collectNear), so that its slide
    /// meets none: each listed cell was tested (testNear) and blocked at the step's time, every
    /// one on the held axis (the step slides, so it hit one axis), where the box then touches the
    /// tile's face; step 2 keeps that axis's span, and a touch is no overlap (heldOverlaps), so
    /// none of them blocks it. `count` counts every hit, stored or not.
    [[gnu::always_inline]] bool slideMeetsOnlyStepOneHits(const Hits& first) const noexcept {
#if defined(TILESWEEP_FAULT_SLIDE_SKIP_ONE_SHORT)
        return first.count + 1 >= nearCount_;  // deliberate fault: a listed cell left untested in step 2
#else
        return first.count == nearCount_;
#endif
    }

    /// The final rounding of both ends (final_rounding.h): at once where the arithmetic can
    /// (roundEndsTogether), otherwise axis by axis; false when it is undecided.
    [[gnu::always_inline]] bool roundEnds(const Coord (&ends)[2], Vec2<T>& out) noexcept {
        if (m_.roundEndsTogether(ends[0], ends[1], out.x, out.y)) return true;
        return roundFinal(m_, ends[0], 0, out.x) && roundFinal(m_, ends[1], 1, out.y);
    }

    /// Sorts a step's stored hits by row, then column, and writes its frame time (the same for
    /// every hit of the step); false when the time's rounding is undecided. A step that stores
    /// no hit rounds its time too: a test to skip the rounding costs a walk's frames more
    /// instructions than it saves a batch's (scripts/instructions.sh).
    bool finishStep(Hits& hits) noexcept {
        const std::int32_t stored = std::min(hits.count, hits.capacity);
        T time = 0;
        if (!m_.roundTime(hits.time, time)) return false;
        for (std::int32_t k = 0; k < stored; ++k) hits.store[k].time = time;
        if (stored > 1)
            std::sort(hits.store, hits.store + stored, [](const Contact<T>& a, const Contact<T>& b) {
                return a.tile.j != b.tile.j ? a.tile.j < b.tile.j : a.tile.i < b.tile.i;
            });
        return true;
    }

    /// Writes the position of every stored contact (Contact::position): the final position,
    /// except on the free axis of step-1 contacts the box slides on from: there the box was at
    /// start + s * displacement at the contact time s, rounded to nearest (the arithmetic's
    /// positionAt). On every other axis the box does not move after the contact, so its
    /// coordinate then is the final one. Costs nothing when no contact is stored; false when the
    /// arithmetic could not settle the free coordinate.
    bool placeContacts(const ResolveOutput<T>& out, const Hits& first, bool slides,
                       const ResolveResult<T>& result) noexcept {
        if (result.contactCount == 0 || out.contactCapacity <= 0) return true;
        const std::int32_t stored = std::min(result.contactCount, out.contactCapacity);
        for (std::int32_t k = 0; k < stored; ++k) out.contacts[k].position = result.position;
        const std::int32_t storedFirst = std::min(first.count, first.capacity);
        if (!slides || storedFirst == 0) return true;
        const int free = first.axisHit[0] ? 1 : 0;
        T at = 0;
        if (!m_.positionAt(free, first.time, first.store[0].time, at)) return false;  // finishStep's time
        for (std::int32_t k = 0; k < storedFirst; ++k)
            (free == 0 ? first.store[k].position.x : first.store[k].position.y) = at;
        return true;
    }

    /// The normal of a hit on `a`: against the motion, (-sign(r_x), 0) or (0, -sign(r_y)).
    [[gnu::always_inline]] Normal normalOn(int a) const noexcept {
        const auto against = static_cast<std::int8_t>(-m_.axis(a).dir);
        return a == 0 ? Normal{against, 0} : Normal{0, against};
    }

    /// The tile edge the box touches when it hits cell k on `a`.
    [[gnu::always_inline]] Edge touchEdge(int a, std::int64_t k) const noexcept {
        return m_.axis(a).dir > 0 ? m_.edge(a, k) : m_.edge(a, k + 1);
    }

    /// Whether the box's span on `a` at t = 0 overlaps (open) cell k's.
    [[gnu::always_inline]] bool overlapsCellAtStart(int a, std::int64_t k) const noexcept {
        return m_.axis(a).overlapsAtStart(m_.edge(a, k), m_.edge(a, k + 1));
    }

    /// Solid cells the box overlaps (open) at the start, by row then column (one-way cells are
    /// never listed; their bytes are in `oneWay`, not here): a solid byte in the
    /// candidate range is the only thing that costs an exact test.
    std::int32_t listStartOverlaps(Cell* store, std::int32_t capacity) const noexcept {
        const CellRange cx = m_.startCells(0);
        const CellRange cy = m_.startCells(1);
        const TileMapView<T>& map = m_.map();
        std::int32_t count = 0;
        for (std::int64_t j = cy.first; j <= cy.last; ++j) {
            const std::uint8_t* row = map.solid + j * map.columns;
            bool rowChecked = false;
            for (std::int64_t i = cx.first; i <= cx.last; ++i) {
                if (row[i] == 0) continue;  // the byte first
                if (!rowChecked) {
                    if (!overlapsCellAtStart(1, j)) break;
                    rowChecked = true;
                }
                if (!overlapsCellAtStart(0, i)) continue;
                if (count < capacity)
                    store[count] = {static_cast<std::int32_t>(i), static_cast<std::int32_t>(j)};
                ++count;
            }
        }
        return count;
    }

    /// First cell along `a` (in the direction of motion) whose far side the trailing edge has
    /// not passed at t = 0, clamped into the map; -1 or cells when no map cell qualifies.
    [[gnu::always_inline]] std::int64_t firstCellAhead(int a) const noexcept {
        if (m_.axis(a).dir > 0) return std::max<std::int64_t>(m_.nearEdgeCell(a), 0);
        // Largest k with edge(k) < the far edge.
        std::int64_t k = m_.cellOf(a, m_.farEdge(a));
        if (k >= 0 && k < m_.cells(a) && compare(m_.farEdge(a), m_.edge(a, k)) == 0) --k;
        return std::min<std::int64_t>(k, m_.cells(a) - 1);
    }

    /// Moves [lo, hi], the edges of a cell on `a`, to the next cell along the motion. One exact
    /// operation (the arithmetic's nextEdge): every tile edge the frame forms is exact, so the
    /// edge a tile past another is the sum of that edge and the tile size, exactly.
    [[gnu::always_inline]] void stepEdges(int a, Edge& lo, Edge& hi) const noexcept {
        if (m_.axis(a).dir > 0) {
            lo = hi;
            hi = m_.nextEdge(a, hi);
        } else {
            hi = lo;
            lo = m_.nextEdge(a, lo);
        }
    }

    /// Step 1 when both axes move: walk the primary axis in time order.
    void sweepBothAxes(Hits& hits) noexcept {
        if (m_.primaryAxis() == 0) {
            sweepBothAxesAlong<0>(hits);
        } else {
            sweepBothAxesAlong<1>(hits);
        }
    }

    /// sweepBothAxes along primary axis `p`, a constant, so that the cells' indices and the
    /// axes' fields take no choice between the axes (as sweepOneAxisAlong does): a walk then
    /// runs fewer instructions a cell (scripts/instructions.sh, FloorAndWalls).
    template <int p>
    void sweepBothAxesAlong(Hits& hits) noexcept {
        const auto& mp = m_.axis(p);
        const auto walk = m_.prepareWalk(p);
        std::int64_t k = firstCellAhead(p);
        Edge lo = m_.edge(p, k);
        Edge hi = m_.edge(p, k + 1);
        for (; k >= 0 && k < m_.cells(p); k += mp.dir, stepEdges(p, lo, hi)) {
            // The walk's distances (the Motion's walkEntry: on double frames the pairs' high
            // parts), the exact entry only once a hit is found.
            const auto entry = mp.walkEntry(lo, hi);
            if (mp.enteredByEnd(entry, lo, hi)) break;  // entered at t >= 1
            // Entered after the hits found so far; on a near tie walking on is harmless.
            if (hits.any && m_.certainlyLater(Time{mp.entryDistance(lo, hi), mp.speed}, hits.time)) break;
            const CellRange range = secondaryCandidates(m_.secondaryCells(walk, entry, mp.walkExit(lo, hi)));
            for (std::int64_t j = range.first; j <= range.last; ++j) {
                const std::int64_t ci = p == 0 ? k : j;
                const std::int64_t cj = p == 0 ? j : k;
                if (solidInMap(ci, cj)) {
                    testAndRecord(ci, cj, hits);
                } else if (kOneWayDown && oneWayInMap(ci, cj)) {
                    testOneWayAndRecord(ci, cj, hits);
                }
            }
        }
    }

    /// Whether cell (i, j), which lies in the map, is solid: TileMapView::isSolid without its
    /// bounds checks. The walks' cells are in the map by construction: the primary index runs in
    /// [0, cells), and a cell range (estimateCells, cell_range.h; cellOf clamped) lies in [0,
    /// cells - 1] whenever it is not empty.
    [[gnu::always_inline]] bool solidInMap(std::int64_t i, std::int64_t j) const noexcept {
        const TileMapView<T>& map = m_.map();
        assert(i >= 0 && i < map.columns && j >= 0 && j < map.rows);
        return map.solid[j * map.columns + i] != 0;
    }

    /// Whether cell (i, j), which lies in the map and is not solid, is one-way; only asked when
    /// kOneWayDown (so the map has a `oneWay` layer).
    [[gnu::always_inline]] bool oneWayInMap(std::int64_t i, std::int64_t j) const noexcept {
        const TileMapView<T>& map = m_.map();
        assert(kOneWayDown && !solidInMap(i, j));
        return map.oneWay[j * map.columns + i] != 0;
    }

    /// Whether a one-way cell can block a move along `a` alone: only one along y, moving down.
    template <int a>
    [[gnu::always_inline]] bool oneWayBlocksAlong() const noexcept {
        return a == 1 && kOneWayDown;
    }

    /// The secondary cells the broadphase tests: those of the walk's secondary range, or the rows
    /// of the swept bounds.
    static CellRange secondaryCandidates(CellRange range) noexcept {
#if defined(TILESWEEP_FAULT_BROADPHASE_SHORT)
        --range.last;  // deliberate fault: the broadphase's secondary range one cell short
#endif
        return range;
    }

    /// Tests tile (i, j) and records it when it blocks; true when the box overlaps it at the start.
    bool testAndRecord(std::int64_t i, std::int64_t j, Hits& hits) noexcept {
        const auto test = m_.testTile(i, j);
        Axis axis = Axis::Y;
        switch (test.verdict) {
            case TileVerdict::Misses:
                return false;
            case TileVerdict::StartsOverlapping:
                return true;  // the box overlaps the tile at t = 0
            case TileVerdict::BlocksOnX:
                axis = Axis::X;
                break;
            case TileVerdict::BlocksOnY:
                axis = Axis::Y;
                break;
            case TileVerdict::Tie: {
                // The cell across the face approached on each axis.
                const bool xExposed = !m_.map().isSolid(i - m_.axis(0).dir, j);
                const bool yExposed = !m_.map().isSolid(i, j - m_.axis(1).dir);
                axis = settleTie(xExposed, yExposed);
                break;
            }
        }
        const int a = axis == Axis::X ? 0 : 1;
        add(hits, {static_cast<std::int32_t>(i), static_cast<std::int32_t>(j)}, a, test.time,
            touchEdge(a, a == 0 ? i : j));
        return false;
    }

    /// Tests one-way tile (i, j) in a step 1 moving down (kOneWayDown) and records it when it
    /// blocks: the contract's rule for one-way tiles, stated once. It blocks on its top face
    /// alone, at entry_y, when the box's bottom is at or above the tile's top at the start and the
    /// box reaches the top while it overlaps the tile on x, or exactly as it starts to
    /// (entry_y >= entry_x). That is the tile test's BlocksOnY, or its Tie (a corner landing
    /// blocks on y): either means 0 <= entry_y < 1, entry_y >= entry_x and I meets (0, 1)
    /// (axis_sweep.h), and with r_y > 0, entry_y >= 0 is bottom <= top. Every other verdict is
    /// no block: BlocksOnX is an entry through a side, StartsOverlapping a box already inside.
    void testOneWayAndRecord(std::int64_t i, std::int64_t j, Hits& hits) noexcept {
        const auto test = m_.testTile(i, j);
#if defined(TILESWEEP_FAULT_ONE_WAY_SIDE_BLOCKS)
        if (test.verdict == TileVerdict::BlocksOnX) {  // deliberate fault: a side entry blocks on x
            add(hits, {static_cast<std::int32_t>(i), static_cast<std::int32_t>(j)}, 0, test.time,
                touchEdge(0, i));
            return;
        }
#endif
#if defined(TILESWEEP_FAULT_ONE_WAY_TIE_ON_X)
        if (test.verdict == TileVerdict::Tie) {  // deliberate fault: a corner landing blocks on x
            add(hits, {static_cast<std::int32_t>(i), static_cast<std::int32_t>(j)}, 0, test.time,
                touchEdge(0, i));
            return;
        }
#endif
        if (test.verdict != TileVerdict::BlocksOnY && test.verdict != TileVerdict::Tie) return;
        add(hits, {static_cast<std::int32_t>(i), static_cast<std::int32_t>(j)}, 1, test.time,
            touchEdge(1, j));
    }

    /// Whether the held span [heldLow, heldHigh] on axis `o` overlaps (open) cell k's span;
    /// touching is not overlapping.
    [[gnu::always_inline]] bool heldOverlaps(int o, const Coord& heldLow, const Coord& heldHigh,
                                             std::int64_t k) const noexcept {
        return overlapsOpen([&] { return compare(heldLow, m_.edge(o, k + 1)); },
                            [&] { return compare(heldHigh, m_.edge(o, k)); });
    }

    /// A move along `a` alone while the other axis stays at [heldLow, heldHigh]: step 1 with a
    /// static axis (from = 0), or step 2 (from = s). Only tiles entered in [from, 1) block; they
    /// are found in the first cell along `a` that has any (entry times grow strictly along the
    /// motion), and all share its time.
    [[gnu::always_inline]] void sweepOneAxis(int a, const Coord& heldLow, const Coord& heldHigh,
                                             const Time& from, bool nearOnly, Hits& hits) noexcept {
        if (a == 0) {
            sweepOneAxisAlong<0>(heldLow, heldHigh, from, nearOnly, hits);
        } else {
            sweepOneAxisAlong<1>(heldLow, heldHigh, from, nearOnly, hits);
        }
    }

    /// sweepOneAxis along `a`, a constant (as sweepBothAxesAlong).
    template <int a>
    void sweepOneAxisAlong(const Coord& heldLow, const Coord& heldHigh, const Time& from, bool nearOnly,
                           Hits& hits) noexcept {
        if (nearOnly) {
            sweepOneAxisNear<a>(heldLow, heldHigh, from, hits);
        } else {
            walkOneAxis<a>(heldLow, heldHigh, from, hits);
        }
    }

    /// sweepOneAxis over the listed cells (collectNear): the earliest of them entered in
    /// [from, 1) whose span meets the held one.
    template <int a>
    void sweepOneAxisNear(Coord heldLow, Coord heldHigh, const Time& from, Hits& hits) noexcept {
        const int o = 1 - a;
        const auto& ma = m_.axis(a);
        for (std::int32_t n = 0; n < nearCount_; ++n) {
            const std::int64_t k = a == 0 ? near_[n].i : near_[n].j;
            // A listed one-way cell (kOneWayDown) blocks a slide down as a solid tile does: with x
            // held, entry_x is minus infinity, and an entry in [from, 1) is a bottom at or above
            // the top at the step's start. It never blocks a move along x.
            if (!oneWayBlocksAlong<a>() && kOneWayDown && !solidInMap(near_[n].i, near_[n].j)) continue;
            if (!heldOverlaps(o, heldLow, heldHigh, a == 0 ? near_[n].j : near_[n].i)) continue;
            const Coord entry = ma.entryDistance(m_.edge(a, k), m_.edge(a, k + 1));
            if (compare(entry, ma.speed) >= 0) continue;  // entered at t >= 1
            const Time at{entry, ma.speed};
            if (m_.compareTimes(at, from) < 0) continue;  // overlapping already at `from`
            add(hits, near_[n], a, at, touchEdge(a, k));
        }
    }

    /// sweepOneAxis by the walk along `a`. The held span comes by value (here and in
    /// sweepOneAxisNear): a copy the stores into the contact buffer cannot alias.
    template <int a>
    void walkOneAxis(Coord heldLow, Coord heldHigh, const Time& from, Hits& hits) noexcept {
        const int o = 1 - a;
        const auto& ma = m_.axis(a);
        const std::int64_t j0 = std::max<std::int64_t>(m_.cellOf(o, heldLow), 0);
        const std::int64_t j1 = std::min<std::int64_t>(m_.cellOf(o, heldHigh), m_.cells(o) - 1);
        if (j0 > j1) return;
        // Entry times grow strictly along the walk, so once a cell is entered at or after `from`
        // every later one is: the comparison runs only until then.
        bool pastFrom = false;
        const std::int64_t k = skipCellsEnteredBefore<a>(firstCellAhead(a), from);
        Edge lo = m_.edge(a, k);
        Edge hi = m_.edge(a, k + 1);
        for (std::int64_t c = k; c >= 0 && c < m_.cells(a); c += ma.dir, stepEdges(a, lo, hi)) {
            if (ma.enteredByEnd(ma.walkEntry(lo, hi), lo, hi)) return;  // entered at t >= 1
            // The exact entry time, for the comparison with `from` and the hits (the compiler
            // builds it only on the paths that read it).
            const Time at{ma.entryDistance(lo, hi), ma.speed};
            if (!pastFrom) {
                if (m_.compareTimes(at, from) < 0) continue;  // already overlapping at `from`
                pastFrom = true;
            }
            for (std::int64_t j = j0; j <= j1; ++j) {
                const std::int64_t ci = a == 0 ? c : j;
                const std::int64_t cj = a == 0 ? j : c;
                // One-way cells block a move down along y as solid ones do (sweepOneAxisNear).
                if (!solidInMap(ci, cj) && !(oneWayBlocksAlong<a>() && oneWayInMap(ci, cj))) continue;
                if (!heldOverlaps(o, heldLow, heldHigh, j)) continue;
                add(hits, {static_cast<std::int32_t>(ci), static_cast<std::int32_t>(cj)}, a, at,
                    touchEdge(a, c));
            }
            if (hits.any) return;
        }
    }

    /// The first cell of walkOneAxis from cell k0: k0, or a cell further along `a` when every cell
    /// before it is entered before `from` (such cells are skipped by the walk anyway, each after
    /// an exact comparison of times). The arithmetic's hint (firstCellNotBefore: an estimate, which
    /// may be wrong either way) proposes the cell; one exact comparison of the entry time of the
    /// cell before it with `from` accepts it (entry times grow strictly along the walk), and
    /// otherwise the walk starts at k0. A slide after a landing at 8 tiles a frame skips the
    /// cells the box crossed before it landed.
    template <int a>
    [[gnu::always_inline]] std::int64_t skipCellsEnteredBefore(std::int64_t k0, const Time& from) noexcept {
        const auto& ma = m_.axis(a);
        const std::int64_t hint = m_.firstCellNotBefore(a, from);
        const std::int64_t before = hint - ma.dir;                  // the last cell the hint skips
        const bool ahead = ma.dir > 0 ? before > k0 : before < k0;  // two cells or more: worth a comparison
        if (!ahead || before < 0 || before >= m_.cells(a)) return k0;
        const Time entry{ma.entryDistance(m_.edge(a, before), m_.edge(a, before + 1)), ma.speed};
        return m_.compareTimes(entry, from) < 0 ? hint : k0;
    }

    /// Lists the solid cells of the frame's swept bounds, row by row, when those bounds hold at
    /// most kNearArea cells, or are sparse (at most kSparseArea cells, kSparseAcross across, and
    /// kSparseSolids solid: the tuning knobs of proof_constants.h); false otherwise (the walk then
    /// runs). Every tile that can block either step, or that the box overlaps at the start, lies
    /// in them: on each axis the box covers [min(low, low + disp), max(high, high + disp)] over
    /// the frame, and step 2 stays inside that (its held axis is at a touch position between the
    /// start and the end, its free axis on the rest of its own motion). The arithmetic's
    /// sweptCells is a superset of that; extra cells are tested exactly and rejected. With every
    /// tile tested, the earliest hits are the same set as the walk's, and so are the counts and
    /// flags; where a step has more hits than the contact buffer holds, which of them are stored
    /// is unspecified (docs/library.md), and the listing's order keeps others than the walk's.
    bool collectNear() noexcept {
        CellRange range[2];
        m_.sweptCellsOfBoth(range);
        for (int a = 0; a < 2; ++a) {
            if (range[a].first > range[a].last) {
                nearCount_ = 0;  // the swept bounds miss the map: nothing to find
                return true;
            }
        }
        const std::int64_t area = (range[0].last - range[0].first + 1) * (range[1].last - range[1].first + 1);
        range[1] = secondaryCandidates(range[1]);
        std::int64_t count = 0;
        if (area <= kNearArea) {
            count = listSolidCells<false, kOneWayDown>(range);
        } else {
            const std::int64_t across =
                std::min(range[0].last - range[0].first, range[1].last - range[1].first) + 1;
            if (area > kSparseArea || across > kSparseAcross) return false;
            count = listSolidCells<true, kOneWayDown>(range);
            if (count > kSparseSolids) return false;  // dense: the walk costs less
        }
        nearCount_ = static_cast<std::int32_t>(count);
        return true;
    }

    /// Lists the cells of `range` into near_, and returns how many are solid, or one-way too when
    /// `oneWay` (the frame moves down: kOneWayDown); those come first, in row-then-column order. Every cell
    /// is written at the next slot and kept when solid, without a branch on the byte (a map's bytes are its
    /// data: a branch on them mispredicts at random); the slots suffice, as the count is below the cells
    /// visited, at most kSparseArea. `sparse`: stop after the first row that takes the count past
    /// kSparseSolids (the caller then walks).
    template <bool sparse, bool oneWay>
    [[gnu::always_inline]] std::int64_t listSolidCells(const CellRange (&range)[2]) noexcept {
        const TileMapView<T>& map = m_.map();
        std::int64_t count = 0;
        for (std::int64_t j = range[1].first; j <= range[1].last; ++j) {
            const std::uint8_t* row = map.solid + j * map.columns;
            const std::uint8_t* oneWayRow = oneWay ? map.oneWay + j * map.columns : nullptr;
            Cell cell{0, static_cast<std::int32_t>(j)};
            for (std::int64_t i = range[0].first; i <= range[0].last; ++i) {
                cell.i = static_cast<std::int32_t>(i);
                near_[count] = cell;
                if constexpr (oneWay) {
                    count += (row[i] | oneWayRow[i]) != 0 ? 1 : 0;
                } else {
                    count += row[i] != 0 ? 1 : 0;
                }
            }
            if (sparse && count > kSparseSolids) break;
        }
        return count;
    }

    /// Step 1 of a short move on both axes, and its start overlaps from the same tests: every
    /// listed cell (collectNear) gets the tile test, and with both axes moving its verdict
    /// StartsOverlapping is exactly the start overlap (axis_sweep.h: both entry distances
    /// negative and both exit distances positive, which on each axis says low < hi and high > lo,
    /// the open overlap of the box's span with the tile's at t = 0). The list holds every start
    /// overlap, in row-then-column order, so the count and the stored cells match
    /// startOverlapsOfNear's.
    std::int32_t testNear(Cell* store, std::int32_t capacity, Hits& hits) noexcept {
        std::int32_t count = 0;
        for (std::int32_t n = 0; n < nearCount_; ++n) {
            if (kOneWayDown &&
                !solidInMap(near_[n].i, near_[n].j)) {  // a one-way cell: never a start overlap
                testOneWayAndRecord(near_[n].i, near_[n].j, hits);
                continue;
            }
            if (!testAndRecord(near_[n].i, near_[n].j, hits)) continue;
            if (count < capacity) store[count] = near_[n];
            ++count;
        }
        return count;
    }

    /// The start overlaps among the listed cells (collectNear), which hold all of them, in the
    /// same row-then-column order.
    std::int32_t startOverlapsOfNear(Cell* store, std::int32_t capacity) const noexcept {
        std::int32_t count = 0;
        for (std::int32_t n = 0; n < nearCount_; ++n) {
            const Cell c = near_[n];
            if (kOneWayDown && !solidInMap(c.i, c.j)) continue;  // a one-way cell is never listed
            if (!overlapsCellAtStart(1, c.j) || !overlapsCellAtStart(0, c.i)) continue;
            if (count < capacity) store[count] = c;
            ++count;
        }
        return count;
    }

    Arith& m_;
    std::int32_t nearCount_ = 0;
    Cell near_[kSparseArea];
};

}  // namespace tilesweep::detail

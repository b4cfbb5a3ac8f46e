// SPDX-License-Identifier: MIT
#pragma once

// A free move: a frame whose swept bounds hold no solid cell, nor a one-way cell when the box
// moves down (the only motion one can block). No tile overlaps the box at the
// start and none can block it, so the frame moves to its end with no contact, as the frame loop
// (frame_loop.h) would find after testing nothing; only the final rounding is left. Most frames
// of a game at 0.5 to 2 tiles a frame are such (a fall through open air, a flight), and they are
// decided here, on the fast path, before the frame loop is entered.
//
// Why here and not in the loop. The loop's near listing finds the same frames (no solid cell
// listed), and an exit there would save as many instructions, but it would cost the frames that
// are not free: the exit and its rounding, inlined into the loop, slow down a walker with a
// contact every frame by more than the instructions they save (tilesweep_batch_bench, Walking).
// Here the loop stays as it is, and a frame that is not free pays only the block read.
//
// Exact: the swept bounds (FastFrame::sweptCellsOfBoth) are a certified superset of the cells
// the box covers over the frame on each axis (cell_range.h), and blockHoldsNoSolidCell reads
// every byte of them; a frame is taken as free only when all of them are empty, or when the
// bounds miss the map. The ends are exact (FastFrame::endOf), and roundEndsTogether is the
// final rounding the loop would apply to them; where it cannot decide, the loop runs.

#include "cell_range.h"
#include "fast_frame.h"
#include "fault_injection.h"
#include "solid_block.h"

#include "tilesweep/resolve.h"

#include <cstdint>

namespace tilesweep::detail {

/// Whether the frame's swept bounds hold no solid cell (nor a one-way one when kOneWayDown: the
/// frame may meet a blocking one, frame_loop.h), decided from one read of their block
/// (blockHoldsNoSolidCell: bounds of at most 4 rows of 16 cells, as a short move's are); false
/// too where the block cannot be read (the loop then lists the bounds as it does any frame's).
template <bool kOneWayDown, class T>
[[nodiscard, gnu::always_inline]] inline bool sweptBoundsHoldNoSolidCell(const FastFrame<T>& frame) noexcept {
    CellRange range[2];
    frame.sweptCellsOfBoth(range);
    if (range[0].first > range[0].last || range[1].first > range[1].last) return true;  // off the map
    const TileMapView<T>& map = frame.map();
#if defined(TILESWEEP_FAULT_FREE_MOVE_FIRST_ROW_SKIPPED)
    if (range[1].first < range[1].last) ++range[1].first;  // deliberate fault: the first row unread
#endif
    if (!blockHoldsNoSolidCell(map.solid, map.columns, map.rows, range[0], range[1])) return false;
    // A frame that may meet a blocking one-way cell (oneWayCellsMayBlock, frame_solve.h) reads their block
    // too.
    return !kOneWayDown || blockHoldsNoSolidCell(map.oneWay, map.columns, map.rows, range[0], range[1]);
}

/// Solves a free move into `result`: moved to its ends, rounded by the final rule, with no
/// contact and no start overlap. False, writing nothing, when the frame is not free or the
/// rounding of both ends at once cannot decide (the frame loop then solves the frame).
template <bool kOneWayDown, class T>
[[nodiscard, gnu::always_inline]] inline bool solveFreeMove(const FastFrame<T>& frame,
                                                            ResolveResult<T>& result) noexcept {
    if (!sweptBoundsHoldNoSolidCell<kOneWayDown>(frame)) return false;
    Vec2<T> position;
    if (!frame.roundEndsTogether(frame.endOf(0), frame.endOf(1), position.x, position.y)) return false;
    result.status = ResolveStatus::Moved;
    result.position = position;
    result.contactCount = 0;
    result.startOverlapCount = 0;
    result.blockedX = result.blockedY = false;
    return true;
}

}  // namespace tilesweep::detail

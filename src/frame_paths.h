// SPDX-License-Identifier: MIT
#pragma once

// A moving frame, solved (solveMovingFrame): on the fast path (solveFastOn) when the range test
// admits it, else on the exact lattice (solveOnLatticeAs). Compiled twice: for frames that may
// meet a blocking one-way cell (kOneWayDown, oneWayCellsMayBlock in frame_solve.h), instantiated
// in frame_solve_one_way.cpp, and for the others, in frame_solve.cpp (and inlined once more into
// the batch's loop over its movers, move_range.cpp). resolveFrame
// (frame_solve.h) chooses before anything else, so the others pay for one-way cells with that
// one test alone; and each copy sits in a unit of its own, so that neither takes the
// other's share of the compiler's inlining budget (in one unit the fast path inlines less, and
// frames on maps without one-way cells run more instructions: scripts/instructions.sh).

#include "fast_frame.h"
#include "frame_input.h"
#include "frame_loop.h"
#include "frame_solve.h"
#include "free_move.h"
#include "lattice.h"
#include "lattice_frame.h"
#include "range_admission.h"

#include "tilesweep/detail/map_range.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace tilesweep::detail {

/// Solves an admitted frame (range_admission.h) on the fast path into `result`; false when it
/// meets a case it hands to the lattice. `refined` is set when some predicate needed its exact
/// refinement (DecisionPath::Filtered).
/// `kOneWayDown`: the frame may meet a blocking one-way cell (oneWayCellsMayBlock, frame_solve.h).
template <bool kOneWayDown, class T>
[[gnu::always_inline]] inline bool solveFastOn(FrameInput<T> input, const ResolveOutput<T>& output,
                                               ContactPositions positions, const MapRange& range,
                                               bool inWindow, ResolveResult<T>& result,
                                               bool& refined) noexcept {
    FastFrame<T> frame(input, range, inWindow);
    if (solveFreeMove<kOneWayDown>(frame, result)) {
        refined = false;
        return true;
    }
    const bool solved = FrameLoop<FastFrame<T>, kOneWayDown>(frame).run(
        output, result, positions == ContactPositions::Placed);
    refined = frame.refined();
    return solved;
}

/// Solves a valid frame exactly: scaled onto its lattice, with integers wide enough for it.
/// `kOneWayDown` as for solveFastOn.
template <bool kOneWayDown, class T>
ResolveResult<T> solveOnLatticeAs(const ResolveInput<T>& in, const ResolveOutput<T>& out,
                                  ContactPositions positions) noexcept {
    const T values[10] = {in.box.pos.x,      in.box.pos.y,      in.box.size.x,   in.box.size.y,
                          in.displacement.x, in.displacement.y, in.map.origin.x, in.map.origin.y,
                          in.map.tileSize.x, in.map.tileSize.y};
    Dyadic d[10];
    decomposeEach(values, 10, d);
    // Every coordinate the frame forms is below 2^top: box edges at the start and the end (a sum
    // of three inputs, so 2 bits above the largest) and tile edges from one cell before the map
    // to one past it (origin + k*tile with |k| <= cells + 2).
    int top = 0;
    for (int k = 0; k < 6; ++k) top = std::max(top, exponentAbove(d[k]) + 2);
    const int cellBits[2] = {bitLength(static_cast<std::uint64_t>(in.map.columns) + 2),
                             bitLength(static_cast<std::uint64_t>(in.map.rows) + 2)};
    for (int a = 0; a < 2; ++a)
        top = std::max(top, std::max(exponentAbove(d[6 + a]), exponentAbove(d[8 + a]) + cellBits[a]) + 1);
    return onLattice(d, 10, top, [&](auto tag, int exponent) {
        LatticeFrame<T, decltype(tag)> frame(in, d, exponent);
        ResolveResult<T> result;
        (void)FrameLoop<LatticeFrame<T, decltype(tag)>, kOneWayDown>(frame).run(  // never undecided
            out, result, positions == ContactPositions::Placed);
        return result;
    });
}

/// solveOnLatticeAs out of line (gnu::noinline): the fast path, inlined into resolveMovingFrame,
/// pays for none of it.
template <bool kOneWayDown, class T>
[[gnu::noinline]] ResolveResult<T> solveOnLattice(const ResolveInput<T>& in, const ResolveOutput<T>& out,
                                                  ContactPositions positions) noexcept {
    return solveOnLatticeAs<kOneWayDown>(in, out, positions);
}

/// resolveMovingFrame on the map's range test, whichever way it came (prepared or computed).
/// `kOneWayDown` as for solveFastOn.
/// Always inlined into both entry points (frame_solve.cpp), so that a prepared map's frame builds no range
/// of its own (a MapRange's fields, zeroed and never read, would cost every frame).
template <bool kOneWayDown, class T>
[[gnu::always_inline]] inline ResolveResult<T> solveMovingFrame(const TileMapView<T>& map,
                                                                const MoveInput<T>& move,
                                                                const ResolveOutput<T>& output,
                                                                ContactPositions positions,
                                                                const MapRange& range) noexcept {
    const FrameInput<T> input{map, move.box, move.displacement};  // no copy (frame_input.h)
    ResolveResult<T> result;  // returned by name on every path (NRVO: the caller's slot)
    // The fast path, when the range test admits the frame: float frames on exact doubles,
    // double frames on exact pairs under a certified filter. The range test implies the frame
    // is valid, so isValid only runs for the frames it turns away.
    const bool inWindow = admitFrameInWindow(input, range);  // the short form: a game's frames
    if (inWindow || admitFrameFully(input, range)) {
        bool refined = false;
        if (solveFastOn<kOneWayDown>(input, output, positions, range, inWindow, result, refined)) {
            recordPath(output, refined ? DecisionPath::Filtered : DecisionPath::Fast);
            return result;
        }
    } else if (!isValid(ResolveInput<T>{map, move.box, move.displacement})) {
        result = ResolveResult<T>{};
        result.status = ResolveStatus::InvalidInput;
        result.position = input.box.pos;
        if (!std::isfinite(result.position.x) || !std::isfinite(result.position.y)) result.position = {0, 0};
        recordPath(output, DecisionPath::Exact);
        return result;
    }
    recordPath(output, DecisionPath::Exact);
    result = solveOnLattice<kOneWayDown>(ResolveInput<T>{map, move.box, move.displacement}, output,
                                         positions);  // over whatever the fast path wrote
    return result;
}

}  // namespace tilesweep::detail

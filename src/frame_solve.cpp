// SPDX-License-Identifier: MIT
#include "frame_solve.h"

#include "fast_frame.h"
#include "frame_loop.h"
#include "free_move.h"
#include "lattice.h"
#include "lattice_frame.h"
#include "range_admission.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace tilesweep::detail {
namespace {

/// Solves an admitted frame (range_admission.h) on the fast path into `result`; false when it
/// meets a case it hands to the lattice. `refined` is set when some predicate needed its exact
/// refinement (DecisionPath::Filtered).
template <class T>
[[gnu::always_inline]] inline bool solveFast(FrameInput<T> input, const ResolveOutput<T>& output,
                                             ContactPositions positions, const MapRange& range, bool inWindow,
                                             ResolveResult<T>& result, bool& refined) noexcept {
    FastFrame<T> frame(input, range, inWindow);
    if (solveFreeMove(frame, result)) {
        refined = false;
        return true;
    }
    const bool solved =
        FrameLoop<FastFrame<T>>(frame).run(output, result, positions == ContactPositions::Placed);
    refined = frame.refined();
    return solved;
}

/// Solves a valid frame exactly: scaled onto its lattice, with integers wide enough for it. Out
/// of line (gnu::noinline): the fast path, inlined into resolveMovingFrame, pays for none of it.
template <class T>
[[gnu::noinline]] ResolveResult<T> solveOnLattice(const ResolveInput<T>& in, const ResolveOutput<T>& out,
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
        (void)FrameLoop<LatticeFrame<T, decltype(tag)>>(frame).run(  // never undecided
            out, result, positions == ContactPositions::Placed);
        return result;
    });
}

/// resolveMovingFrame on the map's range test, whichever way it came (prepared or computed).
/// Always inlined into both entry points below, so that a prepared map's frame builds no range
/// of its own (a MapRange's fields, zeroed and never read, cost 16 instructions a frame).
template <class T>
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
        if (solveFast(input, output, positions, range, inWindow, result, refined)) {
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
    result = solveOnLattice(ResolveInput<T>{map, move.box, move.displacement}, output,
                            positions);  // over whatever the fast path wrote
    return result;
}

}  // namespace

template <class T>
#if defined(__GNUC__)
__attribute__((noinline))
#endif
ResolveResult<T>
resolveMovingFrame(const TileMapView<T>& map, const MoveInput<T>& move, const ResolveOutput<T>& output,
                   ContactPositions positions, const MapRange& range) noexcept {
    return solveMovingFrame(map, move, output, positions, range);
}

template <class T>
#if defined(__GNUC__)
__attribute__((noinline))
#endif
ResolveResult<T>
resolveMovingFrameOnBareMap(const TileMapView<T>& map, const MoveInput<T>& move,
                            const ResolveOutput<T>& output, ContactPositions positions) noexcept {
    return solveMovingFrame(map, move, output, positions, mapRangeOf(map));
}

template ResolveResult<float> resolveMovingFrame<float>(const TileMapView<float>&, const MoveInput<float>&,
                                                        const ResolveOutput<float>&, ContactPositions,
                                                        const MapRange&) noexcept;
template ResolveResult<double> resolveMovingFrame<double>(const TileMapView<double>&,
                                                          const MoveInput<double>&,
                                                          const ResolveOutput<double>&, ContactPositions,
                                                          const MapRange&) noexcept;
template ResolveResult<float> resolveMovingFrameOnBareMap<float>(const TileMapView<float>&,
                                                                 const MoveInput<float>&,
                                                                 const ResolveOutput<float>&,
                                                                 ContactPositions) noexcept;
template ResolveResult<double> resolveMovingFrameOnBareMap<double>(const TileMapView<double>&,
                                                                   const MoveInput<double>&,
                                                                   const ResolveOutput<double>&,
                                                                   ContactPositions) noexcept;

template <class T>
#if defined(__GNUC__)
__attribute__((noinline))
#endif
ResolveResult<T>
resolveStillFrame(const TileMapView<T>& map, const MoveInput<T>& move, const ResolveOutput<T>& output,
                  ContactPositions positions, const MapRange* prepared) noexcept {
    // A zero move: the start overlaps alone, from the cells under the box (zero_move.h).
    ResolveResult<T> result;
    if (resolveZeroMove(FrameInput<T>{map, move.box, move.displacement}, output, result,
                        prepared != nullptr)) {  // prepared: a valid map
        recordPath(output, DecisionPath::Fast);
        return result;
    }
    return resolveMovingOn(map, move, output, positions, prepared);
}

template ResolveResult<float> resolveStillFrame<float>(const TileMapView<float>&, const MoveInput<float>&,
                                                       const ResolveOutput<float>&, ContactPositions,
                                                       const MapRange*) noexcept;
template ResolveResult<double> resolveStillFrame<double>(const TileMapView<double>&, const MoveInput<double>&,
                                                         const ResolveOutput<double>&, ContactPositions,
                                                         const MapRange*) noexcept;

}  // namespace tilesweep::detail

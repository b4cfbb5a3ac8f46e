// SPDX-License-Identifier: MIT
#pragma once

// One frame, solved: a zero move by resolveZeroMove when it settles it (zero_move.h); otherwise
// the fast path when the range test admits the frame, else (or when the fast path answers
// "undecided") the exact lattice. Both are the one frame loop (frame_loop.h) on a different
// arithmetic. resolveMovingFrame is defined in frame_solve.cpp, instantiated there for float
// and double, so that the fast path inlines into it there.

#include "zero_move.h"

#include "tilesweep/detail/map_range.h"
#include "tilesweep/mover.h"
#include "tilesweep/resolve.h"

#include <cstdint>

namespace tilesweep::detail {

/// Records the path that decided the frame when the caller asked for it (frame_stats.h).
template <class T>
inline void recordPath(const ResolveOutput<T>& output, DecisionPath path) noexcept {
    if (output.stats != nullptr) output.stats->path = path;
}

/// Whether a frame writes its stored contacts' positions (Contact::position). resolveMove always
/// does; the game-loop calls (mover.cpp) skip them when the caller will not receive the
/// contacts, so that a frame resolved into their inline buffer pays nothing for them.
enum class ContactPositions : std::uint8_t { Placed, Skipped };

/// resolveMove for every frame but the zero moves resolveZeroMove settles (frame_solve.cpp), on
/// the map's range test (range_admission.h). The map and the move come apart, by reference, and
/// the result is returned in the caller's slot, so that resolveFrame passes on its caller's
/// arguments (a prepared map's view and range, the mover's input) and builds nothing of its own.
template <class T>
[[nodiscard]] ResolveResult<T> resolveMovingFrame(const TileMapView<T>& map, const MoveInput<T>& move,
                                                  const ResolveOutput<T>& output, ContactPositions positions,
                                                  const MapRange& range) noexcept;

/// resolveMovingFrame on a map that was not prepared: the range test's map half is computed for
/// the frame.
template <class T>
[[nodiscard]] ResolveResult<T> resolveMovingFrameOnBareMap(const TileMapView<T>& map,
                                                           const MoveInput<T>& move,
                                                           const ResolveOutput<T>& output,
                                                           ContactPositions positions) noexcept;

/// Whether a frame may meet a one-way cell that blocks it: the map has one-way cells and the box
/// moves down (a one-way cell blocks nothing else). Such a frame runs on FrameLoop<Arith, true>
/// (frame_loop.h), through resolveFrameWithOneWayCells.
template <class T>
[[nodiscard, gnu::always_inline]] constexpr bool oneWayCellsMayBlock(const TileMapView<T>& map,
                                                                     const Vec2<T>& displacement) noexcept {
    return map.oneWay != nullptr && displacement.y > 0;
}

/// resolveMovingFrame for a frame that may meet a blocking one-way cell: the frame loop compiled
/// with their test, in a unit of its own (frame_solve_one_way.cpp, frame_paths.h), on `prepared`
/// or, when it is null, on the bare map.
template <class T>
[[nodiscard]] ResolveResult<T> resolveFrameWithOneWayCells(const TileMapView<T>& map,
                                                           const MoveInput<T>& move,
                                                           const ResolveOutput<T>& output,
                                                           ContactPositions positions,
                                                           const MapRange* prepared) noexcept;

/// resolveMovingFrame on `prepared` (the range of a PreparedMap), or on the bare map when it is
/// null. Each caller passes a constant, so the choice folds away.
template <class T>
[[nodiscard]] inline ResolveResult<T> resolveMovingOn(const TileMapView<T>& map, const MoveInput<T>& move,
                                                      const ResolveOutput<T>& output,
                                                      ContactPositions positions,
                                                      const MapRange* prepared) noexcept {
    if (prepared != nullptr) return resolveMovingFrame(map, move, output, positions, *prepared);
    return resolveMovingFrameOnBareMap(map, move, output, positions);
}

/// resolveMove for a frame whose displacement is zero (frame_solve.cpp): resolveZeroMove when it
/// settles the frame (zero_move.h), otherwise resolveMovingFrame.
template <class T>
[[nodiscard]] ResolveResult<T> resolveStillFrame(const TileMapView<T>& map, const MoveInput<T>& move,
                                                 const ResolveOutput<T>& output, ContactPositions positions,
                                                 const MapRange* prepared) noexcept;

/// resolveMove: resolveMovingFrame or resolveStillFrame, as the displacement is zero or not.
/// `prepared` is the map's range test (range_admission.h) when the map was prepared
/// (PreparedMap), or null: it is then computed for the frame. Inline, so that each entry point
/// (resolve.cpp, mover.cpp) goes straight to one of them, saving one register (GCC 12 does not
/// make it a jump) and passing on its caller's return slot, which the callee writes in place
/// (returned by name on every path, NRVO: a copy at the end would read whole vectors of a struct
/// just written field by field, which stalls the store forwarding).
template <class T>
[[nodiscard]] inline ResolveResult<T> resolveFrame(const TileMapView<T>& map, const MoveInput<T>& move,
                                                   const ResolveOutput<T>& output, ContactPositions positions,
                                                   const MapRange* prepared) noexcept {
    if (move.displacement.x != 0 || move.displacement.y != 0) {  // a NaN too: the moving frame refuses it
        if (oneWayCellsMayBlock(map, move.displacement))
            return resolveFrameWithOneWayCells(map, move, output, positions, prepared);
        return resolveMovingOn(map, move, output, positions, prepared);
    }
    return resolveStillFrame(map, move, output, positions, prepared);
}

extern template ResolveResult<float> resolveMovingFrame<float>(const TileMapView<float>&,
                                                               const MoveInput<float>&,
                                                               const ResolveOutput<float>&, ContactPositions,
                                                               const MapRange&) noexcept;
extern template ResolveResult<double> resolveMovingFrame<double>(const TileMapView<double>&,
                                                                 const MoveInput<double>&,
                                                                 const ResolveOutput<double>&,
                                                                 ContactPositions, const MapRange&) noexcept;
extern template ResolveResult<float> resolveMovingFrameOnBareMap<float>(const TileMapView<float>&,
                                                                        const MoveInput<float>&,
                                                                        const ResolveOutput<float>&,
                                                                        ContactPositions) noexcept;
extern template ResolveResult<double> resolveMovingFrameOnBareMap<double>(const TileMapView<double>&,
                                                                          const MoveInput<double>&,
                                                                          const ResolveOutput<double>&,
                                                                          ContactPositions) noexcept;

extern template ResolveResult<float> resolveFrameWithOneWayCells<float>(const TileMapView<float>&,
                                                                        const MoveInput<float>&,
                                                                        const ResolveOutput<float>&,
                                                                        ContactPositions,
                                                                        const MapRange*) noexcept;
extern template ResolveResult<double> resolveFrameWithOneWayCells<double>(const TileMapView<double>&,
                                                                          const MoveInput<double>&,
                                                                          const ResolveOutput<double>&,
                                                                          ContactPositions,
                                                                          const MapRange*) noexcept;
extern template ResolveResult<float> resolveStillFrame<float>(const TileMapView<float>&,
                                                              const MoveInput<float>&,
                                                              const ResolveOutput<float>&, ContactPositions,
                                                              const MapRange*) noexcept;
extern template ResolveResult<double> resolveStillFrame<double>(const TileMapView<double>&,
                                                                const MoveInput<double>&,
                                                                const ResolveOutput<double>&,
                                                                ContactPositions, const MapRange*) noexcept;

}  // namespace tilesweep::detail

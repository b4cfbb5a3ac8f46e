// SPDX-License-Identifier: MIT
// The frames that may meet a blocking one-way cell, in a unit of their own (frame_paths.h).
#include "frame_paths.h"

namespace tilesweep::detail {

template <class T>
ResolveResult<T> resolveFrameWithOneWayCells(const TileMapView<T>& map, const MoveInput<T>& move,
                                             const ResolveOutput<T>& output, ContactPositions positions,
                                             const MapRange* prepared) noexcept {
    if (prepared != nullptr) return solveMovingFrame<true>(map, move, output, positions, *prepared);
    return solveMovingFrame<true>(map, move, output, positions, mapRangeOf(map));
}

template ResolveResult<float> resolveFrameWithOneWayCells<float>(const TileMapView<float>&,
                                                                 const MoveInput<float>&,
                                                                 const ResolveOutput<float>&,
                                                                 ContactPositions, const MapRange*) noexcept;
template ResolveResult<double> resolveFrameWithOneWayCells<double>(const TileMapView<double>&,
                                                                   const MoveInput<double>&,
                                                                   const ResolveOutput<double>&,
                                                                   ContactPositions,
                                                                   const MapRange*) noexcept;

}  // namespace tilesweep::detail

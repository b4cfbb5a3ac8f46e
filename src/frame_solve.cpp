// SPDX-License-Identifier: MIT
#include "frame_solve.h"

#include "frame_paths.h"
#include "range_admission.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace tilesweep::detail {

template <class T>
#if defined(__GNUC__)
__attribute__((noinline))
#endif
ResolveResult<T>
resolveMovingFrame(const TileMapView<T>& map, const MoveInput<T>& move, const ResolveOutput<T>& output,
                   ContactPositions positions, const MapRange& range) noexcept {
    return solveMovingFrame<false>(map, move, output, positions, range);
}

template <class T>
#if defined(__GNUC__)
__attribute__((noinline))
#endif
ResolveResult<T>
resolveMovingFrameOnBareMap(const TileMapView<T>& map, const MoveInput<T>& move,
                            const ResolveOutput<T>& output, ContactPositions positions) noexcept {
    return solveMovingFrame<false>(map, move, output, positions, mapRangeOf(map));
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

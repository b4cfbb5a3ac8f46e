// SPDX-License-Identifier: MIT
#include "move_range.h"

#include "frame_paths.h"
#include "frame_solve.h"
#include "move_result.h"

#include <new>
#include <type_traits>

// The batch's loop over its movers, with the frame solved inline: a frame that moves and can
// meet no blocking one-way cell (most of a game's) runs solveMovingFrame, the fast path and all,
// inside the loop, where moveAndSlide (mover.cpp) calls resolveFrame's out-of-line solver. A
// mover saves the two calls (their saved registers) and the copy of the frame's result between
// them. Every other frame goes to resolveFrame, as moveAndSlide's does. In a unit of its own, as
// each copy of the frame loop is (frame_paths.h).

namespace tilesweep::detail {

template <class T>
void moveAndSlideRange(const PreparedMap<T>& map, const MoveInput<T>* inputs, MoveResult<T>* results,
                       std::size_t begin, std::size_t end) noexcept {
    // Each result is made in its slot (a placement new of the returned prvalue: no temporary and
    // no copy of it, which an assignment would make); MoveResult is trivially destructible.
    static_assert(std::is_trivially_destructible<MoveResult<T>>::value, "the slot is reused as is");
    if (!map.isValid()) {
        for (std::size_t k = begin; k < end; ++k)
            ::new (&results[k]) MoveResult<T>(refusedMove(inputs[k], MoveStatus::InvalidInput));
        return;
    }
    const TileMapView<T>& view = map.view();
    const MapRange& range = map.mapRange();
    const ResolveOutput<T> noContacts{};  // moveAndSlide without a buffer stores none either
    for (std::size_t k = begin; k < end; ++k) {
        const MoveInput<T>& input = inputs[k];
        const Vec2<T> d = input.displacement;
        const bool moving = d.x != 0 || d.y != 0;  // a NaN too: the moving frame refuses it
#if defined(TILESWEEP_FAULT_BATCH_ONE_WAY_IGNORED)
        const bool here = moving;  // deliberate fault: a frame toward one-way cells solved without them
#else
        const bool here = moving && !oneWayCellsMayBlock(view, d);
#endif
        const ResolveResult<T> s =
            here ? solveMovingFrame<false>(view, input, noContacts, ContactPositions::Skipped, range)
                 : resolveFrame(view, input, noContacts, ContactPositions::Skipped, &range);
        if (s.status == ResolveStatus::InvalidInput) {
            ::new (&results[k]) MoveResult<T>(refusedMove(input, MoveStatus::InvalidInput));
        } else {
            ::new (&results[k]) MoveResult<T>(moveResultOf(s, d));
        }
    }
}

template void moveAndSlideRange<float>(const PreparedMap<float>&, const MoveInput<float>*, MoveResult<float>*,
                                       std::size_t, std::size_t) noexcept;
template void moveAndSlideRange<double>(const PreparedMap<double>&, const MoveInput<double>*,
                                        MoveResult<double>*, std::size_t, std::size_t) noexcept;

}  // namespace tilesweep::detail

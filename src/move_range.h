// SPDX-License-Identifier: MIT
#pragma once

// A range of a batch's movers, each moved as moveAndSlide moves it without a contact buffer
// (move_range.cpp): the work of one range of moveAndSlideBatch (batch.cpp).

#include "tilesweep/mover.h"

#include <cstddef>

namespace tilesweep::detail {

/// results[k] = moveAndSlide(map, inputs[k]) for k in [begin, end), each made in its slot.
template <class T>
void moveAndSlideRange(const PreparedMap<T>& map, const MoveInput<T>* inputs, MoveResult<T>* results,
                       std::size_t begin, std::size_t end) noexcept;

extern template void moveAndSlideRange<float>(const PreparedMap<float>&, const MoveInput<float>*,
                                              MoveResult<float>*, std::size_t, std::size_t) noexcept;
extern template void moveAndSlideRange<double>(const PreparedMap<double>&, const MoveInput<double>*,
                                               MoveResult<double>*, std::size_t, std::size_t) noexcept;

}  // namespace tilesweep::detail

// SPDX-License-Identifier: MIT
#pragma once

#include "tilesweep/batch.h"

#include <cstddef>

// The one batch loop: the C++ batch (batch.cpp) and the C batch (c_api.cpp) both split their
// movers through it, so the chunk size and the dispatch live in one place.

namespace tilesweep::detail {

/// Tuning knob: the fewest movers a range of a batch holds (the pool's ranges start larger, as
/// shares of what is left, and shrink to this); on a game's job system, the minRange it is
/// given. Unit: movers. Usual value: 256, about ten microseconds of work: small enough that the
/// threads finish close together, large enough that handing out a range costs little beside
/// it. Changes cost, never results: every mover is moved once, by the same call, whichever
/// range it falls in.
inline constexpr std::size_t kBatchChunk = 256;

/// Calls work(context, begin, end) over disjoint ranges covering [0, count): on the game's job
/// system when `tasks` has an enqueue callback, else on `pool` when it is given, else on the
/// calling thread.
void runBatch(std::size_t count, void (*work)(void* context, std::size_t begin, std::size_t end),
              void* context, BatchPool* pool, const TaskSystem* tasks = nullptr) noexcept;

}  // namespace tilesweep::detail

// SPDX-License-Identifier: MIT
#pragma once

#include "tilesweep/batch.h"

#include <cstddef>

// The one batch loop: the C++ batch (batch.cpp) and the C batch (c_api.cpp) both split their
// movers through it, so the chunk size and the dispatch live in one place.

namespace tilesweep::detail {

/// Movers per chunk: large enough that the shared cursor is touched rarely (a chunk is tens of
/// microseconds of work), small enough that two threads finish within a chunk of each other.
inline constexpr std::size_t kBatchChunk = 256;

/// Calls work(context, begin, end) over disjoint ranges covering [0, count): on the game's job
/// system when `tasks` has an enqueue callback, else on `pool` when it is given, else on the
/// calling thread.
void runBatch(std::size_t count, void (*work)(void* context, std::size_t begin, std::size_t end),
              void* context, BatchPool* pool, const TaskSystem* tasks = nullptr) noexcept;

}  // namespace tilesweep::detail

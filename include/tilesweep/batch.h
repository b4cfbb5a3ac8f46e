// SPDX-License-Identifier: MIT
#pragma once

#include "tilesweep/mover.h"

#include <cstddef>
#include <cstdint>

// Many movers at once: N independent moveAndSlide frames against one prepared map, on a pool
// of threads made once (target tilesweep::batch; the core tilesweep target stays free of
// threads and dependencies).
//
// Every mover's result is bit for bit the one moveAndSlide gives it alone (tests/batch_test.cpp
// compares them), whatever the number of threads: movers are independent and each is resolved
// by one thread. A batch allocates nothing: the pool's
// threads are made when the pool is, and the caller owns the inputs and the results.
//
// A game with its own job system runs the batch on it instead: a TaskSystem hands the batch's
// ranges to the game's workers (Box2D's enqueueTask/finishTask), and the results are the same
// bit for bit. BatchPool, the built-in pool, stays the default.
//
// Usage, every frame (tests/header_recipes_test.cpp runs it as written):
//
//     tilesweep::BatchPool pool(2);  // once: the caller + 1 worker
//     tilesweep::moveAndSlideBatch(map, inputs.data(), results.data(), inputs.size(), &pool);

namespace tilesweep {

/// Worker threads for moveAndSlideBatch, made once and reused by every batch. A pool of n
/// threads runs batches on the calling thread and n - 1 workers; n <= 1 makes no thread. One
/// batch runs at a time per pool (concurrent calls wait their turn).
class BatchPool {
public:
    /// Starts threads - 1 workers (at most 255). Throws std::system_error if a thread cannot be
    /// started (the C API reports TS_ERROR_THREADS instead).
    explicit BatchPool(int threads);
    /// Stops and joins the workers.
    ~BatchPool();
    BatchPool(const BatchPool&) = delete;
    BatchPool& operator=(const BatchPool&) = delete;

    /// Threads a batch runs on, the caller included (>= 1).
    [[nodiscard]] int threadCount() const noexcept;

    /// Calls work(context, begin, end) over disjoint ranges covering [0, count), on every thread
    /// of the pool; returns when all are done. Allocates nothing. Each range is a share of what
    /// is left (large ones first) and at least `chunk` items long, but the one that ends the work.
    void run(std::size_t count, std::size_t chunk,
             void (*work)(void* context, std::size_t begin, std::size_t end), void* context) noexcept;

    struct State;  ///< the threads and their hand-off (batch.cpp)

private:
    State* state_;
};

/// A game's job system, for running batches on it (in the spirit of Box2D's enqueueTask and
/// finishTask callbacks). A batch calls enqueue once, then finish once with what enqueue
/// returned, and returns after finish; nothing is allocated by the library.
struct TaskSystem {
    /// A range of a batch's work: items [begin, end), on any thread.
    using Task = void (*)(std::size_t begin, std::size_t end, void* taskContext);
    /// Runs task(begin, end, taskContext) over disjoint ranges covering [0, itemCount), each at
    /// least minRange items long (but the last), on any threads, the calling one included;
    /// returns a handle for finish, or null when it has already run every range.
    void* (*enqueue)(Task task, std::size_t itemCount, std::size_t minRange, void* taskContext,
                     void* userContext) = nullptr;
    /// Waits until every range of the task that enqueue returned as `userTask` has run.
    void (*finish)(void* userTask, void* userContext) = nullptr;
    void* userContext = nullptr;  ///< passed to both
};

/// Resolves inputs[k] into results[k] for k < count, each exactly as moveAndSlide(map,
/// inputs[k]) with no contact buffer (flags, positions and counts; no contacts). `pool` null
/// runs on the calling thread. Inputs and results must not overlap.
void moveAndSlideBatch(const PreparedMap<float>& map, const MoveInput<float>* inputs,
                       MoveResult<float>* results, std::size_t count, BatchPool* pool = nullptr) noexcept;
/// The same in double.
void moveAndSlideBatch(const PreparedMap<double>& map, const MoveInput<double>* inputs,
                       MoveResult<double>* results, std::size_t count, BatchPool* pool = nullptr) noexcept;

/// The same batch on a game's job system: the same results, bit for bit. A TaskSystem without
/// enqueue runs on the calling thread.
void moveAndSlideBatch(const PreparedMap<float>& map, const MoveInput<float>* inputs,
                       MoveResult<float>* results, std::size_t count, const TaskSystem& tasks) noexcept;
/// The same in double.
void moveAndSlideBatch(const PreparedMap<double>& map, const MoveInput<double>* inputs,
                       MoveResult<double>* results, std::size_t count, const TaskSystem& tasks) noexcept;

}  // namespace tilesweep

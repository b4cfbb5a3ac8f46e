// SPDX-License-Identifier: MIT
#include "tilesweep/batch.h"

#include "batch_run.h"
#include "move_range.h"

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

// A small pool over std::thread rather than TBB: a batch is one parallel loop over independent
// movers, so the pool needs only a hand-off (a generation counter under a mutex), an atomic
// range cursor and a completion count. It allocates when it is made, never per batch; a TBB
// parallel_for would allocate tasks per call and bring a dependency to every binding of the C
// API.

namespace tilesweep {

namespace {

/// Tuning knob: the most rounds the caller of a batch spins on the workers' last chunks before it
/// sleeps until they finish. Unit: spin rounds, one CPU pause hint each (20 to 140 cycles on
/// x86). Usual value: 4096, about the time of a chunk (kBatchChunk movers), which is as long as
/// a worker that joined can still be working. Changes cost, never results: the caller waits for
/// every worker either way, spinning or asleep.
constexpr int kFinishSpins = 4096;

/// One round of a spin-wait: the CPU's pause hint where there is one.
inline void pauseSpin() noexcept {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
}

}  // namespace

// The hand-off. A batch opens (`open`), wakes the workers and works through the chunks itself;
// a worker that wakes joins by counting itself in `active` and then checking `open`. When the
// caller runs out of chunks it closes the batch and waits only for the workers that joined (all
// seq_cst: either the caller sees a worker's join, or that worker sees the batch closed and
// leaves). So a worker the scheduler has not run yet never holds the caller up: on a loaded
// machine the caller may simply do all the work.
struct BatchPool::State {
    std::vector<std::thread> workers;
    std::mutex runMutex;  // one batch at a time
    std::mutex mutex;     // guards generation and stop; pairs with the two condition variables
    std::condition_variable wake;
    std::condition_variable done;
    std::uint64_t generation = 0;
    bool stop = false;
    // The current batch: written before `open` is set, read after it is seen set.
    std::size_t count = 0;
    std::size_t chunk = 1;
    std::size_t shares = 2;  // a range is 1/shares of what is left: twice the pool's threads
    void (*work)(void*, std::size_t, std::size_t) = nullptr;
    void* context = nullptr;
    // The shared cursor, on a cache line of its own: claiming a range moves only this line
    // between the cores, not the one the batch's parameters are read from.
    alignas(64) std::atomic<std::size_t> next{0};
    alignas(64) std::atomic<bool> open{false};
    std::atomic<int> active{0};

    /// Claims the next range of the batch: a share of what is left (so that a few large ranges
    /// cover most of the batch and the shared cursor moves rarely), never less than `chunk`
    /// (so that the threads finish within a chunk of each other). Returns false when none is left.
    bool claimRange(std::size_t& begin, std::size_t& end) noexcept {
        std::size_t at = next.load(std::memory_order_relaxed);
        for (;;) {
            if (at >= count) return false;
            const std::size_t left = count - at;
            std::size_t take = left / shares;
            if (take < chunk) take = chunk;
            if (take > left) take = left;
            if (next.compare_exchange_weak(at, at + take, std::memory_order_relaxed)) {
                begin = at;
                end = at + take;
                return true;
            }
        }
    }

    void runRanges() noexcept {
        std::size_t begin = 0;
        std::size_t end = 0;
        while (claimRange(begin, end)) work(context, begin, end);
    }

    void leave() noexcept {
        if (active.fetch_sub(1) == 1) {
            std::lock_guard<std::mutex> lock(mutex);
            done.notify_one();
        }
    }

    void workerLoop() noexcept {
        std::uint64_t seen = 0;
        for (;;) {
            {
                std::unique_lock<std::mutex> lock(mutex);
                wake.wait(lock, [&] { return stop || generation != seen; });
                if (stop) return;
                seen = generation;
            }
            active.fetch_add(1);
            if (open.load()) runRanges();
            leave();
        }
    }
};

BatchPool::BatchPool(int threads) : state_(new State) {
    const int workers = threads <= 1 ? 0 : (threads > 256 ? 255 : threads - 1);
    try {
        state_->workers.reserve(static_cast<std::size_t>(workers));
        for (int k = 0; k < workers; ++k) state_->workers.emplace_back([s = state_] { s->workerLoop(); });
    } catch (...) {
        this->~BatchPool();
        throw;
    }
}

BatchPool::~BatchPool() {
    if (state_ == nullptr) return;
    {
        std::lock_guard<std::mutex> lock(state_->mutex);
        state_->stop = true;
    }
    state_->wake.notify_all();
    for (std::thread& t : state_->workers) t.join();
    delete state_;
    state_ = nullptr;
}

int BatchPool::threadCount() const noexcept { return static_cast<int>(state_->workers.size()) + 1; }

void BatchPool::run(std::size_t count, std::size_t chunk, void (*work)(void*, std::size_t, std::size_t),
                    void* context) noexcept {
    if (count == 0) return;
    if (chunk == 0) chunk = 1;
    State& s = *state_;
    // Too little work to be worth waking anyone: run it here.
    if (s.workers.empty() || count <= chunk) {
        work(context, 0, count);
        return;
    }
    std::lock_guard<std::mutex> serial(s.runMutex);
    s.count = count;
    s.chunk = chunk;
    s.shares = 2 * (s.workers.size() + 1);
    s.work = work;
    s.context = context;
    s.next.store(0, std::memory_order_relaxed);
    s.open.store(true);
    {
        std::lock_guard<std::mutex> lock(s.mutex);
        ++s.generation;
    }
    s.wake.notify_all();
    s.runRanges();
    s.open.store(false);
    // The workers that joined are each within one chunk of the end: wait for them spinning
    // first, and sleep only if they take longer. A sleep and its wake-up cost about as much as a
    // chunk's work, a large share of a batch that only takes a few chunks per thread.
    for (int spin = 0; spin < kFinishSpins && s.active.load() != 0; ++spin) pauseSpin();
    if (s.active.load() == 0) return;
    std::unique_lock<std::mutex> lock(s.mutex);
    s.done.wait(lock, [&] { return s.active.load() == 0; });
}

namespace detail {

namespace {

/// A pool-style work function behind the TaskSystem's range signature.
struct TaskAdapter {
    void (*work)(void*, std::size_t, std::size_t);
    void* context;
};

void runAdaptedTask(std::size_t begin, std::size_t end, void* taskContext) {
    const auto& adapter = *static_cast<const TaskAdapter*>(taskContext);
    adapter.work(adapter.context, begin, end);
}

}  // namespace

void runBatch(std::size_t count, void (*work)(void*, std::size_t, std::size_t), void* context,
              BatchPool* pool, const TaskSystem* tasks) noexcept {
    if (count == 0) return;
    if (tasks != nullptr && tasks->enqueue != nullptr) {
        TaskAdapter adapter{work, context};
        void* handle = tasks->enqueue(&runAdaptedTask, count, kBatchChunk, &adapter, tasks->userContext);
        if (handle != nullptr && tasks->finish != nullptr) tasks->finish(handle, tasks->userContext);
        return;
    }
    if (pool == nullptr) {
        work(context, 0, count);
        return;
    }
    pool->run(count, kBatchChunk, work, context);
}

}  // namespace detail

namespace {

template <class T>
struct BatchJob {
    const PreparedMap<T>* map;
    const MoveInput<T>* inputs;
    MoveResult<T>* results;
};

template <class T>
void runRange(void* context, std::size_t begin, std::size_t end) {
    const auto& job = *static_cast<const BatchJob<T>*>(context);
    detail::moveAndSlideRange(*job.map, job.inputs, job.results, begin, end);
}

template <class T>
void batchOf(const PreparedMap<T>& map, const MoveInput<T>* inputs, MoveResult<T>* results, std::size_t count,
             BatchPool* pool, const TaskSystem* tasks) noexcept {
    if (inputs == nullptr || results == nullptr) return;
    BatchJob<T> job{&map, inputs, results};
    detail::runBatch(count, &runRange<T>, &job, pool, tasks);
}

}  // namespace

void moveAndSlideBatch(const PreparedMap<float>& map, const MoveInput<float>* inputs,
                       MoveResult<float>* results, std::size_t count, BatchPool* pool) noexcept {
    batchOf(map, inputs, results, count, pool, nullptr);
}

void moveAndSlideBatch(const PreparedMap<double>& map, const MoveInput<double>* inputs,
                       MoveResult<double>* results, std::size_t count, BatchPool* pool) noexcept {
    batchOf(map, inputs, results, count, pool, nullptr);
}

void moveAndSlideBatch(const PreparedMap<float>& map, const MoveInput<float>* inputs,
                       MoveResult<float>* results, std::size_t count, const TaskSystem& tasks) noexcept {
    batchOf(map, inputs, results, count, nullptr, &tasks);
}

void moveAndSlideBatch(const PreparedMap<double>& map, const MoveInput<double>* inputs,
                       MoveResult<double>* results, std::size_t count, const TaskSystem& tasks) noexcept {
    batchOf(map, inputs, results, count, nullptr, &tasks);
}

}  // namespace tilesweep

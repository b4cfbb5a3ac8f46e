// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>

// The audit's worker threads (runAudit and measureRates): tasks taken in order by whichever
// worker is free, progress reported about twice a second, the first worker's failure ending the
// run. Workers share no mutable state but the task counter: each writes only what its own index
// selects (its shard of the figures), which the caller merges once they have all joined.

namespace tilesweep::audit {

/// What to run, and where to report.
struct ParallelTasks {
    int workers = 1;            ///< threads, at least 1
    std::size_t tasks = 0;      ///< task indices 0 .. tasks - 1
    std::uint64_t units = 0;    ///< the progress all tasks make together (scenes, say)
    const char* name = "task";  ///< names the failure: "<name> worker failed: ..."
    /// Runs one task on one worker (0 .. workers - 1); returns the units of progress it made.
    std::function<std::uint64_t(std::size_t worker, std::size_t task)> run;
    /// Called with (units done, units) now and then, and once at the end; may be empty.
    std::function<void(std::uint64_t, std::uint64_t)> progress;
};

/// Runs every task; throws std::runtime_error naming the first failure of a worker, after all
/// workers have stopped.
void runParallelTasks(const ParallelTasks& p);

}  // namespace tilesweep::audit

// SPDX-License-Identifier: MIT
// The audit's worker threads (parallel_tasks.h).
#include "parallel_tasks.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace tilesweep::audit {

void runParallelTasks(const ParallelTasks& p) {
    const int workers = std::max(1, p.workers);
    std::atomic<std::size_t> next{0};
    std::atomic<std::uint64_t> done{0};
    std::atomic<bool> failed{false};
    std::vector<std::string> errors(static_cast<std::size_t>(workers));  // each written by its worker only
    auto work = [&](std::size_t w) {
        try {
            for (std::size_t t; (t = next.fetch_add(1)) < p.tasks;) done.fetch_add(p.run(w, t));
        } catch (const std::exception& e) {
            errors[w] = e.what();
            failed.store(true);
            next.store(p.tasks);
        }
    };
    std::vector<std::thread> threads;
    for (int w = 0; w < workers; ++w) threads.emplace_back(work, static_cast<std::size_t>(w));
    // Progress about twice a second, in steps of 50 ms so that a short run ends promptly.
    for (int tick = 0; done.load() < p.units && !failed.load(); ++tick) {
        if (p.progress && tick % 10 == 0) p.progress(done.load(), p.units);
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    for (std::thread& t : threads) t.join();
    for (const std::string& e : errors)
        if (!e.empty()) throw std::runtime_error(std::string(p.name) + " worker failed: " + e);
    if (p.progress) p.progress(p.units, p.units);
}

}  // namespace tilesweep::audit

// SPDX-License-Identifier: MIT
// Many movers at once (tilesweep/batch.h): a batch on 1, 2 and 3 threads, and on a game's own
// job system through TaskSystem, gives every mover exactly what moveAndSlide and resolveMove
// give it alone, bit for bit, over random maps and movers (tilesweep/scenarios/mover_scenes.h),
// half of the maps with one-way cells too.
// TILESWEEP_PROPERTY_CASES sets the number of maps (default 300, 500 movers each).
#include "tilesweep/batch.h"

#include "property_cases.h"

#include "tilesweep/resolve.h"
#include "tilesweep/scenarios/mover_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <condition_variable>
#include <cstdint>
#include <cstring>
#include <deque>
#include <functional>
#include <mutex>
#include <random>
#include <set>
#include <thread>
#include <utility>
#include <vector>

namespace tilesweep {
namespace {

template <class T>
class Batch : public ::testing::Test {};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(Batch, Scalars);

template <class T>
bool sameResult(const MoveResult<T>& a, const MoveResult<T>& b) {
    return std::memcmp(&a.position, &b.position, sizeof a.position) == 0 && a.status == b.status &&
           a.blockedX == b.blockedX && a.blockedY == b.blockedY && a.onGround == b.onGround &&
           a.onCeiling == b.onCeiling && a.onWall == b.onWall && a.wallNormalX == b.wallNormalX &&
           a.contactCount == b.contactCount && a.startOverlapCount == b.startOverlapCount &&
           std::memcmp(&a.clippedDisplacement, &b.clippedDisplacement, sizeof a.clippedDisplacement) == 0 &&
           a.contactsStored == b.contactsStored;
}

TYPED_TEST(Batch, givesEveryMoverWhatResolveMoveGivesItAlone) {
    using T = TypeParam;
    std::mt19937_64 rng(0xba7c4);
    BatchPool one(1);
    BatchPool two(2);
    BatchPool three(3);
    EXPECT_EQ(one.threadCount(), 1);
    EXPECT_EQ(two.threadCount(), 2);
    // At least 16 maps at any budget: eight with one-way cells, enough for the check below.
    const std::uint64_t maps = std::max<std::uint64_t>(test::propertyCases(3000) / 10 + 1, 16);
    constexpr std::size_t kMovers = 500;
    std::vector<MoveInput<T>> inputs(kMovers);
    std::vector<MoveResult<T>> alone(kMovers), byOne(kMovers), byTwo(kMovers), byThree(kMovers),
        inline_(kMovers);
    std::vector<Contact<T>> contacts(4096);
    std::uint64_t oneWayFrames = 0;     // frames on maps with one-way cells
    std::uint64_t stoppedByOneWay = 0;  // of them, frames whose contacts a one-way cell changed
    for (std::uint64_t m = 0; m < maps && !::testing::Test::HasFailure(); ++m) {
        const scenarios::RandomScene<T> level = scenarios::randomScene<T>(rng);
        // Every other map has one-way cells: a third of its bytes (a solid flag wins), so that
        // frames moving down meet them and every other frame passes them by.
        std::vector<std::uint8_t> oneWay;
        TileMapView<T> view = level.view();
        if (m % 2 == 1) {
            oneWay.resize(level.cells.size());
            for (auto& b : oneWay) b = rng() % 3 == 0 ? 1 : 0;
            view.oneWay = oneWay.data();
        }
        const PreparedMap<T> map = prepareMap(view);
        ASSERT_TRUE(map.isValid());
        for (auto& in : inputs) scenarios::randomMover(rng, level, in.box, in.displacement);
        for (std::size_t k = 0; k < kMovers; ++k) alone[k] = moveAndSlide(map, inputs[k]);
        moveAndSlideBatch(map, inputs.data(), byOne.data(), kMovers, &one);
        moveAndSlideBatch(map, inputs.data(), byTwo.data(), kMovers, &two);
        moveAndSlideBatch(map, inputs.data(), byThree.data(), kMovers, &three);
        moveAndSlideBatch(map, inputs.data(), inline_.data(), kMovers);
        for (std::size_t k = 0; k < kMovers; ++k) {
            ASSERT_TRUE(sameResult(alone[k], byOne[k]) && sameResult(alone[k], byTwo[k]) &&
                        sameResult(alone[k], byThree[k]) && sameResult(alone[k], inline_[k]))
                << "map " << m << " mover " << k;
            // And the core resolver, with a buffer large enough for any of these frames.
            const ResolveResult<T> s = resolveMove<T>({view, inputs[k].box, inputs[k].displacement},
                                                      {contacts.data(), 4096, nullptr, 0});
            ASSERT_EQ(std::memcmp(&s.position, &byTwo[k].position, sizeof s.position), 0)
                << "map " << m << " mover " << k;
            ASSERT_EQ(s.contactCount, byTwo[k].contactCount);
            ASSERT_EQ(s.startOverlapCount, byTwo[k].startOverlapCount);
            if (view.oneWay != nullptr) {
                const ResolveResult<T> through = resolveMove<T>(
                    {view.withoutOneWay(), inputs[k].box, inputs[k].displacement}, {nullptr, 0, nullptr, 0});
                ++oneWayFrames;
                stoppedByOneWay += through.contactCount != s.contactCount ? 1 : 0;
            }
        }
    }
    // The one-way cells decided frames: the batch was held to them, not only to solid ones.
    EXPECT_GT(stoppedByOneWay, oneWayFrames / 200)
        << "one-way cells changed " << stoppedByOneWay << " of " << oneWayFrames << " frames";
}

TEST(Batch, emptyAndNullBatchesDoNothing) {
    scenarios::Level<float> level({"....", "####"});
    const PreparedMap<float> map = prepareMap(level.view());
    BatchPool pool(2);
    MoveResult<float> result{};
    result.contactCount = 7;
    moveAndSlideBatch(map, nullptr, &result, 1, &pool);
    moveAndSlideBatch(map, nullptr, nullptr, 0, &pool);
    EXPECT_EQ(result.contactCount, 7);
}

// A pool outlives many batches, and a large batch is split across its threads into disjoint
// ranges that cover it: each at least the chunk long (but the one that ends the batch), and
// fewer of them than chunks (large shares of what is left first, so the shared cursor moves
// rarely).
TEST(Batch, poolRunsEveryIndexExactlyOnceInRangesOfAtLeastAChunk) {
    struct Record {
        std::vector<int> hits;
        std::mutex mutex;
        std::vector<std::pair<std::size_t, std::size_t>> ranges;
    };
    constexpr std::size_t kChunk = 64;
    BatchPool pool(3);
    for (int round = 0; round < 50; ++round) {
        Record record;
        record.hits.assign(10007, 0);
        pool.run(
            record.hits.size(), kChunk,
            [](void* ctx, std::size_t b, std::size_t e) {
                auto& r = *static_cast<Record*>(ctx);
                for (std::size_t k = b; k < e; ++k) ++r.hits[k];
                std::lock_guard<std::mutex> lock(r.mutex);
                r.ranges.emplace_back(b, e);
            },
            &record);
        for (int h : record.hits) ASSERT_EQ(h, 1);
        for (const auto& [b, e] : record.ranges)
            ASSERT_TRUE(e - b >= kChunk || e == record.hits.size()) << "range [" << b << ", " << e << ")";
        EXPECT_LT(record.ranges.size(), record.hits.size() / kChunk / 2);
    }
}

/// A game's job system, as small as one can be: worker threads taking jobs from one queue, and
/// a counter per enqueued task that finish waits on. It records the ranges it ran and the
/// threads that ran them.
class ToyJobSystem {
public:
    explicit ToyJobSystem(int workers) {
        for (int k = 0; k < workers; ++k) threads_.emplace_back([this] { workerLoop(); });
    }
    ~ToyJobSystem() {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            stop_ = true;
        }
        wake_.notify_all();
        for (std::thread& t : threads_) t.join();
    }
    ToyJobSystem(const ToyJobSystem&) = delete;
    ToyJobSystem& operator=(const ToyJobSystem&) = delete;

    [[nodiscard]] TaskSystem tasks() { return {&enqueue, &finish, this}; }

    struct Range {
        std::size_t begin, end, minRange, count;
    };
    std::vector<Range> ranges;          ///< every range run, under mutex_
    std::set<std::thread::id> runners;  ///< every thread that ran one, under mutex_
    int enqueued = 0;
    int finished = 0;

private:
    struct Pending {
        int remaining = 0;
    };

    static void* enqueue(TaskSystem::Task task, std::size_t count, std::size_t minRange, void* taskContext,
                         void* user) {
        auto& self = *static_cast<ToyJobSystem*>(user);
        std::lock_guard<std::mutex> lock(self.mutex_);
        ++self.enqueued;
        self.pending_.remaining = 0;
        for (std::size_t begin = 0; begin < count; begin += minRange) {
            const std::size_t end = count - begin < minRange ? count : begin + minRange;
            ++self.pending_.remaining;
            self.jobs_.push_back([&self, task, taskContext, begin, end, minRange, count] {
                task(begin, end, taskContext);
                std::lock_guard<std::mutex> done(self.mutex_);
                self.ranges.push_back({begin, end, minRange, count});
                self.runners.insert(std::this_thread::get_id());
                if (--self.pending_.remaining == 0) self.finishedAll_.notify_all();
            });
        }
        self.wake_.notify_all();
        return &self.pending_;
    }

    static void finish(void* userTask, void* user) {
        auto& self = *static_cast<ToyJobSystem*>(user);
        std::unique_lock<std::mutex> lock(self.mutex_);
        auto& pending = *static_cast<Pending*>(userTask);
        self.finishedAll_.wait(lock, [&] { return pending.remaining == 0; });
        ++self.finished;
    }

    void workerLoop() {
        for (;;) {
            std::function<void()> job;
            {
                std::unique_lock<std::mutex> lock(mutex_);
                wake_.wait(lock, [&] { return stop_ || !jobs_.empty(); });
                if (jobs_.empty()) return;
                job = std::move(jobs_.front());
                jobs_.pop_front();
            }
            job();
        }
    }

    std::mutex mutex_;
    std::condition_variable wake_;
    std::condition_variable finishedAll_;
    std::deque<std::function<void()>> jobs_;
    Pending pending_;
    bool stop_ = false;
    std::vector<std::thread> threads_;
};

// A batch through a game's job system: every mover gets, bit for bit, what moveAndSlide gives it
// alone; the ranges cover every mover once, each at least minRange long but the last; the work
// ran on the game's threads; and enqueue and finish were each called once per batch.
TYPED_TEST(Batch, runsOnAGameJobSystemBitForBit) {
    using T = TypeParam;
    std::mt19937_64 rng(0x70b5);
    ToyJobSystem jobs(3);
    const TaskSystem tasks = jobs.tasks();
    constexpr std::size_t kMovers = 2000;
    std::vector<MoveInput<T>> inputs(kMovers);
    std::vector<MoveResult<T>> alone(kMovers), onJobs(kMovers);
    const int batches = 8;
    for (int b = 0; b < batches; ++b) {
        const scenarios::RandomScene<T> level = scenarios::randomScene<T>(rng);
        const PreparedMap<T> map = prepareMap(level.view());
        ASSERT_TRUE(map.isValid());
        for (auto& in : inputs) scenarios::randomMover(rng, level, in.box, in.displacement);
        for (std::size_t k = 0; k < kMovers; ++k) alone[k] = moveAndSlide(map, inputs[k]);
        moveAndSlideBatch(map, inputs.data(), onJobs.data(), kMovers, tasks);
        for (std::size_t k = 0; k < kMovers; ++k)
            ASSERT_TRUE(sameResult(alone[k], onJobs[k])) << "batch " << b << " mover " << k;
    }
    EXPECT_EQ(jobs.enqueued, batches);
    EXPECT_EQ(jobs.finished, batches);
    std::vector<int> covered(kMovers * batches, 0);
    std::size_t batch = 0;
    std::size_t seen = 0;
    for (const auto& r : jobs.ranges) {
        EXPECT_EQ(r.count, kMovers);
        EXPECT_TRUE(r.end - r.begin >= r.minRange || r.end == r.count) << r.begin << ".." << r.end;
        for (std::size_t k = r.begin; k < r.end; ++k) ++covered[batch * kMovers + k];
        seen += r.end - r.begin;
        if (seen == kMovers) {
            seen = 0;
            ++batch;
        }
    }
    for (int c : covered) ASSERT_EQ(c, 1);
    EXPECT_EQ(jobs.runners.count(std::this_thread::get_id()), 0u);  // the game's threads ran it
    // A TaskSystem without callbacks runs the batch here.
    std::vector<MoveResult<T>> here(kMovers);
    const scenarios::RandomScene<T> level = scenarios::randomScene<T>(rng);
    const PreparedMap<T> map = prepareMap(level.view());
    for (auto& in : inputs) scenarios::randomMover(rng, level, in.box, in.displacement);
    moveAndSlideBatch(map, inputs.data(), here.data(), kMovers, TaskSystem{});
    for (std::size_t k = 0; k < kMovers; ++k) ASSERT_TRUE(sameResult(moveAndSlide(map, inputs[k]), here[k]));
}

}  // namespace
}  // namespace tilesweep

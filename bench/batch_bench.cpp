// SPDX-License-Identifier: MIT
// Many movers at once (tilesweep/batch.h): mover-frames per second for a game's mix of movers
// on 1 and 2 threads. Fixed seed; one iteration resolves one frame of every mover (the inputs
// stay the same, so the mix stays the same). Items/s is mover-frames/s; real time, since a
// batch spans threads.
//
//     build/release/bench/tilesweep_batch_bench --benchmark_filter=Mix
//
// The map: 256 x 256 tiles of 16 px, floors every 16 rows with one-tile gaps, walls four tiles
// high every 32 columns standing on the floors, open air in between. The movers (12 x 14 px):
//   resting  standing on a floor, pushed into it by one frame of gravity (a contact each frame)
//   walking  on a floor, 1.5 px a frame sideways plus gravity
//   falling  in open air, 5 px a frame down (the cheap exit: no solid cell in the swept bounds)
//   fast     dashing 30 px a frame along a floor toward the walls
// MixShuffled is the float mix in random order, as a game's list of movers holds its kinds: Mix
// takes them in turn, a pattern the branch predictor learns; in random order a branch that goes
// one way for a kind mispredicts for the next mover of another kind.
// MixAfterIdle runs the float mix once a millisecond, as a game's one batch a frame: the other
// rows run batches back to back, and find the pool's worker awake.
// MixC is the float mix through the C API (ts_move_and_slide_batch_f, tilesweep.h), on its own
// map and pool: what a game that loads libtilesweep_c gets against the C++ call.
#include "tilesweep/batch.h"
#if defined(TILESWEEP_BENCH_C_API)
#include "tilesweep/tilesweep.h"
#endif

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <random>
#include <thread>
#include <vector>

namespace {

using tilesweep::MoveInput;
using tilesweep::MoveResult;

constexpr std::int32_t kSize = 256;
constexpr int kMovers = 16384;

template <class T>
struct World {
    std::vector<std::uint8_t> cells;
    tilesweep::PreparedMap<T> map;
    std::vector<MoveInput<T>> resting, walking, falling, fast, mix, shuffled;

    static bool isFloor(int j) { return j % 16 == 15; }

    World() : cells(static_cast<std::size_t>(kSize) * kSize, 0) {
        for (int j = 0; j < kSize; ++j)
            for (int i = 0; i < kSize; ++i) {
                const bool floor = isFloor(j) && i % 24 != 7;                   // one-tile gaps
                const bool wall = i % 32 == 31 && j % 16 >= 11 && j % 16 < 15;  // on the floors
                cells[static_cast<std::size_t>(j) * kSize + static_cast<std::size_t>(i)] = floor || wall;
            }
        map = tilesweep::prepareMap(tilesweep::TileMapView<T>{{0, 0}, {16, 16}, kSize, kSize, cells.data()});
        std::mt19937_64 rng(12);
        auto column = [&](bool nearWall) {
            for (;;) {
                const int i = std::uniform_int_distribution<int>(1, kSize - 3)(rng);
                if (i % 24 == 7 || i % 24 == 6 || i % 24 == 8 || i % 32 == 31)
                    continue;  // not over a gap or in a wall
                if (nearWall || (i % 32 != 30 && i % 32 != 0)) return i;
            }
        };
        auto floorRow = [&] { return 16 * std::uniform_int_distribution<int>(0, kSize / 16 - 1)(rng) + 15; };
        const T gravity = static_cast<T>(1200.0 / 3600);  // one frame of 1200 px/s^2 at 60 Hz
        for (int k = 0; k < kMovers / 4; ++k) {
            const int i = column(false);
            const int f = floorRow();
            const T x = static_cast<T>(16 * i + 2);
            const T onFloor = static_cast<T>(16 * f - 14);
            resting.push_back({{{x, onFloor}, {12, 14}}, {0, gravity}});
            walking.push_back({{{x, onFloor}, {12, 14}}, {k % 2 ? T(1.5) : T(-1.5), gravity}});
            const int air = 16 * (f / 16) + std::uniform_int_distribution<int>(2, 8)(rng);
            falling.push_back({{{x, static_cast<T>(16 * air + 1)}, {12, 14}}, {k % 2 ? T(1) : T(-1), 5}});
            fast.push_back({{{static_cast<T>(16 * column(true) + 2), onFloor}, {12, 14}},
                            {k % 2 ? T(30) : T(-30), gravity}});
        }
        for (int k = 0; k < kMovers / 4; ++k) {
            mix.push_back(resting[static_cast<std::size_t>(k)]);
            mix.push_back(walking[static_cast<std::size_t>(k)]);
            mix.push_back(falling[static_cast<std::size_t>(k)]);
            mix.push_back(fast[static_cast<std::size_t>(k)]);
        }
        shuffled = mix;
        std::shuffle(shuffled.begin(), shuffled.end(), rng);
    }
};

template <class T>
const World<T>& world() {
    static const World<T> w;
    return w;
}

/// How the batches of a benchmark come: back to back, or each 1 ms after the last, as a game's
/// one batch a frame does (the pool's worker has gone to sleep by then, so its wake-up is in the
/// time; only the batch is timed, with the benchmark's manual time).
enum class Pace { BackToBack, AfterIdle };

template <class T>
void runBatch(benchmark::State& state, const std::vector<MoveInput<T>>& movers,
              Pace pace = Pace::BackToBack) {
    const World<T>& w = world<T>();
    tilesweep::BatchPool pool(static_cast<int>(state.range(0)));
    std::vector<MoveResult<T>> results(movers.size());
    for (auto _ : state) {
        if (pace == Pace::AfterIdle) std::this_thread::sleep_for(std::chrono::milliseconds(1));
        const auto start = pace == Pace::AfterIdle ? std::chrono::steady_clock::now()
                                                   : std::chrono::steady_clock::time_point{};
        tilesweep::moveAndSlideBatch(w.map, movers.data(), results.data(), movers.size(), &pool);
        benchmark::DoNotOptimize(results.data());
        benchmark::ClobberMemory();
        if (pace == Pace::AfterIdle)
            state.SetIterationTime(
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(movers.size()));
    state.counters["threads"] = static_cast<double>(pool.threadCount());
}

// The target: the game's mix (a quarter each), float and double, on 1 and 2 threads.
void BM_MoveAndSlideBatch_Mix(benchmark::State& state) { runBatch<float>(state, world<float>().mix); }
void BM_MoveAndSlideBatch_MixShuffled(benchmark::State& state) {
    runBatch<float>(state, world<float>().shuffled);
}
void BM_MoveAndSlideBatch_MixDouble(benchmark::State& state) { runBatch<double>(state, world<double>().mix); }
// The float mix as a game's one batch a frame: the worker woken for it.
void BM_MoveAndSlideBatch_MixAfterIdle(benchmark::State& state) {
    runBatch<float>(state, world<float>().mix, Pace::AfterIdle);
}
// Each kind alone on one thread: where the time of the mix goes.
void BM_MoveAndSlideBatch_Resting(benchmark::State& state) { runBatch<float>(state, world<float>().resting); }
void BM_MoveAndSlideBatch_Walking(benchmark::State& state) { runBatch<float>(state, world<float>().walking); }
void BM_MoveAndSlideBatch_Falling(benchmark::State& state) { runBatch<float>(state, world<float>().falling); }
void BM_MoveAndSlideBatch_Fast(benchmark::State& state) { runBatch<float>(state, world<float>().fast); }

#if defined(TILESWEEP_BENCH_C_API)
/// The float mix through the C API: the world's cells in a ts_map_f, its movers as ts_mover_fs.
void BM_MoveAndSlideBatch_MixC(benchmark::State& state) {
    const World<float>& w = world<float>();
    const ts_map_desc_f desc = {{0, 0}, {16, 16}, kSize, kSize, w.cells.data(), nullptr};
    ts_map_f* map = nullptr;
    ts_pool* pool = nullptr;
    if (ts_map_create_f(&desc, &map) != TS_OK ||
        ts_pool_create(static_cast<std::int32_t>(state.range(0)), &pool) != TS_OK) {
        state.SkipWithError("the C map or pool could not be made");
        ts_map_destroy_f(map);
        return;
    }
    std::vector<ts_mover_f> movers;
    for (const MoveInput<float>& m : w.mix)
        movers.push_back({{{m.box.pos.x, m.box.pos.y}, {m.box.size.x, m.box.size.y}},
                          {m.displacement.x, m.displacement.y}});
    std::vector<ts_result_f> results(movers.size());
    for (auto _ : state) {
        ts_move_and_slide_batch_f(map, movers.data(), results.data(), movers.size(), pool);
        benchmark::DoNotOptimize(results.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(movers.size()));
    state.counters["threads"] = static_cast<double>(state.range(0));
    ts_pool_destroy(pool);
    ts_map_destroy_f(map);
}
#endif

BENCHMARK(BM_MoveAndSlideBatch_Mix)->ArgName("threads")->Arg(1)->Arg(2)->UseRealTime();
BENCHMARK(BM_MoveAndSlideBatch_MixShuffled)->ArgName("threads")->Arg(1)->Arg(2)->UseRealTime();
BENCHMARK(BM_MoveAndSlideBatch_MixDouble)->ArgName("threads")->Arg(1)->Arg(2)->UseRealTime();
BENCHMARK(BM_MoveAndSlideBatch_MixAfterIdle)->ArgName("threads")->Arg(1)->Arg(2)->UseManualTime();
BENCHMARK(BM_MoveAndSlideBatch_Resting)->ArgName("threads")->Arg(1)->UseRealTime();
BENCHMARK(BM_MoveAndSlideBatch_Walking)->ArgName("threads")->Arg(1)->UseRealTime();
BENCHMARK(BM_MoveAndSlideBatch_Falling)->ArgName("threads")->Arg(1)->UseRealTime();
BENCHMARK(BM_MoveAndSlideBatch_Fast)->ArgName("threads")->Arg(1)->UseRealTime();
#if defined(TILESWEEP_BENCH_C_API)
BENCHMARK(BM_MoveAndSlideBatch_MixC)->ArgName("threads")->Arg(1)->Arg(2)->UseRealTime();
#endif

}  // namespace

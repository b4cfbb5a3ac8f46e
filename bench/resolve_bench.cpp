// SPDX-License-Identifier: MIT
// Benchmarks of the resolver and its peers, fixed seeds, items/s. Ratios are read side by side
// from one run (scripts/bench.sh computes them from the medians of repeated runs).
//
// Speeds are in tiles per frame, the benchmark argument divided by 2: 1 -> 0.5, 4 -> 2,
// 16 -> 8, 64 -> 32.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#if TILESWEEP_BENCH_HAVE_BOX2D
#include <box2d/b2_collision.h>
#include <box2d/b2_distance.h>
#include <box2d/b2_polygon_shape.h>
#include <box2d/b2_time_of_impact.h>
#endif

#include "frame_scenarios.h"
#include "side_by_side.h"

#include "tilesweep/baselines/grid_resolve.h"
#include "tilesweep/baselines/twin_resolve.h"
#include "tilesweep/oracle/exact/exact_geometry.h"
#include "tilesweep/oracle/exact/exact_resolve.h"
#include "tilesweep/oracle/seed/seed_resolve.h"
#include "tilesweep/oracle/substep/substep_float.h"
#include "tilesweep/scene/scene.h"
#include "tilesweep/tilesweep.hpp"

namespace {

using tilesweep::Box;
using tilesweep::Vec2;

constexpr int kTile = 16;
constexpr int kSamples = 512;

enum class Level { Random30, FloorAndWalls };

/// A map, and kSamples boxes that start in empty cells near its middle, each with a move of
/// the given speed in a random direction (the scenario library's map-size scenarios).
template <class T>
using Scenario = tilesweep::scenarios::FrameScenario<T>;

template <class T>
Scenario<T> makeScenario(int size, Level level, double tilesPerFrame, std::uint32_t seed = 12345) {
    using tilesweep::scenarios::FrameKind;
    return tilesweep::scenarios::makeMapScenario<T>(
        size, level == Level::Random30 ? FrameKind::Random30 : FrameKind::FloorAndWalls, tilesPerFrame,
        kSamples, seed);
}

template <class T>
const Scenario<T>& scenario(int size, Level level, int speedArg) {
    // One scenario per parameter set, built once (not timed).
    static std::vector<std::pair<std::tuple<int, int, int>, Scenario<T>>> cache;
    const auto key = std::make_tuple(size, static_cast<int>(level), speedArg);
    for (const auto& entry : cache)
        if (entry.first == key) return entry.second;
    cache.emplace_back(key, makeScenario<T>(size, level, speedArg / 2.0));
    return cache.back().second;
}

template <class T>
void resolveLoop(benchmark::State& state, const Scenario<T>& s) {
    const tilesweep::TileMapView<T> view = s.map.view();
    tilesweep::Contact<T> contacts[64];
    tilesweep::Cell overlaps[64];
    std::size_t k = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(
            tilesweep::resolveMove<T>({view, s.boxes[k], s.moves[k]}, {contacts, 64, overlaps, 64}));
        k = (k + 1) % s.boxes.size();
    }
    state.SetItemsProcessed(state.iterations());
}

// The production resolver, the common game case: one frame on a 256x256 map, 30% solid.
template <class T>
void BM_ResolveMove_Random30(benchmark::State& state) {
    resolveLoop<T>(state, scenario<T>(256, Level::Random30, static_cast<int>(state.range(0))));
}
BENCHMARK_TEMPLATE(BM_ResolveMove_Random30, float)->Arg(1)->Arg(4)->Arg(16)->Arg(64);
BENCHMARK_TEMPLATE(BM_ResolveMove_Random30, double)->Arg(1)->Arg(4)->Arg(16)->Arg(64);

// A platformer-like level: long floors and walls, long free flights.
template <class T>
void BM_ResolveMove_FloorAndWalls(benchmark::State& state) {
    resolveLoop<T>(state, scenario<T>(256, Level::FloorAndWalls, static_cast<int>(state.range(0))));
}
BENCHMARK_TEMPLATE(BM_ResolveMove_FloorAndWalls, float)->Arg(1)->Arg(4)->Arg(16)->Arg(64);
BENCHMARK_TEMPLATE(BM_ResolveMove_FloorAndWalls, double)->Arg(1)->Arg(4)->Arg(16)->Arg(64);

// The same level with every other floor a row of one-way platforms ('-'): a frame moving down
// runs the loop that tests them (src/frame_paths.h), the others the loop without; beside
// BM_ResolveMove_FloorAndWalls, the cost of the platforms.
template <class T>
const Scenario<T>& platformScenario(int speedArg) {
    static std::vector<std::pair<int, Scenario<T>>> cache;
    for (const auto& entry : cache)
        if (entry.first == speedArg) return entry.second;
    Scenario<T> s = makeScenario<T>(256, Level::FloorAndWalls, speedArg / 2.0);
    s.map.oneWay.assign(s.map.solid.size(), 0);
    const auto columns = static_cast<std::size_t>(s.map.columns);
    for (std::size_t j = 11; j < static_cast<std::size_t>(s.map.rows); j += 24)
        for (std::size_t i = 0; i < columns; ++i)
            if (s.map.solid[j * columns + i] != 0) {
                s.map.solid[j * columns + i] = 0;
                s.map.oneWay[j * columns + i] = 1;
            }
    cache.emplace_back(speedArg, std::move(s));
    return cache.back().second;
}

template <class T>
void BM_ResolveMove_Platforms(benchmark::State& state) {
    resolveLoop<T>(state, platformScenario<T>(static_cast<int>(state.range(0))));
}
BENCHMARK_TEMPLATE(BM_ResolveMove_Platforms, float)->Arg(1)->Arg(4)->Arg(16)->Arg(64);
BENCHMARK_TEMPLATE(BM_ResolveMove_Platforms, double)->Arg(1)->Arg(4)->Arg(16)->Arg(64);

// The map's size must cost nothing: the same motion (8 tiles/frame) on 64^2, 1024^2, 4096^2.
void BM_ResolveMove_MapSize(benchmark::State& state) {
    resolveLoop<float>(state, scenario<float>(static_cast<int>(state.range(0)), Level::Random30, 16));
}
BENCHMARK(BM_ResolveMove_MapSize)->Arg(64)->Arg(1024)->Arg(4096);

// What the broadphase buys: every solid tile of the map swept one by one (the narrow phase only,
// no frame loop), against the resolver's full frame above. 256^2 map, 8 tiles/frame.
void BM_BruteForce_EveryTile(benchmark::State& state) {
    const Scenario<float>& s = scenario<float>(static_cast<int>(state.range(0)), Level::Random30, 16);
    std::vector<std::pair<Vec2<float>, Vec2<float>>> tiles;
    for (int j = 0; j < s.map.rows; ++j)
        for (int i = 0; i < s.map.columns; ++i)
            if (s.map.solid[static_cast<std::size_t>(j * s.map.columns + i)] != 0)
                tiles.push_back(
                    {{float(i * kTile), float(j * kTile)}, {float((i + 1) * kTile), float((j + 1) * kTile)}});
    std::size_t k = 0;
    for (auto _ : state) {
        int hits = 0;
        for (const auto& [lo, hi] : tiles)
            hits += tilesweep::sweepBox<float>({s.boxes[k], s.moves[k], lo, hi}).status ==
                    tilesweep::BoxSweepStatus::Blocks;
        benchmark::DoNotOptimize(hits);
        k = (k + 1) % s.boxes.size();
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_BruteForce_EveryTile)->Arg(64)->Arg(256);

// The naive baselines the audit measures: the seed article's algorithm as written.
template <class T>
void BM_SeedResolve_Random30(benchmark::State& state) {
    const Scenario<T>& s = scenario<T>(256, Level::Random30, static_cast<int>(state.range(0)));
    std::size_t k = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(tilesweep::oracle::resolveFrameSeed<T>(s.map, s.boxes[k], s.moves[k]));
        k = (k + 1) % s.boxes.size();
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK_TEMPLATE(BM_SeedResolve_Random30, float)->Arg(1)->Arg(4)->Arg(16)->Arg(64);
BENCHMARK_TEMPLATE(BM_SeedResolve_Random30, double)->Arg(1)->Arg(4)->Arg(16)->Arg(64);

// The game-style float substep loop at N substeps (second argument), on a small map window so
// the copy of the scene it takes stays out of the measurement's way: 64^2 map.
void BM_SubstepFloat_Random30(benchmark::State& state) {
    const Scenario<float>& s = scenario<float>(64, Level::Random30, static_cast<int>(state.range(0)));
    std::vector<tilesweep::Scene<float>> scenes;
    for (std::size_t k = 0; k < 64; ++k) scenes.push_back({"", s.map, s.boxes[k], {s.moves[k]}});
    std::size_t k = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(
            tilesweep::oracle::resolveSceneSubstepFloat<float>(scenes[k], state.range(1)));
        k = (k + 1) % scenes.size();
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_SubstepFloat_Random30)->ArgsProduct({{1, 4, 16, 64}, {4, 16, 256}});

// The exact rational reference (GMP), every solid tile of a 64x64 map: what the property
// suite pays per frame it checks.
void BM_ExactReference_Random30(benchmark::State& state) {
    const Scenario<float>& s = scenario<float>(64, Level::Random30, static_cast<int>(state.range(0)));
    const tilesweep::oracle::ExactTileMap map = tilesweep::oracle::toExact(s.map);
    std::size_t k = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(tilesweep::oracle::resolveFrameExact(
            map, tilesweep::oracle::toExact(s.boxes[k]), tilesweep::oracle::toExact(s.moves[k])));
        k = (k + 1) % 64;
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ExactReference_Random30)->Arg(1)->Arg(16);

// One box against one tile, the narrow phase alone, on pairs that hit about half the time.
template <class T>
std::vector<tilesweep::BoxSweepInput<T>> makePairs() {
    std::mt19937 rng(777);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::vector<tilesweep::BoxSweepInput<T>> pairs;
    for (int k = 0; k < kSamples; ++k)
        pairs.push_back({{{static_cast<T>(unit(rng) * 40), static_cast<T>(unit(rng) * 40)}, {T(12), T(12)}},
                         {static_cast<T>(unit(rng) * 80), static_cast<T>(unit(rng) * 80)},
                         {T(0), T(0)},
                         {T(16), T(16)}});
    return pairs;
}

template <class T>
void BM_SweepBox_Pairs(benchmark::State& state) {
    const auto pairs = makePairs<T>();
    std::size_t k = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(tilesweep::sweepBox<T>(pairs[k]));
        k = (k + 1) % pairs.size();
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK_TEMPLATE(BM_SweepBox_Pairs, float);
BENCHMARK_TEMPLATE(BM_SweepBox_Pairs, double);

#if TILESWEEP_BENCH_HAVE_BOX2D
// Box2D's general time of impact (conservative advancement) on the same pairs: the peer a user
// might pick instead. It stops short of contact by design (its target separation). Float only:
// Box2D has no double build (v2.4's b2Vec2 holds floats, and v3's b2Vec2 too), so against
// BM_SweepBox_Pairs<double> there is no Box2D row to set beside it.
void BM_Box2D_TimeOfImpact_Pairs(benchmark::State& state) {
    const auto pairs = makePairs<float>();
    b2PolygonShape moving;
    moving.SetAsBox(6.0f, 6.0f);
    b2PolygonShape tile;
    tile.SetAsBox(8.0f, 8.0f);
    std::size_t k = 0;
    for (auto _ : state) {
        const auto& p = pairs[k];
        b2TOIInput input;
        input.proxyA.Set(&moving, 0);
        input.proxyB.Set(&tile, 0);
        const b2Vec2 c0(p.box.pos.x + 6.0f, p.box.pos.y + 6.0f);
        input.sweepA.localCenter.SetZero();
        input.sweepA.c0 = c0;
        input.sweepA.c = c0 + b2Vec2(p.displacement.x, p.displacement.y);
        input.sweepA.a0 = input.sweepA.a = 0.0f;
        input.sweepA.alpha0 = 0.0f;
        input.sweepB.localCenter.SetZero();
        input.sweepB.c0 = input.sweepB.c = b2Vec2(8.0f, 8.0f);
        input.sweepB.a0 = input.sweepB.a = 0.0f;
        input.sweepB.alpha0 = 0.0f;
        input.tMax = 1.0f;
        b2TOIOutput output;
        b2TimeOfImpact(&output, &input);
        benchmark::DoNotOptimize(output);
        k = (k + 1) % pairs.size();
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Box2D_TimeOfImpact_Pairs);
#endif

// ---------------------------------------------------------------------------------------------
// Side by side: tilesweep's exact resolver against the baselines a game developer
// would pick instead, on the same pre-generated frames (frame_scenarios.h, 65,536 per
// scenario), each with what it keeps per map (side_by_side.h): tilesweep on its PreparedMap
// (and TilesweepView, on the bare view, redoing the map's checks each frame); the lean inexact twin
// (baselines/: tilesweep/baselines/twin_resolve.h, plain T arithmetic, the same path-order walk, no libm
// call, the tile reciprocal computed once per map and the displacement's inverse once per step) and the lean
// swept-bounds grid resolver (grid_resolve.h there); TwinDividing, the twin that divides by the displacement
// in every tile test; and TwinLibm, which also takes its cell indices as std::floor/std::ceil of a quotient
// per cell. The last two are kept so that what each trick saves stays visible. Named
// BM_<Impl>_<Scenario><T>[/speed], registered scenario by scenario so that the implementations run next to
// each other.
// Why each scenario: Random30 and FloorAndWalls are the common cases at five speeds, up to the fast movers
// a sweep exists for; a box wider than a tile meets several cells in each column it crosses; resting on a
// floor is what a platformer does most frames (a hit at t = 0 and a slide, every frame); free flight is the
// cheapest useful frame (no hit: the walk's cost alone); far from the origin tilesweep's lattice needs wider
// integers; a zero move measures the fixed cost per call.

using tilesweep::bench::Impl;

template <class T>
const tilesweep::bench::FrameScenario<T>& frameScenario(tilesweep::bench::FrameKind kind, int speedArg) {
    // Built once per parameter set, outside the timed loop; kept for the whole run.
    static std::vector<std::pair<std::pair<int, int>, std::unique_ptr<tilesweep::bench::FrameScenario<T>>>>
        cache;
    const auto key = std::make_pair(static_cast<int>(kind), speedArg);
    for (const auto& entry : cache)
        if (entry.first == key) return *entry.second;
    cache.emplace_back(key, std::make_unique<tilesweep::bench::FrameScenario<T>>(
                                tilesweep::bench::makeFrameScenario<T>(kind, speedArg / 2.0)));
    return *cache.back().second;
}

template <class T, Impl I>
void frameLoop(benchmark::State& state, tilesweep::bench::FrameKind kind, int speedArg) {
    const tilesweep::bench::FrameScenario<T>& s = frameScenario<T>(kind, speedArg);
    const tilesweep::TileMapView<T> view = s.map.view();
    tilesweep::Contact<T> contacts[64];
    tilesweep::Cell overlaps[64];
    const tilesweep::ResolveOutput<T> out{contacts, 64, overlaps, 64};
    // What each resolver keeps per map, once, as a game keeps it beside its map.
    const tilesweep::bench::PerMap<T> perMap(view);
    std::size_t k = 0;
    for (auto _ : state) {
        const tilesweep::ResolveInput<T> in{view, s.boxes[k], s.moves[k]};
        benchmark::DoNotOptimize(tilesweep::bench::resolveWith<T, I>(in, out, perMap));
        benchmark::ClobberMemory();
        k = (k + 1) & (tilesweep::bench::kFrameCount - 1);
    }
    state.SetItemsProcessed(state.iterations());
}

template <class T, Impl I>
void registerFrameBenchmark(const char* impl, const char* scalar, tilesweep::bench::FrameKind kind,
                            int speedArg) {
    std::string name = std::string("BM_") + impl + "_" + tilesweep::bench::nameOf(kind) + "<" + scalar + ">";
    if (speedArg > 0) name += "/" + std::to_string(speedArg);
    benchmark::RegisterBenchmark(
        name.c_str(), [kind, speedArg](benchmark::State& state) { frameLoop<T, I>(state, kind, speedArg); });
}

template <class T>
void registerFrameBenchmarks(const char* scalar, tilesweep::bench::FrameKind kind, int speedArg) {
    registerFrameBenchmark<T, Impl::Tilesweep>("Tilesweep", scalar, kind, speedArg);
    registerFrameBenchmark<T, Impl::TilesweepView>("TilesweepView", scalar, kind, speedArg);
    registerFrameBenchmark<T, Impl::Twin>("Twin", scalar, kind, speedArg);
    registerFrameBenchmark<T, Impl::Grid>("Grid", scalar, kind, speedArg);
    registerFrameBenchmark<T, Impl::TwinDividing>("TwinDividing", scalar, kind, speedArg);
    registerFrameBenchmark<T, Impl::TwinLibm>("TwinLibm", scalar, kind, speedArg);
}

bool registerSideBySide() {
    for (const tilesweep::bench::SideBySideScenario& e : tilesweep::bench::kSideBySideScenarios) {
        registerFrameBenchmarks<float>("float", e.kind, e.speedArg);
        registerFrameBenchmarks<double>("double", e.kind, e.speedArg);
    }
    return true;
}

const bool kSideBySideRegistered = registerSideBySide();

}  // namespace

// SPDX-License-Identifier: MIT
// First timings of the resolver: one frame of a 12x12 box through a 256x256 map with 30% solid
// cells, at several speeds, in float and double; and a single box-against-tile sweep.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "tilesweep/sweep.h"

namespace {

using tilesweep::Box;
using tilesweep::Vec2;

constexpr int kMapSize = 256;
constexpr int kTile = 16;
constexpr int kScenes = 1024;

template <class T>
struct Scenario {
    std::vector<std::uint8_t> cells;
    tilesweep::TileMapView<T> map;
    std::vector<Box<T>> boxes;
    std::vector<Vec2<T>> moves;
};

/// A random 30% map and kScenes boxes, each starting in an empty cell, moving `tilesPerFrame`
/// tiles in a random direction. Fixed seed: the same scenes every run.
template <class T>
Scenario<T> makeScenario(double tilesPerFrame) {
    Scenario<T> s;
    std::mt19937 rng(12345);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    s.cells.resize(kMapSize * kMapSize);
    for (auto& c : s.cells) c = unit(rng) < 0.3 ? 1 : 0;
    s.map = {{0, 0}, {T(kTile), T(kTile)}, kMapSize, kMapSize, s.cells.data()};
    std::uniform_int_distribution<int> cell(8, kMapSize - 8);
    while (static_cast<int>(s.boxes.size()) < kScenes) {
        const int i = cell(rng);
        const int j = cell(rng);
        if (s.cells[static_cast<std::size_t>(j * kMapSize + i)] != 0) continue;
        const double angle = unit(rng) * 6.283185307179586;
        const double speed = tilesPerFrame * kTile;
        s.boxes.push_back({{static_cast<T>(i * kTile + 2 + unit(rng)), static_cast<T>(j * kTile + 2 + unit(rng))},
                           {T(12), T(12)}});
        s.moves.push_back({static_cast<T>(speed * std::cos(angle)), static_cast<T>(speed * std::sin(angle))});
    }
    return s;
}

// The common game case: one frame of motion at a given speed, tiles per frame as the argument
// divided by 2 (1 -> 0.5, 4 -> 2, 16 -> 8, 64 -> 32).
template <class T>
void BM_ResolveMove_RandomMap(benchmark::State& state) {
    const Scenario<T> s = makeScenario<T>(static_cast<double>(state.range(0)) / 2.0);
    tilesweep::Contact<T> contacts[64];
    tilesweep::Cell overlaps[64];
    std::size_t k = 0;
    for (auto _ : state) {
        const auto r = tilesweep::resolveMove<T>({s.map, s.boxes[k], s.moves[k]}, {contacts, 64, overlaps, 64});
        benchmark::DoNotOptimize(r);
        k = (k + 1) % s.boxes.size();
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK_TEMPLATE(BM_ResolveMove_RandomMap, float)->Arg(1)->Arg(4)->Arg(16)->Arg(64);
BENCHMARK_TEMPLATE(BM_ResolveMove_RandomMap, double)->Arg(1)->Arg(4)->Arg(16)->Arg(64);

// One box against one tile: the narrow phase on its own.
template <class T>
void BM_SweepBox_SingleTile(benchmark::State& state) {
    const Scenario<T> s = makeScenario<T>(2.0);
    std::size_t k = 0;
    for (auto _ : state) {
        const Box<T>& b = s.boxes[k];
        const tilesweep::BoxSweepInput<T> in{b, s.moves[k], {b.pos.x + 20, b.pos.y - 4}, {b.pos.x + 36, b.pos.y + 12}};
        benchmark::DoNotOptimize(tilesweep::sweepBox<T>(in));
        k = (k + 1) % s.boxes.size();
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK_TEMPLATE(BM_SweepBox_SingleTile, float);
BENCHMARK_TEMPLATE(BM_SweepBox_SingleTile, double);

}  // namespace

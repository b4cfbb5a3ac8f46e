// SPDX-License-Identifier: MIT
#pragma once

#include "tilesweep/scene/scene.h"
#include "tilesweep/tilesweep.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

// The benchmarks' frame scenarios (scenarios/README.md): pre-generated frames for the
// side-by-side benchmarks of tilesweep, the inexact twin and the swept-bounds grid resolver
// (resolve_bench.cpp), and for the decision-agreement count (twin_agreement.cpp): one 256x256 map of 16-px
// tiles per scenario and kFrameCount independent frames (box, move) on it. Fixed seeds: the same frames every
// run, on every machine with the same standard library.

namespace tilesweep::scenarios {

/// Frames per scenario: 65,536, a power of two, so that the loop index wraps by mask.
inline constexpr std::size_t kFrameCount = 65536;
inline constexpr int kFrameMapSize = 256;
inline constexpr int kFrameTile = 16;

/// Which frames; see makeFrameScenario for what each one is and why it matters.
enum class FrameKind { Random30, FloorAndWalls, RestingOnFloor, FreeFlight, FarRandom30, ZeroMove, WideBox };

/// The name used in benchmark names, BM_<Impl>_<name>.
inline const char* nameOf(FrameKind kind) noexcept {
    switch (kind) {
        case FrameKind::Random30:
            return "Random30";
        case FrameKind::FloorAndWalls:
            return "FloorAndWalls";
        case FrameKind::RestingOnFloor:
            return "RestingOnFloor";
        case FrameKind::FreeFlight:
            return "FreeFlight";
        case FrameKind::FarRandom30:
            return "FarRandom30";
        case FrameKind::ZeroMove:
            return "ZeroMove";
        case FrameKind::WideBox:
            return "WideBox";
    }
    return "?";
}

/// One side-by-side scenario: the frames of `kind` at `speedArg`, twice the speed in tiles a frame
/// (1 -> 0.5, 4 -> 2, 16 -> 8, 64 -> 32, 128 -> 64; 0 for the kinds without a speed).
struct SideBySideScenario {
    FrameKind kind;
    int speedArg;
};

/// The scenarios the benchmarks time tilesweep and the baselines on side by side
/// (BM_<Impl>_<Scenario>) and the twin agreement tool counts their disagreements on, in order.
inline constexpr SideBySideScenario kSideBySideScenarios[] = {
    {FrameKind::Random30, 1},        {FrameKind::Random30, 4},       {FrameKind::Random30, 16},
    {FrameKind::Random30, 64},       {FrameKind::Random30, 128},     {FrameKind::FloorAndWalls, 1},
    {FrameKind::FloorAndWalls, 4},   {FrameKind::FloorAndWalls, 16}, {FrameKind::FloorAndWalls, 64},
    {FrameKind::FloorAndWalls, 128}, {FrameKind::WideBox, 16},       {FrameKind::RestingOnFloor, 0},
    {FrameKind::FreeFlight, 4},      {FrameKind::FarRandom30, 1},    {FrameKind::FarRandom30, 4},
    {FrameKind::FarRandom30, 16},    {FrameKind::FarRandom30, 64},   {FrameKind::ZeroMove, 0},
};

/// A map and kFrameCount frames on it.
template <class T>
struct FrameScenario {
    TileMap<T> map;
    std::vector<Box<T>> boxes;
    std::vector<Vec2<T>> moves;
};

/// Far from the origin: 2^20 on both axes, where a float's ulp is 1/8 px.
inline constexpr double kFarOrigin = 1048576.0;

/// Builds one scenario. `tilesPerFrame` is the speed of the random-direction moves (Random30,
/// FloorAndWalls, FreeFlight, FarRandom30); RestingOnFloor and ZeroMove ignore it.
template <class T>
FrameScenario<T> makeFrameScenario(FrameKind kind, double tilesPerFrame) {
    constexpr int n = kFrameMapSize;
    FrameScenario<T> s;
    std::mt19937 rng(20240 + static_cast<std::uint32_t>(kind));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double origin = kind == FrameKind::FarRandom30 ? kFarOrigin : 0.0;
    s.map.origin = {static_cast<T>(origin), static_cast<T>(origin)};
    s.map.tileSize = {T(kFrameTile), T(kFrameTile)};
    s.map.columns = n;
    s.map.rows = n;
    s.map.solid.assign(static_cast<std::size_t>(n) * n, 0);
    const auto at = [](int i, int j) {
        return static_cast<std::size_t>(j) * n + static_cast<std::size_t>(i);
    };
    const bool random30 = kind == FrameKind::Random30 || kind == FrameKind::FarRandom30 ||
                          kind == FrameKind::ZeroMove || kind == FrameKind::WideBox;
    const bool floors = kind == FrameKind::FloorAndWalls || kind == FrameKind::RestingOnFloor;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            bool solid = false;
            if (random30) solid = unit(rng) < 0.3;
            // Floors every 12 rows with gaps, walls every 20 columns with doors (as makeScenario).
            if (floors) solid = (j % 12 == 11 && i % 9 != 4) || (i % 20 == 19 && j % 12 < 8);
            s.map.solid[at(i, j)] = solid ? 1 : 0;
        }
    // Boxes start in a 64x64-cell window in the middle, 12x12 px, inside an empty cell; WideBox's
    // are 40x40 px (2.5 tiles), inside a 3x3 block of empty cells.
    const double side = kind == FrameKind::WideBox ? 40.0 : 12.0;
    std::uniform_int_distribution<int> cell(n / 2 - 30, n / 2 + 29);
    s.boxes.reserve(kFrameCount);
    s.moves.reserve(kFrameCount);
    while (s.boxes.size() < kFrameCount) {
        const int i = cell(rng);
        const int j = cell(rng);
        if (kind == FrameKind::RestingOnFloor) {
            // Standing exactly on a floor tile's top (y + h == its top edge), walking at up to
            // 2 px/frame, with one frame of gravity (900 px/s^2 at 60 Hz: 0.25 px) pulling down.
            if (j % 12 != 11 || s.map.solid[at(i, j)] == 0) continue;
            s.boxes.push_back(
                {{static_cast<T>(i * kFrameTile + 4 * unit(rng)), static_cast<T>(j * kFrameTile - 12)},
                 {T(12), T(12)}});
            s.moves.push_back({static_cast<T>(4 * unit(rng) - 2), T(0.25)});
            continue;
        }
        if (s.map.solid[at(i, j)] != 0) continue;
        if (kind == FrameKind::WideBox) {
            bool clear = true;
            for (int dj = 0; dj < 3; ++dj)
                for (int di = 0; di < 3; ++di) clear = clear && s.map.solid[at(i + di, j + dj)] == 0;
            if (!clear) continue;
        }
        const double angle = unit(rng) * 6.283185307179586;
        const double speed = kind == FrameKind::ZeroMove ? 0.0 : tilesPerFrame * kFrameTile;
        s.boxes.push_back({{static_cast<T>(origin + i * kFrameTile + 2 + unit(rng)),
                            static_cast<T>(origin + j * kFrameTile + 2 + unit(rng))},
                           {static_cast<T>(side), static_cast<T>(side)}});
        s.moves.push_back({static_cast<T>(speed * std::cos(angle)), static_cast<T>(speed * std::sin(angle))});
    }
    return s;
}

/// The map-size scenarios of the resolver benchmarks (BM_*_Random30, BM_*_FloorAndWalls over map
/// sizes): a size x size map of 16-px tiles, Random30 or FloorAndWalls as above, and `samples`
/// boxes (12 x 12) starting in empty cells of a 64x64-cell window in its middle, so the motion is
/// the same on every map size, each with a move of `tilesPerFrame` tiles in a random direction.
/// The same seed gives the same frames every run.
template <class T>
FrameScenario<T> makeMapScenario(int size, FrameKind kind, double tilesPerFrame, std::size_t samples,
                                 std::uint32_t seed = 12345) {
    FrameScenario<T> s;
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    s.map.origin = {0, 0};
    s.map.tileSize = {T(kFrameTile), T(kFrameTile)};
    s.map.columns = size;
    s.map.rows = size;
    s.map.solid.assign(static_cast<std::size_t>(size) * static_cast<std::size_t>(size), 0);
    const auto at = [size](int i, int j) {
        return static_cast<std::size_t>(j) * static_cast<std::size_t>(size) + static_cast<std::size_t>(i);
    };
    for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i) {
            bool solid = false;
            if (kind == FrameKind::Random30) solid = unit(rng) < 0.3;
            // Floors every 12 rows with gaps, walls every 20 columns with doors.
            if (kind == FrameKind::FloorAndWalls)
                solid = (j % 12 == 11 && i % 9 != 4) || (i % 20 == 19 && j % 12 < 8);
            s.map.solid[at(i, j)] = solid ? 1 : 0;
        }
    const int lo = size / 2 - std::min(size / 2, 32) + 2;
    const int hi = size / 2 + std::min(size / 2, 32) - 2;
    std::uniform_int_distribution<int> cell(lo, hi - 1);
    while (s.boxes.size() < samples) {
        const int i = cell(rng);
        const int j = cell(rng);
        if (s.map.solid[at(i, j)] != 0) continue;
        const double angle = unit(rng) * 6.283185307179586;
        const double speed = tilesPerFrame * kFrameTile;
        s.boxes.push_back(
            {{static_cast<T>(i * kFrameTile + 2 + unit(rng)), static_cast<T>(j * kFrameTile + 2 + unit(rng))},
             {T(12), T(12)}});
        s.moves.push_back({static_cast<T>(speed * std::cos(angle)), static_cast<T>(speed * std::sin(angle))});
    }
    return s;
}

}  // namespace tilesweep::scenarios

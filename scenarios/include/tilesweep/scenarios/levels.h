// SPDX-License-Identifier: MIT
#pragma once

#include "tilesweep/tile_map.h"

#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

// Platformer levels (scenarios/README.md): a bordered map of 128 x 48 cells with ground three
// cells thick broken by pits, platforms and walls standing on the ground, at tile sizes and
// origins a game might use, near and far from the origin (far away the positions are coarse: the
// ulp at 2^20 is 1/8 for float, and every frame rounds). The soak's random walkers run through
// them. Header-only and free of the scene layer: it needs only the library's types.

namespace tilesweep::scenarios {

inline constexpr std::int32_t kLevelColumns = 128;
inline constexpr std::int32_t kLevelRows = 48;

/// A level: its cells (row-major from the top, 1 solid) and where the map lies.
template <class T>
struct PlatformLevel {
    std::vector<std::uint8_t> solid;
    Vec2<T> origin{};
    T tile{};

    /// A view of the level, valid while it lives and is not rebuilt.
    [[nodiscard]] TileMapView<T> view() const {
        return {origin, {tile, tile}, kLevelColumns, kLevelRows, solid.data()};
    }
};

/// Builds a level from `random`, drawing from it in a fixed order (the same engine state gives
/// the same level).
template <class T>
[[nodiscard]] PlatformLevel<T> buildPlatformLevel(std::mt19937_64& random) {
    const auto uniform = [&random](double lo, double hi) {
        return std::uniform_real_distribution<double>(lo, hi)(random);
    };
    PlatformLevel<T> level;
    level.solid.assign(static_cast<std::size_t>(kLevelColumns * kLevelRows), 0);
    const auto set = [&level](std::int32_t i, std::int32_t j) {
        if (i >= 0 && i < kLevelColumns && j >= 0 && j < kLevelRows)
            level.solid[static_cast<std::size_t>(j * kLevelColumns + i)] = 1;
    };
    for (std::int32_t i = 0; i < kLevelColumns; ++i) set(i, 0), set(i, kLevelRows - 1);
    for (std::int32_t j = 0; j < kLevelRows; ++j) set(0, j), set(kLevelColumns - 1, j);
    // Ground three cells thick, broken by pits that drop to the bottom border.
    for (std::int32_t i = 1; i < kLevelColumns - 1; ++i) {
        if (uniform(0, 1) < 0.06) {
            i += static_cast<std::int32_t>(uniform(2, 6));
            continue;
        }
        for (std::int32_t j = kLevelRows - 4; j < kLevelRows - 1; ++j) set(i, j);
    }
    for (int k = 0; k < 45; ++k) {  // platforms
        const auto i = static_cast<std::int32_t>(uniform(1, kLevelColumns - 10));
        const auto j = static_cast<std::int32_t>(uniform(4, kLevelRows - 8));
        const auto length = static_cast<std::int32_t>(uniform(2, 11));
        for (std::int32_t n = 0; n < length; ++n) set(i + n, j);
    }
    for (int k = 0; k < 12; ++k) {  // walls standing on the ground
        const auto i = static_cast<std::int32_t>(uniform(2, kLevelColumns - 3));
        const auto height = static_cast<std::int32_t>(uniform(2, 9));
        for (std::int32_t n = 1; n <= height; ++n) set(i, kLevelRows - 4 - n);
    }
    const T tiles[] = {T(16), T(8), T(32), T(12.5), T(0.75)};
    level.tile = tiles[static_cast<std::size_t>(uniform(0, 5))];
    const T far = sizeof(T) == 4 ? T(1048576) : T(1099511627776.0);
    const T origins[] = {T(0), T(-640), T(0.5), far, -far};
    const T origin = origins[static_cast<std::size_t>(uniform(0, 5))];
    level.origin = {origin, origin * T(0.5)};
    return level;
}

}  // namespace tilesweep::scenarios

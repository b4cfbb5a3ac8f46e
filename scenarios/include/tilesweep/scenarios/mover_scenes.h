// SPDX-License-Identifier: MIT
#pragma once

// The mover scenes: random scenes for the game-loop and batch tests (tests/mover_test.cpp,
// tests/batch_test.cpp), small maps with full floors and walls mixed in, boxes and moves on a
// quarter-tile lattice (so exact corner ties, grid-aligned edges and contacts on many tiles at
// once are common) or at arbitrary values, in float or double; and Level, a map written as rows
// of '#' and '.'. Plain std::mt19937_64, no RapidCheck: target tilesweep::mover_scenes needs
// only the library.

#include "tilesweep/math.h"
#include "tilesweep/tile_map.h"

#include <cstdint>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

namespace tilesweep::scenarios {

/// A map from rows of '#' and '.', owning its cells.
template <class T>
struct Level {
    std::vector<std::uint8_t> cells;
    Vec2<T> origin{0, 0};
    Vec2<T> tile{16, 16};
    std::int32_t columns = 0;
    std::int32_t rows = 0;

    Level() = default;
    explicit Level(const std::vector<std::string>& lines, Vec2<T> o = {0, 0}, Vec2<T> t = {16, 16})
        : origin(o), tile(t) {
        for (const std::string& line : lines)
            for (char c : line) cells.push_back(c == '#' ? 1 : 0);
        columns = static_cast<std::int32_t>(lines.empty() ? 0 : lines[0].size());
        rows = static_cast<std::int32_t>(lines.size());
    }
    [[nodiscard]] TileMapView<T> view() const noexcept { return {origin, tile, columns, rows, cells.data()}; }
};

template <class T>
struct RandomScene : Level<T> {
    Box<T> box{};
    Vec2<T> move{};

    [[nodiscard]] std::string describe() const {
        char buf[256];
        std::snprintf(buf, sizeof buf, "box (%a, %a, %a, %a) move (%a, %a) tile (%a, %a) origin (%a, %a) ",
                      static_cast<double>(box.pos.x), static_cast<double>(box.pos.y),
                      static_cast<double>(box.size.x), static_cast<double>(box.size.y),
                      static_cast<double>(move.x), static_cast<double>(move.y),
                      static_cast<double>(this->tile.x), static_cast<double>(this->tile.y),
                      static_cast<double>(this->origin.x), static_cast<double>(this->origin.y));
        std::string s = buf;
        s += "rows [";
        for (std::int32_t j = 0; j < this->rows; ++j) {
            s += '"';
            for (std::int32_t i = 0; i < this->columns; ++i)
                s += this->cells[static_cast<std::size_t>(j * this->columns + i)] ? '#' : '.';
            s += j + 1 < this->rows ? "\", " : "\"";
        }
        return s + "]";
    }
};

namespace detail {

inline int pick(std::mt19937_64& rng, int lo, int hi) {
    return std::uniform_int_distribution<int>(lo, hi)(rng);
}

inline double real(std::mt19937_64& rng, double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng);
}

}  // namespace detail

/// A random box and move for a mover on `level` (sizes, positions and moves as randomScene's).
template <class T>
void randomMover(std::mt19937_64& rng, const Level<T>& level, Box<T>& box, Vec2<T>& move) {
    using detail::pick;
    using detail::real;
    const double t[2] = {static_cast<double>(level.tile.x), static_cast<double>(level.tile.y)};
    const double o[2] = {static_cast<double>(level.origin.x), static_cast<double>(level.origin.y)};
    // Sizes: whole tiles, fractions of a tile, or arbitrary.
    auto size = [&](double tile) {
        switch (pick(rng, 0, 2)) {
            case 0:
                return static_cast<T>(tile * pick(rng, 1, 4));
            case 1:
                return static_cast<T>(tile * pick(rng, 1, 15) / 4.0);
            default:
                return static_cast<T>(tile * real(rng, 0.05, 5));
        }
    };
    box.size = {size(t[0]), size(t[1])};
    // Positions: on the quarter-tile lattice around the map, or arbitrary.
    auto coordinate = [&](double origin, double tile, int count) {
        if (pick(rng, 0, 3) != 0) return static_cast<T>(origin + tile * pick(rng, -8, 4 * count + 8) / 4.0);
        return static_cast<T>(origin + tile * real(rng, -2, count + 2));
    };
    box.pos = {coordinate(o[0], t[0], level.columns), coordinate(o[1], t[1], level.rows)};
    // Moves: zero, lattice steps, arbitrary, tiny or huge.
    auto displacement = [&](double tile) {
        switch (pick(rng, 0, 5)) {
            case 0:
                return T(0);
            case 1:
            case 2:
                return static_cast<T>(tile * pick(rng, -64, 64) / 8.0);
            case 3:
                return static_cast<T>(tile * real(rng, -6, 6));
            case 4:
                return static_cast<T>(tile * real(rng, -1, 1) * 1e-6);
            default:
                return static_cast<T>(tile * real(rng, -1000, 1000));
        }
    };
    move = {displacement(t[0]), displacement(t[1])};
}

/// One random scene (map, box, move) in T.
template <class T>
RandomScene<T> randomScene(std::mt19937_64& rng) {
    using detail::pick;
    using detail::real;
    RandomScene<T> s;
    static const double tiles[][2] = {{16, 16}, {1, 1}, {8, 4}, {0.5, 2}, {3, 5}};
    static const double origins[][2] = {{0, 0}, {-8, 4}, {0.25, -0.75}, {1000, -2000}};
    const auto& t = tiles[pick(rng, 0, 4)];
    const auto& o = origins[pick(rng, 0, 3)];
    s.tile = {static_cast<T>(t[0]), static_cast<T>(t[1])};
    s.origin = {static_cast<T>(o[0]), static_cast<T>(o[1])};
    s.columns = pick(rng, 1, 14);
    s.rows = pick(rng, 1, 14);
    static const double densities[] = {0, 0.1, 0.3, 0.6, 0.95};
    const double density = densities[pick(rng, 0, 4)];
    s.cells.assign(static_cast<std::size_t>(s.columns * s.rows), 0);
    for (auto& c : s.cells) c = real(rng, 0, 1) < density ? 1 : 0;
    if (pick(rng, 0, 2) == 0) {  // a full floor row
        const int j = pick(rng, 0, s.rows - 1);
        for (int i = 0; i < s.columns; ++i) s.cells[static_cast<std::size_t>(j * s.columns + i)] = 1;
    }
    if (pick(rng, 0, 3) == 0) {  // a full wall column
        const int i = pick(rng, 0, s.columns - 1);
        for (int j = 0; j < s.rows; ++j) s.cells[static_cast<std::size_t>(j * s.columns + i)] = 1;
    }
    randomMover(rng, s, s.box, s.move);
    return s;
}

}  // namespace tilesweep::scenarios

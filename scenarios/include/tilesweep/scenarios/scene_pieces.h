// SPDX-License-Identifier: MIT
#pragma once

// The parameterised pieces every family is built from (families.h): a grid of cells, tile sizes,
// origins near and far, lengths and displacements on the tile/8 grid, a scene from them, the
// cells under a box cleared, one-ulp nudges, the axes swapped. RapidCheck generators, so a
// failing scene shrinks on clean values; every function inline (RapidCheck's example
// Generators.h is an ODR trap otherwise).

#include "tilesweep/scenarios/family.h"
#include "tilesweep/scene/scene.h"

#include <rapidcheck.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <type_traits>
#include <vector>

namespace tilesweep::scenarios {

/// Calls `f(v)` for every number of `scene` that is an input: the map's origin and tile size, the
/// box's position and size, then every move, x before y.
template <class T, class F>
void forEachSceneValue(const Scene<T>& scene, F&& f) {
    for (const Vec2<T>& v : {scene.map.origin, scene.map.tileSize, scene.box.pos, scene.box.size}) {
        f(v.x);
        f(v.y);
    }
    for (const Vec2<T>& m : scene.moves) {
        f(m.x);
        f(m.y);
    }
}

}  // namespace tilesweep::scenarios

namespace tilesweep::scenarios::detail {

/// What a Grid cell holds: the map's three kinds, one byte each.
inline constexpr std::uint8_t kEmptyCell = 0;
inline constexpr std::uint8_t kSolidCell = 1;
inline constexpr std::uint8_t kOneWayCell = 2;

/// The cells of a map being built, row-major from the top row; makeScene splits them into the
/// map's solid and one-way flags. Writes outside the grid are ignored.
template <class T>
struct Grid {
    int columns = 0;
    int rows = 0;
    std::vector<std::uint8_t> cells;  ///< kEmptyCell, kSolidCell or kOneWayCell
    void put(int i, int j, std::uint8_t kind) {
        if (i >= 0 && j >= 0 && i < columns && j < rows)
            cells[static_cast<std::size_t>(j * columns + i)] = kind;
    }
    void set(int i, int j, bool solid) { put(i, j, solid ? kSolidCell : kEmptyCell); }
    void setOneWay(int i, int j) { put(i, j, kOneWayCell); }
    [[nodiscard]] std::uint8_t kind(int i, int j) const {
        return i >= 0 && j >= 0 && i < columns && j < rows ? cells[static_cast<std::size_t>(j * columns + i)]
                                                           : kEmptyCell;
    }
    /// Whether cell (i, j) holds anything, solid or one-way.
    [[nodiscard]] bool get(int i, int j) const { return kind(i, j) != kEmptyCell; }
};

/// Tile sizes: powers of two and integers such as 12 or 24.
inline rc::Gen<int> genTileSize() { return rc::gen::element(16, 8, 32, 12, 24, 16, 4); }

/// The origin that genOrigin gives while buildScene places a scene at a magnitude (the audit's
/// far columns): set and cleared by buildScene on its own thread, empty otherwise.
inline std::optional<double>& placedOriginMagnitude() {
    static thread_local std::optional<double> magnitude;
    return magnitude;
}

/// A map origin: zero mostly, a few tiles off, or far away (up to 2^23 in float, 2^40 in
/// double) where the ulp of a coordinate is large. Always a multiple of the tile size, so every
/// edge is an integer and representable. While buildScene places a scene at a magnitude, that
/// magnitude rounded down to whole tiles: the same local scene, built where the magnitude's ulps
/// are (a one-ulp nudge is one ulp there).
template <class T>
rc::Gen<double> genOrigin(int tile) {
    if (const std::optional<double>& m = placedOriginMagnitude())
        return rc::gen::just(std::floor(*m / tile) * tile);
    const double far = std::is_same<T, float>::value ? 8388608.0 : 1099511627776.0;
    return rc::gen::weightedOneOf<double>(
        {{6, rc::gen::just(0.0)},
         {2, rc::gen::map(rc::gen::inRange(-8, 9), [tile](int k) { return double(k * tile); })},
         {2, rc::gen::map(rc::gen::inRange(-2, 3), [far, tile](int k) {
              return k * far + (k < 0 ? -8.0 : 8.0) * tile;  // stays a multiple of tile
          })}});
}

/// A length on the grid tile/8, from a fraction of a tile to `maxTiles` tiles; sometimes a
/// non-dyadic decimal such as 12.3 (rounded once to T).
template <class T>
rc::Gen<T> genLength(int tile, int maxEighths) {
    return rc::gen::weightedOneOf<T>(
        {{8, rc::gen::map(rc::gen::inRange(1, maxEighths + 1),
                          [tile](int n) { return static_cast<T>(n * tile / 8.0); })},
         {2, rc::gen::map(rc::gen::inRange(1, maxEighths * tile / 8 * 10 + 1),
                          [](int n) { return static_cast<T>(n / 10.0); })}});
}

/// A displacement component: zero, below one ulp of `at`, on the tile/8 grid up to 100 tiles,
/// or a decimal; either sign.
template <class T>
rc::Gen<T> genDisplacement(int tile, T at) {
    const T ulp = std::nextafter(std::fabs(at), std::numeric_limits<T>::infinity()) - std::fabs(at);
    return rc::gen::weightedOneOf<T>(
        {{2, rc::gen::just(T(0))},
         {1, rc::gen::map(rc::gen::inRange(-3, 4), [ulp](int n) { return static_cast<T>(n) * ulp / 4; })},
         {6,
          rc::gen::map(rc::gen::inRange(-64, 65), [tile](int n) { return static_cast<T>(n * tile / 8.0); })},
         {2, rc::gen::map(rc::gen::inRange(-800, 801),
                          [tile](int n) { return static_cast<T>(n * tile / 8.0); })},
         {2, rc::gen::map(rc::gen::inRange(-3000, 3001), [](int n) { return static_cast<T>(n / 10.0); })}});
}

template <class T>
Scene<T> makeScene(const Grid<T>& g, double ox, double oy, double tile, Box<T> box,
                   std::vector<Vec2<T>> moves) {
    Scene<T> s;
    s.map.origin = {static_cast<T>(ox), static_cast<T>(oy)};
    s.map.tileSize = {static_cast<T>(tile), static_cast<T>(tile)};
    s.map.columns = g.columns;
    s.map.rows = g.rows;
    s.map.solid.resize(g.cells.size());
    const bool anyOneWay = std::find(g.cells.begin(), g.cells.end(), kOneWayCell) != g.cells.end();
    if (anyOneWay) s.map.oneWay.assign(g.cells.size(), 0);
    for (std::size_t k = 0; k < g.cells.size(); ++k) {
        s.map.solid[k] = g.cells[k] == kSolidCell ? 1 : 0;
        if (anyOneWay) s.map.oneWay[k] = g.cells[k] == kOneWayCell ? 1 : 0;
    }
    s.box = box;
    s.moves = std::move(moves);
    return s;
}

/// Clears the cells the box overlaps (or touches) at its start, so it starts free; with
/// `keepOneWay`, only the solid ones (a box may start inside a platform: it jumps through it).
template <class T>
void clearUnder(Grid<T>& g, double ox, double oy, double tile, Box<T> box, bool keepOneWay = false) {
    const double x0 = (static_cast<double>(box.pos.x) - ox) / tile;
    const double y0 = (static_cast<double>(box.pos.y) - oy) / tile;
    const double x1 = x0 + static_cast<double>(box.size.x) / tile;
    const double y1 = y0 + static_cast<double>(box.size.y) / tile;
    // Cell indices clamped to just outside the grid first: a box far beyond the map (the extreme
    // family) would overflow an int.
    const auto cell = [](double v, int cells) {
        return static_cast<int>(std::max(-2.0, std::min(v, cells + 1.0)));
    };
    for (int j = cell(std::floor(y0) - 1, g.rows); j <= cell(std::floor(y1), g.rows); ++j)
        for (int i = cell(std::floor(x0) - 1, g.columns); i <= cell(std::floor(x1), g.columns); ++i)
            if (i + 1 > x0 && i < x1 && j + 1 > y0 && j < y1 && !(keepOneWay && g.kind(i, j) == kOneWayCell))
                g.set(i, j, false);
}

template <class T>
T offGrid(T v, int direction) {
    return std::nextafter(
        v, direction > 0 ? std::numeric_limits<T>::infinity() : -std::numeric_limits<T>::infinity());
}

/// Swaps the axes of a scene: the same scene on y, when it has no one-way cell (a platform is
/// one-way on y only; its cells are carried over, but the scene is another one).
template <class T>
Scene<T> transposed(const Scene<T>& scene) {
    Scene<T> t = scene;
    std::swap(t.map.origin.x, t.map.origin.y);
    std::swap(t.map.tileSize.x, t.map.tileSize.y);
    std::swap(t.box.pos.x, t.box.pos.y);
    std::swap(t.box.size.x, t.box.size.y);
    for (Vec2<T>& m : t.moves) std::swap(m.x, m.y);
    std::swap(t.map.columns, t.map.rows);
    for (int j = 0; j < scene.map.rows; ++j)
        for (int i = 0; i < scene.map.columns; ++i) {
            const auto from = static_cast<std::size_t>(j * scene.map.columns + i);
            const auto to = static_cast<std::size_t>(i * t.map.columns + j);
            t.map.solid[to] = scene.map.solid[from];
            if (!scene.map.oneWay.empty()) t.map.oneWay[to] = scene.map.oneWay[from];
        }
    return t;
}

}  // namespace tilesweep::scenarios::detail

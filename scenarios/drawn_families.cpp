// SPDX-License-Identifier: MIT
// The drawn families (drawn_families.h): the audit's populations, seeded std::mt19937_64 builders.
#include "tilesweep/scenarios/drawn_families.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <random>
#include <stdexcept>

namespace tilesweep::scenarios {
namespace {

// The random source of one scene, with the few draws the families need. Coordinates are drawn
// in double in the scene's local frame (the map's origin at 0), then translated by `offset`
// and rounded once to T.
template <class T>
class Draw {
public:
    Draw(std::uint64_t seed, double offset) : rng_(seed), offset_(offset) {}

    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
    int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
    bool chance(double p) { return uniform(0, 1) < p; }
    int sign() { return chance(0.5) ? 1 : -1; }
    /// x rounded down to a multiple of `quantum` (a lattice value, so that contacts can touch).
    static double snap(double x, double quantum) { return std::floor(x / quantum) * quantum; }
    /// A local coordinate, translated and rounded to T.
    [[nodiscard]] T place(double local) const { return static_cast<T>(offset_ + local); }
    [[nodiscard]] double offset() const { return offset_; }

    /// `value` moved by k ulps of T (k may be negative).
    static T nudge(T value, int k) {
        const T toward = k > 0 ? std::numeric_limits<T>::infinity() : -std::numeric_limits<T>::infinity();
        for (int n = 0; n < (k > 0 ? k : -k); ++n) value = std::nextafter(value, toward);
        return value;
    }

private:
    std::mt19937_64 rng_;
    double offset_;
};

template <class T>
TileMap<T> emptyMap(double origin, double tile, std::int32_t columns, std::int32_t rows) {
    TileMap<T> map;
    map.origin = {static_cast<T>(origin), static_cast<T>(origin)};
    map.tileSize = {static_cast<T>(tile), static_cast<T>(tile)};
    map.columns = columns;
    map.rows = rows;
    map.solid.assign(static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows), 0);
    return map;
}

template <class T>
void setSolid(TileMap<T>& map, std::int32_t i, std::int32_t j, bool solid = true) {
    if (i < 0 || j < 0 || i >= map.columns || j >= map.rows) return;
    map.solid[static_cast<std::size_t>(j) * static_cast<std::size_t>(map.columns) +
              static_cast<std::size_t>(i)] = solid ? 1 : 0;
}

template <class T>
double drawTile(Draw<T>& d) {
    static constexpr double kSizes[] = {8, 12, 16, 24, 32};
    return kSizes[d.integer(0, 4)];
}

/// The translation of a family: its magnitude rounded down to whole tiles.
double originFor(double magnitude, double tile) { return std::floor(magnitude / tile) * tile; }

// Random maps, boxes and moves; a share of the values snapped to the tile lattice so that
// touching contacts and ties occur.
template <class T>
Scene<T> uniformScene(Draw<T>& d) {
    const double tile = drawTile(d);
    const std::int32_t columns = d.integer(5, 9);
    const std::int32_t rows = d.integer(5, 9);
    Scene<T> s;
    s.map = emptyMap<T>(originFor(d.offset(), tile), tile, columns, rows);
    for (std::int32_t j = 0; j < rows; ++j)
        for (std::int32_t i = 0; i < columns; ++i) setSolid(s.map, i, j, d.chance(0.3));
    const auto value = [&](double lo, double hi, double quantum) {
        const double v = d.uniform(lo, hi);
        return d.chance(0.3) ? std::max(quantum, Draw<T>::snap(v, quantum)) : v;
    };
    const double w = value(0.2 * tile, 1.6 * tile, tile / 4);
    const double h = value(0.2 * tile, 1.6 * tile, tile / 4);
    const double origin = originFor(d.offset(), tile);
    s.box = {{static_cast<T>(origin + value(-0.5 * tile, columns * tile, tile / 8)),
              static_cast<T>(origin + value(-0.5 * tile, rows * tile, tile / 8))},
             {static_cast<T>(w), static_cast<T>(h)}};
    const int frames = d.integer(1, 3);
    for (int k = 0; k < frames; ++k) {
        const double dx = d.chance(0.15) ? 0.0 : d.uniform(-3 * tile, 3 * tile);
        const double dy = d.chance(0.15) ? 0.0 : d.uniform(-3 * tile, 3 * tile);
        s.moves.push_back({static_cast<T>(dx), static_cast<T>(dy)});
    }
    return s;
}

// A box aimed at a corner of tile (2, 2) of a 5 x 5 map. With `tie`, both axes enter at t0 (an
// exact corner hit, settled by the exposed-face rule); otherwise one axis enters at t0 while
// the other leaves at t0 (a path through the corner point exactly: a miss). Then, with some
// probability, one of the four inputs is moved by a few ulps: a clip or a miss by that much.
template <class T>
Scene<T> cornerScene(Draw<T>& d, bool tie) {
    const double tile = drawTile(d);
    const double origin = originFor(d.offset(), tile);
    Scene<T> s;
    s.map = emptyMap<T>(origin, tile, 5, 5);
    setSolid(s.map, 2, 2);
    const int sx = d.sign();
    const int sy = d.sign();
    if (tie) {
        // The cells across the two faces the motion approaches decide the tie.
        setSolid(s.map, 2 - sx, 2, d.chance(0.5));
        setSolid(s.map, 2, 2 - sy, d.chance(0.5));
    } else {
        for (int dj = -1; dj <= 1; ++dj)
            for (int di = -1; di <= 1; ++di)
                if ((di != 0 || dj != 0) && d.chance(0.15)) setSolid(s.map, 2 + di, 2 + dj);
        setSolid(s.map, 2 - sx, 2 - sy, false);  // keep the approach clear
    }
    const double quantum = tile / 16;
    const double size[2] = {std::max(quantum, Draw<T>::snap(d.uniform(0.3, 1.5) * tile, quantum)),
                            std::max(quantum, Draw<T>::snap(d.uniform(0.3, 1.5) * tile, quantum))};
    const double t0 = d.integer(2, 14) / 16.0;
    const double motion[2] = {sx * std::max(quantum, Draw<T>::snap(d.uniform(0.5, 3) * tile, quantum)),
                              sy * std::max(quantum, Draw<T>::snap(d.uniform(0.5, 3) * tile, quantum))};
    const int signs[2] = {sx, sy};
    const double lo = 2 * tile;
    const double hi = 3 * tile;
    const int entering = d.integer(0, 1);  // without a tie, the other axis leaves at t0
    double pos[2];
    for (int a = 0; a < 2; ++a) {
        const bool enters = tie || a == entering;
        // Entering at t0: the leading edge reaches the near face. Leaving at t0: the trailing
        // edge reaches the far face. All values are small dyadics: exact in double.
        if (signs[a] > 0)
            pos[a] = enters ? lo - size[a] - t0 * motion[a] : hi - t0 * motion[a];
        else
            pos[a] = enters ? hi - t0 * motion[a] : lo - size[a] - t0 * motion[a];
    }
    s.box = {{static_cast<T>(origin + pos[0]), static_cast<T>(origin + pos[1])},
             {static_cast<T>(size[0]), static_cast<T>(size[1])}};
    Vec2<T> move{static_cast<T>(motion[0]), static_cast<T>(motion[1])};
    const bool perturb = tie ? d.chance(0.3) : d.chance(2.0 / 3.0);
    if (perturb) {
        const int k = tie ? d.sign() : d.sign() * d.integer(1, 4);
        switch (d.integer(0, 3)) {
            case 0:
                move.x = Draw<T>::nudge(move.x, k);
                break;
            case 1:
                move.y = Draw<T>::nudge(move.y, k);
                break;
            case 2:
                s.box.pos.x = Draw<T>::nudge(s.box.pos.x, k);
                break;
            default:
                s.box.pos.y = Draw<T>::nudge(s.box.pos.y, k);
                break;
        }
    }
    s.moves.push_back(move);
    return s;
}

// A floor with seams every tile: a box resting on it sliding for several frames (with or
// without gravity), or a box landing on it across a seam or with an edge exactly on one.
template <class T>
Scene<T> seamScene(Draw<T>& d) {
    const double tile = drawTile(d);
    const double origin = originFor(d.offset(), tile);
    const std::int32_t columns = d.integer(10, 16);
    const std::int32_t rows = 5;
    Scene<T> s;
    s.map = emptyMap<T>(origin, tile, columns, rows);
    for (std::int32_t i = 0; i < columns; ++i) setSolid(s.map, i, rows - 1);
    if (d.chance(0.4)) setSolid(s.map, d.integer(0, columns - 1), rows - 2);  // a step
    const T floorTop = static_cast<T>(origin + (rows - 1) * tile);
    const double w =
        d.chance(0.5) ? Draw<T>::snap(d.uniform(0.4, 1.5) * tile, tile / 8) : d.uniform(0.4, 1.5) * tile;
    double h = d.uniform(0.4, 1.5) * tile;
    T x;
    if (d.chance(0.3)) {
        // An edge exactly on a seam.
        const double seam = d.integer(1, columns - 2) * tile;
        x = static_cast<T>(origin + (d.chance(0.5) ? seam : seam - w));
    } else {
        x = static_cast<T>(origin + d.uniform(0.5 * tile, (columns - 2) * tile));
    }
    T y;
    T height;
    if (d.chance(0.5)) {
        // Resting: bottom exactly on the floor's top (the height is adjusted to make it exact
        // in T; floorTop - y is exact by Sterbenz's lemma, y being within a factor 2 of it).
        y = static_cast<T>(floorTop - static_cast<T>(h));
        height = floorTop - y;
        if (!(height > T(0))) {
            height = static_cast<T>(tile);
            y = floorTop - height;
        }
        s.box = {{x, y}, {static_cast<T>(w), height}};
        const int frames = d.integer(2, 6);
        const int direction = d.sign();
        const bool gravity = d.chance(0.5);
        for (int k = 0; k < frames; ++k) {
            const double dx = direction * d.uniform(0.1, 4) * tile;
            const double dy = gravity ? (d.chance(0.5) ? Draw<T>::snap(d.uniform(0.01, 0.5) * tile, tile / 64)
                                                       : d.uniform(0.01, 0.5) * tile)
                                      : 0.0;
            s.moves.push_back({static_cast<T>(dx), static_cast<T>(dy)});
        }
    } else {
        const double gap =
            d.chance(0.3) ? Draw<T>::snap(d.uniform(0, 2) * tile, tile / 4) : d.uniform(0, 2) * tile;
        h = d.chance(0.5) ? Draw<T>::snap(h, tile / 8) : h;
        s.box = {{x, static_cast<T>(origin + (rows - 1) * tile - h - gap)},
                 {static_cast<T>(w), static_cast<T>(h)}};
        const int frames = d.integer(1, 3);
        for (int k = 0; k < frames; ++k) {
            const double dy = gap + d.uniform(0.1, 2) * tile;
            const double dx = d.chance(0.3) ? 0.0 : d.uniform(-1, 1) * tile;
            s.moves.push_back({static_cast<T>(dx), static_cast<T>(dy)});
        }
    }
    return s;
}

// Displacements below one ulp of the position, on a random map; half of the boxes touch a
// tile face and move into it by that much.
template <class T>
Scene<T> tinyScene(Draw<T>& d) {
    const double tile = drawTile(d);
    Scene<T> s = uniformScene(d);
    s.moves.resize(1);
    const auto below = [&](T position) {
        const T ulp =
            std::nextafter(std::fabs(position), std::numeric_limits<T>::infinity()) - std::fabs(position);
        const T scale = static_cast<T>(std::ldexp(d.uniform(0.5, 1.0), -d.integer(1, 8)));
        return static_cast<T>(ulp * scale);
    };
    Vec2<T> move{static_cast<T>(d.sign()) * below(s.box.pos.x),
                 static_cast<T>(d.sign()) * below(s.box.pos.y)};
    if (d.chance(0.2)) move.x = T(0);
    if (d.chance(0.2)) move.y = T(0);
    if (d.chance(0.5)) {
        // Touch the near face of a solid tile on one axis and push into it.
        const std::int32_t i = d.integer(0, s.map.columns - 1);
        const std::int32_t j = d.integer(0, s.map.rows - 1);
        setSolid(s.map, i, j);
        const T left = s.map.origin.x + static_cast<T>(i) * s.map.tileSize.x;
        const T top = s.map.origin.y + static_cast<T>(j) * s.map.tileSize.y;
        const bool onX = d.chance(0.5);
        const T across = static_cast<T>(d.uniform(-0.5, 0.9) * tile);
        if (onX) {
            s.box.pos = {left - s.box.size.x, top + across};
            s.box.size.x = left - s.box.pos.x;  // exact: makes the right edge meet the face
            move.x = std::fabs(move.x) > T(0) ? std::fabs(move.x) : below(left);
        } else {
            s.box.pos = {left + across, top - s.box.size.y};
            s.box.size.y = top - s.box.pos.y;
            move.y = std::fabs(move.y) > T(0) ? std::fabs(move.y) : below(top);
        }
        if (!(s.box.size.x > T(0))) s.box.size.x = static_cast<T>(tile);
        if (!(s.box.size.y > T(0))) s.box.size.y = static_cast<T>(tile);
    }
    s.moves[0] = move;
    return s;
}

}  // namespace

template <class T>
Scene<T> drawScene(DrawnFamily family, std::uint64_t seed, double magnitude) {
    Draw<T> d(seed, magnitude);
    switch (family) {
        case DrawnFamily::Uniform:
            return uniformScene(d);
        case DrawnFamily::NearCorner:
            return cornerScene(d, false);
        case DrawnFamily::Tie:
            return cornerScene(d, true);
        case DrawnFamily::Seam:
            return seamScene(d);
        case DrawnFamily::Tiny:
            return tinyScene(d);
    }
    return uniformScene(d);
}

template Scene<float> drawScene<float>(DrawnFamily, std::uint64_t, double);
template Scene<double> drawScene<double>(DrawnFamily, std::uint64_t, double);

}  // namespace tilesweep::scenarios

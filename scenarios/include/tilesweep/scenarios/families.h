// SPDX-License-Identifier: MIT
#pragma once

// The scenario families: every kind of scene the suite, the audit, the benchmarks and the soak
// generate, defined once (tilesweep_scenarios, scenarios/README.md).
//
// Each family is a RapidCheck generator built from shared parameterised pieces (genTileSize,
// genOrigin, genLength, genDisplacement, clearUnder, ...), so the property suite draws it and
// shrinks a counterexample to a small scene; `buildScene(family, seed)` runs the same generator
// once from a seed, deterministically, for the tools that are not properties (the audit's
// property-family columns, tools that want "the scene of family F, number N").
//
// RapidCheck's own float generator never yields -0, subnormals or tile-edge values and shrinks
// poorly, so every number here is an integer on a grid mapped to T (a multiple of tile/8, say),
// which keeps shrinking on clean values; adversarial builders then place boxes exactly on
// corners, seams and gaps, and perturb them by one ulp. Scenes are built valid directly (the
// cells under the box's start are cleared when a start without overlap is wanted) rather than
// filtered with RC_PRE. Every function is inline (RapidCheck's example Generators.h is an ODR
// trap otherwise).

#include "tilesweep/scene/scene.h"

#include <rapidcheck.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <mutex>
#include <ostream>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

namespace tilesweep::scenarios {

/// The families of scenes; each is reachable on its own, and `Mixed` draws from all.
enum class Family : std::uint8_t {
    Random,       ///< random density, any box and motion
    Floor,        ///< flat floors and ceilings, walls one tile thick, corridors
    Stairs,       ///< a staircase
    SingleTile,   ///< one solid tile
    CornerTie,    ///< the box's leading corner aimed exactly at a tile corner; random exposed faces
    CornerPass,   ///< a path exactly through a corner point, or off it by one ulp either way
    SeamLanding,  ///< landing straddling the seam between two floor tiles
    Gap,          ///< a box exactly as wide as a one-tile gap, or one ulp wider
    Resting,      ///< resting on a floor under gravity for many frames, possibly sliding
    FarSubUlp,    ///< far from the origin, moves of a few ulps past a tile corner: rounding at work
    FarEdge,      ///< far edge a few ulps past a grid line, a tiny move away, then back: the rounding rule
    FineBits,     ///< frame times exactly halfway between two values, tiles reached at t = 1, wide lattices
    Extreme,      ///< empty maps (0 x 0, or no solid cell), huge moves, huge coordinates
    FilterBand,   ///< exact corner ties whose rounded time comparison lands deep in the filter's band
    HighSpeed,    ///< 1 to 100 tiles a frame along a corridor with thin walls: no tunnelling
    NearTie,      ///< the filter band's corner ties nudged one ulp off: nonzero signs its refinement decides
    TinyScale,    ///< a mixed scene scaled by a power of two near the bottom of T's normal range
    Capacity,     ///< boxes whose contact bound is the inline limit or just past it, into a corner
    Mixed,
};

[[nodiscard]] inline const char* familyName(Family f) {
    switch (f) {
        case Family::Random:
            return "random";
        case Family::Floor:
            return "floor";
        case Family::Stairs:
            return "stairs";
        case Family::SingleTile:
            return "single-tile";
        case Family::CornerTie:
            return "corner-tie";
        case Family::CornerPass:
            return "corner-pass";
        case Family::SeamLanding:
            return "seam-landing";
        case Family::Gap:
            return "gap";
        case Family::Resting:
            return "resting";
        case Family::FarSubUlp:
            return "far-sub-ulp";
        case Family::FarEdge:
            return "far-edge";
        case Family::FineBits:
            return "fine-bits";
        case Family::Extreme:
            return "extreme";
        case Family::FilterBand:
            return "filter-band";
        case Family::HighSpeed:
            return "high-speed";
        case Family::NearTie:
            return "near-tie";
        case Family::TinyScale:
            return "tiny-scale";
        case Family::Capacity:
            return "capacity";
        case Family::Mixed:
            return "mixed";
    }
    return "?";
}

/// A generated scene and the family that built it.
template <class T>
struct GeneratedScene {
    Scene<T> scene;
    Family family = Family::Random;
    bool farOrigin = false;
};

namespace detail {

template <class T>
struct Grid {
    int columns = 0;
    int rows = 0;
    std::vector<std::uint8_t> solid;
    void set(int i, int j, bool v) {
        if (i >= 0 && j >= 0 && i < columns && j < rows)
            solid[static_cast<std::size_t>(j * columns + i)] = v ? 1 : 0;
    }
    bool get(int i, int j) const {
        return i >= 0 && j >= 0 && i < columns && j < rows &&
               solid[static_cast<std::size_t>(j * columns + i)] != 0;
    }
};

/// Tile sizes: powers of two and integers such as 12 or 24.
inline rc::Gen<int> genTileSize() { return rc::gen::element(16, 8, 32, 12, 24, 16, 4); }

/// A map origin: zero mostly, a few tiles off, or far away (up to 2^23 in float, 2^40 in
/// double) where the ulp of a coordinate is large. Always a multiple of the tile size, so every
/// edge is an integer and representable.
template <class T>
rc::Gen<double> genOrigin(int tile) {
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
    s.map.solid = g.solid;
    s.box = box;
    s.moves = std::move(moves);
    return s;
}

/// Clears the cells the box overlaps (or touches) at its start, so it starts free.
template <class T>
void clearUnder(Grid<T>& g, double ox, double oy, double tile, Box<T> box) {
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
            if (i + 1 > x0 && i < x1 && j + 1 > y0 && j < y1) g.set(i, j, false);
}

template <class T>
T offGrid(T v, int direction) {
    return std::nextafter(
        v, direction > 0 ? std::numeric_limits<T>::infinity() : -std::numeric_limits<T>::infinity());
}

/// Random maps: density, floors, walls, corridors, stairs, single tiles.
template <class T>
rc::Gen<GeneratedScene<T>> genLayoutScene(Family family) {
    return rc::gen::exec([family] {
        const int tile = *genTileSize();
        const double ox = *genOrigin<T>(tile);
        const double oy = *genOrigin<T>(tile);
        Grid<T> g;
        g.columns =
            *rc::gen::weightedOneOf<int>({{8, rc::gen::inRange(1, 17)}, {1, rc::gen::inRange(17, 65)}});
        g.rows = *rc::gen::weightedOneOf<int>({{8, rc::gen::inRange(1, 17)}, {1, rc::gen::inRange(17, 65)}});
        g.solid.assign(static_cast<std::size_t>(g.columns * g.rows), 0);
        switch (family) {
            case Family::Floor: {
                const int floorRow = *rc::gen::inRange(0, g.rows);
                for (int i = 0; i < g.columns; ++i) g.set(i, floorRow, true);
                if (*rc::gen::arbitrary<bool>())  // a ceiling too: a corridor
                    for (int i = 0; i < g.columns; ++i) g.set(i, *rc::gen::inRange(0, g.rows), true);
                if (*rc::gen::arbitrary<bool>()) {  // a wall one tile thick
                    const int col = *rc::gen::inRange(0, g.columns);
                    for (int j = 0; j < g.rows; ++j) g.set(col, j, true);
                    if (*rc::gen::arbitrary<bool>())
                        g.set(col, *rc::gen::inRange(0, g.rows), false);  // a gap
                }
                break;
            }
            case Family::Stairs: {
                const int step = *rc::gen::inRange(1, 3);
                for (int i = 0; i < g.columns; ++i)
                    for (int j = std::max(0, g.rows - 1 - i / step); j < g.rows; ++j) g.set(i, j, true);
                break;
            }
            case Family::SingleTile:
                g.set(*rc::gen::inRange(0, g.columns), *rc::gen::inRange(0, g.rows), true);
                break;
            default: {
                const int percent = *rc::gen::element(0, 10, 30, 50, 80);
                // A roll shrinks toward 0, which here means empty: a shrunk counterexample keeps
                // only the solid cells it needs. Fixed size: inRange scales with RapidCheck's size,
                // which would thin out the maps of the early cases.
                for (auto& c : g.solid)
                    c = *rc::gen::resize(100, rc::gen::inRange(0, 100)) >= 100 - percent ? 1 : 0;
                break;
            }
        }
        Box<T> box;
        box.size = {*genLength<T>(tile, 24), *genLength<T>(tile, 24)};
        const int bi = *rc::gen::inRange(-2, g.columns + 2);
        const int bj = *rc::gen::inRange(-2, g.rows + 2);
        box.pos = {static_cast<T>(ox + bi * tile + *rc::gen::inRange(0, 8) * tile / 8.0),
                   static_cast<T>(oy + bj * tile + *rc::gen::inRange(0, 8) * tile / 8.0)};
        if (*rc::gen::inRange(0, 100) < 85) clearUnder(g, ox, oy, tile, box);
        std::vector<Vec2<T>> moves;
        const int frames = *rc::gen::weightedOneOf<int>({{6, rc::gen::just(1)}, {3, rc::gen::inRange(2, 5)}});
        for (int f = 0; f < frames; ++f)
            moves.push_back({*genDisplacement<T>(tile, box.pos.x), *genDisplacement<T>(tile, box.pos.y)});
        return GeneratedScene<T>{makeScene(g, ox, oy, tile, box, moves), family,
                                 ox != 0 && std::fabs(ox) >= 1048576.0};
    });
}

/// A corner scene: one target tile, a box coming at it diagonally so that at t = 1/2 either its
/// leading corner meets the tile's near corner (an exact tie) or its corner passes exactly
/// through one of the tile's corner points (touch, no hit); the pass may be nudged by one ulp in
/// any input, which clips the corner or misses it.
template <class T>
rc::Gen<GeneratedScene<T>> genCornerScene(Family family) {
    return rc::gen::exec([family] {
        const int tile = *genTileSize();
        const double ox = *genOrigin<T>(tile);
        const double oy = *genOrigin<T>(tile);
        Grid<T> g;
        g.columns = 7;
        g.rows = 7;
        g.solid.assign(49, 0);
        const int ci = 3;
        const int cj = 3;
        g.set(ci, cj, true);
        const int sx = *rc::gen::element(-1, 1);
        const int sy = *rc::gen::element(-1, 1);
        // Neighbours across the faces the box approaches: every combination of exposed faces.
        g.set(ci - sx, cj, *rc::gen::arbitrary<bool>());
        g.set(ci, cj - sy, *rc::gen::arbitrary<bool>());
        const T w = static_cast<T>(*rc::gen::inRange(1, 17) * tile / 8.0);
        const T h = static_cast<T>(*rc::gen::inRange(1, 17) * tile / 8.0);
        // Half the displacement, on the grid tile/8, at least one tile long per axis so the box
        // starts clear of the tile.
        const double hx = sx * (*rc::gen::inRange(8, 33)) * tile / 8.0;
        const double hy = sy * (*rc::gen::inRange(8, 33)) * tile / 8.0;
        const double x0 = ox + ci * tile;
        const double y0 = oy + cj * tile;
        const double nearX = sx > 0 ? x0 : x0 + tile;  // face the box reaches first
        const double nearY = sy > 0 ? y0 : y0 + tile;
        double leadX = 0;  // the box's x edge that meets the corner at t = 1/2
        double leadY = 0;
        if (family == Family::CornerTie) {
            leadX = nearX;  // leading corner on the near corner: both axes enter at 1/2
            leadY = nearY;
        } else {
            // The leading x edge reaches the near x face as the trailing y edge leaves the far
            // y face: entry on x equals exit on y, the path passes through the corner point.
            leadX = nearX;
            leadY = sy > 0 ? y0 + tile : y0;
        }
        // Which edge meets the corner: on x always the leading one; on y the leading one for a
        // tie, the trailing one for a pass.
        const bool leadIsHighX = sx > 0;
        const bool leadIsHighY = family == Family::CornerTie ? sy > 0 : sy < 0;
        const double startLeadX = leadX - hx;
        const double startLeadY = leadY - hy;
        Box<T> box{{static_cast<T>(leadIsHighX ? startLeadX - static_cast<double>(w) : startLeadX),
                    static_cast<T>(leadIsHighY ? startLeadY - static_cast<double>(h) : startLeadY)},
                   {w, h}};
        Vec2<T> d{static_cast<T>(2 * hx), static_cast<T>(2 * hy)};
        if (family == Family::CornerPass) {
            switch (*rc::gen::inRange(0, 5)) {  // 0: exact pass; else nudge one input by one ulp
                case 1:
                    d.x = offGrid(d.x, *rc::gen::element(-1, 1));
                    break;
                case 2:
                    d.y = offGrid(d.y, *rc::gen::element(-1, 1));
                    break;
                case 3:
                    box.pos.x = offGrid(box.pos.x, *rc::gen::element(-1, 1));
                    break;
                case 4:
                    box.pos.y = offGrid(box.pos.y, *rc::gen::element(-1, 1));
                    break;
                default:
                    break;
            }
        }
        clearUnder(g, ox, oy, tile, box);
        g.set(ci, cj, true);
        return GeneratedScene<T>{makeScene(g, ox, oy, tile, box, {d}), family, std::fabs(ox) >= 1048576.0};
    });
}

/// Floor scenes: a landing straddling a seam at t = 1/2, a box as wide as a one-tile gap (or one
/// ulp wider), or resting on the floor under gravity for many frames, sliding or not.
template <class T>
rc::Gen<GeneratedScene<T>> genFloorScene(Family family) {
    return rc::gen::exec([family] {
        const int tile = *genTileSize();
        const double ox = *genOrigin<T>(tile);
        const double oy = *genOrigin<T>(tile);
        Grid<T> g;
        g.columns = *rc::gen::inRange(6, 33);
        g.rows = 6;
        g.solid.assign(static_cast<std::size_t>(g.columns * g.rows), 0);
        const int floorRow = 4;
        for (int i = 0; i < g.columns; ++i) g.set(i, floorRow, true);
        const double floorY = oy + floorRow * tile;
        Box<T> box;
        std::vector<Vec2<T>> moves;
        int gapColumn = -1;
        if (family == Family::Gap) {
            const int gap = *rc::gen::inRange(1, g.columns - 1);
            gapColumn = gap;
            T w = T(tile);
            T x = static_cast<T>(ox + gap * tile);
            switch (*rc::gen::inRange(0, 3)) {
                case 1:
                    w = offGrid(w, 1);
                    break;  // one ulp too wide
                case 2:
                    x = offGrid(x, *rc::gen::element(-1, 1));
                    break;  // one ulp off the gap
                default:
                    break;
            }
            box = {{x, static_cast<T>(floorY - 2.0 * tile)}, {w, T(tile)}};
            moves.push_back({0, static_cast<T>(*rc::gen::inRange(1, 5) * tile)});
        } else if (family == Family::SeamLanding) {
            const int seam = *rc::gen::inRange(1, g.columns);
            const double w = *rc::gen::inRange(2, 17) * tile / 8.0;
            const double h = *rc::gen::inRange(2, 17) * tile / 8.0;
            const double fall = *rc::gen::inRange(1, 33) * tile / 8.0;  // gap above the floor
            const double hx = *rc::gen::inRange(-16, 17) * tile / 8.0;  // half the x motion
            // At t = 1/2 the box's bottom meets the floor and its centre is over the seam.
            box = {{static_cast<T>(ox + seam * tile - w / 2 - hx), static_cast<T>(floorY - h - fall)},
                   {static_cast<T>(w), static_cast<T>(h)}};
            moves.push_back({static_cast<T>(2 * hx), static_cast<T>(2 * fall)});
            const int slides = *rc::gen::inRange(0, 6);
            for (int k = 0; k < slides; ++k)
                moves.push_back({static_cast<T>(2 * hx), static_cast<T>(tile / 4.0)});
        } else {  // Resting
            // Bottom exactly on the floor: sizes on the tile/8 grid keep y = floorY - h exact.
            const T h = static_cast<T>(*rc::gen::inRange(1, 25) * tile / 8.0);
            const T w = *genLength<T>(tile, 24);
            const T y = static_cast<T>(floorY - static_cast<double>(h));
            box = {{static_cast<T>(ox + *rc::gen::inRange(0, g.columns * 8) * tile / 8.0), y}, {w, h}};
            const T vx = *rc::gen::weightedOneOf<T>(
                {{2, rc::gen::just(T(0))}, {3, rc::gen::map(rc::gen::inRange(-32, 33), [tile](int n) {
                                                return static_cast<T>(n * tile / 16.0);
                                            })}});
            const T gravity = static_cast<T>(*rc::gen::inRange(1, 33) * tile / 32.0);
            const int frames = *rc::gen::inRange(2, 40);
            for (int k = 0; k < frames; ++k) moves.push_back({vx, gravity});
        }
        clearUnder(g, ox, oy, tile, box);
        // The floor stays solid (the box only touches it), but for the gap.
        for (int i = 0; i < g.columns; ++i) g.set(i, floorRow, i != gapColumn);
        return GeneratedScene<T>{makeScene(g, ox, oy, tile, box, moves), family, std::fabs(ox) >= 1048576.0};
    });
}

/// Far from the origin (2^20 in float, 2^49 in double, where one ulp is 1/8), a 0.75 tile and a
/// box of decimal size next to one of its corners, moving by a few ulps on each axis, either
/// sign: where rounding toward the start decides what the box ends up overlapping.
template <class T>
rc::Gen<GeneratedScene<T>> genFarSubUlpScene() {
    return rc::gen::exec([] {
        const double far = std::is_same<T, float>::value ? 1048576.0 : 562949953421312.0;
        const double ulp = 0.125;
        const double tile = 0.75;
        Grid<T> g;
        g.columns = 5;
        g.rows = 5;
        g.solid.assign(25, 0);
        g.set(2, 2, true);
        for (int k = 0; k < 3; ++k)
            g.set(*rc::gen::inRange(0, 5), *rc::gen::inRange(0, 5), *rc::gen::arbitrary<bool>());
        const double ox = far * *rc::gen::element(1, -1);
        const double oy = far / 2 * *rc::gen::element(1, -1);
        const T w = static_cast<T>(*rc::gen::inRange(1, 100) / 100.0);
        const T h = static_cast<T>(*rc::gen::inRange(1, 100) / 100.0);
        // The box's corner within a couple of ulps of one of the tile's corners.
        const double cx = ox + (2 + *rc::gen::element(0, 1)) * tile + *rc::gen::inRange(-3, 4) * ulp;
        const double cy = oy + (2 + *rc::gen::element(0, 1)) * tile + *rc::gen::inRange(-3, 4) * ulp;
        const Box<T> box{{static_cast<T>(cx - (*rc::gen::arbitrary<bool>() ? static_cast<double>(w) : 0.0)),
                          static_cast<T>(cy - (*rc::gen::arbitrary<bool>() ? static_cast<double>(h) : 0.0))},
                         {w, h}};
        // One axis moves less than an ulp (so it rounds back to its start unless it is stopped),
        // the other a few ulps: the motion that lets rounding undo a corner miss.
        const auto sign = [] { return *rc::gen::element(1.0, -1.0); };
        const double slow = sign() * *rc::gen::inRange(1, 100) / 100.0 * ulp;
        const double fast =
            sign() * (*rc::gen::inRange(5, 40) * ulp / 10.0 + *rc::gen::inRange(0, 7) / 1000.0);
        const bool slowOnX = *rc::gen::arbitrary<bool>();
        const auto move = [&](bool xAxis) { return static_cast<T>(xAxis == slowOnX ? slow : fast); };
        clearUnder(g, ox, oy, tile, box);
        return GeneratedScene<T>{makeScene(g, ox, oy, tile, box, {{move(true), move(false)}}),
                                 Family::FarSubUlp, true};
    });
}

/// Swaps the axes of a scene: the same scene on y.
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
        for (int i = 0; i < scene.map.columns; ++i)
            t.map.solid[static_cast<std::size_t>(i * t.map.columns + j)] =
                scene.map.solid[static_cast<std::size_t>(j * scene.map.columns + i)];
    return t;
}

/// The rounding rule's family (CONTRACT.md, "Positions"). Far from the origin (float 2^17 to 2^21,
/// double 2^46 to 2^50), the box's far edge lies a few ulps past a grid line, just above a solid
/// tile on the far side of that line. Frame 1 moves toward minus infinity on that axis by a
/// few ulps, mostly just enough to take the exact far edge back over the line, and down
/// onto the tile's row, often missing its corner; rounding back toward the start would put the
/// far edge over the line again, inside the tile. Frames 2 and 3 move back toward the tile: the
/// box must stop at its face, never walk into it. Half the scenes swap the axes.
template <class T>
rc::Gen<GeneratedScene<T>> genFarEdgeScene() {
    return rc::gen::exec([] {
        const bool isFloat = std::is_same<T, float>::value;
        const double tile = *rc::gen::element(16.0, 8.0, 0.75, 12.0, 2.5);
        const int binade = isFloat ? *rc::gen::inRange(17, 22) : *rc::gen::inRange(46, 51);
        // A multiple of the tile near 2^binade, on either side of the origin.
        const double ox = std::round(std::ldexp(1.0, binade) / tile) * tile * *rc::gen::element(1, -1);
        const double oy = *rc::gen::element(0.0, ox, -ox);
        Grid<T> g;
        g.columns = 6;
        g.rows = 6;
        g.solid.assign(36, 0);
        g.set(3, 3, true);  // the tile beyond the line x = ox + 3*tile, one row down
        for (int k = 0; k < 2; ++k)
            g.set(*rc::gen::inRange(3, 6), *rc::gen::inRange(3, 6), *rc::gen::arbitrary<bool>());
        const double line = ox + 3 * tile;
        const double ulp =
            static_cast<double>(std::nextafter(static_cast<T>(line), std::numeric_limits<T>::infinity())) -
            static_cast<double>(static_cast<T>(line));
        const T w =
            static_cast<T>(*rc::gen::inRange(101, 400) / 100.0 * tile / 4);  // decimal: off the lattice
        const T h = static_cast<T>(*rc::gen::inRange(1, 9) * tile / 8.0);
        // Far edge a few ulps past the line; bottom a little above the tile's top.
        const T x = static_cast<T>(line + *rc::gen::inRange(1, 5) * ulp - static_cast<double>(w));
        const double gapY = *rc::gen::element(0.0, 1.0, 3.0) * ulp + *rc::gen::inRange(0, 5) * tile / 16.0;
        const T y = static_cast<T>(oy + 3 * tile - static_cast<double>(h) - gapY);
        const Box<T> box{{x, y}, {w, h}};
        // Away by the far edge's offset past the line and a fraction of an ulp more, so that the
        // exact far edge ends just short of the line (where rounding back up would cross it);
        // now and then a plain quarter of an ulp to four ulps.
        const double offset = static_cast<double>(x) + static_cast<double>(w) - line;
        const double fraction = *rc::gen::element(1.0 / 16, 1.0 / 8, 1.0 / 4, 1.0 / 2);
        const T away = *rc::gen::arbitrary<bool>() || *rc::gen::arbitrary<bool>()
                           ? static_cast<T>(-(offset + fraction * ulp))
                           : static_cast<T>(-*rc::gen::inRange(1, 17) * ulp / 4);
        const T down = static_cast<T>(gapY + *rc::gen::inRange(1, 9) * tile / 8.0);
        const T back =
            static_cast<T>(*rc::gen::element(1.0, 3.0, 8.0) * ulp + *rc::gen::element(0.0, tile / 2));
        std::vector<Vec2<T>> moves{{away, down}, {back, T(0)}, {back, static_cast<T>(tile / 8.0)}};
        Grid<T> cleared = g;
        clearUnder(cleared, ox, oy, tile, box);
        cleared.set(3, 3, true);  // the box starts above it, never in it
        Scene<T> scene = makeScene(cleared, ox, oy, tile, box, moves);
        if (*rc::gen::arbitrary<bool>()) scene = transposed(scene);  // the same on y
        return GeneratedScene<T>{scene, Family::FarEdge, true};
    });
}

/// The events the other families never aim at, a third each (then half of them on y):
///   - a frame time exactly halfway between two T values: the box's far edge lies an odd
///     number D of units before a wall, D of digits(T) + 1 bits, and the move is 2^(digits+1)
///     units, so the entry time D / 2^(digits+1) needs one bit more than T has;
///   - a wall reached at exactly t = 1 while both axes move (no hit, by the contract);
///   - a finest bit far below the coordinates: near a far origin, a box size of 8 + 2^-40
///     (double), a large move on one axis and a tiny one of full precision on the other: the
///     frames that need the resolver's 192-bit and wider integers.
template <class T>
rc::Gen<GeneratedScene<T>> genFineBitsScene() {
    return rc::gen::exec([] {
        constexpr int digits = std::numeric_limits<T>::digits;
        Grid<T> g;
        Scene<T> scene;
        const int kind = *rc::gen::element(0, 1, 2);  // (inRange leans to its low end at small sizes)
        if (kind == 0) {
            const double unit = std::ldexp(1.0, -*rc::gen::inRange(0, 9));
            const double tile = 16 * unit;
            g.columns = 2;
            g.rows = 3;
            g.solid.assign(6, 0);
            for (int j = 0; j < 3; ++j) g.set(0, j, true);  // the wall: its left face is x = 0
            // D odd in [2^digits, 2^(digits+1)); x = -(D + 1) units is even, so representable.
            const auto high = static_cast<std::int64_t>(*rc::gen::inRange(0, 1 << 20));
            const std::int64_t d = (std::int64_t{1} << digits) + 2 * (high << (digits - 21)) + 1;
            const Box<T> box{{static_cast<T>(-static_cast<double>(d + 1) * unit), static_cast<T>(tile)},
                             {static_cast<T>(unit), static_cast<T>(tile / 2)}};
            const T dy = static_cast<T>(*rc::gen::inRange(-2, 3) * tile / 8);
            scene = makeScene(g, 0.0, 0.0, tile, box, {{static_cast<T>(std::ldexp(unit, digits + 1)), dy}});
        } else if (kind == 1) {
            const double tile = 16;
            g.columns = 8;
            g.rows = 8;
            g.solid.assign(64, 0);
            for (int j = 0; j < 8; ++j) g.set(5, j, true);  // a wall: left face x = 80
            const double dx = *rc::gen::inRange(1, 41) * 0.5;
            const double w = 12;
            const Box<T> box{{static_cast<T>(80 - dx - w), T(30)}, {static_cast<T>(w), T(10)}};
            const T dy = static_cast<T>(*rc::gen::element(-1, 1) * *rc::gen::inRange(1, 33) / 8.0);
            scene = makeScene(g, 0.0, 0.0, tile, box, {{static_cast<T>(dx), dy}});
        } else {
            const bool isFloat = std::is_same<T, float>::value;
            // Float: a tile of 2^(e-20) keeps every edge near 2^e representable.
            const int e = isFloat ? *rc::gen::inRange(36, 80) : *rc::gen::inRange(36, 52);
            const double tile = isFloat ? std::ldexp(1.0, e - 20) : 16.0;
            const double ox = std::ldexp(1.0, e) * *rc::gen::element(1, -1);
            g.columns = 8;
            g.rows = 8;
            g.solid.assign(64, 0);
            for (int k = 0; k < 12; ++k) g.set(*rc::gen::inRange(0, 8), *rc::gen::inRange(0, 8), true);
            const double size = isFloat ? tile * (1 + std::ldexp(1.0, -23)) / 2 : 8 + std::ldexp(1.0, -40);
            const Box<T> box{
                {static_cast<T>(ox + *rc::gen::inRange(0, 48) * tile / 8), static_cast<T>(ox + 3 * tile)},
                {static_cast<T>(size), static_cast<T>(size)}};
            clearUnder(g, ox, ox, tile, box);
            // One axis moves on the tile grid, the other by a value of full precision whose
            // finest bit lies 50 to 120 bits below the origin's: from just inside double's 53
            // bits (where the resolver's float fast path must still be exact, or refuse the
            // frame) to past the 128- and 192-bit integer tiers.
            const T coarse =
                static_cast<T>(*rc::gen::inRange(-64, 65) * tile / 8 * *rc::gen::element(1.0, 1.0, 1024.0));
            const int below = isFloat ? *rc::gen::element(26, 27, 28, 29, 30, 31, 41, 55, 75, 96)
                                      : *rc::gen::element(11, 25, 45, 67);
            const T fine = static_cast<T>(std::ldexp(1.0 + std::ldexp(1.0, 1 - digits), e - below) *
                                          *rc::gen::element(1.0, -1.0));
            scene = makeScene(g, ox, ox, tile, box, {{coarse, fine}});
        }
        if (*rc::gen::arbitrary<bool>()) scene = transposed(scene);
        const bool far = std::fabs(scene.map.origin.x) >= 1048576 || std::fabs(scene.map.origin.y) >= 1048576;
        return GeneratedScene<T>{scene, Family::FineBits, far};
    });
}

/// What the unit tests alone used to reach: a map of 0 x 0 cells or with no solid cell, moves of
/// 2^20 up to near the largest finite value, boxes far beyond the map (2^60 to 2^120 in float,
/// to 2^1000 in double), each on a small random map otherwise.
template <class T>
rc::Gen<GeneratedScene<T>> genExtremeScene() {
    return rc::gen::exec([] {
        const bool isFloat = std::is_same<T, float>::value;
        const int maxExponent = std::numeric_limits<T>::max_exponent - 2;
        const double tile = *rc::gen::element(16.0, 8.0, 0.5);
        Grid<T> g;
        const int kind = *rc::gen::element(0, 1, 2, 3);
        g.columns = kind == 0 ? 0 : *rc::gen::element(1, 4, 9, 16);
        g.rows = kind == 0 ? 0 : *rc::gen::element(1, 3, 8, 16);
        g.solid.assign(static_cast<std::size_t>(g.columns * g.rows), 0);
        if (kind >= 2)
            for (int k = 0; k < g.columns * g.rows / 3 + 1; ++k)
                g.set(*rc::gen::inRange(0, g.columns), *rc::gen::inRange(0, g.rows), true);
        const auto huge = [maxExponent] {
            const int e = *rc::gen::element(20, 40, 60, 100, maxExponent);
            return static_cast<T>(std::ldexp(*rc::gen::element(1.0, -1.0, 1.5, -0.75), e));
        };
        const auto small = [tile] { return static_cast<T>(*rc::gen::inRange(-32, 33) * tile / 8); };
        Box<T> box{
            {static_cast<T>(*rc::gen::inRange(0, 8) * tile), static_cast<T>(*rc::gen::inRange(0, 8) * tile)},
            {static_cast<T>(tile * 0.75), static_cast<T>(tile)}};
        if (kind == 3) {  // far beyond the map
            const int e = isFloat ? *rc::gen::element(60, 90, 120) : *rc::gen::element(60, 300, 1000);
            box.pos = {static_cast<T>(std::ldexp(*rc::gen::element(1.0, -1.0), e)), box.pos.y};
        }
        clearUnder(g, 0.0, 0.0, tile, box);
        std::vector<Vec2<T>> moves;
        const int frames = *rc::gen::element(1, 2, 3);
        for (int k = 0; k < frames; ++k) {
            const int which = *rc::gen::element(0, 1, 2);
            moves.push_back({which == 1 ? small() : huge(), which == 0 ? small() : huge()});
        }
        return GeneratedScene<T>{makeScene(g, 0.0, 0.0, tile, box, moves), Family::Extreme, false};
    });
}

/// Exact corner ties aimed at the resolver's floating-point filter. The box's far corner starts
/// at (a*g, b*g) and moves by (a*s, b*s) toward a tile corner at (a*K, b*K), K = 2^k, s = 2K: the
/// entry distances a(K - g) and b(K - g) are in exact ratio a : b, so the entry times tie exactly,
/// but in double they are not doubles (the resolver carries them as exact pairs hi + lo), and the
/// rounded comparison of a(K-g)*b*s against b(K-g)*a*s comes out nonzero in about 28% of cases.
/// The search below asks for a rounded difference in the upper half of the certified band
/// (kPairProductErrorBound, src/exact_double.h); these constructions reach only a third of it
/// (3 million candidates, none above 0.334), so every double scene is the stream's last
/// candidate. What catches a halved bound (FILTER_BOUND_HALVED) is the neighbours: a solid tile
/// across the approached face is hit at the same time as the corner tile, through a comparison of
/// two pair-valued times that the halved band decides wrongly ("1 contacts != 2"). Drawing one
/// candidate instead of the stream's last did not reach it in 3 x 4000 cases, so the stream stays.
/// Float scenes are the same construction, where the fast path's rounded products tie and
/// TwoProduct settles them. The tile's neighbours across both faces are random.
///
/// With `nearTie`, one input (the box's position or the move, on x or y) is then nudged by one ulp
/// either way: the two products now differ, by far less than the filter's bound, and the exact
/// refinement (TwoProduct, the expansion's sign) must decide a nonzero sign the right way round.
template <class T>
rc::Gen<GeneratedScene<T>> genFilterBandScene(bool nearTie = false) {
    return rc::gen::exec([nearTie] {
        const bool isFloat = std::is_same<T, float>::value;
        std::mt19937_64 rng(*rc::gen::arbitrary<std::uint64_t>());
        // a and b just above powers of two, g < 0: the distances a(K - g), b(K - g) and both
        // products then sit just above a power of two, where a rounding errs by up to u of the
        // value.
        const double near[] = {257, 513, 1025, 2049, 4097, 8193};
        const double u = std::ldexp(1.0, -53);
        const double band = (3.0 + 16.0 * u) * u;  // the certified bound, relative to |p| + |q|
        double a = 257;
        double b = 513;
        double K = 0;
        double g = 0;
        for (int attempt = 0; attempt < 50000; ++attempt) {
            a = near[rng() % 6];
            b = near[rng() % 6];
            if (a == b) continue;
            K = std::ldexp(1.0,
                           isFloat ? 8 + static_cast<int>(rng() % 6) : 24 + static_cast<int>(rng() % 14));
            const int bits = isFloat ? 8 : 38;  // a*g and b*g stay exact
            g = -std::ldexp(static_cast<double>((rng() >> (64 - bits)) | 1),
                            -bits + static_cast<int>(rng() % 8) - 2);
            if (isFloat || nearTie) break;  // a near tie needs no search: any exact tie, nudged
            // The resolver's comparison: p = fl(Dx.hi * vy), q = fl(Dy.hi * vx), D = fl(p - q).
            const double dx = a * K - a * g;
            const double dy = b * K - b * g;
            const double p = dx * (b * 2 * K);
            const double q = dy * (a * 2 * K);
            const double d = std::fabs(p - q);
            const double bound = band * (std::fabs(p) + std::fabs(q));
            if (d > bound / 2 && d <= bound) break;
        }
        const double tile = 16;
        // The tile at cell (1, 1): its top-left corner is (a*K, b*K).
        const double ox = a * K - tile;
        const double oy = b * K - tile;
        Grid<T> grid;
        grid.columns = 3;
        grid.rows = 3;
        grid.solid.assign(9, 0);
        grid.set(1, 1, true);
        grid.set(0, 1, *rc::gen::arbitrary<bool>());  // across the left face
        grid.set(1, 0, *rc::gen::arbitrary<bool>());  // across the top face
        Box<T> box{{static_cast<T>(a * g - 1), static_cast<T>(b * g - 1)}, {T(1), T(1)}};
        Vec2<T> move{static_cast<T>(a * 2 * K), static_cast<T>(b * 2 * K)};
        if (nearTie) {
            const int direction = *rc::gen::element(-1, 1);
            switch (*rc::gen::inRange(0, 4)) {
                case 0:
                    box.pos.x = offGrid(box.pos.x, direction);
                    break;
                case 1:
                    box.pos.y = offGrid(box.pos.y, direction);
                    break;
                case 2:
                    move.x = offGrid(move.x, direction);
                    break;
                default:
                    move.y = offGrid(move.y, direction);
                    break;
            }
        }
        return GeneratedScene<T>{makeScene(grid, ox, oy, tile, box, {move}),
                                 nearTie ? Family::NearTie : Family::FilterBand, std::fabs(ox) >= 1048576.0};
    });
}

/// 1 to 100 tiles a frame along a 128-column corridor six rows high, with one to three thin
/// walls (full height or partial) and scattered single tiles: a move of dozens of tiles must stop
/// at the first wall, never pass through it, whatever the tile size and the box's size.
template <class T>
rc::Gen<GeneratedScene<T>> genHighSpeedScene() {
    return rc::gen::exec([] {
        const int tile = *rc::gen::element(8, 16);
        const double ox = *genOrigin<T>(tile);
        const double oy = *genOrigin<T>(tile);
        Grid<T> g;
        g.columns = 128;
        g.rows = 6;
        g.solid.assign(static_cast<std::size_t>(g.columns * g.rows), 0);
        const int sx = *rc::gen::element(1, -1);
        Box<T> box;
        box.size = {static_cast<T>(*rc::gen::inRange(2, 11) * tile / 8.0),
                    static_cast<T>(*rc::gen::inRange(2, 11) * tile / 8.0)};
        const int startColumn =
            sx > 0 ? *rc::gen::inRange(0, 4) : *rc::gen::inRange(g.columns - 8, g.columns - 4);
        const int startRow = *rc::gen::inRange(0, g.rows - 1);
        box.pos = {static_cast<T>(ox + startColumn * tile + *rc::gen::inRange(0, 8) * tile / 8.0),
                   static_cast<T>(oy + startRow * tile + *rc::gen::inRange(0, 8) * tile / 8.0)};
        // Speed in eighths of a tile: 1 to 100 tiles (fixed size: RapidCheck's size would keep the
        // early cases slow).
        const int eighths = *rc::gen::resize(rc::kNominalSize, rc::gen::inRange(8, 801));
        const double speed = eighths * tile / 8.0;
        // Walls one tile thick (full height or partial) within the move's reach, so that most
        // moves meet one; scattered single tiles anywhere.
        const int walls = *rc::gen::inRange(1, 4);
        for (int k = 0; k < walls; ++k) {
            const int reach = std::max(2, eighths / 8);
            const int i =
                startColumn + sx * (2 + *rc::gen::resize(rc::kNominalSize, rc::gen::inRange(0, reach)));
            const bool full =
                *rc::gen::weightedOneOf<bool>({{3, rc::gen::just(true)}, {2, rc::gen::just(false)}});
            const int from = full ? 0 : *rc::gen::inRange(0, g.rows);
            const int to = full ? g.rows - 1 : *rc::gen::inRange(from, g.rows);
            for (int j = from; j <= to; ++j) g.set(i, j, true);
        }
        const int scattered = *rc::gen::inRange(0, 7);
        for (int k = 0; k < scattered; ++k)
            g.set(*rc::gen::inRange(8, 121), *rc::gen::inRange(0, g.rows), true);
        clearUnder(g, ox, oy, tile, box);
        double dy = 0;
        switch (*rc::gen::inRange(0, 3)) {
            case 1:
                dy = *rc::gen::inRange(-80, 81) * speed / 800.0;
                break;  // a shallow slope
            case 2:
                dy = *rc::gen::inRange(-16, 17) * tile / 8.0;
                break;  // up to two tiles across
            default:
                break;  // level
        }
        std::vector<Vec2<T>> moves{{static_cast<T>(sx * speed), static_cast<T>(dy)}};
        return GeneratedScene<T>{makeScene(g, ox, oy, tile, box, moves), Family::HighSpeed,
                                 std::fabs(ox) >= 1048576.0};
    });
}

/// Every length of a scene times 2^-shift (origin, tile size, box, moves): exact, so long as every
/// nonzero value stays normal (the caller's shift keeps it so).
template <class T>
Scene<T> scaledDown(const Scene<T>& scene, int shift) {
    Scene<T> s = scene;
    const auto scale = [shift](Vec2<T>& v) { v = {std::ldexp(v.x, -shift), std::ldexp(v.y, -shift)}; };
    scale(s.map.origin);
    scale(s.map.tileSize);
    scale(s.box.pos);
    scale(s.box.size);
    for (Vec2<T>& m : s.moves) scale(m);
    return s;
}

/// The tiny end of the range: a scene of `base` with every length scaled by 2^-shift, the shift
/// drawn near the bottom of T's normal range (double: 2^-600 to the least normal, float: 2^-60
/// to it) and capped so that the scene's smallest nonzero value stays normal, so the scaled
/// scene is exact and, by the contract, decides exactly as the original did. A range test that
/// forgets its lower bound lets products and TwoProduct error terms underflow here.
template <class T>
rc::Gen<GeneratedScene<T>> genTinyScaleScene(rc::Gen<GeneratedScene<T>> base) {
    return rc::gen::exec([base] {
        GeneratedScene<T> g = *base;
        const bool isFloat = std::is_same<T, float>::value;
        int lowest = std::numeric_limits<int>::max();  // the least frexp exponent of a nonzero value
        const auto note = [&lowest](T v) {
            if (v == 0) return;
            int e = 0;
            (void)std::frexp(v, &e);
            lowest = std::min(lowest, e);
        };
        const Scene<T>& s = g.scene;
        for (const Vec2<T>& v : {s.map.origin, s.map.tileSize, s.box.pos, s.box.size}) {
            note(v.x);
            note(v.y);
        }
        for (const Vec2<T>& m : s.moves) {
            note(m.x);
            note(m.y);
        }
        // v * 2^-shift stays normal while frexp's exponent e - shift >= min_exponent.
        const int most = lowest - std::numeric_limits<T>::min_exponent;
        const int wanted = isFloat ? *rc::gen::element(100, 110, 120, 1000, 60)
                                   : *rc::gen::element(600, 700, 900, 1000, 5000);
        g.scene = scaledDown(s, std::max(0, std::min(wanted, most)));
        g.family = Family::TinyScale;
        return g;
    });
}

/// Capacity boundaries: a box whose contact bound maxContacts = (floor(w/tw) + 2) + (floor(h/th)
/// + 2) is the inline limit (64, mover.h's kInlineContacts) or one or two past it (the wide
/// path's bound), or one below, driven diagonally into the corner of a solid floor row and a
/// solid wall column, so that one frame hits a whole row and a whole column of tiles: contact
/// counts near the bound, which the claims store into buffers of exactly that many entries.
template <class T>
rc::Gen<GeneratedScene<T>> genCapacityScene() {
    return rc::gen::exec([] {
        const double tile = *rc::gen::element(16.0, 8.0, 1.0, 0.5, 12.0);
        const double ox = *rc::gen::element(0.0, -4.0 * tile, 64.0 * tile);
        const double oy = *rc::gen::element(0.0, 8.0 * tile);
        const int bound = *rc::gen::element(64, 64, 65, 65, 66, 63);
        // floor(w/tw) + floor(h/th) = bound - 4, w and h a whole number of tiles plus a fraction
        // in eighths (0 to 7/8): the fraction lets the box span one more cell than it is long.
        const int across = *rc::gen::inRange(1, bound - 4);
        const int down = bound - 4 - across;
        const double w = (across + *rc::gen::inRange(0, 8) / 8.0) * tile;
        const double h = (down + *rc::gen::inRange(0, 8) / 8.0) * tile;
        Grid<T> g;
        g.columns = across + 8;
        g.rows = down + 8;
        g.solid.assign(static_cast<std::size_t>(g.columns * g.rows), 0);
        const int wallColumn = g.columns - 2;
        const int floorRow = g.rows - 2;
        for (int j = 0; j < g.rows; ++j) g.set(wallColumn, j, true);
        for (int i = 0; i < g.columns; ++i) g.set(i, floorRow, true);
        // The box's far corner starts gapX, gapY (eighths of a tile) short of the wall and the
        // floor; the move closes both gaps with a margin, equal gaps a corner tie.
        const double gapX = *rc::gen::inRange(0, 17) * tile / 8.0;
        const double gapY = *rc::gen::element(true, false) ? gapX : *rc::gen::inRange(0, 17) * tile / 8.0;
        const Box<T> box{{static_cast<T>(ox + wallColumn * tile - gapX - w),
                          static_cast<T>(oy + floorRow * tile - gapY - h)},
                         {static_cast<T>(w), static_cast<T>(h)}};
        const double more = *rc::gen::inRange(1, 17) * tile / 8.0;
        const Vec2<T> move{static_cast<T>(gapX + more), static_cast<T>(gapY + more)};
        Scene<T> scene = makeScene(g, ox, oy, tile, box, {move});
        if (*rc::gen::arbitrary<bool>()) scene = transposed(scene);
        return GeneratedScene<T>{scene, Family::Capacity, false};
    });
}

}  // namespace detail

/// Scenes of one family, or of all of them (`Mixed`).
template <class T>
rc::Gen<GeneratedScene<T>> genScene(Family family) {
    using detail::genCornerScene;
    using detail::genExtremeScene;
    using detail::genFarEdgeScene;
    using detail::genFarSubUlpScene;
    using detail::genFilterBandScene;
    using detail::genFineBitsScene;
    using detail::genFloorScene;
    using detail::genHighSpeedScene;
    using detail::genLayoutScene;
    switch (family) {
        case Family::Random:
        case Family::Floor:
        case Family::Stairs:
        case Family::SingleTile:
            return genLayoutScene<T>(family);
        case Family::CornerTie:
        case Family::CornerPass:
            return genCornerScene<T>(family);
        case Family::SeamLanding:
        case Family::Gap:
        case Family::Resting:
            return genFloorScene<T>(family);
        case Family::FarSubUlp:
            return genFarSubUlpScene<T>();
        case Family::FarEdge:
            return genFarEdgeScene<T>();
        case Family::FineBits:
            return genFineBitsScene<T>();
        case Family::Extreme:
            return genExtremeScene<T>();
        case Family::FilterBand:
            return genFilterBandScene<T>();
        case Family::NearTie:
            return genFilterBandScene<T>(true);
        case Family::HighSpeed:
            return genHighSpeedScene<T>();
        case Family::TinyScale:
            return detail::genTinyScaleScene<T>(genScene<T>(Family::Mixed));
        case Family::Capacity:
            return detail::genCapacityScene<T>();
        case Family::Mixed:
            break;
    }
    return rc::gen::weightedOneOf<GeneratedScene<T>>({
        {4, genLayoutScene<T>(Family::Random)},
        {2, genLayoutScene<T>(Family::Floor)},
        {1, genLayoutScene<T>(Family::Stairs)},
        {1, genLayoutScene<T>(Family::SingleTile)},
        {2, genCornerScene<T>(Family::CornerTie)},
        {3, genCornerScene<T>(Family::CornerPass)},
        {2, genFloorScene<T>(Family::SeamLanding)},
        {1, genFloorScene<T>(Family::Gap)},
        {2, genFloorScene<T>(Family::Resting)},
        {1, genFarSubUlpScene<T>()},
        {1, genFarEdgeScene<T>()},
        {1, genFineBitsScene<T>()},
    });
}

/// Every family but `Mixed`, in declaration order.
[[nodiscard]] inline std::vector<Family> allFamilies() {
    std::vector<Family> out;
    for (int f = 0; f < static_cast<int>(Family::Mixed); ++f) out.push_back(static_cast<Family>(f));
    return out;
}

/// RapidCheck keeps the generator being run in process-wide state (rc::detail::ImplicitParam), so
/// two threads must not run generators at once; buildScene takes this lock.
[[nodiscard]] inline std::mutex& generatorMutex() {
    static std::mutex mutex;
    return mutex;
}

/// The scene that `genScene<T>(family)` draws from `seed` at RapidCheck's size `size`: the same
/// builders, run once outside any property, so the same (family, seed, size) always gives the
/// same scene, on every machine with the same standard library. Thread-safe.
template <class T>
[[nodiscard]] GeneratedScene<T> buildScene(Family family, std::uint64_t seed, int size = rc::kNominalSize) {
    const std::lock_guard<std::mutex> lock(generatorMutex());
    return genScene<T>(family)(rc::Random(seed), size).value();
}

/// Prints a generated scene as the scene line it is (every number a hexfloat), so a
/// counterexample reads back bit for bit.
template <class T>
void showValue(const GeneratedScene<T>& g, std::ostream& os) {
    os << familyName(g.family) << ": " << formatScene(g.scene);
}

}  // namespace tilesweep::scenarios

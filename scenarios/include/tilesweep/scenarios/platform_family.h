// SPDX-License-Identifier: MIT
#pragma once

// The one-way families (platforms, platform-landing, platform-jump, platform-walk): jump-through
// platforms ('-', docs/contract.md "One-way tiles") among solid tiles; landed on at every speed
// and on an exact corner, jumped up through and landed on over the following frames, entered from
// the side, walked along across seams. Every value is on the tile/8 (or tile/16, tile/32) grid,
// so a box placed on a platform's top is exactly on it, near the origin and far from it
// (genOrigin).

#include "tilesweep/scenarios/scene_pieces.h"

#include <rapidcheck.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace tilesweep::scenarios::detail {

/// A roll of 0 to n - 1, uniform at every RapidCheck size (inRange at small sizes gives its low
/// end almost always, which would make the first cases of a run all one variant).
inline int roll(int n) { return *rc::gen::resize(100, rc::gen::inRange(0, n)); }

/// Whether a family's origin is far enough that coordinates have coarse ulps (the "far-origin"
/// tag's threshold).
inline bool isFarOrigin(double ox, double oy) { return std::max(std::fabs(ox), std::fabs(oy)) >= 1048576.0; }

/// Random maps of solid and one-way cells: runs of platforms over scattered solid tiles and a
/// floor, any box (sometimes starting inside a platform) and any motion.
template <class T>
rc::Gen<GeneratedScene<T>> genPlatformLayoutScene() {
    return rc::gen::exec([] {
        const int tile = *genTileSize();
        const double ox = *genOrigin<T>(tile);
        const double oy = *genOrigin<T>(tile);
        Grid<T> g;
        g.columns = *rc::gen::inRange(2, 25);
        g.rows = *rc::gen::inRange(3, 17);
        g.cells.assign(static_cast<std::size_t>(g.columns * g.rows), kEmptyCell);
        const int percent = *rc::gen::element(0, 10, 20);
        for (auto& c : g.cells)
            c = *rc::gen::resize(100, rc::gen::inRange(0, 100)) >= 100 - percent ? kSolidCell : kEmptyCell;
        const int runs = *rc::gen::inRange(2, 11);
        for (int k = 0; k < runs; ++k) {
            const int j = *rc::gen::inRange(0, g.rows);
            const int from = *rc::gen::inRange(0, g.columns);
            const int to = *rc::gen::inRange(from, g.columns);
            for (int i = from; i <= to; ++i) g.setOneWay(i, j);
        }
        if (*rc::gen::arbitrary<bool>())
            for (int i = 0; i < g.columns; ++i) g.set(i, g.rows - 1, true);  // a floor
        Box<T> box;
        box.size = {*genLength<T>(tile, 24), *genLength<T>(tile, 24)};
        box.pos = {static_cast<T>(ox + *rc::gen::inRange(-16, g.columns * 8 + 16) * tile / 8.0),
                   static_cast<T>(oy + *rc::gen::inRange(-16, g.rows * 8 + 8) * tile / 8.0)};
        clearUnder(g, ox, oy, tile, box, *rc::gen::arbitrary<bool>());
        std::vector<Vec2<T>> moves;
        const int frames = *rc::gen::weightedOneOf<int>({{5, rc::gen::just(1)}, {4, rc::gen::inRange(2, 7)}});
        for (int f = 0; f < frames; ++f) {  // mostly down: what a platform can stop
            const T dy = *genDisplacement<T>(tile, box.pos.y);
            moves.push_back({*genDisplacement<T>(tile, box.pos.x), roll(4) == 0 ? dy : std::fabs(dy)});
        }
        return GeneratedScene<T>{makeScene(g, ox, oy, tile, box, moves), Family::Platforms,
                                 isFarOrigin(ox, oy)};
    });
}

/// A stack of thin platforms (one tile thick, one to three rows apart) over a solid floor, and a
/// box above them falling at 1/8 of a tile to 100 tiles a frame: it must land on the first
/// platform under it, never tunnel through. Variants: a bottom exactly on a top, or one ulp below
/// it (jumping through) or above; the bottom corner aimed exactly at a platform's top corner, or
/// one ulp either side (a tie lands on y, the side entry passes); entering a platform through
/// its side with the bottom below its top (passes).
template <class T>
rc::Gen<GeneratedScene<T>> genPlatformLandingScene() {
    return rc::gen::exec([] {
        const int tile = *genTileSize();
        const double ox = *genOrigin<T>(tile);
        const double oy = *genOrigin<T>(tile);
        Grid<T> g;
        g.columns = *rc::gen::inRange(6, 33);
        const int topRow = 3;
        const int spacing = *rc::gen::inRange(1, 4);
        const int count = *rc::gen::inRange(1, 6);
        g.rows = topRow + count * spacing + 2;
        g.cells.assign(static_cast<std::size_t>(g.columns * g.rows), kEmptyCell);
        // The platforms' spans; the top one's ends are where the corner and side variants aim.
        int topFrom = 0;
        int topTo = 0;
        for (int k = 0; k < count; ++k) {
            const int from = *rc::gen::inRange(0, g.columns - 1);
            const int to = *rc::gen::inRange(from, g.columns);
            if (k == 0) {
                topFrom = from;
                topTo = to;
            }
            for (int i = from; i <= to; ++i) g.setOneWay(i, topRow + k * spacing);
        }
        for (int i = 0; i < g.columns; ++i) g.set(i, g.rows - 1, true);
        const double top = oy + topRow * tile;
        const double w = *rc::gen::inRange(2, 17) * tile / 8.0;
        const double h = *rc::gen::inRange(2, 17) * tile / 8.0;
        double x = 0;
        double y = 0;
        double dx = 0;
        double dy = 0;
        int nudgeX = 0;
        int nudgeY = 0;
        switch (roll(4)) {
            case 0: {  // falling onto the stack from a height, at any speed
                x = ox + *rc::gen::inRange(topFrom * 8 - 16, (topTo + 1) * 8 + 8) * tile / 8.0;
                y = top - h - *rc::gen::inRange(0, 17) * tile / 8.0;
                dx = *rc::gen::inRange(-32, 33) * tile / 8.0;
                dy = (top - h - y) + *rc::gen::weightedOneOf<int>(
                                         {{3, rc::gen::inRange(1, 17)}, {2, rc::gen::inRange(17, 801)}}) *
                                         tile / 8.0;
                break;
            }
            case 1: {  // the bottom on the top, or one ulp off it, moving down
                x = ox + *rc::gen::inRange(topFrom * 8 - 4, (topTo + 1) * 8 + 4) * tile / 8.0;
                y = top - h;
                nudgeY = *rc::gen::element(0, 0, 1, -1);
                dx = *rc::gen::inRange(-16, 17) * tile / 8.0;
                dy = *rc::gen::weightedOneOf<int>(
                         {{3, rc::gen::inRange(1, 17)}, {1, rc::gen::inRange(17, 801)}}) *
                     tile / 8.0;
                break;
            }
            case 2: {  // a bottom corner aimed at a top corner of the platform: a tie at t = 1/2
                const bool fromRight = *rc::gen::arbitrary<bool>();
                const double px = *rc::gen::inRange(1, 17) * tile / 8.0;
                const double py = *rc::gen::inRange(1, 17) * tile / 8.0;
                const double corner = ox + (fromRight ? topTo + 1 : topFrom) * tile;
                x = fromRight ? corner + px : corner - w - px;
                y = top - h - py;
                dx = (fromRight ? -2 : 2) * px;
                dy = 2 * py;
                nudgeX = *rc::gen::element(0, 0, 1, -1);
                break;
            }
            default: {  // into a platform's side with the bottom below its top
                const bool fromRight = *rc::gen::arbitrary<bool>();
                const double away = *rc::gen::inRange(1, 17) * tile / 8.0;
                const double end = ox + (fromRight ? topTo + 1 : topFrom) * tile;
                x = fromRight ? end + away : end - w - away;
                y = top - h +
                    *rc::gen::inRange(1, static_cast<int>(std::min(h, double(tile)) * 8 / tile) + 1) * tile /
                        8.0;
                dx = (fromRight ? -1 : 1) * (away + *rc::gen::inRange(1, 33) * tile / 8.0);
                dy = *rc::gen::inRange(0, 9) * tile / 8.0;
                break;
            }
        }
        Box<T> box{{static_cast<T>(x), static_cast<T>(y)}, {static_cast<T>(w), static_cast<T>(h)}};
        if (nudgeX != 0) box.pos.x = offGrid(box.pos.x, nudgeX);
        if (nudgeY != 0) box.pos.y = offGrid(box.pos.y, nudgeY);
        clearUnder(g, ox, oy, tile, box, true);
        for (int i = 0; i < g.columns; ++i) g.set(i, g.rows - 1, true);
        std::vector<Vec2<T>> moves{{static_cast<T>(dx), static_cast<T>(dy)}};
        const int after = *rc::gen::weightedOneOf<int>({{3, rc::gen::just(0)}, {1, rc::gen::inRange(1, 6)}});
        for (int k = 0; k < after; ++k)  // then gravity: stays on what it landed on
            moves.push_back({static_cast<T>(*rc::gen::inRange(-8, 9) * tile / 8.0),
                             static_cast<T>(*rc::gen::inRange(1, 65) * tile / 8.0)});
        return GeneratedScene<T>{makeScene(g, ox, oy, tile, box, moves), Family::PlatformLanding,
                                 isFarOrigin(ox, oy)};
    });
}

/// A jump from a solid floor up through a platform two to four tiles above it, then the fall
/// back onto it over the following frames, under constant gravity and a constant walk (the
/// moves a game's velocity integration gives, in sixteenths of a tile); sometimes a solid
/// ceiling over part of the platform, or a start already inside the platform.
template <class T>
rc::Gen<GeneratedScene<T>> genPlatformJumpScene() {
    return rc::gen::exec([] {
        const int tile = *genTileSize();
        const double ox = *genOrigin<T>(tile);
        const double oy = *genOrigin<T>(tile);
        Grid<T> g;
        g.columns = *rc::gen::inRange(6, 21);
        g.rows = 12;
        g.cells.assign(static_cast<std::size_t>(g.columns * g.rows), kEmptyCell);
        const int floorRow = 10;
        for (int i = 0; i < g.columns; ++i) g.set(i, floorRow, true);
        const int platformRow = floorRow - *rc::gen::inRange(2, 5);
        const int from = *rc::gen::inRange(0, g.columns - 2);
        const int to = *rc::gen::inRange(from + 1, g.columns);
        for (int i = from; i <= to; ++i) g.setOneWay(i, platformRow);
        if (roll(4) == 0) {  // a solid ceiling over part of the platform
            const int ceiling = platformRow - *rc::gen::inRange(2, 4);
            const int c0 = *rc::gen::inRange(0, g.columns);
            for (int i = c0; i <= std::min(g.columns - 1, c0 + *rc::gen::inRange(0, 4)); ++i)
                g.set(i, ceiling, true);
        }
        const double h = *rc::gen::inRange(4, 13) * tile / 8.0;
        const double w = *rc::gen::inRange(2, 17) * tile / 8.0;
        double y = oy + floorRow * tile - h;  // standing on the floor
        if (roll(4) == 0)                     // already inside the platform, its bottom below the top
            y = oy + platformRow * tile - h + *rc::gen::inRange(1, 9) * tile / 8.0;
        const double x = ox + *rc::gen::inRange(from * 8 - 8, (to + 1) * 8) * tile / 8.0;
        const Box<T> box{{static_cast<T>(x), static_cast<T>(y)}, {static_cast<T>(w), static_cast<T>(h)}};
        // Velocities in sixteenths of a tile a frame: a gravity, a jump whose apex lifts the
        // box's bottom above the platform mostly (by up to three tiles) or short of it, a
        // terminal fall speed (sometimes many tiles a frame), a walk; frames enough to come down.
        const int gravity = *rc::gen::inRange(1, 7);
        const int rise = 16 * (floorRow - platformRow) + *rc::gen::inRange(-8, 49);
        const int jump = static_cast<int>(std::ceil(std::sqrt(2.0 * gravity * std::max(rise, 1))));
        const int terminal =
            *rc::gen::weightedOneOf<int>({{3, rc::gen::inRange(8, 33)}, {1, rc::gen::inRange(33, 801)}});
        const int walk = *rc::gen::inRange(-6, 7);
        const int frames = 2 * jump / gravity + *rc::gen::inRange(1, 12);
        std::vector<Vec2<T>> moves;
        for (int k = 0; k < frames; ++k) {
            const int vy = std::min(terminal, -jump + k * gravity);
            moves.push_back({static_cast<T>(walk * tile / 16.0), static_cast<T>(vy * tile / 16.0)});
        }
        Grid<T> cleared = g;
        clearUnder(cleared, ox, oy, tile, box, true);
        for (int i = 0; i < g.columns; ++i) cleared.set(i, floorRow, true);
        return GeneratedScene<T>{makeScene(cleared, ox, oy, tile, box, moves), Family::PlatformJump,
                                 isFarOrigin(ox, oy)};
    });
}

/// A box standing exactly on a row of platforms (one-way tiles, with solid ones among them),
/// walking across the seams under gravity for many frames; the row may end (it walks off and
/// falls to a floor below), and a solid block may stand on the row in its way.
template <class T>
rc::Gen<GeneratedScene<T>> genPlatformWalkScene() {
    return rc::gen::exec([] {
        const int tile = *genTileSize();
        const double ox = *genOrigin<T>(tile);
        const double oy = *genOrigin<T>(tile);
        Grid<T> g;
        g.columns = *rc::gen::inRange(8, 33);
        g.rows = 7;
        g.cells.assign(static_cast<std::size_t>(g.columns * g.rows), kEmptyCell);
        const int row = 3;
        const int from = *rc::gen::inRange(0, g.columns / 2);
        const int to = *rc::gen::inRange(g.columns / 2, g.columns);
        for (int i = from; i <= to; ++i) g.put(i, row, roll(6) == 0 ? kSolidCell : kOneWayCell);
        for (int i = 0; i < g.columns; ++i) g.set(i, g.rows - 1, true);
        if (roll(3) == 0) g.set(*rc::gen::inRange(from, to + 1), row - 1, true);  // a block
        const double top = oy + row * tile;
        const T h = static_cast<T>(*rc::gen::inRange(1, 17) * tile / 8.0);
        const T w = *genLength<T>(tile, 24);
        const Box<T> box{{static_cast<T>(ox + *rc::gen::inRange(from * 8, (to + 1) * 8) * tile / 8.0),
                          static_cast<T>(top - static_cast<double>(h))},
                         {w, h}};
        const T vx = static_cast<T>(*rc::gen::inRange(-32, 33) * tile / 16.0);
        const T gravity = static_cast<T>(
            *rc::gen::weightedOneOf<int>({{4, rc::gen::inRange(1, 33)}, {1, rc::gen::inRange(33, 513)}}) *
            tile / 32.0);
        const int frames = *rc::gen::inRange(2, 41);
        std::vector<Vec2<T>> moves(static_cast<std::size_t>(frames), Vec2<T>{vx, gravity});
        clearUnder(g, ox, oy, tile, box, true);
        return GeneratedScene<T>{makeScene(g, ox, oy, tile, box, moves), Family::PlatformWalk,
                                 isFarOrigin(ox, oy)};
    });
}

/// Scenes of one of the one-way families.
template <class T>
rc::Gen<GeneratedScene<T>> genPlatformScene(Family family) {
    switch (family) {
        case Family::PlatformLanding:
            return genPlatformLandingScene<T>();
        case Family::PlatformJump:
            return genPlatformJumpScene<T>();
        case Family::PlatformWalk:
            return genPlatformWalkScene<T>();
        default:
            return genPlatformLayoutScene<T>();
    }
}

}  // namespace tilesweep::scenarios::detail

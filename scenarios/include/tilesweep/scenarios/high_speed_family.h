// SPDX-License-Identifier: MIT
#pragma once

// The high-speed family: 1 to 100 tiles a frame through thin walls.

#include "tilesweep/scenarios/scene_pieces.h"

#include <rapidcheck.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

namespace tilesweep::scenarios::detail {

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
        g.cells.assign(static_cast<std::size_t>(g.columns * g.rows), 0);
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

}  // namespace tilesweep::scenarios::detail

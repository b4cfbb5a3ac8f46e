// SPDX-License-Identifier: MIT
#pragma once

// The layout families (random, floor, stairs, single-tile): random maps of any density, floors,
// walls, corridors, stairs, single tiles, any box and motion.

#include "tilesweep/scenarios/scene_pieces.h"

#include <rapidcheck.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

namespace tilesweep::scenarios::detail {

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
        g.cells.assign(static_cast<std::size_t>(g.columns * g.rows), 0);
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
                for (auto& c : g.cells)
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

}  // namespace tilesweep::scenarios::detail

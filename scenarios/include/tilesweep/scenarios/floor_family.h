// SPDX-License-Identifier: MIT
#pragma once

// The floor families (seam-landing, gap, resting): landings across seams, a box exactly as wide
// as a gap, a box resting on a floor under gravity.

#include "tilesweep/scenarios/scene_pieces.h"

#include <rapidcheck.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

namespace tilesweep::scenarios::detail {

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
        g.cells.assign(static_cast<std::size_t>(g.columns * g.rows), 0);
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

}  // namespace tilesweep::scenarios::detail

// SPDX-License-Identifier: MIT
#pragma once

// The corner families (corner-tie, corner-pass): a box aimed exactly at a tile corner, or on a
// path exactly through a corner point, or one ulp off it.

#include "tilesweep/scenarios/scene_pieces.h"

#include <rapidcheck.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

namespace tilesweep::scenarios::detail {

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
        g.cells.assign(49, 0);
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

}  // namespace tilesweep::scenarios::detail

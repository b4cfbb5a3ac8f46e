// SPDX-License-Identifier: MIT
#pragma once

// The capacity family: contact bounds at the inline limit and just past it.

#include "tilesweep/scenarios/scene_pieces.h"

#include <rapidcheck.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

namespace tilesweep::scenarios::detail {

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
        g.cells.assign(static_cast<std::size_t>(g.columns * g.rows), 0);
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

}  // namespace tilesweep::scenarios::detail

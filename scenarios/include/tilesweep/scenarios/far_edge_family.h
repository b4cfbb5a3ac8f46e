// SPDX-License-Identifier: MIT
#pragma once

// The far-edge family: the rounding rule at work, a far edge a few ulps past a grid line.

#include "tilesweep/scenarios/scene_pieces.h"

#include <rapidcheck.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

namespace tilesweep::scenarios::detail {

/// The rounding rule's family (docs/contract.md, "Positions"). Far from the origin (float 2^17 to
/// 2^21, double 2^46 to 2^50), the box's far edge lies a few ulps past a grid line, just above a
/// solid tile on the far side of that line. Frame 1 moves toward minus infinity on that axis by a
/// few ulps, mostly just enough to take the exact far edge back over the line, and down onto the
/// tile's row, often missing its corner; rounding back toward the start would put the far edge
/// over the line again, inside the tile. Frames 2 and 3 move back toward the tile: the box must
/// stop at its face, never walk into it. Half the scenes swap the axes.
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
        g.cells.assign(36, 0);
        g.set(3, 3, true);  // the tile beyond the line x = ox + 3*tile, one row down
        for (int k = 0; k < 2; ++k)
            g.set(*rc::gen::inRange(3, 6), *rc::gen::inRange(3, 6), *rc::gen::arbitrary<bool>());
        const double line = ox + 3 * tile;
        const double ulp =
            static_cast<double>(std::nextafter(static_cast<T>(line), std::numeric_limits<T>::infinity())) -
            static_cast<double>(static_cast<T>(line));
        // Decimal: off the lattice. In double, half the sizes keep 8 fractional bits, so that the
        // frame's span fits the fast path (with a full significand it goes to the lattice, and
        // only the fast path's filtered grid-line test would be left untried).
        const double width = *rc::gen::inRange(101, 400) / 100.0 * tile / 4;
        const bool shortWidth = !isFloat && *rc::gen::arbitrary<bool>();
        const T w = static_cast<T>(shortWidth ? std::ldexp(std::round(std::ldexp(width, 8)), -8) : width);
        const T h = static_cast<T>(*rc::gen::inRange(1, 9) * tile / 8.0);
        // Far edge a few ulps past the line; bottom a little above the tile's top.
        const T x = static_cast<T>(line + *rc::gen::inRange(1, 5) * ulp - static_cast<double>(w));
        const double gapY = *rc::gen::element(0.0, 1.0, 3.0) * ulp + *rc::gen::inRange(0, 5) * tile / 16.0;
        const T y = static_cast<T>(oy + 3 * tile - static_cast<double>(h) - gapY);
        const Box<T> box{{x, y}, {w, h}};
        // Away by the far edge's offset past the line and a fraction of an ulp more, so that the
        // exact far edge ends just short of the line (where rounding back up would cross it), up
        // to nearly an ulp short (what a filter whose reach is too small misses);
        // now and then a plain quarter of an ulp to four ulps.
        const double offset = static_cast<double>(x) + static_cast<double>(w) - line;
        const double fraction = *rc::gen::element(1.0 / 16, 1.0 / 8, 1.0 / 4, 1.0 / 2, 3.0 / 4, 15.0 / 16);
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
        // One scene in four puts the map at the origin, far from the box: its tiles are out of
        // reach, and the rule acts on the same grid line (ox is a multiple of the tile), now with
        // nothing but the box's own coordinates to bound the rounding's error (no origin as large).
        const bool mapAtOrigin = *rc::gen::inRange(0, 4) == 0;
        Scene<T> scene = makeScene(cleared, mapAtOrigin ? 0.0 : ox, oy, tile, box, moves);
        if (*rc::gen::arbitrary<bool>()) scene = transposed(scene);  // the same on y
        return GeneratedScene<T>{scene, Family::FarEdge, true};
    });
}

}  // namespace tilesweep::scenarios::detail

// SPDX-License-Identifier: MIT
#pragma once

// The extreme family: empty maps, huge moves, huge coordinates.

#include "tilesweep/scenarios/scene_pieces.h"

#include <rapidcheck.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

namespace tilesweep::scenarios::detail {

/// Inputs the other families seldom make: a map of 0 x 0 cells or with no solid cell, moves of
/// 2^20 up to near the largest finite value, boxes far beyond the map (2^60 to 2^120 in float,
/// to 2^1000 in double), half of them coming straight back by exactly their own coordinate, each
/// on a small random map otherwise.
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
        g.cells.assign(static_cast<std::size_t>(g.columns * g.rows), 0);
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
        // A far box coming back by exactly its own coordinate: every cell on its way is entered
        // at a distance whose nearest value is the speed itself, so the walk's tie of a double
        // pair's high part with the speed is decided by the low part (fast_axis.h).
        if (kind == 3 && *rc::gen::element(false, true)) moves.front() = {static_cast<T>(-box.pos.x), T(0)};
        return GeneratedScene<T>{makeScene(g, 0.0, 0.0, tile, box, moves), Family::Extreme, false};
    });
}

}  // namespace tilesweep::scenarios::detail

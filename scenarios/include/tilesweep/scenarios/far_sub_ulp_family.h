// SPDX-License-Identifier: MIT
#pragma once

// The far-sub-ulp family: far from the origin, moves of a few ulps past a tile corner.

#include "tilesweep/scenarios/scene_pieces.h"

#include <rapidcheck.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

namespace tilesweep::scenarios::detail {

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
        g.cells.assign(25, 0);
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

}  // namespace tilesweep::scenarios::detail

// SPDX-License-Identifier: MIT
#pragma once

// The fine-bits family: frame times halfway between two values, tiles reached at t = 1, wide
// lattices.

#include "tilesweep/scenarios/scene_pieces.h"

#include <rapidcheck.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

namespace tilesweep::scenarios::detail {

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
            g.cells.assign(6, 0);
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
            g.cells.assign(64, 0);
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
            g.cells.assign(64, 0);
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

}  // namespace tilesweep::scenarios::detail

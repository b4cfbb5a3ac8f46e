// SPDX-License-Identifier: MIT
#pragma once

// The range-edge family: frames at the edge of the float fast path's range test.

#include "tilesweep/scenarios/scene_pieces.h"

#include <rapidcheck.h>

#include <cmath>
#include <vector>

namespace tilesweep::scenarios::detail {

/// Frames at the edge of the float range test (admitFloatFrame, src/range_admission.h): the span
/// C + 1 - G it computes (kFastSpanBits, src/proof_constants.h) is 56 to 52, where 53 and below
/// are admitted (the fast path must hold every value exactly) and 54 to 56 are turned away (the
/// lattice decides).
///
/// The box's inputs are below 2^B (its position and move in [2^(B-1), 2^B), B drawn from 1 to
/// 40), the tile is t = 3 * 2^(B-5) and the map 13 columns by 3 rows, so that the grid's bound is
/// 2^(B+2) too: C = B + 2. The map's origin o and the box's width w = o + 2^G are the only fine
/// inputs, of 24 bits with their ulp at 2^G, G = B - 53 + j for j in 0..4: span = 56 - j. The box
/// moves along row 1 into a wall at column 11 or 12, whose near face e = o + k*t is a grid line
/// past 2^B, and stops with its near face at e - w = k*t - 2^G. At j = 0 neither is a double:
/// e lies halfway between two doubles 2^(G+1) apart and rounds up, to even (o = 3 mod 4 in units
/// of 2^G), so a range test three binades too generous (FAST_RANGE_TOO_WIDE) computes the touch
/// position fl(e) - w = k*t and leaves the box 2^G inside the wall, where the contract's
/// position is the float below k*t. At j >= 1 both are doubles; at j >= 3 the frame is admitted
/// and the fast path decides it. A third of the scenes have j = 0; half move on y a little too
/// (a slide after the hit), half are the same on y (transposed); the other rows are random.
template <class T>
rc::Gen<GeneratedScene<T>> genRangeEdgeScene() {
    return rc::gen::exec([] {
        const int top = *rc::gen::inRange(1, 41);  // B
        const int j = *rc::gen::element(0, 0, 1, 2, 3, 4);
        const int fine = top - 53 + j;  // G
        const double t = 3 * std::ldexp(1.0, top - 5);
        const int k = *rc::gen::element(11, 12);  // the wall's column: k*t in [1.03, 1.13] * 2^B
        // o in [2^(G+23), 2^(G+24)): 24 bits with the ulp 2^G, 3 mod 4 in units of 2^G; w = o + 2^G.
        const double originBits = std::ldexp(1.0, 23) + *rc::gen::inRange(0, 1 << 21) * 4.0 + 3;
        const double o = std::ldexp(originBits, fine);
        const double w = std::ldexp(originBits + 1, fine);
        Grid<T> g;
        g.columns = 13;
        g.rows = 3;
        g.solid.assign(39, 0);
        for (int i = 0; i < 13; ++i) {
            g.set(i, 0, *rc::gen::arbitrary<bool>());
            g.set(i, 2, *rc::gen::arbitrary<bool>());
        }
        g.set(k, 1, true);
        if (k == 11) g.set(12, 1, *rc::gen::arbitrary<bool>());
        const double unit = std::ldexp(1.0, top - 6);  // 2^B / 64: the box's position and move grid
        const double x = 32 * unit + *rc::gen::inRange(0, 32) * unit;  // [2^(B-1), 2^B)
        const double d = k * t - x + *rc::gen::inRange(1, 17) * unit;  // past the wall's face
        const double y = t + *rc::gen::inRange(1, 5) * t / 8;
        const double h = *rc::gen::inRange(1, 4) * t / 8;  // inside row 1
        const double dy = *rc::gen::element(0, 0, -1, 1) * t / 8;
        const Box<T> box{{static_cast<T>(x), static_cast<T>(y)}, {static_cast<T>(w), static_cast<T>(h)}};
        Scene<T> scene = makeScene(g, o, 0.0, t, box, {{static_cast<T>(d), static_cast<T>(dy)}});
        if (*rc::gen::arbitrary<bool>()) scene = transposed(scene);  // the same on y
        return GeneratedScene<T>{scene, Family::RangeEdge, false};
    });
}

}  // namespace tilesweep::scenarios::detail

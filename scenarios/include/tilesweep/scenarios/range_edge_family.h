// SPDX-License-Identifier: MIT
#pragma once

// The range-edge family: frames at the edge of the float fast path's range test.

#include "tilesweep/scenarios/scene_pieces.h"

#include <rapidcheck.h>

#include <cmath>
#include <vector>

namespace tilesweep::scenarios::detail {

/// Frames at the edge of the float range test (admitFloatFrame, src/range_admission.h): the span
/// C + 1 - G it computes for the first frame (kFastSpanBits, src/proof_constants.h) is 57 to 52,
/// where 53 and below are admitted (the fast path must hold every value exactly) and 54 to 57
/// are turned away (the lattice decides).
///
/// The box's left face x is a grid line in [2^(B-1), 2^B) (B drawn from 1 to 40), on a map of
/// 4 by 3 tiles of t = 2^(B-4) (every edge a float) from 2t left of it: B bounds the box's
/// inputs, B + 1 the grid's, C = B + 2. The box's width w and the first move d are the only
/// fine inputs, 24 bits with the ulp at 2^G, G = B - 54 + j for j in 0..5 (span 57 - j): w is
/// odd in units of 2^G and d = -(w - 2^G), so the box moves toward minus infinity by less than
/// its width and its far face ends at x + 2^G, just past the grid line x. The contract rounds
/// the position toward the start, to x: the far face, back at x + w, crosses no line the exact
/// one had not passed. At j = 0, x + 2^G (>= 2^(G+53)) is not a double: it lies halfway between
/// x and x + 2^(G+1) and rounds to x, so a range test four binades too generous
/// (FAST_RANGE_TOO_WIDE) sees the line x inside [far face, far face rounded) and rounds the
/// position down, one float below x. At j >= 1 it is a double; at j >= 4 the frame is admitted
/// and the fast path decides it. The second frame moves the box into the wall at column 3 (a
/// hit). A third of the scenes have j = 0; half are the same on y (transposed); the other rows
/// are random.
template <class T>
rc::Gen<GeneratedScene<T>> genRangeEdgeScene() {
    return rc::gen::exec([] {
        const int top = *rc::gen::inRange(1, 41);  // B
        const int j = *rc::gen::element(0, 0, 0, 1, 2, 3, 4, 5);
        const int fine = top - 54 + j;  // G
        const double t = std::ldexp(1.0, top - 4);
        const double x = *rc::gen::inRange(8, 16) * t;  // a grid line in [2^(B-1), 2^B)
        // w: 24 bits, odd in units of 2^G; d = -(w - 2^G), 24 bits with the same ulp.
        const double wBits = std::ldexp(1.0, 23) + *rc::gen::inRange(0, 1 << 22) * 2.0 + 1;
        const double w = std::ldexp(wBits, fine);
        const double d = -std::ldexp(wBits - 1, fine);
        Grid<T> g;
        g.columns = 4;
        g.rows = 3;
        g.cells.assign(12, 0);
        for (int i = 0; i < 4; ++i) {
            g.set(i, 0, *rc::gen::arbitrary<bool>());
            g.set(i, 2, *rc::gen::arbitrary<bool>());
        }
        g.set(0, 1, *rc::gen::arbitrary<bool>());
        g.set(3, 1, true);  // the wall the second frame meets
        const double y = t + *rc::gen::inRange(1, 5) * t / 8;
        const double h = *rc::gen::inRange(1, 4) * t / 8;  // inside row 1
        const Box<T> box{{static_cast<T>(x), static_cast<T>(y)}, {static_cast<T>(w), static_cast<T>(h)}};
        const std::vector<Vec2<T>> moves{{static_cast<T>(d), T(0)},
                                         {static_cast<T>(*rc::gen::inRange(9, 17) * t / 8),
                                          static_cast<T>(*rc::gen::element(0, 0, -1, 1) * t / 8)}};
        Scene<T> scene = makeScene(g, x - 2 * t, 0.0, t, box, moves);
        if (*rc::gen::arbitrary<bool>()) scene = transposed(scene);  // the same on y
        return GeneratedScene<T>{scene, Family::RangeEdge, false};
    });
}

}  // namespace tilesweep::scenarios::detail

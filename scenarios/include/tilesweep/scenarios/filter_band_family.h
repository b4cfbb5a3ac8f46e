// SPDX-License-Identifier: MIT
#pragma once

// The filter-band and near-tie families: exact corner ties aimed at the resolver's floating-point
// filter, and the same nudged one ulp off.

#include "tilesweep/scenarios/scene_pieces.h"

#include <rapidcheck.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <type_traits>
#include <vector>

namespace tilesweep::scenarios::detail {

/// Exact corner ties aimed at the resolver's floating-point filter. The box's far corner starts
/// at (a*g, b*g) and moves by (a*s, b*s) toward a tile corner at (a*K, b*K), K = 2^k, s = 2K: the
/// entry distances a(K - g) and b(K - g) are in exact ratio a : b, so the entry times tie exactly,
/// but in double they are not doubles (the resolver carries them as exact pairs hi + lo), and the
/// rounded comparison of a(K-g)*b*s against b(K-g)*a*s comes out nonzero in about 28% of cases.
/// The search below asks for a rounded difference in the upper half of the certified band
/// (kPairProductErrorBound, src/proof_constants.h: (2 + 16u)u, which no exact
/// tie passes). Its four parts (the roundings of both products, both low parts) each reach u of
/// their value only when every significand is just above 1, and add up only when all four are
/// near their largest with one sign: then the two rounded products land two ulps apart. So in
/// double a and b are odd from 259 to 293 (significands 1.01 to 1.15) and K - g's significand
/// is just above 1: the search found the upper half in every double scene of 300 (tag
/// filter-upper-half, floor 50%: 23% of them at 0.7 to 0.8 of the bound, 75% at 0.8 to 0.9, 1%
/// above 0.9), where a and b anywhere in [257, 8193) found it in 66% (the rest are the stream's
/// last candidate). tests/exact_primitives_test.cpp (comparesExactTiesInTheFilterBandsUpperHalf)
/// builds the same ties without a scene. Float's a and b are just above powers of two (257,
/// 513, ..., 8193: its products are exact doubles, compared by monotonic rounding and
/// TwoProduct, with no band). A halved bound (FILTER_BOUND_HALVED) decides the upper half's
/// ties by the sign of D, wrongly; the neighbours show it too: a solid tile across the
/// approached face is hit at the same time as the corner tile, through a comparison of two
/// pair-valued times that the halved band decides wrongly ("1 contacts != 2"). The tile's
/// neighbours across both faces are random.
///
/// With `nearTie`, one input (the box's position or the move, on x or y) is then nudged by one ulp
/// either way: the two products now differ, by far less than the filter's bound, and the exact
/// refinement (TwoProduct, the expansion's sign) must decide a nonzero sign the right way round.
template <class T>
rc::Gen<GeneratedScene<T>> genFilterBandScene(bool nearTie = false) {
    return rc::gen::exec([nearTie] {
        const bool isFloat = std::is_same<T, float>::value;
        std::mt19937_64 rng(*rc::gen::arbitrary<std::uint64_t>());
        // a and b just above powers of two, g < 0: the distances a(K - g), b(K - g) and both
        // products then sit just above a power of two, where a rounding errs by up to u of the
        // value.
        const double near[] = {257, 513, 1025, 2049, 4097, 8193};
        const double u = std::ldexp(1.0, -53);
        const double band = (2.0 + 16.0 * u) * u;  // the certified bound, relative to |p| + |q|
        double a = 257;
        double b = 513;
        double K = 0;
        double g = 0;
        for (int attempt = 0; attempt < 50000; ++attempt) {
            // Double: odd, from 259 to 293 (significands 1.01 to 1.15).
            a = isFloat ? near[rng() % 6] : static_cast<double>(259 + 2 * (rng() % 18));
            b = isFloat ? near[rng() % 6] : static_cast<double>(259 + 2 * (rng() % 18));
            if (a == b) continue;
            K = std::ldexp(1.0,
                           isFloat ? 8 + static_cast<int>(rng() % 6) : 24 + static_cast<int>(rng() % 14));
            const int bits = isFloat ? 8 : 38;  // a*g and b*g stay exact
            g = -std::ldexp(static_cast<double>((rng() >> (64 - bits)) | 1),
                            -bits + static_cast<int>(rng() % 8) - 2);
            if (isFloat || nearTie) break;  // a near tie needs no search: any exact tie, nudged
            // The resolver's comparison: p = fl(Dx.hi * vy), q = fl(Dy.hi * vx), D = fl(p - q).
            const double dx = a * K - a * g;
            const double dy = b * K - b * g;
            const double p = dx * (b * 2 * K);
            const double q = dy * (a * 2 * K);
            const double d = std::fabs(p - q);
            const double bound = band * (std::fabs(p) + std::fabs(q));
            if (d > bound / 2 && d <= bound) break;
        }
        const double tile = 16;
        // The tile at cell (1, 1): its top-left corner is (a*K, b*K).
        const double ox = a * K - tile;
        const double oy = b * K - tile;
        Grid<T> grid;
        grid.columns = 3;
        grid.rows = 3;
        grid.cells.assign(9, 0);
        grid.set(1, 1, true);
        grid.set(0, 1, *rc::gen::arbitrary<bool>());  // across the left face
        grid.set(1, 0, *rc::gen::arbitrary<bool>());  // across the top face
        Box<T> box{{static_cast<T>(a * g - 1), static_cast<T>(b * g - 1)}, {T(1), T(1)}};
        Vec2<T> move{static_cast<T>(a * 2 * K), static_cast<T>(b * 2 * K)};
        if (nearTie) {
            const int direction = *rc::gen::element(-1, 1);
            switch (*rc::gen::inRange(0, 4)) {
                case 0:
                    box.pos.x = offGrid(box.pos.x, direction);
                    break;
                case 1:
                    box.pos.y = offGrid(box.pos.y, direction);
                    break;
                case 2:
                    move.x = offGrid(move.x, direction);
                    break;
                default:
                    move.y = offGrid(move.y, direction);
                    break;
            }
        }
        return GeneratedScene<T>{makeScene(grid, ox, oy, tile, box, {move}),
                                 nearTie ? Family::NearTie : Family::FilterBand, std::fabs(ox) >= 1048576.0};
    });
}

}  // namespace tilesweep::scenarios::detail

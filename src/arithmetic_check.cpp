// SPDX-License-Identifier: MIT
#include "tilesweep/tile_map.h"

#include <cfloat>

// The floating-point environment the exact code assumes, checked where it runs.
//
// The library's few floating-point steps are exact only in IEEE 754 binary32/binary64 arithmetic
// with every operation rounded to nearest on its own: Dekker's TwoProduct (src/exact_double.h)
// and Knuth's TwoSum (src/tile_map.cpp) give wrong error terms when a*b+c is fused into one FMA
// (-ffp-contract=fast, GCC's default), when intermediates keep excess precision (x87), or when
// the rounding mode is not to-nearest (fesetround). Robust-predicate libraries check the same
// (Shewchuk's exactinit). The first two are settled at compile time: -ffp-contract=off on the
// library targets (cmake/warnings.cmake) and the static_assert below. This file checks all three
// again at run time, on the operations as this translation unit was compiled (the build flags of
// the library apply to it) and under the caller's rounding mode: validateTileMap (and so
// prepareMap and ts_map_create_*) refuses every map with MapError::InexactArithmetic when any of
// them fails, so exact code never runs where it would not be exact.

static_assert(FLT_EVAL_METHOD == 0,
              "tilesweep needs float and double expressions evaluated in their own type (FLT_EVAL_METHOD "
              "0, e.g. SSE2 rather than x87): excess precision breaks its exact error terms");

namespace tilesweep {
namespace {

// Loaded through volatile so that the compiler cannot fold the checks at compile time (under its
// own rounding mode and precision) instead of running them as the library's code runs.
template <class T>
T opaque(T value) noexcept {
    volatile T v = value;
    return v;
}

/// Round to nearest, on both signs: 1 + u/4 and 1 + 3u/4 (u the ulp of 1) round to 1 and 1 + u
/// only to nearest (toward zero and downward give 1 for both, upward 1 + u for both); the same
/// on -1 separates downward from toward zero.
template <class T>
bool roundsToNearest(T ulp) noexcept {
    const T one = opaque<T>(1);
    const T quarter = opaque<T>(ulp / 4);
    const T threeQuarters = opaque<T>(ulp / 4 * 3);
    return one + quarter == 1 && one + threeQuarters == 1 + ulp && -one - quarter == -1 &&
           -one - threeQuarters == -1 - ulp;
}

/// No excess precision: (1 + u/2) - 1 is 0 when the sum is rounded to T (a tie, to even), u/2
/// when it is kept wider.
template <class T>
bool roundsEachOperation(T ulp) noexcept {
    const T one = opaque<T>(1);
    const T half = opaque<T>(ulp / 2);
    return (one + half) - one == 0;
}

/// No contraction: a = 1 + d with d^2 below a quarter ulp of 1 (d = 2^-27 in double, 2^-13 in
/// float), so a*a = 1 + 2d + d^2 rounds to p = 1 + 2d, and a*a - p is fl(p - p) = 0 unless the
/// compiler fuses it into fma(a, a, -p) = d^2. Written as TwoProduct's error terms are.
template <class T>
bool multipliesAndAddsSeparately(T d) noexcept {
    const T a = opaque<T>(1 + d);
    const T p = opaque<T>(a * a);
    return a * a - p == 0;
}

template <class T>
bool isExactIn(T ulp, T d) noexcept {
    return roundsToNearest(ulp) && roundsEachOperation(ulp) && multipliesAndAddsSeparately(d);
}

}  // namespace

bool isArithmeticExact() noexcept {
    return isExactIn<float>(0x1p-23f, 0x1p-13f) && isExactIn<double>(0x1p-52, 0x1p-27);
}

}  // namespace tilesweep

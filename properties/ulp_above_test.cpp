// SPDX-License-Identifier: MIT
// ulpAbove (src/exact_double.h) on every kind of finite double: zero, subnormals, the normals
// whose ulp is subnormal, and the rest: always the spacing of doubles just above |v|.
#include "exact_double.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>

namespace tilesweep::detail {
namespace {

double spacingAbove(double v) {
    const double a = std::fabs(v);
    return std::nextafter(a, std::numeric_limits<double>::infinity()) - a;
}

TEST(UlpAbove, isTheSpacingAboveForZeroSubnormalsAndNormals) {
    const double tiny = std::numeric_limits<double>::denorm_min();
    EXPECT_EQ(ulpAbove(0.0), tiny);
    EXPECT_EQ(ulpAbove(-0.0), tiny);
    EXPECT_EQ(ulpAbove(tiny), tiny);
    EXPECT_EQ(ulpAbove(DBL_MIN / 3), tiny);
    EXPECT_EQ(ulpAbove(DBL_MIN), tiny);
    EXPECT_EQ(ulpAbove(std::ldexp(1.0, -970)), std::ldexp(1.0, -1022));
    EXPECT_EQ(ulpAbove(1.0), std::ldexp(1.0, -52));
    EXPECT_EQ(ulpAbove(-1.5), std::ldexp(1.0, -52));
    std::mt19937_64 rng(20);
    for (int k = 0; k < 100000; ++k) {
        std::uint64_t bits = rng() & ~(std::uint64_t{1} << 63);
        if (k % 2 == 0) bits &= (std::uint64_t{1} << 60) - 1;  // small exponents half the time
        double v = 0;
        std::memcpy(&v, &bits, sizeof v);
        if (!std::isfinite(v) || v == DBL_MAX) continue;
        ASSERT_EQ(ulpAbove(v), spacingAbove(v)) << std::hexfloat << v;
        ASSERT_EQ(ulpAbove(-v), spacingAbove(v)) << std::hexfloat << v;
    }
}

}  // namespace
}  // namespace tilesweep::detail

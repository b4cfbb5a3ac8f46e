// SPDX-License-Identifier: MIT
// The float <-> rational helpers: exact conversion in, one directed or nearest rounding out.
// Expected values are worked out from the IEEE 754 binary32/binary64 formats.

#include "tilesweep/oracle/exact/rational_convert.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace tilesweep::oracle {
namespace {

Rational pow2(int k) {
    Rational r(1);
    const Rational two(2);
    for (int n = 0; n < (k < 0 ? -k : k); ++n) {
        r *= two;
    }
    return k < 0 ? Rational(1 / r) : r;
}

Rational ratio(std::int64_t a, std::int64_t b) { return Rational(a) / Rational(b); }

template <class T>
bool sameBits(T a, T b) {
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}

constexpr Rounding kAllRoundings[] = {Rounding::TowardNegative, Rounding::TowardPositive,
                                      Rounding::NearestEven};

TEST(RationalConvert, floatToRationalIsTheExactDyadicValue) {
    EXPECT_EQ(toRational(0.0f), Rational(0));
    EXPECT_EQ(toRational(-0.0f), Rational(0));
    EXPECT_EQ(toRational(1.5f), ratio(3, 2));
    EXPECT_EQ(toRational(-40.25f), ratio(-161, 4));
    // 0.1f = 0x1.99999ap-4 = 0xCCCCCD * 2^-27.
    EXPECT_EQ(toRational(0.1f), Rational(0xCCCCCD) * pow2(-27));
    // 0.1 = 0x1.999999999999ap-4 = 0x1999999999999A * 2^-56.
    EXPECT_EQ(toRational(0.1), Rational(0x1999999999999ALL) * pow2(-56));
    EXPECT_EQ(toRational(std::numeric_limits<float>::denorm_min()), pow2(-149));
    EXPECT_EQ(toRational(std::numeric_limits<double>::denorm_min()), pow2(-1074));
    EXPECT_EQ(toRational(std::numeric_limits<float>::min()), pow2(-126));
    EXPECT_EQ(toRational(std::numeric_limits<float>::max()), (pow2(24) - 1) * pow2(104));
    EXPECT_EQ(toRational(std::numeric_limits<double>::max()), (pow2(53) - 1) * pow2(971));
    EXPECT_EQ(toRational(-std::numeric_limits<double>::max()), -(pow2(53) - 1) * pow2(971));
    // The largest float subnormal: (2^23 - 1) * 2^-149.
    EXPECT_EQ(toRational(std::nextafter(std::numeric_limits<float>::min(), 0.0f)),
              (pow2(23) - 1) * pow2(-149));
}

TEST(RationalConvert, nonFiniteValuesAreRefused) {
    EXPECT_THROW((void)toRational(std::numeric_limits<float>::infinity()), std::invalid_argument);
    EXPECT_THROW((void)toRational(-std::numeric_limits<double>::infinity()), std::invalid_argument);
    EXPECT_THROW((void)toRational(std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
}

template <class T, class Bits>
void expectRoundTrips(std::uint64_t seed) {
    std::vector<T> values{T(0),
                          T(1),
                          T(-1),
                          T(0.1),
                          T(1) / T(3),
                          std::numeric_limits<T>::denorm_min(),
                          -std::numeric_limits<T>::denorm_min(),
                          std::nextafter(std::numeric_limits<T>::min(), T(0)),
                          std::numeric_limits<T>::min(),
                          std::numeric_limits<T>::max(),
                          std::numeric_limits<T>::lowest(),
                          std::nextafter(T(1), T(2)),
                          std::nextafter(T(1), T(0))};
    std::mt19937_64 random(seed);
    while (values.size() < 20000) {
        const auto bits = static_cast<Bits>(random());
        T value;
        std::memcpy(&value, &bits, sizeof value);
        if (std::isfinite(value)) {
            values.push_back(value);
        }
    }
    for (T value : values) {
        const Rational q = toRational(value);
        for (Rounding rounding : kAllRoundings) {
            const T back = fromRational<T>(q, rounding);
            ASSERT_TRUE(sameBits(back, value) || (value == T(0) && back == T(0)))
                << value << " came back as " << back;
        }
    }
}

TEST(RationalConvert, everyFiniteFloatRoundTripsInEveryMode) { expectRoundTrips<float, std::uint32_t>(1); }
TEST(RationalConvert, everyFiniteDoubleRoundTripsInEveryMode) { expectRoundTrips<double, std::uint64_t>(2); }

TEST(RationalConvert, directedRoundingBracketsAValueInsideABinade) {
    // Float spacing in [1, 2) is 2^-23, in [1/2, 1) it is 2^-24.
    const Rational above = 1 + pow2(-60);
    EXPECT_EQ(fromRational<float>(above, Rounding::TowardNegative), 1.0f);
    EXPECT_EQ(fromRational<float>(above, Rounding::TowardPositive), 1.0f + 0x1p-23f);
    EXPECT_EQ(fromRational<float>(above, Rounding::NearestEven), 1.0f);
    const Rational below = 1 - pow2(-60);
    EXPECT_EQ(fromRational<float>(below, Rounding::TowardNegative), 1.0f - 0x1p-24f);
    EXPECT_EQ(fromRational<float>(below, Rounding::TowardPositive), 1.0f);
    EXPECT_EQ(fromRational<float>(below, Rounding::NearestEven), 1.0f);
    EXPECT_EQ(fromRational<double>(below, Rounding::TowardNegative), 1.0 - 0x1p-53);
    EXPECT_EQ(fromRational<double>(above, Rounding::TowardPositive), 1.0 + 0x1p-52);
    // Negative values mirror: toward -inf goes away from zero.
    EXPECT_EQ(fromRational<float>(-above, Rounding::TowardNegative), -(1.0f + 0x1p-23f));
    EXPECT_EQ(fromRational<float>(-above, Rounding::TowardPositive), -1.0f);
    EXPECT_EQ(fromRational<float>(-below, Rounding::TowardPositive), -(1.0f - 0x1p-24f));
}

TEST(RationalConvert, roundingUpCarriesIntoTheNextBinade) {
    // 2 - 2^-24 is the midpoint between 2 - 2^-23 (odd significand, all ones) and 2.
    const Rational midpoint = 2 - pow2(-24);
    EXPECT_EQ(fromRational<float>(midpoint, Rounding::NearestEven), 2.0f);
    EXPECT_EQ(fromRational<float>(midpoint, Rounding::TowardNegative), 2.0f - 0x1p-23f);
    EXPECT_EQ(fromRational<float>(midpoint, Rounding::TowardPositive), 2.0f);
    EXPECT_EQ(fromRational<double>(2 - pow2(-53), Rounding::NearestEven), 2.0);
    EXPECT_EQ(fromRational<double>(2 - pow2(-53), Rounding::TowardNegative), 2.0 - 0x1p-52);
}

TEST(RationalConvert, nearestBreaksTiesToEven) {
    EXPECT_EQ(fromRational<float>(1 + pow2(-24), Rounding::NearestEven), 1.0f);  // 1 is even
    EXPECT_EQ(fromRational<float>(1 + 3 * pow2(-24), Rounding::NearestEven),
              1.0f + 0x1p-22f);  // 1+2^-23 is odd
    EXPECT_EQ(fromRational<float>(1 + pow2(-24) + pow2(-80), Rounding::NearestEven), 1.0f + 0x1p-23f);
    EXPECT_EQ(fromRational<double>(1 + pow2(-53), Rounding::NearestEven), 1.0);
    EXPECT_EQ(fromRational<double>(1 + 3 * pow2(-53), Rounding::NearestEven), 1.0 + 0x1p-51);
    EXPECT_EQ(fromRational<double>(-(1 + 3 * pow2(-53)), Rounding::NearestEven), -(1.0 + 0x1p-51));
}

TEST(RationalConvert, subnormalsUseTheFixedQuantum) {
    const float tiny = std::numeric_limits<float>::denorm_min();  // 2^-149
    EXPECT_EQ(fromRational<float>(ratio(3, 2) * pow2(-149), Rounding::NearestEven),
              2 * tiny);  // tie, 1 is odd
    EXPECT_EQ(fromRational<float>(ratio(5, 2) * pow2(-149), Rounding::NearestEven),
              2 * tiny);  // tie, 2 is even
    EXPECT_EQ(fromRational<float>(ratio(3, 2) * pow2(-149), Rounding::TowardNegative), tiny);
    EXPECT_EQ(fromRational<float>(ratio(3, 2) * pow2(-149), Rounding::TowardPositive), 2 * tiny);
    // Half the smallest subnormal is a tie between 0 (even) and 2^-149.
    EXPECT_EQ(fromRational<float>(pow2(-150), Rounding::NearestEven), 0.0f);
    EXPECT_EQ(fromRational<float>(pow2(-150) + pow2(-200), Rounding::NearestEven), tiny);
    EXPECT_EQ(fromRational<float>(pow2(-151), Rounding::TowardPositive), tiny);
    EXPECT_EQ(fromRational<float>(pow2(-151), Rounding::TowardNegative), 0.0f);
    EXPECT_EQ(fromRational<float>(-pow2(-151), Rounding::TowardNegative), -tiny);
    const float negativeZero = fromRational<float>(-pow2(-151), Rounding::TowardPositive);
    EXPECT_EQ(negativeZero, 0.0f);
    EXPECT_TRUE(std::signbit(negativeZero));
    EXPECT_TRUE(std::signbit(fromRational<double>(-pow2(-1100), Rounding::NearestEven)));
    // Across the subnormal/normal boundary 2^-126.
    const Rational justBelowMinNormal = pow2(-126) - pow2(-160);
    EXPECT_EQ(fromRational<float>(justBelowMinNormal, Rounding::TowardNegative),
              std::nextafter(std::numeric_limits<float>::min(), 0.0f));
    EXPECT_EQ(fromRational<float>(justBelowMinNormal, Rounding::TowardPositive),
              std::numeric_limits<float>::min());
    EXPECT_EQ(fromRational<float>(justBelowMinNormal, Rounding::NearestEven),
              std::numeric_limits<float>::min());
    EXPECT_EQ(fromRational<double>(ratio(7, 2) * pow2(-1074), Rounding::NearestEven),
              4 * std::numeric_limits<double>::denorm_min());  // tie between 3 (odd) and 4
    EXPECT_EQ(fromRational<double>(ratio(7, 2) * pow2(-1074), Rounding::TowardNegative),
              3 * std::numeric_limits<double>::denorm_min());
}

TEST(RationalConvert, overflowFollowsIeee) {
    constexpr float kMax = std::numeric_limits<float>::max();
    constexpr float kInf = std::numeric_limits<float>::infinity();
    const Rational max = toRational(kMax);  // (2^24 - 1) * 2^104; the next step would be 2^128
    const Rational halfUlp = pow2(103);
    EXPECT_EQ(fromRational<float>(max + halfUlp - pow2(50), Rounding::NearestEven), kMax);
    EXPECT_EQ(fromRational<float>(max + halfUlp, Rounding::NearestEven), kInf);  // tie, max is odd
    EXPECT_EQ(fromRational<float>(max + pow2(60), Rounding::TowardNegative), kMax);
    EXPECT_EQ(fromRational<float>(max + pow2(60), Rounding::TowardPositive), kInf);
    const Rational huge = pow2(1200);
    EXPECT_EQ(fromRational<float>(huge, Rounding::TowardNegative), kMax);
    EXPECT_EQ(fromRational<float>(huge, Rounding::TowardPositive), kInf);
    EXPECT_EQ(fromRational<float>(huge, Rounding::NearestEven), kInf);
    EXPECT_EQ(fromRational<float>(-huge, Rounding::TowardPositive), -kMax);
    EXPECT_EQ(fromRational<float>(-huge, Rounding::TowardNegative), -kInf);
    EXPECT_EQ(fromRational<float>(-huge, Rounding::NearestEven), -kInf);
    EXPECT_EQ(fromRational<double>(huge, Rounding::TowardNegative), std::numeric_limits<double>::max());
    EXPECT_EQ(fromRational<double>(huge, Rounding::NearestEven), std::numeric_limits<double>::infinity());
    EXPECT_EQ(fromRational<double>(-huge, Rounding::TowardPositive), std::numeric_limits<double>::lowest());
}

// Division of two integers that are exact in T is correctly rounded by IEEE hardware: an
// independent check of the nearest mode over many non-dyadic values.
TEST(RationalConvert, nearestMatchesCorrectlyRoundedDivision) {
    std::mt19937_64 random(3);
    std::uniform_int_distribution<std::int64_t> numerator53(-(std::int64_t{1} << 53) + 1,
                                                            (std::int64_t{1} << 53) - 1);
    std::uniform_int_distribution<std::int64_t> denominator53(1, (std::int64_t{1} << 53) - 1);
    std::uniform_int_distribution<std::int32_t> numerator24(-(1 << 24) + 1, (1 << 24) - 1);
    std::uniform_int_distribution<std::int32_t> denominator24(1, (1 << 24) - 1);
    for (int n = 0; n < 20000; ++n) {
        const std::int64_t a = numerator53(random) >> (random() % 53);
        const std::int64_t b = (denominator53(random) >> (random() % 53)) | 1;
        ASSERT_EQ(fromRational<double>(ratio(a, b), Rounding::NearestEven),
                  static_cast<double>(a) / static_cast<double>(b))
            << a << "/" << b;
        const std::int32_t c = numerator24(random) >> (random() % 24);
        const std::int32_t d = (denominator24(random) >> (random() % 24)) | 1;
        ASSERT_EQ(fromRational<float>(ratio(c, d), Rounding::NearestEven),
                  static_cast<float>(c) / static_cast<float>(d))
            << c << "/" << d;
    }
}

// For any q in range, toward -inf gives r <= q < next(r), toward +inf gives prev(r) < q <= r.
template <class T>
void expectDirectedBrackets(std::uint64_t seed, int minExponent, int maxExponent) {
    std::mt19937_64 random(seed);
    std::uniform_int_distribution<std::int64_t> small(-1000000007, 1000000007);
    std::uniform_int_distribution<std::int64_t> positive(1, 999999937);
    std::uniform_int_distribution<int> exponent(minExponent, maxExponent);
    constexpr T kInf = std::numeric_limits<T>::infinity();
    const Rational largest = toRational(std::numeric_limits<T>::max());
    for (int n = 0; n < 3000; ++n) {
        // One draw per statement: the order in which a call's arguments are evaluated is
        // unspecified (GCC and clang differ), and the values must not depend on the compiler.
        const std::int64_t numerator = small(random);
        const std::int64_t denominator = positive(random);
        const int e = exponent(random);
        const Rational q = ratio(numerator, denominator) * pow2(e);
        if (q >= largest || q <= -largest) continue;  // no finite value above (or below) it to bracket with
        const T down = fromRational<T>(q, Rounding::TowardNegative);
        const T up = fromRational<T>(q, Rounding::TowardPositive);
        ASSERT_LE(toRational(down), q);
        ASSERT_LT(q, toRational(std::nextafter(down, kInf)));
        ASSERT_GE(toRational(up), q);
        ASSERT_GT(q, toRational(std::nextafter(up, -kInf)));
        const T nearest = fromRational<T>(q, Rounding::NearestEven);
        ASSERT_TRUE(nearest == down || nearest == up);
        const Rational gapDown = q - toRational(down);
        const Rational gapUp = toRational(up) - q;
        if (gapDown < gapUp) {
            ASSERT_EQ(nearest, down);
        } else if (gapUp < gapDown) {
            ASSERT_EQ(nearest, up);
        }
    }
}

TEST(RationalConvert, directedRoundingBracketsRandomFloats) { expectDirectedBrackets<float>(4, -160, 120); }
TEST(RationalConvert, directedRoundingBracketsRandomDoubles) {
    expectDirectedBrackets<double>(5, -1090, 1000);
}

TEST(RationalConvert, roundTowardStaysBetweenStartAndTarget) {
    // From 0 toward 1/3 (above): the largest float <= 1/3; from 1 toward 1/3 (below): the
    // smallest float >= 1/3. 1/3 in float lies between 0x1.555554p-2 and 0x1.555556p-2.
    EXPECT_EQ(roundToward<float>(ratio(1, 3), 0.0f), 0x1.555554p-2f);
    EXPECT_EQ(roundToward<float>(ratio(1, 3), 1.0f), 0x1.555556p-2f);
    EXPECT_EQ(roundToward<float>(ratio(1, 3), 0x1.555554p-2f), 0x1.555554p-2f);  // already there
    // A target equal to the start returns the start itself, sign of zero included.
    EXPECT_TRUE(std::signbit(roundToward<float>(Rational(0), -0.0f)));
    // The start bounds the result even when the target is out of range.
    EXPECT_EQ(roundToward<float>(pow2(300), 1.0f), std::numeric_limits<float>::max());
    EXPECT_EQ(roundToward<double>(-pow2(3000), 0.0), std::numeric_limits<double>::lowest());
}

}  // namespace
}  // namespace tilesweep::oracle

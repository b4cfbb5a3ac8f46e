// SPDX-License-Identifier: MIT
// The exact double primitives of the fast path (src/exact_double.h, the time rounding of
// src/time_rounding.h) against the oracle's exact rationals, on inputs built to sit
// where a filter cannot decide: products that round to the same double, pairs whose products
// differ by far less than the filter's bound, and quotients next to a rounding midpoint. These
// are the cases that double frames reach rarely (double near-ties); each test counts how many
// of its draws took the exact refinement and asserts a floor, so none of them is vacuous.
#include "exact_double.h"
#include "fast_frame.h"
#include "range_admission.h"
#include "time_rounding.h"

#include "tilesweep/oracle/exact/rational.h"
#include "tilesweep/oracle/exact/rational_convert.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <sstream>
#include <type_traits>
#include <vector>

namespace tilesweep::detail {
namespace {

using oracle::Rational;

Rational exactly(double d) { return oracle::toRational(d); }

int signOf(const Rational& r) { return r < 0 ? -1 : (r > 0 ? 1 : 0); }

/// A random double with a full 53-bit significand, either sign, and a binary exponent in
/// [low, high].
double randomDouble(std::mt19937_64& rng, int low, int high) {
    const double significand = 1.0 + std::ldexp(static_cast<double>(rng() >> 12), -52);  // [1, 2)
    const int exponent = std::uniform_int_distribution<int>(low, high)(rng);
    const double v = std::ldexp(significand, exponent);
    return (rng() & 1) ? -v : v;
}

/// A positive double with at most `bits` significant bits and a binary exponent in [low, high].
double shortDouble(std::mt19937_64& rng, int bits, int low, int high) {
    const std::uint64_t top = std::uint64_t{1} << (bits - 1);
    const std::uint64_t significand = top | (rng() & (top - 1));
    const int exponent = std::uniform_int_distribution<int>(low, high)(rng);
    return std::ldexp(static_cast<double>(significand), exponent - (bits - 1));
}

double nextUp(double v) { return std::nextafter(v, INFINITY); }
double nextDown(double v) { return std::nextafter(v, -INFINITY); }

bool hasEvenSignificand(double v) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    return (bits & 1) == 0;
}

/// The double nearest x among the candidates, ties to the even significand: the correct
/// rounding of x when the candidates surround it.
double nearestOf(const Rational& x, std::initializer_list<double> candidates) {
    double best = 0;
    Rational bestDistance = -1;
    for (const double c : candidates) {
        const Rational distance = abs(x - exactly(c));
        if (bestDistance < 0 || distance < bestDistance ||
            (distance == bestDistance && hasEvenSignificand(c) && !hasEvenSignificand(best))) {
            best = c;
            bestDistance = distance;
        }
    }
    return best;
}

TEST(ExactPrimitives, productErrorIsTheExactRoundingErrorOfAProduct) {
    std::mt19937_64 rng(2026120201);
    int lowTermsUsed = 0;  // draws where the split halves' low product is not zero
    for (int k = 0; k < 20000; ++k) {
        const double a = randomDouble(rng, -300, 300);
        const double b = randomDouble(rng, -300, 300);
        const double p = a * b;
        const double e = productError(a, b, p);
        ASSERT_EQ(exactly(e), exactly(a) * exactly(b) - exactly(p)) << std::hexfloat << a << " * " << b;
        const double ca = 134217729.0 * a;
        const double cb = 134217729.0 * b;
        lowTermsUsed += ((a - (ca - (ca - a))) * (b - (cb - (cb - b))) != 0) ? 1 : 0;
    }
    EXPECT_GT(lowTermsUsed, 15000) << "the draws should exercise every term of TwoProduct";
}

TEST(ExactPrimitives, comparesProductsThatRoundToTheSameDoubleExactly) {
    std::mt19937_64 rng(2026120202);
    int ties = 0;  // draws where fl(a*b) == fl(c*d), so the rounding errors decide
    for (int k = 0; k < 20000; ++k) {
        const double a = randomDouble(rng, -40, 40);
        const double b = std::fabs(randomDouble(rng, -40, 40));
        const double c = randomDouble(rng, -40, 40);
        double d = std::fabs(a * b / c);
        for (int step = std::uniform_int_distribution<int>(-2, 2)(rng); step != 0; step += step > 0 ? -1 : 1)
            d = step > 0 ? nextUp(d) : nextDown(d);
        const double cc = (a < 0) == (c < 0) ? c : -c;  // the same sign as a, so the products are close
        bool refined = false;
        const int order = compareProducts(a, b, cc, d, refined);
        const int exact = signOf(exactly(a) * exactly(b) - exactly(cc) * exactly(d));
        ASSERT_EQ(order, exact) << std::hexfloat << a << " * " << b << " vs " << cc << " * " << d;
        ties += refined ? 1 : 0;
    }
    EXPECT_GT(ties, 2000) << "too few products rounded to the same double to test the refinement";
}

/// Products with a zero factor (a box touching a tile at t = 0, its entry distance against the
/// zero time): equal when each product has one, decided without refinement; against a nonzero
/// product, by its sign. (compareProducts' callers keep products away from underflow, so a
/// product rounds to zero only with a zero factor.)
TEST(ExactPrimitives, comparesProductsWithZeroFactorsExactly) {
    std::mt19937_64 rng(2026120301);
    int bothZero = 0;  // draws where each product has a zero factor
    int oneZero = 0;   // draws where exactly one has
    for (int k = 0; k < 20000; ++k) {
        double f[4];
        for (double& v : f) {
            switch (rng() % 3) {
                case 0:
                    v = (rng() & 1) ? -0.0 : 0.0;
                    break;
                default:
                    v = randomDouble(rng, -40, 40);
                    break;
            }
        }
        bool refined = false;
        const int order = compareProducts(f[0], f[1], f[2], f[3], refined);
        const int exact = signOf(exactly(f[0]) * exactly(f[1]) - exactly(f[2]) * exactly(f[3]));
        ASSERT_EQ(order, exact) << std::hexfloat << f[0] << " * " << f[1] << " vs " << f[2] << " * " << f[3];
        const bool zeroLeft = f[0] == 0 || f[1] == 0;
        const bool zeroRight = f[2] == 0 || f[3] == 0;
        if (zeroLeft && zeroRight) {
            ASSERT_FALSE(refined) << "two zero products need no refinement";
            ++bothZero;
        }
        oneZero += zeroLeft != zeroRight ? 1 : 0;
    }
    EXPECT_GT(bothZero, 4000) << "too few draws with a zero factor in each product";
    EXPECT_GT(oneZero, 6000) << "too few draws with a zero product against a nonzero one";
}

/// A normalized pair hi + lo (hi = fl(hi + lo)) near `near`, with a random low part.
ExactPair randomPair(std::mt19937_64& rng, double near) {
    const double lo =
        std::ldexp(randomDouble(rng, 0, 0), std::ilogb(near) - 54 - static_cast<int>(rng() % 20));
    return twoSum(near, lo);
}

TEST(ExactPrimitives, comparesPairProductsInsideTheFilterBandExactly) {
    std::mt19937_64 rng(2026120203);
    int refinedCount = 0;
    int bothSides = 0;
    for (int k = 0; k < 20000; ++k) {
        // A*s against B*t with t = s * 2^j and B = A / 2^j nudged in its low part: the two
        // products differ by a few units in the 100th bit, far inside the filter's band.
        const double s = std::fabs(randomDouble(rng, -20, 20));
        const int j = std::uniform_int_distribution<int>(-8, 8)(rng);
        const double t = std::ldexp(s, j);
        const ExactPair a = randomPair(rng, std::fabs(randomDouble(rng, -20, 20)));
        ExactPair b = {std::ldexp(a.hi, -j), std::ldexp(a.lo, -j)};
        const int nudge = std::uniform_int_distribution<int>(-2, 2)(rng);
        if (nudge != 0 && b.lo != 0) {
            const double lo = nudge > 0 ? nextUp(b.lo) : nextDown(b.lo);
            b = twoSum(b.hi, lo);
        }
        if (k % 8 == 0) b = twoSum(b.hi, b.lo + std::ldexp(b.hi, -60));  // still inside the band
        if (k % 8 == 4) b = twoSum(b.hi, std::ldexp(b.hi, -45));         // outside: the filter decides
        bool refined = false;
        const int order = compareProducts(a, s, b, t, refined);
        const Rational exact =
            (exactly(a.hi) + exactly(a.lo)) * exactly(s) - (exactly(b.hi) + exactly(b.lo)) * exactly(t);
        ASSERT_EQ(order, signOf(exact)) << std::hexfloat << "A = " << a.hi << " + " << a.lo << ", s = " << s
                                        << "; B = " << b.hi << " + " << b.lo << ", t = " << t;
        refinedCount += refined ? 1 : 0;
        bothSides += (refined && order != 0) ? 1 : 0;
    }
    EXPECT_GT(refinedCount, 5000) << "too few comparisons reached the exact refinement";
    EXPECT_GT(bothSides, 2000) << "too few refined comparisons had a nonzero answer";
}

/// The filter's error, |X - D| with X = A*s - B*t exact and D = fl(fl(a.hi*s) - fl(b.hi*t)), as a
/// fraction of its bound kPairProductErrorBound * (|p| + |q|) (proof_constants.h). For an exact
/// tie (X = 0) it is |D| over the bound.
double fractionOfTheBand(ExactPair a, double s, ExactPair b, double t) {
    const double p = a.hi * s;
    const double q = b.hi * t;
    return std::fabs(p - q) / (kPairProductErrorBound * (std::fabs(p) + std::fabs(q)));
}

TEST(ExactPrimitives, comparesExactTiesInTheFilterBandsUpperHalf) {
    // A = t*M and B = s*M as exact pairs (TwoProduct of a double and a small integer), so that
    // A*s = B*t exactly, and the filter's D is all error. Its four parts (the rounding of p and of
    // q, and the low parts of A and B, each up to u of its value) add up to about 2u(|p| + |q|)
    // when all are near their largest and of the same sign: the upper half of the band. With M's
    // significand just above 1 and s, t's at 1.01 to 1.15, p and q are the roundings of two
    // values within about an ulp of each other, and land two ulps apart in about 1 case in 4,000:
    // then |D| is two ulps of p, the bound over p's significand. A bound halved
    // (FILTER_BOUND_HALVED) decides those ties as D's sign, which is not 0.
    std::mt19937_64 rng(2026120207);
    int upper = 0;
    int candidates = 0;
    double largest = 0;
    for (int k = 0; k < 300000; ++k) {
        const double m = 1.0 + std::ldexp(static_cast<double>(rng() >> 11), -53) / 64;  // [1, 1 + 2^-6)
        const double M = std::ldexp(m, std::uniform_int_distribution<int>(-30, 30)(rng));
        const auto multiplier = [&rng] { return static_cast<double>(259 + rng() % 36); };  // [259, 294]
        const double t = multiplier();
        const double s = multiplier();
        if (s == t) continue;
        ++candidates;
        const double aHi = t * M;
        const double bHi = s * M;
        const ExactPair a{aHi, productError(t, M, aHi)};
        const ExactPair b{bHi, productError(s, M, bHi)};
        const double fraction = fractionOfTheBand(a, s, b, t);
        largest = std::max(largest, fraction);
        if (fraction <= 0.5) continue;
        ++upper;
        const Rational exactA = exactly(a.hi) + exactly(a.lo);
        const Rational exactB = exactly(b.hi) + exactly(b.lo);
        ASSERT_EQ(signOf(exactA * exactly(s) - exactB * exactly(t)), 0) << "the construction is an exact tie";
        bool refined = false;
        ASSERT_EQ(compareProducts(a, s, b, t, refined), 0)
            << std::hexfloat << "A = " << a.hi << " + " << a.lo << ", s = " << s << "; B = " << b.hi << " + "
            << b.lo << ", t = " << t << "; |D| at " << std::defaultfloat << fraction << " of the bound";
        EXPECT_TRUE(refined);
        // One ulp off the tie in B's low part: the same D, a nonzero exact sign.
        const ExactPair nudged = twoSum(b.hi, (k & 1) != 0 ? nextUp(b.lo) : nextDown(b.lo));
        const int exact =
            signOf(exactA * exactly(s) - (exactly(nudged.hi) + exactly(nudged.lo)) * exactly(t));
        ASSERT_EQ(compareProducts(a, s, nudged, t, refined), exact)
            << std::hexfloat << "A = " << a.hi << " + " << a.lo << ", s = " << s << "; B = " << nudged.hi
            << " + " << nudged.lo << ", t = " << t;
    }
    std::printf(
        "filter band: %d of %d exact ties in the upper half (%.3f%%), the largest at %.4f of the bound\n",
        upper, candidates, 100.0 * upper / candidates, largest);
    // Measured with this seed: 70 of 291,804 (0.024%), the largest at 0.946 of the bound.
    EXPECT_GT(upper, 40) << "too few exact ties reached the upper half of the filter's band";
    EXPECT_GT(largest, 0.9) << "the construction should come near the top of the band";
    EXPECT_LE(largest, 1.0) << "an exact tie outside the band: the filter would decide it";
}

TEST(ExactPrimitives, signOfSumIsTheSignOfTheExactSum) {
    std::mt19937_64 rng(2026120204);
    for (int k = 0; k < 20000; ++k) {
        // Terms that nearly cancel: x, -x + tiny, and small ones of mixed magnitudes.
        double terms[6];
        const double x = randomDouble(rng, -30, 30);
        terms[0] = x;
        terms[1] = -x;
        for (int i = 2; i < 6; ++i)
            terms[i] = std::ldexp(randomDouble(rng, 0, 0), std::ilogb(x) - 53 * (i - 1) / 2);
        if (k % 3 == 0) terms[5] = -(terms[2] + terms[3]);  // sometimes a zero tail
        Rational sum = 0;
        for (const double term : terms) sum += exactly(term);
        ASSERT_EQ(signOfSum(terms, 6), signOf(sum)) << "draw " << k;
    }
}

/// Draws a time num / den next to the rounding midpoint just above (or just below) a double q
/// in [2^-12, 1), with num an exact pair. Half the draws take a short den (20 bits) and offsets
/// from the midpoint of 2^-30 of q's ulp; the other half a full den (53 bits) and offsets of a
/// few units in the last place of q*den's low half, which put R = num - q*den within the
/// filter's bound of the midpoint without being on it. Returns false when num is not a pair.
bool drawTimeNearDoubleMidpoint(std::mt19937_64& rng, TimeRatio<ExactPair, double>& time, Rational& exact,
                                bool& onMidpoint) {
    const double q = std::ldexp(1.0 + std::ldexp(static_cast<double>(rng() >> 12), -52),
                                -1 - static_cast<int>(rng() % 12));
    const bool fullDen = (rng() & 1) != 0;
    const double den = fullDen ? std::fabs(randomDouble(rng, -4, 20)) : shortDouble(rng, 20, -4, 20);
    const bool above = (rng() & 1) != 0;
    const double ulp = above ? nextUp(q) - q : q - nextDown(q);
    const Rational midpoint = exactly(q) + (above ? 1 : -1) * exactly(ulp) / 2;
    // A third of the draws on the midpoint itself.
    const int offset = rng() % 3 == 0 ? 0 : std::uniform_int_distribution<int>(-3, 3)(rng);
    const Rational unit = fullDen ? exactly(ulp) * exactly(nextUp(den) - den) / 4
                                  : exactly(ulp) * exactly(den) / Rational(0x1p30);
    const Rational num = midpoint * exactly(den) + offset * unit;
    onMidpoint = offset == 0;
    // hi: the double nearest num (from the double estimate and its neighbours), lo = num - hi.
    const double estimate = q * den;
    const double hi = nearestOf(num, {nextDown(nextDown(estimate)), nextDown(estimate), estimate,
                                      nextUp(estimate), nextUp(nextUp(estimate))});
    const Rational rest = num - exactly(hi);
    const double lo = static_cast<double>(rest);
    if (exactly(lo) != rest) return false;  // lo needs more than 53 bits: not a pair
    if (abs(rest) * 2 >= exactly(nextUp(std::fabs(hi)) - std::fabs(hi))) return false;
    if (num > exactly(den)) return false;  // times lie in [0, 1]
    time = {{hi, lo}, den};
    exact = num / exactly(den);
    return true;
}

TEST(ExactPrimitives, roundsPairTimesNextToADoubleMidpointCorrectly) {
    std::mt19937_64 rng(2026120205);
    int drawn = 0;
    int refinedCount = 0;
    int refinedOffMidpoint = 0;  // inside the band but not on the midpoint: the filter's hard case
    for (int k = 0; k < 40000 && drawn < 20000; ++k) {
        TimeRatio<ExactPair, double> time{};
        Rational exact;
        bool onMidpoint = false;
        if (!drawTimeNearDoubleMidpoint(rng, time, exact, onMidpoint)) continue;
        ++drawn;
        bool refined = false;
        double out = 0;
        // The quotient starts within two ulps of the answer and moves one at a time, so the
        // rounding always settles in its four steps: a false here is a lost fast answer.
        ASSERT_TRUE(roundTimeToDouble(time, refined, out))
            << std::hexfloat << "(" << time.num.hi << " + " << time.num.lo << ") / " << time.den;
        const double guess = time.num.hi / time.den;
        const double expected = nearestOf(
            exact, {nextDown(nextDown(guess)), nextDown(guess), guess, nextUp(guess), nextUp(nextUp(guess))});
        ASSERT_EQ(out, expected) << std::hexfloat << "(" << time.num.hi << " + " << time.num.lo << ") / "
                                 << time.den;
        refinedCount += refined ? 1 : 0;
        refinedOffMidpoint += (refined && !onMidpoint) ? 1 : 0;
    }
    EXPECT_GT(drawn, 10000) << "too few valid draws";
    EXPECT_GT(refinedOffMidpoint, 500) << "too few times inside the filter's band off the midpoint";
    EXPECT_GT(refinedCount, drawn / 5) << "too few times reached the exact refinement";
}

TEST(ExactPrimitives, roundsDoubleTimesNextToAFloatMidpointCorrectly) {
    std::mt19937_64 rng(2026120206);
    int refinedCount = 0;
    for (int k = 0; k < 20000; ++k) {
        // num = m * den + a small offset, m a float rounding midpoint in [2^-12, 1): 25 bits.
        const auto f = static_cast<float>(std::ldexp(1.0 + std::ldexp(static_cast<double>(rng() >> 41), -23),
                                                     -1 - static_cast<int>(rng() % 12)));
        const double m = static_cast<double>(f) +
                         (static_cast<double>(std::nextafter(f, 2.0f)) - static_cast<double>(f)) / 2;
        const double den = shortDouble(rng, 20, -4, 20);
        const double base = m * den;  // exact: 25 + 20 bits
        const int offset = std::uniform_int_distribution<int>(-2, 2)(rng);
        const double num = offset == 0 ? base : (offset > 0 ? nextUp(base) : nextDown(base));
        if (num > den) continue;
        bool refined = false;
        float out = 0;
        ASSERT_TRUE(roundTimeToFloat({num, den}, refined, out));
        const Rational exact = exactly(num) / exactly(den);
        const float below = f;
        const float aboveF = std::nextafter(f, 2.0f);
        const Rational toBelow = abs(exact - exactly(static_cast<double>(below)));
        const Rational toAbove = abs(exact - exactly(static_cast<double>(aboveF)));
        std::uint32_t bits = 0;
        std::memcpy(&bits, &below, sizeof bits);
        const float expected =
            toBelow < toAbove ? below : (toAbove < toBelow ? aboveF : ((bits & 1) == 0 ? below : aboveF));
        ASSERT_EQ(out, expected) << std::hexfloat << num << " / " << den;
        refinedCount += refined ? 1 : 0;
    }
    EXPECT_GT(refinedCount, 3000) << "too few times landed on a float midpoint";
}

/// The bits of a float or a double, to compare values with their sign of zero.
template <class T>
std::uint64_t bitsOf(T v) {
    if constexpr (sizeof(T) == 4) {
        std::uint32_t b = 0;
        std::memcpy(&b, &v, sizeof b);
        return b;
    } else {
        std::uint64_t b = 0;
        std::memcpy(&b, &v, sizeof b);
        return b;
    }
}

/// stepBy and stepFromNonzero (the branch-free steps of the rounding) against std::nextafter, on values of
/// every kind its callers can meet and some they cannot: zeros of both signs, subnormals, both
/// signs of normal values, and the largest finite value (one step past it is the infinity).
template <class T>
void stepByMatchesNextafter() {
    std::mt19937_64 rng(91);
    constexpr T inf = std::numeric_limits<T>::infinity();
    std::vector<T> values = {T(0),
                             -T(0),
                             std::numeric_limits<T>::denorm_min(),
                             -std::numeric_limits<T>::denorm_min(),
                             std::numeric_limits<T>::min(),
                             -std::numeric_limits<T>::min(),
                             std::numeric_limits<T>::max(),
                             -std::numeric_limits<T>::max(),
                             T(1),
                             T(-1)};
    for (int k = 0; k < 20000; ++k) {
        const double v = randomDouble(rng, sizeof(T) == 4 ? -150 : -1075, sizeof(T) == 4 ? 126 : 1022);
        values.push_back(static_cast<T>(v));
    }
    // From the infinities, one step toward zero is the largest finite value.
    ASSERT_EQ(stepFromNonzero(inf, -1), std::numeric_limits<T>::max());
    ASSERT_EQ(stepFromNonzero(-inf, 1), -std::numeric_limits<T>::max());
    int negatives = 0;
    int zeros = 0;
    for (const T v : values) {
        ASSERT_EQ(bitsOf(stepBy(v, 0)), bitsOf(v)) << std::hexfloat << v;
        ASSERT_EQ(bitsOf(stepBy(v, 1)), bitsOf(std::nextafter(v, inf))) << std::hexfloat << v;
        ASSERT_EQ(bitsOf(stepBy(v, -1)), bitsOf(std::nextafter(v, -inf))) << std::hexfloat << v;
        // The final rounding's step, from a nonzero value (and no step from any).
        ASSERT_EQ(bitsOf(stepFromNonzero(v, 0)), bitsOf(v)) << std::hexfloat << v;
        if (v != 0) {
            ASSERT_EQ(bitsOf(stepFromNonzero(v, 1)), bitsOf(std::nextafter(v, inf))) << std::hexfloat << v;
            ASSERT_EQ(bitsOf(stepFromNonzero(v, -1)), bitsOf(std::nextafter(v, -inf))) << std::hexfloat << v;
        }
        negatives += std::signbit(v) ? 1 : 0;
        zeros += v == 0 ? 1 : 0;
    }
    EXPECT_GT(negatives, 5000);
    EXPECT_GE(zeros, 2);
}

TEST(Step, MatchesNextafterOnFloats) { stepByMatchesNextafter<float>(); }
TEST(Step, MatchesNextafterOnDoubles) { stepByMatchesNextafter<double>(); }

/// roundToFloat (the fast path's directed rounding of an exact double) against the exact order:
/// rounded up, the float is at or above v and the float below it is below v; rounded down, the
/// mirror. On doubles with full significands (nearly all inexact as floats) and on floats
/// (exact), of both signs, across float's normal and subnormal ranges.
TEST(RoundToFloat, IsTheDirectedRounding) {
    std::mt19937_64 rng(17);
    int inexact = 0;
    for (int k = 0; k < 200000; ++k) {
        double v = randomDouble(rng, -140, 129);  // past 2^128 too: the rounding up overflows
        if (k % 4 == 0 && std::fabs(v) < 0x1p127)
            v = static_cast<double>(static_cast<float>(v));  // a float: exact either way
        const float up = roundToFloat(v, true);
        const float down = roundToFloat(v, false);
        ASSERT_GE(static_cast<double>(up), v) << std::hexfloat << v;
        ASSERT_LT(static_cast<double>(std::nextafter(up, -std::numeric_limits<float>::infinity())), v)
            << std::hexfloat << v;
        ASSERT_LE(static_cast<double>(down), v) << std::hexfloat << v;
        ASSERT_GT(static_cast<double>(std::nextafter(down, std::numeric_limits<float>::infinity())), v)
            << std::hexfloat << v;
        inexact += up != down ? 1 : 0;
    }
    EXPECT_GT(inexact, 140000);
}

/// The bits of a float or a double, for comparisons that tell -0 from +0.
template <class T>
std::uint64_t bitsOfValue(T v) {
    std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t> bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    return bits;
}

/// What roundFinal makes of one end (final_rounding.h), from the exact order alone: an end equal
/// to its start is the start (its sign of zero too); another representable end is itself (a zero
/// +0); an inexact one is the nearest T on the start's side: below the end for an end above the
/// start, above it for one below. `exactEnd` is the end as a rational, `nearest` its rounding to
/// nearest in T; `inexact` whether they differ.
template <class T>
T expectedEnd(const Rational& exactEnd, T nearest, bool inexact, T start) {
    const Rational s = exactly(static_cast<double>(start));
    if (!inexact) return exactEnd == s ? start : static_cast<T>(nearest + T(0));
    const bool above = std::isinf(nearest) ? nearest > 0 : exactly(static_cast<double>(nearest)) > exactEnd;
    if (exactEnd > s) return above ? std::nextafter(nearest, -std::numeric_limits<T>::infinity()) : nearest;
    return above ? nearest : std::nextafter(nearest, std::numeric_limits<T>::infinity());
}

/// The T nearest to the double `hi` (hi itself for doubles), without converting a double beyond
/// float's range: those round to an infinity from 2^128 - 2^103 on (the midpoint after the largest
/// float, which rounds to the even infinity).
template <class T>
T nearestOfHigh(double hi) {
    if constexpr (std::is_same<T, float>::value) {
        if (std::fabs(hi) >= 0x1.ffffffp127)
            return std::copysign(std::numeric_limits<float>::infinity(),
                                 static_cast<float>(std::signbit(hi) ? -1 : 1));
        return static_cast<float>(hi);
    } else {
        return hi;
    }
}

/// One lane's draw: a start and an end that the start plus a displacement makes, exactly, as a
/// float frame's (an exact double) or a double frame's (an exact pair) end is. Starts of both
/// signs and zeros of both signs; displacements from far below the start's ulp to far above it.
template <class T>
void drawEnd(std::mt19937_64& rng, T& start, double& endHi, double& endLo) {
    constexpr int digits = std::numeric_limits<T>::digits;
    const int kind = static_cast<int>(rng() % 8);
    start = kind == 0 ? T(0) : static_cast<T>(randomDouble(rng, -20, 40));
    if (kind == 1) start = -start;  // -0 among them
    T move = static_cast<T>(randomDouble(rng, -30 - digits, 40));
    if (std::is_same<T, float>::value && kind == 7) {
        // Far out, moving farther: the end can pass the largest float (the nearest is then an
        // infinity, and the rounding toward the start the largest float).
        const double largest = static_cast<double>(std::numeric_limits<T>::max());
        const double out = std::min(std::fabs(randomDouble(rng, 127, 127)), largest);
        start = static_cast<T>(std::copysign(out, static_cast<double>(move)));
        move =
            static_cast<T>(std::copysign(std::fabs(randomDouble(rng, 100, 126)), static_cast<double>(move)));
    }
    if (kind == 2) move = -start;  // back to zero
    if (kind == 3) move = T(0);    // a still axis: the start's bits
    const ExactPair sum = twoSum(static_cast<double>(start), static_cast<double>(move));
    endHi = sum.hi;
    endLo = sum.lo;
}

/// roundFloatEndsTogether and roundDoubleEndsTogether (final_rounding.h: both ends of a frame
/// rounded at once) against expectedEnd on each lane, bit for bit, and their refusals against
/// the rule: exactly when an inexact end lies below its start on an axis whose lines are not
/// clear (the amended rule may apply there). Floors on the inexact negative ends rounded (the
/// sign of the bit step), the ends equal to a start of -0, the float ends beyond the largest
/// float, and the refusals, so that every case is reached.
template <class T>
void checkEndsTogether(std::uint64_t seed) {
#if !defined(TILESWEEP_FINAL_ROUNDING_SSE2)
    float out = 0;
    EXPECT_FALSE(roundFloatEndsTogether(
        1.5, 2.5, 1.0F, 2.0F, [] { return 3; }, out, out));  // roundFinal only
    static_cast<void>(seed);
    GTEST_SKIP() << "no SSE2 lanes here: roundFinal rounds every end";
#else
    std::mt19937_64 rng(seed);
    int negativeInexact = 0;
    int negativeZeroStart = 0;
    int refused = 0;
    int beyondLargest = 0;
    for (int k = 0; k < 100000; ++k) {
        T start[2];
        double hi[2];
        double lo[2];
        for (int a = 0; a < 2; ++a) drawEnd(rng, start[a], hi[a], lo[a]);
        if constexpr (std::is_same<T, float>::value) {
            if (lo[0] != 0 || lo[1] != 0) continue;  // a float frame's end is an exact double
        }
        const int linesClear = static_cast<int>(rng() % 4);
        bool mustRefuse = false;
        T expected[2];
        for (int a = 0; a < 2; ++a) {
            const Rational exactEnd = exactly(hi[a]) + exactly(lo[a]);
            const T nearest = nearestOfHigh<T>(hi[a]);
            const bool inexact = std::isinf(nearest) || exactly(static_cast<double>(nearest)) != exactEnd;
            expected[a] = expectedEnd(exactEnd, nearest, inexact, start[a]);
            const bool below = exactEnd < exactly(static_cast<double>(start[a]));
            mustRefuse |= inexact && below && ((linesClear >> a) & 1) == 0;
            ASSERT_TRUE(std::isfinite(expected[a]));  // rounding toward a finite start never overflows
            negativeInexact += inexact && exactEnd < 0 ? 1 : 0;
            negativeZeroStart += !inexact && exactEnd == 0 && std::signbit(start[a]) ? 1 : 0;
            beyondLargest += std::fabs(hi[a]) > static_cast<double>(std::numeric_limits<T>::max()) ? 1 : 0;
        }
        T out[2] = {T(7), T(7)};
        bool together = false;
        if constexpr (std::is_same<T, float>::value) {
            together = roundFloatEndsTogether(
                hi[0], hi[1], start[0], start[1], [&] { return linesClear; }, out[0], out[1]);
        } else {
            together = roundDoubleEndsTogether(
                {hi[0], lo[0]}, {hi[1], lo[1]}, start[0], start[1], [&] { return linesClear; }, out[0],
                out[1]);
        }
        ASSERT_EQ(together, !mustRefuse) << std::hexfloat << hi[0] << " " << hi[1] << " from " << start[0]
                                         << " " << start[1] << ", lines clear " << linesClear;
        refused += together ? 0 : 1;
        if (!together) continue;
        for (int a = 0; a < 2; ++a)
            ASSERT_EQ(bitsOfValue(out[a]), bitsOfValue(expected[a]))
                << std::hexfloat << "end " << hi[a] << " + " << lo[a] << " from " << start[a] << ": "
                << out[a] << ", expected " << expected[a];
    }
    EXPECT_GT(negativeInexact, 10000);
    EXPECT_GT(negativeZeroStart, 500);
    EXPECT_GT(refused, 5000);
    if (std::is_same<T, float>::value) {
        EXPECT_GT(beyondLargest, 500);
    }
#endif
}

TEST(FinalRounding, BothEndsAtOnceRoundTowardTheStartsInFloat) { checkEndsTogether<float>(48); }
TEST(FinalRounding, BothEndsAtOnceRoundTowardTheStartsInDouble) { checkEndsTogether<double>(49); }

/// The range test's promise to double frames (admitDoubleFrame, range_admission.h): every frame
/// it admits, by its short form or its full test, gets the far box edge's distances to the tile
/// edges as exact pairs (FastAxis::farEdgeMinus: a three-term sum made a pair again, exact only
/// while the box's and the grid's bits span at most kDoubleFramePairSpanBits), and exact tile
/// edges. The draws aim at that span's limit: a box far out (up to 2^62) with a size whose
/// lowest bit lies 90 to 125 bits below the box's top on a map of tiles of a few bits, and in a
/// quarter of the draws a tiny map of 50-bit tiles at the origin with a box of a game's range far
/// from it (the span then lies in the map's bits). Every
/// admitted frame's distances to the edges of cells -1 to cells + 1 are checked against the exact
/// rational; the test counts the admitted frames whose span exceeds 100 bits and asserts a floor,
/// so that the limit is reached, not only approached.
TEST(DoubleFrameRange, AdmitsOnlyFramesWithExactFarEdgeDistances) {
    std::mt19937_64 rng(2026);
    std::vector<std::uint8_t> solid(64 * 2, 0);
    int admitted = 0;
    int nearTheLimit = 0;
    int shortForm = 0;
    for (int draw = 0; draw < 40000; ++draw) {
        double tile = 0;
        double origin = 0;
        std::int32_t cells = 0;
        int boxExponent = 0;
        int sizeExponent = 0;
        int span = 0;
        if (draw % 4 == 0) {
            // A tiny map at the origin (50-bit tiles near 2^-35, a few cells: its edges are exact,
            // their lowest bits near 2^-84) and a box of a game's range far from it (2^20 to 2^30,
            // size 2^-20 to 1): the span lies in the map's bits, which the short form must check.
            tile = shortDouble(rng, 50, -40, -30);
            cells = static_cast<std::int32_t>(4 + rng() % 3);
            boxExponent = std::uniform_int_distribution<int>(20, 29)(rng);
            sizeExponent = std::uniform_int_distribution<int>(-20, 0)(rng);
            span = boxExponent + 2 + 84;
        } else {
            tile = shortDouble(rng, 3, -4, 8);
            origin = tile * static_cast<double>(static_cast<std::int64_t>(rng() % 1000) - 500);
            cells = static_cast<std::int32_t>(4 + rng() % 60);
            boxExponent = std::uniform_int_distribution<int>(10, 62)(rng);
            span = std::uniform_int_distribution<int>(90, 125)(rng);
            sizeExponent = boxExponent + 54 - span;
        }
        const double x = randomDouble(rng, boxExponent, boxExponent);
        const double w = std::fabs(randomDouble(rng, sizeExponent, sizeExponent));
        const TileMapView<double> map{{origin, 0}, {tile, 1}, cells, 2, solid.data()};
        const ResolveInput<double> in{map, {{x, 0.5}, {w, 0.5}}, {-w, 0.25}};
        const MapRange range = doubleMapRange(map);
        if (!admitDoubleFrame(in, range)) continue;
        ++admitted;
        nearTheLimit += span > 100 ? 1 : 0;
        shortForm += range.common && std::fabs(x) < 0x1p30 && w >= 0x1p-20 ? 1 : 0;
        const FastFrame<double> frame(in, range);
        const auto& axis = frame.axis(0);
        const Rational farEdge = exactly(x) + exactly(w);
        for (std::int64_t k : {std::int64_t{-1}, std::int64_t{0}, std::int64_t{1}, std::int64_t{cells / 2},
                               std::int64_t{cells}, std::int64_t{cells + 1}}) {
            const double e = axis.edge(k);
            ASSERT_EQ(exactly(e), exactly(origin) + Rational(k) * exactly(tile))
                << "edge " << k << " of tile " << std::hexfloat << tile << " origin " << origin;
            const ExactPair d = axis.farEdgeMinus(e);
            ASSERT_EQ(exactly(d.hi) + exactly(d.lo), farEdge - exactly(e))
                << std::hexfloat << "box " << x << " size " << w << " edge " << e << " (span " << span << ")";
        }
    }
    EXPECT_GT(admitted, 5000);
    EXPECT_GT(nearTheLimit, 1000) << "too few admitted frames beyond a 100-bit span";
    EXPECT_GT(shortForm, 500) << "too few frames the short form admits";
}

/// The float range test's short form (admitFloatFrameInWindow) admits only frames the full test
/// admits. Each input's binade is drawn from three below the map's window to two above it (and
/// zeros, negative sizes, subnormals, infinities and NaNs now and then), so that the draws cross
/// both ends of the window, where a window one binade too wide would admit what the span test
/// refuses.
TEST(FloatFrameRange, TheShortFormAdmitsOnlyWhatTheFullTestAdmits) {
    std::mt19937_64 rng(43);
    const std::vector<std::uint8_t> solid(4096, 0);
    int maps = 0;
    int admittedShort = 0;
    int atTheWindowsFloor = 0;
    int refusedBelowIt = 0;
    for (int draw = 0; draw < 200000; ++draw) {
        const float tile = std::ldexp(static_cast<float>(rng() % 16 + 1), static_cast<int>(rng() % 13) - 4);
        const std::int32_t cells = static_cast<std::int32_t>(1 + rng() % 2000);
        const float origin =
            (rng() % 2) ? 0.0F : tile * static_cast<float>(static_cast<int>(rng() % 1001) - 500);
        const TileMapView<float> map{{origin, 0}, {tile, tile}, cells, 2, solid.data()};
        const MapRange range = floatMapRange(map);
        if (!range.common) continue;
        ++maps;
        const int low = std::ilogb(range.commonLeast) + 127;  // the window's fields, fL to fH
        const int high = std::isinf(range.commonLimit) ? 254 : std::ilogb(range.commonLimit) + 127 - 1;
        const auto input = [&](bool size) {
            const unsigned pick = static_cast<unsigned>(rng() % 64);
            if (pick == 0) return size ? -1.0F : 0.0F;
            if (pick == 1)
                return std::numeric_limits<float>::denorm_min() * static_cast<float>(rng() % 100 + 1);
            if (pick == 2) return (rng() % 2) ? std::numeric_limits<float>::infinity() : std::nanf("");
            const int field =
                std::uniform_int_distribution<int>(std::max(1, low - 3), std::min(254, high + 2))(rng);
            const std::uint32_t bits = (static_cast<std::uint32_t>(field) << 23) |
                                       static_cast<std::uint32_t>(rng() & 0x7fffff) |
                                       (!size && rng() % 2 ? 0x80000000u : 0u);
            float v = 0;
            std::memcpy(&v, &bits, sizeof v);
            return v;
        };
        const float x = input(false);
        const float y = input(false);
        const float w = input(true);
        const float h = input(true);
        const float dx = input(false);
        const float dy = input(false);
        const ResolveInput<float> in{map, {{x, y}, {w, h}}, {dx, dy}};
        const bool inWindow = admitFloatFrameInWindow(in, range);
        const bool fully = admitFloatFrameFully(in, range);
        if (inWindow) {
            ASSERT_TRUE(fully) << std::hexfloat << "box " << x << ", " << y << " size " << w << ", " << h
                               << " move " << dx << ", " << dy << " origin " << origin << " tile " << tile
                               << " cells " << cells << " window fields " << low << " to " << high;
        }
        admittedShort += inWindow ? 1 : 0;
        int least = 255;
        for (float v : {x, y, w, h, dx, dy}) {
            std::uint32_t bits = 0;
            std::memcpy(&bits, &v, sizeof bits);
            if ((bits & 0x7fffffffu) != 0) least = std::min(least, static_cast<int>((bits >> 23) & 0xff));
        }
        atTheWindowsFloor += inWindow && least == low ? 1 : 0;
        refusedBelowIt += !fully && least == low - 1 ? 1 : 0;
    }
    EXPECT_GT(maps, 100000);
    EXPECT_GT(admittedShort, 20000) << "too few frames the short form admits";
    EXPECT_GT(atTheWindowsFloor, 2000)
        << "too few admitted frames with an input in the window's lowest binade";
    EXPECT_GT(refusedBelowIt, 2000) << "too few refused frames with an input one binade below the window";
}

/// A frame in its map's window takes the map's magnitude bound for its cell estimates' margins
/// (MapRange::windowMagnitude, FastFrame::magnitude): it is at least the frame's own on each
/// axis. The draws put every input of the box in the window's top binade half the time, where
/// the high edge x + w nears twice the limit and the sum its largest.
template <class T>
void checkWindowMagnitude(std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    const std::vector<std::uint8_t> solid(4096, 0);
    int inWindow = 0;
    int nearTheBound = 0;
    for (int draw = 0; draw < 100000; ++draw) {
        const T tile = std::ldexp(static_cast<T>(rng() % 16 + 1), static_cast<int>(rng() % 13) - 4);
        const std::int32_t cells = static_cast<std::int32_t>(1 + rng() % 2000);
        const T origin = (rng() % 2) ? T(0) : tile * static_cast<T>(static_cast<int>(rng() % 1001) - 500);
        const TileMapView<T> map{{origin, origin}, {tile, tile}, cells, 2, solid.data()};
        const MapRange range = mapRangeOf(map);
        if (!range.common) continue;
        double limit = 0x1p30;  // the double window's
        if constexpr (std::is_same<T, float>::value) limit = static_cast<double>(range.commonLimit);
        const auto input = [&](bool size) {
            // In the top binade [limit / 2, limit) half the time, else anywhere in 2^-12 to 1 of it.
            const int below = (rng() % 2) ? 1 : 1 + static_cast<int>(rng() % 12);
            const double unit = std::ldexp(limit, -below);
            const T v = static_cast<T>(unit + unit * std::ldexp(static_cast<double>(rng() % 1024), -10));
            return size || rng() % 2 ? v : -v;
        };
        const ResolveInput<T> in{
            map, {{input(false), input(false)}, {input(true), input(true)}}, {input(false), input(false)}};
        bool shortForm = false;
        if constexpr (std::is_same<T, float>::value) {
            shortForm = admitFloatFrameInWindow(in, range);
        } else {
            shortForm = admitDoubleFrameInWindow(in, range);
        }
        if (!shortForm) continue;
        ++inWindow;
        const FastFrame<T> bounded(in, range, true);
        const FastFrame<T> own(in, range, false);
        for (int a = 0; a < 2; ++a) {
            ASSERT_GE(bounded.magnitude(a), own.magnitude(a))
                << std::hexfloat << "axis " << a << " box " << in.box.pos.x << ", " << in.box.pos.y
                << " size " << in.box.size.x << ", " << in.box.size.y << " move " << in.displacement.x << ", "
                << in.displacement.y << " origin " << origin;
            nearTheBound += own.magnitude(a) > 0.875 * bounded.magnitude(a) ? 1 : 0;
        }
    }
    EXPECT_GT(inWindow, 20000);
    EXPECT_GT(nearTheBound, 1000) << "too few frames whose magnitude comes within 1/8 of the bound";
}

TEST(WindowMagnitude, BoundsTheFramesOwnInFloat) { checkWindowMagnitude<float>(44); }
TEST(WindowMagnitude, BoundsTheFramesOwnInDouble) { checkWindowMagnitude<double>(45); }

/// The grid-line shortcut's window form (setWindowLinesClear, FastFrame::linesClear on a frame
/// in its map's window) claims no more than the general form (linesClearOf, which
/// LinesClear.NoGridLineFallsBetweenAnEndAndTheValueAbove* holds to the exact rationals). The
/// draws aim at the bound: grids whose lowest bit 2^q puts q + p near the window's exponent W
/// (tiles of up to 16 significant bits, origins on the grid), boxes in the window's top two
/// binades, and sizes whose lowest bit lies within two of the grain 2^(W + 1 - p).
template <class T>
void checkWindowLinesClear(std::uint64_t seed) {
    constexpr int p = std::numeric_limits<T>::digits;
    std::mt19937_64 rng(seed);
    const std::vector<std::uint8_t> solid(1 << 16, 0);
    int inWindow = 0;
    int clearInWindow = 0;
    int refusedAtTheBound = 0;
    int axesDiffer = 0;
    for (int draw = 0; draw < 200000; ++draw) {
        const int tileBits = 1 + static_cast<int>(rng() % 16);
        const double odd = static_cast<double>(2 * (rng() % (std::uint64_t{1} << (tileBits - 1))) + 1);
        // Float windows follow the map (2^W near its extent); the double one is 2^30, so its
        // grids' lowest bit must come near 2^(30 - p).
        const int tileExponent = std::is_same<T, float>::value ? static_cast<int>(rng() % 12) - 10
                                                               : static_cast<int>(rng() % 13) - 26;
        const T tile = static_cast<T>(std::ldexp(odd, tileExponent));
        const std::int32_t cells = static_cast<std::int32_t>(1 + rng() % 4000);
        // Each axis its own origin, now and then a few bits finer than the tile, so that the two
        // axes' grids can differ in their lowest bit.
        const auto drawOrigin = [&] {
            const T onGrid = tile * static_cast<T>(static_cast<int>(rng() % 2001) - 1000);
            switch (rng() % 4) {
                case 0:
                    return T(0);
                case 1:
                    return static_cast<T>(
                        std::ldexp(static_cast<double>(onGrid) + static_cast<double>(tile) / 2,
                                   -static_cast<int>(rng() % 3)));
                default:
                    return onGrid;
            }
        };
        const T origin = drawOrigin();
        const T originY = drawOrigin();
        const TileMapView<T> map{{origin, originY}, {tile, tile}, cells, 16, solid.data()};
        const MapRange range = mapRangeOf(map);
        if (!range.common) continue;
        int windowExponent = 30;  // the double window's
        if constexpr (std::is_same<T, float>::value) windowExponent = std::ilogb(range.commonLimit);
        const double limit = std::ldexp(1.0, windowExponent);
        const auto inTop = [&] {  // in [limit / 4, limit), either sign
            const double v = limit * (0.25 + 0.75 * std::ldexp(static_cast<double>(rng() % 4096), -12));
            return static_cast<T>((rng() % 2) ? v : -v);
        };
        const int sizeBit = windowExponent + 1 - p + static_cast<int>(rng() % 5) - 2;
        const T size = static_cast<T>(std::ldexp(static_cast<double>(2 * (rng() % 64) + 1), sizeBit));
        const ResolveInput<T> in{map, {{inTop(), inTop()}, {size, size}}, {inTop(), inTop()}};
        if (!admitFrameInWindow(in, range)) continue;
        ++inWindow;
        const FastFrame<T> window(in, range, true);
        const FastFrame<T> general(in, range, false);
        // The final rounding's two-lane form reads both axes' answers at once (linesClearBits):
        // bit a must be axis a's own.
        const int bits = window.linesClearBits();
        axesDiffer += range.windowLinesClearBits == 1 || range.windowLinesClearBits == 2 ? 1 : 0;
        for (int a = 0; a < 2; ++a) {
            ASSERT_EQ((bits >> a) & 1, window.linesClear(a) ? 1 : 0) << "axis " << a;
            if (window.linesClear(a)) {
                ASSERT_TRUE(general.linesClear(a))
                    << std::hexfloat << "axis " << a << " box " << in.box.pos.x << ", " << in.box.pos.y
                    << " size " << size << " move " << in.displacement.x << ", " << in.displacement.y
                    << " origin " << origin << " tile " << tile << " window 2^" << windowExponent;
                ++clearInWindow;
            }
            refusedAtTheBound += !general.linesClear(a) && range.lineBit[a] + p == windowExponent ? 1 : 0;
        }
    }
    EXPECT_GT(inWindow, 20000);
    EXPECT_GT(clearInWindow, 5000) << "too few axes the window form clears";
    EXPECT_GT(refusedAtTheBound, 500)
        << "too few refused axes whose grid bit is one short of the window's ends";
    EXPECT_GT(axesDiffer, 500) << "too few frames whose two axes' grids differ in the window's answer";
}

TEST(WindowLinesClear, ClaimsNoMoreThanTheGeneralShortcutInFloat) { checkWindowLinesClear<float>(46); }
TEST(WindowLinesClear, ClaimsNoMoreThanTheGeneralShortcutInDouble) { checkWindowLinesClear<double>(47); }

/// The bits of a double, so that -0 and +0 (and every other pair of values) compare as bits.
std::uint64_t bitsOf(double v) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    return bits;
}

/// The fast frame's set-up (FastFrame's constructor: on two SSE2 lanes where they are at hand,
/// setUpOnLanes) gives each axis the numbers of its per-axis definitions, bit for bit: the
/// motion (pos, fl(pos + size) and its error, disp, |disp|, its sign, the grid), the exact end
/// low + disp (sumOf), and the swept cells (FastFrame::sweptCells, the scalar estimate). Each
/// axis draws its own values, from families that reach every lane operation's corner: zeros of
/// either sign (std::min and a lane's min differ only in the order of their operands, which
/// shows on +0 against -0), negative and zero moves, boxes off the map on either side (empty and
/// clamped ranges), ends whose sum with the size is inexact (a nonzero pair error in double), and
/// frames in the map's window or not, with the window's magnitude or the frame's own. A lane
/// read from the other axis, or a min for a max, fails here.
template <class T>
void checkSetUpOnLanes(std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    const std::vector<std::uint8_t> solid(200 * 200, 0);
    int frames = 0;
    int negativeMoves = 0;
    int zeroMoves = 0;
    int signedZeroEnds = 0;
    int inexactFarEdges = 0;
    int exactDistanceFrames = 0;  // double frames whose tile distances are all exact doubles
    int emptyRanges = 0;
    int clampedRanges = 0;
    int inWindowFrames = 0;
    for (int draw = 0; draw < 100000; ++draw) {
        const auto drawTile = [&] {
            switch (rng() % 3) {
                case 0:
                    return T(1);
                case 1:
                    return static_cast<T>(std::ldexp(1.0, static_cast<int>(rng() % 9) - 4));
                default:
                    return static_cast<T>(shortDouble(rng, 12, -3, 5));
            }
        };
        const T tiles[2] = {drawTile(), drawTile()};
        const T origins[2] = {
            rng() % 2 ? T(0) : static_cast<T>(tiles[0] * static_cast<T>(static_cast<int>(rng() % 41) - 20)),
            rng() % 2 ? T(0) : static_cast<T>(tiles[1] * static_cast<T>(static_cast<int>(rng() % 41) - 20))};
        const std::int32_t cells[2] = {static_cast<std::int32_t>(1 + rng() % 200),
                                       static_cast<std::int32_t>(1 + rng() % 200)};
        const TileMapView<T> map{
            {origins[0], origins[1]}, {tiles[0], tiles[1]}, cells[0], cells[1], solid.data()};
        // A coordinate on axis a: a zero of either sign, a point of the map or near it (either side),
        // or a value of full precision.
        const auto drawCoordinate = [&](int a) {
            const double extent = static_cast<double>(tiles[a]) * cells[a];
            switch (rng() % 6) {
                case 0:
                    return T(0);
                case 1:
                    return T(-0.0);
                case 2:
                    return static_cast<T>(
                        static_cast<double>(origins[a]) +
                        extent * (1.4 * std::ldexp(static_cast<double>(rng() % 4096), -12) - 0.2));
                case 3:
                    return static_cast<T>(
                        static_cast<double>(origins[a]) +
                        static_cast<double>(tiles[a]) *
                            static_cast<double>(rng() % static_cast<std::uint64_t>(cells[a] + 1)));
                default:
                    return static_cast<T>(static_cast<double>(origins[a]) + randomDouble(rng, -8, 8) +
                                          extent / 2);
            }
        };
        const auto drawMove = [&](int a) {
            switch (rng() % 5) {
                case 0:
                    return T(0);
                case 1:
                    return T(-0.0);
                case 2:
                    return static_cast<T>(tiles[a] * static_cast<T>(static_cast<int>(rng() % 9) - 4));
                default:
                    return static_cast<T>(randomDouble(rng, -6, 3) * static_cast<double>(tiles[a]));
            }
        };
        const auto drawSize = [&](int a) {
            return rng() % 2
                       ? static_cast<T>(tiles[a] * static_cast<T>(1 + rng() % 3) / 2)
                       : static_cast<T>(std::fabs(randomDouble(rng, -4, 1)) * static_cast<double>(tiles[a]));
        };
        const ResolveInput<T> in{map,
                                 {{drawCoordinate(0), drawCoordinate(1)}, {drawSize(0), drawSize(1)}},
                                 {drawMove(0), drawMove(1)}};
        const MapRange range = mapRangeOf(map);
        const bool inWindow = admitFrameInWindow(in, range);
        if (!inWindow && !admitFrameFully(in, range)) continue;
        ++frames;
        inWindowFrames += inWindow ? 1 : 0;
        const T pos[2] = {in.box.pos.x, in.box.pos.y};
        const T size[2] = {in.box.size.x, in.box.size.y};
        const T disp[2] = {in.displacement.x, in.displacement.y};
        for (const bool window : {inWindow, false}) {
            const FastFrame<T> frame(in, range, window);
            CellRange swept[2];
            frame.sweptCellsOfBoth(swept);
            if constexpr (std::is_same<T, double>::value) {
                ASSERT_EQ(frame.distancesExact(), frame.distancesExactOn(0) && frame.distancesExactOn(1));
                if (window == inWindow) exactDistanceFrames += frame.distancesExact() ? 1 : 0;
            }
            for (int a = 0; a < 2; ++a) {
                const auto& m = frame.axis(a);
                const auto p = static_cast<double>(pos[a]);
                const auto w = static_cast<double>(size[a]);
                const auto d = static_cast<double>(disp[a]);
                const ExactPair far = twoSum(p, w);
                const ExactPair end = twoSum(p, d);
                const auto where = [&] {
                    std::ostringstream s;
                    s << std::hexfloat << "axis " << a << " pos " << p << " size " << w << " disp " << d
                      << " origin " << static_cast<double>(origins[a]) << " tile "
                      << static_cast<double>(tiles[a]) << " cells " << cells[a]
                      << (window ? " (window)" : "");
                    return s.str();
                };
                ASSERT_EQ(bitsOf(m.low), bitsOf(p)) << where();
                ASSERT_EQ(bitsOf(m.high), bitsOf(far.hi)) << where();
                ASSERT_EQ(bitsOf(m.highLow), bitsOf(std::is_same<T, float>::value ? 0.0 : far.lo)) << where();
                ASSERT_EQ(bitsOf(m.disp), bitsOf(d)) << where();
                ASSERT_EQ(bitsOf(m.speed), bitsOf(std::fabs(d))) << where();
                ASSERT_EQ(m.dir, (d > 0) - (d < 0)) << where();
                ASSERT_EQ(bitsOf(m.origin), bitsOf(static_cast<double>(origins[a]))) << where();
                ASSERT_EQ(bitsOf(m.tile), bitsOf(static_cast<double>(tiles[a]))) << where();
                ASSERT_EQ(m.cells, cells[a]) << where();
                ASSERT_EQ(bitsOf(m.invTile), bitsOf(range.inverseTile[a])) << where();
                ASSERT_EQ(bitsOf(m.size), bitsOf(w)) << where();
                if constexpr (std::is_same<T, float>::value) {
                    ASSERT_EQ(bitsOf(frame.endOf(a)), bitsOf(p + d)) << where();
                } else {
                    ASSERT_EQ(bitsOf(frame.endOf(a).hi), bitsOf(end.hi)) << where();
                    ASSERT_EQ(bitsOf(frame.endOf(a).lo), bitsOf(end.lo)) << where();
                }
                const CellRange own = frame.sweptCells(a);
                ASSERT_EQ(swept[a].first, own.first) << where();
                ASSERT_EQ(swept[a].last, own.last) << where();
                if (window != inWindow) continue;  // count each frame once
                negativeMoves += d < 0 ? 1 : 0;
                zeroMoves += d == 0 ? 1 : 0;
                signedZeroEnds += p == 0 && d == 0 && std::signbit(p) != std::signbit(d) ? 1 : 0;
                inexactFarEdges += far.lo != 0 ? 1 : 0;
                emptyRanges += own.first > own.last ? 1 : 0;
                clampedRanges += own.first == 0 && own.last == cells[a] - 1 ? 1 : 0;
            }
        }
    }
    EXPECT_GT(frames, 50000);
    EXPECT_GT(inWindowFrames, 10000) << "too few frames in the map's window";
    EXPECT_GT(negativeMoves, 20000) << "too few negative moves";
    EXPECT_GT(zeroMoves, 10000) << "too few zero moves";
    EXPECT_GT(signedZeroEnds, 1000) << "too few zero moves from a zero of the other sign";
    EXPECT_GT(emptyRanges, 1000) << "too few swept bounds off the map";
    EXPECT_GT(clampedRanges, 1000) << "too few swept bounds clamped at both ends";
    if (std::is_same<T, double>::value) {
        EXPECT_GT(inexactFarEdges, 20000) << "too few inexact far edges";
        EXPECT_GT(exactDistanceFrames, 1000) << "too few frames whose tile distances are exact doubles";
    }
    std::printf(
        "set-up on lanes (%s): %d frames, %d in the window; axes: %d negative moves, %d zero "
        "moves, %d zero moves from a zero of the other sign, %d inexact far edges, %d empty and "
        "%d clamped swept ranges\n",
        std::is_same<T, float>::value ? "float" : "double", frames, inWindowFrames, negativeMoves, zeroMoves,
        signedZeroEnds, inexactFarEdges, emptyRanges, clampedRanges);
}

TEST(FastFrameLanes, TheSetUpIsThePerAxisOneInFloat) { checkSetUpOnLanes<float>(50); }
TEST(FastFrameLanes, TheSetUpIsThePerAxisOneInDouble) { checkSetUpOnLanes<double>(51); }

/// The fast path's shortcut for the amended rule (FastFrame::linesClearOf): where it says no grid
/// line can fall between an end and the value above it, none does. Each draw aims at the line the
/// shortcut must see: a box size, tile and origin whose lowest set bit is 2^q (the size's, the
/// tile's or the origin's, in turn), and an end 2^(q - 5)
/// short of g - size for a grid line g, at magnitudes from 2^(q + p - 2) to 2^(q + p + 2) (p = 24
/// for float, 53 for double), where g - size stops being representable. In half the draws g - size
/// lies just above a power of two and the start just below it, so that the end crosses into the
/// next binade: the case an off-by-one in the bound would clear. Every end the draw can give (the
/// free end, a touch position e - size or e) is checked against the exact rationals (the interval
/// [exact + size, up + size), up the rounding up of the exact end, and oracle::gridLineIn).
/// Floors: frames the shortcut clears at the limit (g - size at or above 2^(q + p - 1)), frames it
/// does not clear with a line in the interval, and of those, ends that crossed a power of two.
template <class T>
void checkLinesClear(std::uint64_t seed) {
    constexpr int p = std::numeric_limits<T>::digits;
    std::mt19937_64 rng(seed);
    std::vector<std::uint8_t> solid(8, 0);
    int admitted = 0;
    int clearAtTheLimit = 0;
    int lineWhereNotClear = 0;
    int lineAcrossABinade = 0;
    for (int draw = 0; draw < 20000; ++draw) {
        const int q = std::uniform_int_distribution<int>(-12, 6)(rng);
        // A size, a tile and an origin with a few bits each; the size, the tile or the origin (in
        // turn) has the lowest bit, 2^q, the others' lie at least two bits above it.
        const int finest = (draw / 2) % 3;
        const auto odd = [&rng](std::uint64_t below) { return static_cast<double>(2 * (rng() % below) + 1); };
        const double size = std::ldexp(odd(64), q + static_cast<int>(rng() % 2) + (finest == 0 ? 0 : 2));
        const double tile = std::ldexp(odd(8), finest == 1 ? q : q + 2 + static_cast<int>(rng() % 3));
        double origin =
            (rng() % 2) ? 0.0 : tile * static_cast<double>(static_cast<std::int64_t>(rng() % 64) - 32);
        if (finest == 2) origin = std::ldexp(odd(32), q) * ((rng() % 2) ? 1.0 : -1.0);
        const bool acrossABinade = (draw % 2) == 0;
        const int magnitude = std::uniform_int_distribution<int>(q + p - 2, q + p + 1)(rng);
        const double power = std::ldexp(1.0, magnitude);
        // A grid line g: the first one with g - size above 2^magnitude, or one near 1.5 times it.
        const double k =
            acrossABinade ? std::ceil((power + size - origin) / tile) : std::floor(1.5 * power / tile);
        const Rational lineExactly = exactly(origin) + exactly(k) * exactly(tile);
        const double line = origin + k * tile;
        if (exactly(line) != lineExactly) continue;  // not a double: another draw
        const double target = line - size;           // exact: a multiple of 2^q below 2^(q + p + 3)
        const double offset =
            acrossABinade
                ? -std::ldexp(static_cast<double>(rng() % 64 + 1), q)
                : std::ldexp(static_cast<double>(static_cast<std::int64_t>(rng() % 2048) - 1024), q);
        const double start =
            static_cast<double>(static_cast<T>(acrossABinade ? power + offset : target + offset));
        const double disp = (target - start) - std::ldexp(1.0, q - 5);  // the end 2^(q - 5) short of g - size
        if (static_cast<double>(static_cast<T>(disp)) != disp ||
            static_cast<double>(static_cast<T>(size)) != size ||
            static_cast<double>(static_cast<T>(tile)) != tile ||
            static_cast<double>(static_cast<T>(origin)) != origin)
            continue;
        const TileMapView<T> map{{static_cast<T>(origin), 0}, {static_cast<T>(tile), 1}, 4, 2, solid.data()};
        const ResolveInput<T> in{map,
                                 {{static_cast<T>(start), T(0.5)}, {static_cast<T>(size), T(0.5)}},
                                 {static_cast<T>(disp), T(0.25)}};
        const MapRange range = mapRangeOf(map);
        bool fits = false;
        if constexpr (std::is_same<T, float>::value) {
            fits = admitFloatFrame(in, range);
        } else {
            fits = admitDoubleFrame(in, range);
        }
        if (!fits) continue;
        ++admitted;
        const FastFrame<T> frame(in, range);
        const Rational low = exactly(start);
        const Rational high = low + exactly(disp);
        std::vector<Rational> ends{high};
        for (std::int64_t n = -2; n <= 2; ++n) {  // touch positions next to the free end
            const Rational e = lineExactly + Rational(n) * exactly(tile);
            for (const Rational& end : {e, e - exactly(size)})
                if ((end - low) * (end - high) <= 0) ends.push_back(end);
        }
        bool lineFound = false;
        for (const Rational& end : ends) {
            const T up = oracle::fromRational<T>(end, oracle::Rounding::TowardPositive);
            const bool hasLine = oracle::gridLineIn(
                end + exactly(size), oracle::toRational(up) + exactly(size), exactly(origin), exactly(tile));
            if (frame.linesClear(0)) {
                ASSERT_FALSE(hasLine) << std::hexfloat << "start " << start << " disp " << disp << " size "
                                      << size << " origin " << origin << " tile " << tile;
            }
            lineFound = lineFound || hasLine;
        }
        clearAtTheLimit += frame.linesClear(0) && std::fabs(target) >= std::ldexp(1.0, q + p - 1) ? 1 : 0;
        lineWhereNotClear += !frame.linesClear(0) && lineFound ? 1 : 0;
        lineAcrossABinade += !frame.linesClear(0) && lineFound && std::fabs(start) < power ? 1 : 0;
    }
    EXPECT_GT(admitted, 10000);
    EXPECT_GT(clearAtTheLimit, 500) << "too few frames cleared at the bound's limit";
    EXPECT_GT(lineWhereNotClear, 1000) << "too few frames with a line between an end and the value above it";
    EXPECT_GT(lineAcrossABinade, 500) << "too few such frames whose end crossed a power of two";
}

TEST(LinesClear, NoGridLineFallsBetweenAnEndAndTheValueAboveInFloat) { checkLinesClear<float>(41); }
TEST(LinesClear, NoGridLineFallsBetweenAnEndAndTheValueAboveInDouble) { checkLinesClear<double>(42); }

}  // namespace
}  // namespace tilesweep::detail

// SPDX-License-Identifier: MIT
#include "tilesweep/oracle/exact/rational_convert.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

namespace tilesweep::oracle {
namespace {

// 2^k as an exact integer, k >= 0.
Integer powerOfTwo(std::int64_t k) { return Integer(1) << static_cast<unsigned>(k); }

// The dyadic split: value = m * 2^(e - digits) with m = frexp's significand scaled by 2^digits,
// an integer of at most `digits` bits, so the conversion to int64 and everything after is exact.
// frexp normalises subnormals too, so they need no special case.
template <class T>
Rational dyadicValue(T value) {
    if (!std::isfinite(value)) {
        throw std::invalid_argument("toRational: value is not finite");
    }
    if (value == T(0)) {
        return Rational(0);
    }
    constexpr int kDigits = std::numeric_limits<T>::digits;
    int exponent = 0;
    const T fraction = std::frexp(value, &exponent);  // value = fraction * 2^exponent, |fraction| in [1/2, 1)
    const auto significand = static_cast<std::int64_t>(std::ldexp(fraction, kDigits));
    const std::int64_t shift = static_cast<std::int64_t>(exponent) - kDigits;
    Rational result{Integer(significand)};
    if (shift >= 0) {
        result *= Rational(powerOfTwo(shift));
    } else {
        result /= Rational(powerOfTwo(-shift));
    }
    return result;
}

// floor(log2(a)) for a rational a > 0: the e with 2^e <= a < 2^(e+1).
std::int64_t floorLog2(const Integer& numerator, const Integer& denominator) {
    auto e = static_cast<std::int64_t>(boost::multiprecision::msb(numerator)) -
             static_cast<std::int64_t>(boost::multiprecision::msb(denominator));
    // Now 2^(e-1) < a < 2^(e+1); one comparison settles which side of 2^e it is.
    const bool belowPowerOfTwo = e >= 0 ? numerator < (denominator << static_cast<unsigned>(e))
                                        : (numerator << static_cast<unsigned>(-e)) < denominator;
    if (belowPowerOfTwo) {
        --e;
    }
    return e;
}

}  // namespace

Rational toRational(float value) { return dyadicValue(value); }
Rational toRational(double value) { return dyadicValue(value); }

template <class T>
T fromRational(const Rational& q, Rounding rounding) {
    static_assert(std::numeric_limits<T>::is_iec559 && std::numeric_limits<T>::radix == 2);
    constexpr std::int64_t kDigits = std::numeric_limits<T>::digits;                 // p: 24 or 53
    constexpr std::int64_t kMinExponent = std::numeric_limits<T>::min_exponent - 1;  // -126, -1022
    constexpr std::int64_t kMaxExponent = std::numeric_limits<T>::max_exponent - 1;  // 127, 1023

    if (q == 0) {
        return T(0);
    }
    const bool negative = q < 0;
    const Rational magnitude = negative ? Rational(-q) : q;
    const Integer numerator = boost::multiprecision::numerator(magnitude);
    const Integer denominator = boost::multiprecision::denominator(magnitude);

    // The representable values near the magnitude a are the multiples of the quantum 2^qe, with
    // qe = max(e, emin) - (p - 1): p significant bits in a normal binade, and the fixed spacing of
    // the subnormals below 2^emin. a / 2^qe < 2^p, so the rounded multiple m is at most 2^p (a
    // carry into the next binade, still exact as m * 2^qe).
    const std::int64_t e = floorLog2(numerator, denominator);
    const std::int64_t quantumExponent = (e > kMinExponent ? e : kMinExponent) - (kDigits - 1);

    Integer scaledNumerator = numerator;
    Integer scaledDenominator = denominator;
    if (quantumExponent >= 0) {
        scaledDenominator <<= static_cast<unsigned>(quantumExponent);
    } else {
        scaledNumerator <<= static_cast<unsigned>(-quantumExponent);
    }
    Integer multiple = scaledNumerator / scaledDenominator;  // floor, both positive
    const Integer remainder = scaledNumerator - multiple * scaledDenominator;

    // Decide, on the magnitude, whether to round away from zero.
    bool awayFromZero = false;
    bool towardZeroDirected = false;  // a directed rounding that moves toward zero for this sign
    switch (rounding) {
        case Rounding::TowardNegative:
            awayFromZero = negative && remainder != 0;
            towardZeroDirected = !negative;
            break;
        case Rounding::TowardPositive:
            awayFromZero = !negative && remainder != 0;
            towardZeroDirected = negative;
            break;
        case Rounding::NearestEven: {
            const Integer twiceRemainder = remainder << 1U;
            awayFromZero =
                twiceRemainder > scaledDenominator ||
                (twiceRemainder == scaledDenominator && boost::multiprecision::bit_test(multiple, 0));
            break;
        }
    }
    if (awayFromZero) {
        multiple += 1;
    }

    // Overflow: the largest finite value is (2^p - 1) * 2^(emax - p + 1).
    const std::int64_t topQuantumExponent = kMaxExponent - (kDigits - 1);
    const bool overflows =
        quantumExponent > topQuantumExponent ||
        (quantumExponent == topQuantumExponent && multiple == (Integer(1) << static_cast<unsigned>(kDigits)));
    T result;
    if (overflows) {
        result = towardZeroDirected ? std::numeric_limits<T>::max() : std::numeric_limits<T>::infinity();
    } else {
        // multiple <= 2^p fits in 64 bits and in T exactly; ldexp by the quantum is then exact,
        // subnormal results included.
        const auto small = multiple.convert_to<std::uint64_t>();
        result = std::ldexp(static_cast<T>(small), static_cast<int>(quantumExponent));
    }
    return negative ? -result : result;
}

template <class T>
T roundToward(const Rational& q, T from) {
    const Rational start = toRational(from);
    if (q == start) {
        return from;
    }
    // From below the start the nearest value on the start's side is the one just above q, and
    // the other way round; the start itself is representable, so the result never passes it.
    return fromRational<T>(q, q < start ? Rounding::TowardPositive : Rounding::TowardNegative);
}

bool gridLineIn(const Rational& low, const Rational& high, const Rational& gridOrigin, const Rational& tile) {
    if (!(low < high)) {
        return false;
    }
    // The first grid line at or above `low`: k = ceil((low - gridOrigin) / tile).
    const Rational steps = (low - gridOrigin) / tile;
    Integer k = numerator(steps) / denominator(steps);  // truncates toward zero
    if (Rational(k) < steps) {
        k += 1;
    }
    return gridOrigin + Rational(k) * tile < high;
}

template <class T>
T roundFinalCoordinate(const Rational& exact, T from, const Rational& size, const Rational& gridOrigin,
                       const Rational& tile) {
    const T towardStart = roundToward<T>(exact, from);
    const Rational start = toRational(from);
    if (!(exact < start)) {
        return towardStart;  // not a move toward minus infinity: the rule is plain
    }
    const Rational rounded = toRational(towardStart);
    if (!gridLineIn(exact + size, rounded + size, gridOrigin, tile)) {
        return towardStart;
    }
    const T down = fromRational<T>(exact, Rounding::TowardNegative);
    return std::isfinite(down) ? down : towardStart;
}

template float fromRational<float>(const Rational&, Rounding);
template double fromRational<double>(const Rational&, Rounding);
template float roundToward<float>(const Rational&, float);
template double roundToward<double>(const Rational&, double);
template float roundFinalCoordinate<float>(const Rational&, float, const Rational&, const Rational&,
                                           const Rational&);
template double roundFinalCoordinate<double>(const Rational&, double, const Rational&, const Rational&,
                                             const Rational&);

}  // namespace tilesweep::oracle

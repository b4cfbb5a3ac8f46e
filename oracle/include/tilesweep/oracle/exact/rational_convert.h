// SPDX-License-Identifier: MIT
#pragma once

#include "tilesweep/oracle/exact/rational.h"

#include <cstdint>

// Exact conversions between IEEE binary floating point (float, double) and Rational.
//
// float/double -> Rational is exact: a finite binary float is m * 2^e with an integer m of at
// most `digits` bits, found with frexp/ldexp (the dyadic split). Rational -> float/double rounds
// once, in the direction asked for, with the full IEEE range: subnormals (fixed quantum
// 2^(min_exponent - digits)), binade boundaries (rounding up may carry into the next binade), and
// overflow. On overflow the result follows IEEE 754: rounding toward zero's side of a huge value
// gives the largest finite value, rounding away from it (and round-to-nearest at or beyond
// max + half an ulp) gives infinity. A negative value that rounds to zero gives -0.
//
// These are written here rather than taken from Boost's convert_to<>, whose rounding direction is
// not specified and not promised for subnormals.

namespace tilesweep::oracle {

/// How a Rational is rounded to a binary float.
enum class Rounding : std::uint8_t {
    TowardNegative,  ///< the largest representable value <= q (IEEE roundTowardNegative)
    TowardPositive,  ///< the smallest representable value >= q (IEEE roundTowardPositive)
    NearestEven,     ///< the nearest representable value; ties to the even significand
};

/// The exact value of a finite float. Throws std::invalid_argument on NaN or infinity.
[[nodiscard]] Rational toRational(float value);

/// The exact value of a finite double. Throws std::invalid_argument on NaN or infinity.
[[nodiscard]] Rational toRational(double value);

/// q rounded to T (float or double) in the given direction; see the header note for overflow.
template <class T>
[[nodiscard]] T fromRational(const Rational& q, Rounding rounding);

/// q rounded to the representable T nearest q that lies between `from` and q, inclusive: the
/// contract's rounding of a final position toward the start coordinate `from` (a T value).
/// Never overflows, since `from` itself is finite and lies on that side.
template <class T>
[[nodiscard]] T roundToward(const Rational& q, T from);

/// The contract's rounding of a final coordinate on one axis ("Positions"): `exact` rounded
/// toward the start `from`, except on an axis that moved toward minus infinity when that would
/// carry the box's far edge (exact + `size`) over a grid line `gridOrigin + k*tile` (any integer
/// k) that the exact far edge had not passed; then toward minus infinity instead. When no finite
/// value lies at or below `exact` (it is below the lowest finite T), the rounding toward the
/// start stands.
template <class T>
[[nodiscard]] T roundFinalCoordinate(const Rational& exact, T from, const Rational& size,
                                     const Rational& gridOrigin, const Rational& tile);

/// Whether a grid line gridOrigin + k*tile (k any integer, tile > 0) lies in [low, high).
[[nodiscard]] bool gridLineIn(const Rational& low, const Rational& high, const Rational& gridOrigin,
                              const Rational& tile);

extern template float fromRational<float>(const Rational&, Rounding);
extern template double fromRational<double>(const Rational&, Rounding);
extern template float roundToward<float>(const Rational&, float);
extern template double roundToward<double>(const Rational&, double);
extern template float roundFinalCoordinate<float>(const Rational&, float, const Rational&, const Rational&,
                                                  const Rational&);
extern template double roundFinalCoordinate<double>(const Rational&, double, const Rational&, const Rational&,
                                                    const Rational&);

}  // namespace tilesweep::oracle

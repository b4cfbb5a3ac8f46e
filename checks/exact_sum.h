// SPDX-License-Identifier: MIT
#pragma once

#include <limits>

// The exact sign of a short sum of floats or doubles, so that the contract checks
// (frame_safety.h) can test the safety rules ("x + w > a", "s + d - e >= 0") without rounding,
// and without the library's lattice code or the GMP oracle (they stay light enough for the
// fuzz targets and the soak, and a check that shared code with the resolver could share its bugs).
//
// Why it is exact. Every float and double converts exactly to x87 extended precision (64-bit
// significand, 15-bit exponent). Knuth's TwoSum gives the exact rounding error of a sum
// whenever nothing overflows or underflows; sums of a few doubles stay far below the extended
// range (at most a few times DBL_MAX), and every partial sum and error is a multiple of
// 2^-1074, far above extended's subnormals. So Shewchuk's Grow-Expansion ("Adaptive Precision
// Floating-Point Arithmetic and Fast Robust Geometric Predicates", 1997, section 2.4) carried
// out in long double holds the sum exactly, as nonoverlapping components of increasing
// magnitude, and the sign of the sum is the sign of its largest nonzero component.
// Needs -ffp-contract=off (tilesweep_warnings sets it) and round-to-nearest.

namespace tilesweep::checks {

static_assert(std::numeric_limits<long double>::radix == 2 &&
                  std::numeric_limits<long double>::digits >= 64 &&
                  std::numeric_limits<long double>::max_exponent >= 16384,
              "the exact checks need x87 extended (or wider) long double");

/// The most terms signOfSum takes.
inline constexpr int kMaxSumTerms = 6;

/// The sign (-1, 0 or 1) of the exact sum of `count` (at most kMaxSumTerms) finite terms,
/// each a float or a double widened to long double.
[[nodiscard]] inline int signOfSum(const long double* terms, int count) noexcept {
    long double expansion[kMaxSumTerms] = {};
    int size = 0;
    for (int k = 0; k < count && k < kMaxSumTerms; ++k) {
        long double carry = terms[k];
        for (int c = 0; c < size; ++c) {
            // TwoSum(carry, expansion[c]): sum and its exact rounding error.
            const long double sum = carry + expansion[c];
            const long double bVirtual = sum - carry;
            const long double aVirtual = sum - bVirtual;
            expansion[c] = (carry - aVirtual) + (expansion[c] - bVirtual);
            carry = sum;
        }
        expansion[size++] = carry;
    }
    for (int c = size - 1; c >= 0; --c)
        if (expansion[c] != 0) return expansion[c] > 0 ? 1 : -1;
    return 0;
}

/// The sign of the exact a + b - c, for finite floats or doubles.
template <class T>
[[nodiscard]] int signOfSumMinus(T a, T b, T c) noexcept {
    const long double terms[3] = {static_cast<long double>(a), static_cast<long double>(b),
                                  -static_cast<long double>(c)};
    return signOfSum(terms, 3);
}

}  // namespace tilesweep::checks

// SPDX-License-Identifier: MIT
#pragma once

// A contact's position on the axis the box slides on after it (resolve.h, Contact::position), on
// the fast path (fast_frame.h). When step 1 hits one axis and the other moves on, the contact's
// coordinate on that free axis is where the box was at the contact time s = num / den:
//     V = x0 + (num / den) * d       (x0 the start, d the frame's displacement on the free axis)
// rounded to the nearest T, ties to even (like the frame times, time_rounding.h). The lattice
// computes it with its own integers (lattice_frame.h, roundRatioToNearest); the exact reference
// defines it (oracle/exact/exact_resolve.cpp).
//
// For a candidate c, V lies above the midpoint c + h (h half the gap to the next T above c) iff
//     (x0 - c)*den + num*d - h*den > 0,
// where x0 - c is an exact pair by TwoSum, each product is p + e by TwoProduct (exact_double.h),
// num is a double (float frames) or an exact pair (double frames), and h*den is exact (h is a
// power of two): a sum of nine exact doubles (remainderTerms); likewise below the midpoint under
// c. The candidate comes from a double estimate of V and moves by one T at a time
// until V lies between its two midpoints; on a midpoint the even one is taken. Each sign is
// filtered (signOfSumFiltered) and settled exactly inside the filter's band.
//
// Range. The range test (range_admission.h) keeps every product and TwoProduct error term of
// the inputs far from overflow and underflow. A candidate below kPositionFloor in magnitude (or
// zero) would take c*den's error term and h*den toward the subnormals: V = 0 exactly is settled
// (+0, as the lattice and the reference round a zero), anything else there goes to the lattice.

#include "exact_double.h"
#include "proof_constants.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace tilesweep::detail {

/// Candidates smaller than this in magnitude are left to the lattice (see the top of this file).
inline constexpr double kPositionFloor = 0x1p-500;

/// The sign of the exact sum of `count` doubles (count <= 16), by a filter with a certified
/// bound, and by the exact expansion (signOfSum) inside the bound, which sets `refined`.
///
/// Recursive summation of n terms errs by at most gamma(n-1) * sum|t|, gamma(k) = k*u / (1 - k*u)
/// (Higham, "Accuracy and Stability of Numerical Algorithms", 4.2). The bound, computed as
/// fl((n+1)u * M) with M = fl(sum|t|) >= (1-u)^(n-1) sum|t|, is at least (n+1)u(1-u)^n sum|t|,
/// which exceeds gamma(n-1) sum|t| for every n <= 16. So a computed sum beyond the bound has the
/// exact sum's sign. Additions that underflow are exact, and the callers' terms stay far above
/// the subnormals, so the bound's product does not underflow either.
[[nodiscard]] inline int signOfSumFiltered(const double* terms, int count, bool& refined) noexcept {
    double sum = 0;
    double magnitude = 0;
    for (int k = 0; k < count; ++k) {
        sum += terms[k];
        magnitude += std::fabs(terms[k]);
    }
    const double bound = (count + 1) * kUnitRoundoff * magnitude;
    if (sum > bound) return 1;
    if (sum < -bound) return -1;
    refined = true;
    return signOfSum(terms, count);
}

/// The low part of an exact coordinate: zero for a double, the pair's low part otherwise.
[[nodiscard]] inline double lowPartOf(double) noexcept { return 0; }
[[nodiscard]] inline double lowPartOf(ExactPair v) noexcept { return v.lo; }
/// The high part of an exact coordinate: the double itself, or the pair's high part.
[[nodiscard]] inline double highPartOf(double v) noexcept { return v; }
[[nodiscard]] inline double highPartOf(ExactPair v) noexcept { return v.hi; }

/// Whether a float or double has an odd significand (the last bit of its encoding).
template <class T>
[[nodiscard]] inline bool isOddSignificand(T v) noexcept {
    using Bits = std::conditional_t<sizeof(T) == sizeof(std::uint32_t), std::uint32_t, std::uint64_t>;
    Bits bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    return (bits & 1) != 0;
}

/// The terms of (V - c) * den = (x0 - c) * den + num * d (see the top of this file), as eight
/// doubles that sum to it exactly. The two large products nearly cancel when c is near V; their
/// rounded values are added by TwoSum first, so that every term left is about as small as the
/// remainder itself, and the filter's bound (a multiple of the terms' magnitudes) stays far below
/// the half-gap it is compared with.
inline void remainderTerms(double x0, double d, double hi, double lo, double den, double c,
                           double* terms) noexcept {
    const ExactPair start = twoSum(x0, -c);  // x0 - c, exactly
    const double p1 = start.hi * den;
    const double p2 = hi * d;
    const ExactPair big = twoSum(p1, p2);
    const double p3 = start.lo * den;
    const double p4 = lo * d;
    terms[0] = big.hi;
    terms[1] = big.lo;
    terms[2] = productError(start.hi, den, p1);
    terms[3] = productError(hi, d, p2);
    terms[4] = p3;
    terms[5] = productError(start.lo, den, p3);
    terms[6] = p4;
    terms[7] = productError(lo, d, p4);
}

/// The coordinate V = x0 + (num / den) * d rounded to the nearest T, ties to even, into `out`;
/// false when it is left to the lattice (a result near zero, or an estimate more than a few T
/// away). x0 and d are the free axis's start and displacement, num / den the contact time
/// (0 < num < den, den > 0), all exact (see the top of this file); `refined` is set when a filter
/// could not decide alone.
template <class T, class Coord>
[[nodiscard]] bool roundPositionAtTime(double x0, double d, const Coord& num, double den, bool& refined,
                                       T& out) noexcept {
    const double hi = highPartOf(num);
    const double lo = lowPartOf(num);
    double terms[9];
    T c = static_cast<T>(x0 + hi / den * d);
    for (int step = 0; step < 4; ++step) {
        const auto cd = static_cast<double>(c);
        if (!(std::fabs(cd) >= kPositionFloor)) {
            remainderTerms(x0, d, hi, lo, den, 0, terms);
            if (c != 0 || signOfSumFiltered(terms, 8, refined) != 0) return false;
            out = T(0);  // V = 0 exactly: +0
            return true;
        }
        const T up = stepScalar(c, true);
        const T down = stepScalar(c, false);
        remainderTerms(x0, d, hi, lo, den, cd, terms);
        terms[8] = -(0.5 * (static_cast<double>(up) - cd)) * den;
        const int above = signOfSumFiltered(terms, 9, refined);  // V against c's upper midpoint
        if (above > 0) {
            c = up;
            continue;
        }
        terms[8] = (0.5 * (cd - static_cast<double>(down))) * den;
        const int below = signOfSumFiltered(terms, 9, refined);  // against its lower midpoint
        if (below < 0) {
            c = down;
            continue;
        }
        if (isOddSignificand(c)) {  // V on a midpoint: the even neighbour
            if (above == 0) c = up;
            if (below == 0) c = down;
        }
        out = c;
        return true;
    }
    return false;
}

}  // namespace tilesweep::detail

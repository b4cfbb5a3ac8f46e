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
// filtered (signAgainst) and settled exactly inside the filter's band. Before that, a
// shortcut per type settles most candidates from the rounded estimate and a certified bound on
// its error (nearestFloatOfEstimate, nearestDoubleOfEstimate).
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

/// (V - c) * den for a candidate c, as up to eight exact doubles whose sum it is exactly
/// (remainderOf), with their recursive sum and the sum of their magnitudes, so that the tests
/// against both midpoints of c (signAgainst) add one term each to what is summed once.
struct Remainder {
    double terms[9];
    int count = 0;
    double sum = 0;
    double magnitude = 0;

    void add(double t) noexcept {
        terms[count++] = t;
        sum += t;
        magnitude += std::fabs(t);
    }
};
static_assert(std::extent<decltype(Remainder::terms)>::value <= kSumFilterMostTerms,
              "signAgainst's filter is sound for every sum a Remainder holds");

/// The sign of the exact sum of r's terms and `extra`, by a filter with a certified bound, and
/// by the exact expansion (signOfSum) inside the bound, which sets `refined`.
///
/// Recursive summation of n terms errs by at most gamma(n-1) * sum|t|, gamma(k) = k*u / (1 - k*u)
/// (Higham, "Accuracy and Stability of Numerical Algorithms", 4.2); `extra` is the n-th term,
/// added last. The bound, computed as fl((n+1)u * M) with M = fl(sum|t|) >= (1-u)^(n-1) sum|t|,
/// is at least (n+1)u(1-u)^n sum|t|, which exceeds gamma(n-1) sum|t| for every n up to
/// kSumFilterMostTerms (proof_constants.h), more than a Remainder holds. So a computed sum beyond
/// the bound has the exact sum's sign. Additions that underflow are exact, and the terms stay far
/// above the subnormals (kPositionFloor), so the bound's product does not underflow either.
[[nodiscard]] inline int signAgainst(Remainder& r, double extra, bool& refined) noexcept {
    const int n = r.count + 1;
    const double sum = r.sum + extra;
    const double bound = (n + 1) * kUnitRoundoff * (r.magnitude + std::fabs(extra));
    if (sum > bound) return 1;
    if (sum < -bound) return -1;
    refined = true;
    r.terms[r.count] = extra;
    return signOfSum(r.terms, n);
}

/// The terms of (V - c) * den = (x0 - c) * den + num * d (see the top of this file). The two
/// large products nearly cancel when c is near V; their rounded values are added by TwoSum first,
/// so that every term left is about as small as the remainder itself, and the filter's bound (a
/// multiple of the terms' magnitudes) stays far below the half-gap it is compared with. Terms
/// that are zero by construction (x0 - c exact, or num a double) are left out.
[[nodiscard]] inline Remainder remainderOf(double x0, double d, double hi, double lo, double den,
                                           double c) noexcept {
    const ExactPair start = twoSum(x0, -c);  // x0 - c, exactly
    const double p1 = start.hi * den;
    const double p2 = hi * d;
    const ExactPair big = twoSum(p1, p2);
    Remainder r;
    r.add(big.hi);
    r.add(big.lo);
    r.add(productError(start.hi, den, p1));
    r.add(productError(hi, d, p2));
    if (start.lo != 0) {
        const double p3 = start.lo * den;
        r.add(p3);
        r.add(productError(start.lo, den, p3));
    }
    if (lo != 0) {
        const double p4 = lo * d;
        r.add(p4);
        r.add(productError(lo, d, p4));
    }
    return r;
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

/// Float frames' shortcut: the float nearest the double estimate v = fl(x0 + fl(q * d)) when v
/// lies farther than its error bound from both float midpoints around it; false when it does not
/// (or the nearest float is zero), and the exact test decides. q is num / den rounded to the
/// nearest double (roundPositionAtTime). Three roundings, each within u of its result, and
/// |fl(q * d) - P| <= (2u + u^2)|P| for P = num*d/den: |v - V| <= u|v|/(1 - u) + 2.01u|P~| <
/// 3u(|v| + |P~|), P~ the computed product; the bound, computed as fl(4u * fl(|v| + |P~|))
/// (kPositionEstimateErrorUlps), exceeds that. The midpoints are exact doubles (25 bits).
[[nodiscard]] inline bool nearestFloatOfEstimate(double x0, double d, double q, float& out) noexcept {
    const double product = q * d;
    const double v = x0 + product;
    const auto c = static_cast<float>(v);
    if (c == 0) return false;
    const double bound = kPositionEstimateErrorUlps * kUnitRoundoff * (std::fabs(v) + std::fabs(product));
    const auto cd = static_cast<double>(c);
    const double midUp = 0.5 * (cd + static_cast<double>(stepFloat(c, true)));
    const double midDown = 0.5 * (cd + static_cast<double>(stepFloat(c, false)));
    if (!(v + bound < midUp && v - bound > midDown)) return false;
    out = c;
    return true;
}

/// Double frames' shortcut: the double nearest V when a cheap estimate settles it; false when
/// it does not, and the exact test decides. q is num / den rounded to the nearest double
/// (roundPositionAtTime): |q - s| <= u s for s = num / den (s lies far above the subnormals in
/// the range test's frames). With p = fl(q * d), TwoSum gives v + r = x0 + p exactly (v = fl(x0 +
/// p)), and p is within u|q * d| + u|s * d| <= u|p| (1 / (1 - u) + 1 / (1 - u)^2) < 2.01u|p| of
/// s * d: V = v + r + e with |e| < 2.01u|p| < 4u|p|, the bound, exact as computed (a power of two
/// times |p|, far above the subnormals in the range test's frames). v is the nearest double to V
/// when r + e lies strictly between minus half the gap below v and half the gap above it (a
/// quarter of the spacing above |v| on the side toward zero when |v| is a power of two), which
/// r + bound < above and r - bound > -below imply: the half gaps are doubles, and rounding is
/// monotonic, so a computed sum below one is below it exactly. A midpoint is never taken (the
/// bound is positive), so ties go to the exact test. Near zero (|v| < kPositionFloor) too.
[[nodiscard]] inline bool nearestDoubleOfEstimate(double x0, double d, double q, double& out) noexcept {
    const double p = q * d;
    const ExactPair s = twoSum(x0, p);
    if (!(std::fabs(s.hi) >= kPositionFloor)) return false;
    const double bound = kPositionEstimateErrorUlps * kUnitRoundoff * std::fabs(p);
    const double spacing = ulpAbove(s.hi);
    std::uint64_t bits = 0;
    std::memcpy(&bits, &s.hi, sizeof bits);
    const bool powerOfTwo = (bits & ((std::uint64_t{1} << 52) - 1)) == 0;
    const double awayFromZero = 0.5 * spacing;
    const double towardZero = powerOfTwo ? 0.25 * spacing : awayFromZero;
    const double above = s.hi > 0 ? awayFromZero : towardZero;
    const double below = s.hi > 0 ? towardZero : awayFromZero;
    if (!(s.lo + bound < above && s.lo - bound > -below)) return false;
    out = s.hi;
    return true;
}

/// The coordinate V = x0 + (num / den) * d rounded to the nearest T, ties to even, into `out`;
/// false when it is left to the lattice (a result near zero, or an estimate more than a few T
/// away). x0 and d are the free axis's start and displacement, num / den the contact time
/// (0 < num < den, den > 0), all exact (see the top of this file), and q that time rounded to the
/// nearest double (on a float frame fl(num / den), num a double; on a double frame the frame time
/// itself, roundTimeToDouble's, which a contact carries: no second division); `refined` is set
/// when a filter could not decide alone.
template <class T, class Coord>
[[nodiscard]] bool roundPositionAtTime(double x0, double d, const Coord& num, double den, double q,
                                       bool& refined, T& out) noexcept {
    const double hi = highPartOf(num);
    const double lo = lowPartOf(num);
    if constexpr (std::is_same<T, float>::value) {
        if (nearestFloatOfEstimate(x0, d, q, out)) return true;
    } else {
        if (nearestDoubleOfEstimate(x0, d, q, out)) return true;
    }
    T c = static_cast<T>(x0 + q * d);
    for (int step = 0; step < 4; ++step) {
        const auto cd = static_cast<double>(c);
        if (!(std::fabs(cd) >= kPositionFloor)) {
            Remainder atZero = remainderOf(x0, d, hi, lo, den, 0);
            if (c != 0 || signAgainst(atZero, 0, refined) != 0) return false;
            out = T(0);  // V = 0 exactly: +0
            return true;
        }
        const T up = stepScalar(c, true);
        const T down = stepScalar(c, false);
        Remainder r = remainderOf(x0, d, hi, lo, den, cd);
        const int above = signAgainst(r, -(0.5 * (static_cast<double>(up) - cd)) * den, refined);
        if (above > 0) {  // V above c's upper midpoint
            c = up;
            continue;
        }
        const int below = signAgainst(r, (0.5 * (cd - static_cast<double>(down))) * den, refined);
        if (below < 0) {  // V below its lower midpoint
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

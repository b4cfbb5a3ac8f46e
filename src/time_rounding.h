// SPDX-License-Identifier: MIT
#pragma once

// Time rounding of the fast path: a contact time num / den, exact, rounded to the nearest float
// (float frames) or double (double frames), ties to even, as the contract asks of frame times.
// The lattice rounds its own (roundRatioToNearest, lattice.h). Each function may answer "cannot
// settle", and the frame then goes to the lattice.

#include "axis_sweep.h"
#include "exact_double.h"
#include "fault_injection.h"
#include "proof_constants.h"

#include <cmath>
#include <cstdint>
#include <cstring>

namespace tilesweep::detail {

/// The exact time num / den (0 <= num <= den, exact doubles) rounded to the nearest float,
/// ties to even; false for a time in float's subnormal range (the lattice rounds those).
/// `refined` is set when the rounded quotient landed on a float rounding midpoint.
[[nodiscard]] inline bool roundTimeToFloat(const TimeRatio<double, double>& t, bool& refined,
                                           float& out) noexcept {
    const double q = t.num / t.den + 0.0;  // -0 (from -0 - +0) reads +0, as the lattice's does
    if (q != 0 && q < 0x1p-126) return false;
    std::uint64_t bits = 0;
    std::memcpy(&bits, &q, sizeof bits);
    // The 29 bits of q below float's 24 (q is a normal double in float's normal range).
    // Rounding q to float is the correct rounding of num/den unless q is a float rounding
    // midpoint: q = fl(num/den) lies on the same side of every float and every midpoint as
    // num/den does (monotonic rounding, and floats and their midpoints are doubles).
    if ((bits & 0x1fffffffu) != 0x10000000u) {
        out = static_cast<float>(q);
        return true;
    }
    // q is a midpoint: the sign of num - q*den decides. q*den = p + e exactly (TwoProduct),
    // and num - p is exact (Sterbenz: p is within a factor 2 of num).
    refined = true;
    const double p = q * t.den;
    const double e = productError(q, t.den, p);
    const double r = t.num - p;
    if (r > e) {
        out = roundToFloat(q, true);
    } else if (r < e) {
        out = roundToFloat(q, false);
    } else {
#if defined(TILESWEEP_FAULT_TIME_TIES_AWAY)
        out = roundToFloat(q, true);  // deliberate fault: an exact halfway time rounded away
#else
        out = static_cast<float>(q);                      // exactly the midpoint: ties to even
#endif
    }
    return true;
}

/// The exact time num / den (num an exact pair, 0 <= num <= den, den a double) rounded to the
/// nearest double, ties to even; false when it cannot settle it (the lattice then rounds).
///
/// A pair with a zero low part is a double, and IEEE division rounds correctly. Otherwise take
/// q = fl(hi / den) and R = num - q*den = (hi - p) - e + lo exactly, where q*den = p + e
/// (TwoProduct) and hi - p is exact (Sterbenz: p is within a factor 2 of hi). q is the correct
/// rounding iff -down < R < up, with up = den*ulp(q)/2 and down the same below q (a quarter
/// ulp when q is a power of two), both exact; R = up or R = -down is a tie. The filter computes
/// R~ = fl(fl(d - e) + lo), d = hi - p, within (2u + u^2)(|d| + |e| + |lo|) of R; the bound,
/// computed as fl(3u fl(fl(|d| + |e|) + |lo|)), exceeds that. Inside it the sign of the exact
/// five-term sum decides (Filtered). q moves by one ulp at a time (it starts within two).
[[nodiscard]] inline bool roundTimeToDouble(const TimeRatio<ExactPair, double>& t, bool& refined,
                                            double& out) noexcept {
    double q = t.num.hi / t.den + 0.0;  // -0 reads +0
    if (t.num.lo == 0) {
        out = q;
        return true;
    }
    for (int step = 0; step < 4; ++step) {
        const double p = q * t.den;
        const double e = productError(q, t.den, p);
        const double d = t.num.hi - p;
        const double r = (d - e) + t.num.lo;
        const double bound =
            kTimeRemainderErrorUlps * kUnitRoundoff * ((std::fabs(d) + std::fabs(e)) + std::fabs(t.num.lo));
        const double ulp = ulpAbove(q);
        const double up = 0.5 * ulp * t.den;
        std::uint64_t bits = 0;
        std::memcpy(&bits, &q, sizeof bits);
        const bool powerOfTwo = (bits & ((std::uint64_t{1} << 52) - 1)) == 0;
        const double down = (powerOfTwo ? 0.25 : 0.5) * ulp * t.den;
        int above = 0;  // sign of R - up
        if (r - bound > up) {
            above = 1;
        } else if (r + bound < up) {
            above = -1;
        } else {
            refined = true;
            const double terms[4] = {-up, t.num.lo, -e, d};
            above = signOfSum(terms, 4);
        }
        if (above > 0) {
            q = stepDouble(q, true);
            continue;
        }
        int below = 0;  // sign of R + down
        if (r + bound < -down) {
            below = -1;
        } else if (r - bound > -down) {
            below = 1;
        } else {
            refined = true;
            const double terms[4] = {down, t.num.lo, -e, d};
            below = signOfSum(terms, 4);
        }
        if (below < 0) {
            q = stepDouble(q, false);
            continue;
        }
        const bool odd = (bits & 1) != 0;
#if defined(TILESWEEP_FAULT_TIME_TIES_AWAY)
        if (above == 0) q = stepDouble(q, true);  // deliberate fault: an exact halfway time rounded away
        (void)odd;
#else
        if (above == 0 && odd) q = stepDouble(q, true);   // halfway to the even one above
        if (below == 0 && odd) q = stepDouble(q, false);  // halfway to the even one below
#endif
        out = q;
        return true;
    }
    return false;
}

}  // namespace tilesweep::detail

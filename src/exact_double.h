// SPDX-License-Identifier: MIT
#pragma once

// Exact decisions on exact doubles: the arithmetic of the fast path (fast_frame.h).
//
// The fast path holds every coordinate of a frame as a double that is exactly its value (the
// range test guarantees it). Sums and differences of them are then exact too, but a product
// of two of them is rounded. Two facts make comparisons of products exact all the same:
//   1. Rounding to nearest is monotonic: x <= y implies fl(x) <= fl(y). So fl(a*b) < fl(c*d)
//      implies a*b < c*d: whenever the two rounded products differ, their order is the exact
//      one, with no error bound to check.
//   2. When they are equal, p = fl(a*b) = fl(c*d), then a*b - c*d = e1 - e2 where e1 = a*b - p
//      and e2 = c*d - p are the rounding errors, which Dekker's TwoProduct gives exactly as
//      doubles (Dekker 1971; Shewchuk 1997, "Adaptive Precision Floating-Point Arithmetic",
//      Theorem 18), without a fused multiply-add: the build uses -ffp-contract=off.
// TwoProduct is exact when nothing overflows and the error term does not underflow; the range
// test keeps every nonzero factor between 2^-149 and 2^122 (products and their errors between
// 2^-400 and 2^244), far inside both limits.

#include "fault_injection.h"
#include "proof_constants.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

#if defined(__SSE2__) && !defined(TILESWEEP_PORTABLE_INTEGERS)
#include <emmintrin.h>
#endif

namespace tilesweep::detail {

/// The rounding error of p = fl(a*b): a*b - p, exactly (Dekker's TwoProduct with Veltkamp's
/// split; no FMA).
[[nodiscard]] inline double productError(double a, double b, double p) noexcept {
    const double ca = kVeltkampSplitter * a;
    const double aHigh = ca - (ca - a);
    const double aLow = a - aHigh;
    const double cb = kVeltkampSplitter * b;
    const double bHigh = cb - (cb - b);
    const double bLow = b - bHigh;
    return ((aHigh * bHigh - p) + aHigh * bLow + aLow * bHigh) + aLow * bLow;
}

// The refinements below run on a small share of comparisons: out of line (gnu::cold), so that
// the filters that call them inline into the solver's loops (gnu::always_inline; other
// compilers ignore both).

/// The order of a*b and c*d when their rounded values p and q are equal: that of the rounding
/// errors, exactly (see the top of this file).
[[gnu::noinline, gnu::cold]] inline int compareEqualProducts(double a, double b, double c, double d, double p,
                                                             double q) noexcept {
    const double e = productError(a, b, p);
    const double f = productError(c, d, q);
    return e < f ? -1 : (e > f ? 1 : 0);
}

/// -1, 0 or 1 as a*b compares with c*d, exactly. `refined` is set when the rounded products
/// were equal and the exact rounding errors had to settle the order.
[[nodiscard, gnu::always_inline]] inline int compareProducts(double a, double b, double c, double d,
                                                             bool& refined) noexcept {
    const double p = a * b;
    const double q = c * d;
    if (p < q) return -1;  // monotonic rounding: the order of the rounded values is exact
    if (p > q) return 1;
    // Both products exactly zero, a factor of each being zero (a box touching a tile at t = 0:
    // its entry distance against the zero time): equal, and no refinement was needed.
    if (p == 0 && (a == 0 || b == 0) && (c == 0 || d == 0)) return 0;
    refined = true;
    return compareEqualProducts(a, b, c, d, p, q);
}

/// A real number held exactly as hi + lo, where hi = fl(hi + lo) (the sum rounded to nearest)
/// and |lo| <= ulp(hi) / 2: what TwoSum makes of a sum or difference of two floating-point
/// numbers. Because hi is the rounded value, comparisons with a double are exact by monotonic
/// rounding (compare).
template <class T>
struct ExactSum {
    T hi;
    T lo;
};
/// The fast path's exact pair of doubles.
using ExactPair = ExactSum<double>;

/// a + b exactly, as a normalized pair (Knuth's TwoSum: six operations, no branch, exact for
/// any finite floats or doubles whose sum does not overflow; no FMA: -ffp-contract=off). The
/// one TwoSum of the library (with its two-lane form below): the fast path, the zero move and map
/// validation use it.
template <class T>
[[nodiscard]] inline ExactSum<T> twoSum(T a, T b) noexcept {
    const T s = a + b;
    const T bVirtual = s - a;
    const T aVirtual = s - bVirtual;
    return {s, (a - aVirtual) + (b - bVirtual)};
}

#if defined(__SSE2__) && !defined(TILESWEEP_PORTABLE_INTEGERS)
/// Two TwoSums at once, one in each SSE2 lane: twoSum's six operations, lane by lane, so each
/// lane's pair is the one twoSum gives for it, bit for bit (the frame's set-up, fast_frame.h).
struct PairLanes {
    __m128d hi;
    __m128d lo;
};
[[nodiscard, gnu::always_inline]] inline PairLanes twoSumOnLanes(__m128d a, __m128d b) noexcept {
    const __m128d s = _mm_add_pd(a, b);
    const __m128d bVirtual = _mm_sub_pd(s, a);
    const __m128d aVirtual = _mm_sub_pd(s, bVirtual);
    return {s, _mm_add_pd(_mm_sub_pd(a, aVirtual), _mm_sub_pd(b, bVirtual))};
}
#endif

/// -1, 0 or 1 as the exact value v compares with the double d. When hi != d, hi = fl(v) lies on
/// the same side of d as v (monotonic rounding, d representable); when hi == d, lo decides.
[[nodiscard]] inline int compare(ExactPair v, double d) noexcept {
    if (v.hi < d) return -1;
    if (v.hi > d) return 1;
    return v.lo < 0 ? -1 : (v.lo > 0 ? 1 : 0);
}

/// The sign of the exact sum of `count` doubles (count <= 16). Shewchuk's Grow-Expansion with
/// zero elimination (1997, Theorem 10): the running expansion stays nonoverlapping and sorted by
/// magnitude, so its largest component carries the sign of the sum. Exact whenever no TwoSum
/// overflows; slow (quadratic), for the rare refinements only.
[[nodiscard]] inline int signOfSum(const double* terms, int count) noexcept {
    double e[16];
    int m = 0;
    for (int k = 0; k < count; ++k) {
        double q = terms[k];
        int kept = 0;
        for (int i = 0; i < m; ++i) {
            const ExactPair s = twoSum(q, e[i]);
            if (s.lo != 0) e[kept++] = s.lo;
            q = s.hi;
        }
        if (q != 0) e[kept++] = q;
        m = kept;
    }
    return m == 0 ? 0 : (e[m - 1] > 0 ? 1 : -1);
}

/// The sign of a*s - b*t, exactly, from the eight-term expansion (four TwoProducts), for the
/// pair comparison below when its filter cannot decide; p = fl(a.hi*s), q = fl(b.hi*t).
[[gnu::noinline, gnu::cold]] inline int signOfPairProducts(ExactPair a, double s, ExactPair b, double t,
                                                           double p, double q) noexcept {
    const double p2 = a.lo * s;
    const double q2 = b.lo * t;
    const double terms[8] = {productError(a.hi, s, p),
                             productError(a.lo, s, p2),
                             -productError(b.hi, t, q),
                             -productError(b.lo, t, q2),
                             p2,
                             -q2,
                             p,
                             -q};
    return signOfSum(terms, 8);
}

/// The filter of compareProducts on exact pairs below, from p = fl(a.hi*s) and q = fl(b.hi*t)
/// alone: 1 or -1 when it settles the order of A*s and B*t (whatever the low parts), 0 when
/// only the exact refinement can. It reads no low part, so a caller that holds only the high
/// parts (the tile screen, fast_frame.h) gets the very answer compareProducts would.
[[nodiscard, gnu::always_inline]] inline int pairProductFilter(double p, double q) noexcept {
    const double d = p - q;
#if defined(TILESWEEP_FAULT_FILTER_BOUND_HALVED)
    const double bound = kPairProductErrorBound / 2 * (std::fabs(p) + std::fabs(q));  // deliberate fault
#else
    const double bound = kPairProductErrorBound * (std::fabs(p) + std::fabs(q));
#endif
    if (d > bound) return 1;
    if (d < -bound) return -1;
    return 0;
}

/// -1, 0 or 1 as A*s compares with B*t, exactly, for exact pairs A, B and doubles s, t >= 0.
/// A semi-static filter decides first (Shewchuk 1997; the CGAL filtered kernels), whatever the
/// low parts (a zero one meets its assumption |lo| <= u|hi| too), and only inside its band do
/// pairs whose low parts are zero go to the product comparison above (exact by monotonic
/// rounding and TwoProduct), the others to the exact expansion: the common case pays for one
/// filter and no test of the low parts. With p = fl(a.hi*s), q = fl(b.hi*t), S = |p| + |q| and D = fl(p - q),
///   |(A*s - B*t) - D| <= u|p| + u|q| + u|D| + |a.lo*s| + |b.lo*t| <= (2u + u^2)S + u|D|
/// (each rounding to nearest errs by at most u times its result; |lo| <= ulp(hi)/2 <= u|hi|), so
/// the sign of D is exact once |D|(1 - u) > (2u + u^2)S. The bound (kPairProductErrorBound,
/// proof_constants.h, c = (2 + 16u)u) is computed as fl(c * fl(S)) >= c(1 - u)^2 S, and |D| above
/// it is above (2u + u^2)S / (1 - u). Inside it, the sign of the eight-term exact sum (four
/// TwoProducts) settles it, and `refined` is set. The caller's range keeps every product and
/// every TwoProduct error term far from overflow and underflow.
[[nodiscard, gnu::always_inline]] inline int compareProducts(ExactPair a, double s, ExactPair b, double t,
                                                             bool& refined) noexcept {
    const double p = a.hi * s;
    const double q = b.hi * t;
    const int filtered = pairProductFilter(p, q);
    if (filtered != 0) return filtered;
    // Inside the band: pairs that are doubles compare exactly as products of doubles (above).
    if (a.lo == 0 && b.lo == 0) return compareProducts(a.hi, s, b.hi, t, refined);
    refined = true;
#if defined(TILESWEEP_FAULT_PAIR_REFINEMENT_SWAPPED)
    return signOfPairProducts(b, t, a, s, q, p);  // deliberate fault: the refinement's operands swapped
#else
    return signOfPairProducts(a, s, b, t, p, q);
#endif
}

/// v moved by `steps` (-1, 0 or 1) representable values, as std::nextafter toward plus or minus
/// infinity (the least subnormal, with its sign, from a zero), or v itself, its bits kept (0). By
/// integer arithmetic alone, without a branch: the bits map to integers that order like the
/// values (a magnitude's bits, negated for a negative value, so that both zeros map to 0), which
/// move by `steps` and map back. Past the largest finite value it gives the infinity of that sign.
template <class T>
[[nodiscard, gnu::always_inline]] inline T stepBy(T v, int steps) noexcept {
    using Bits = std::conditional_t<sizeof(T) == sizeof(std::uint32_t), std::uint32_t, std::uint64_t>;
    using Ordered = std::make_signed_t<Bits>;
    static_assert(sizeof(Bits) == sizeof(T), "float or double");
    constexpr int kSignShift = 8 * sizeof(Bits) - 1;
    constexpr Bits kSign = Bits{1} << kSignShift;
    Bits bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    const auto magnitude = static_cast<Ordered>(bits & ~kSign);
    const auto negative = static_cast<Ordered>(Bits{0} - (bits >> kSignShift));  // all ones or zero
    const Ordered next = ((magnitude ^ negative) - negative) + steps;
    const auto nextNegative = static_cast<Ordered>(Bits{0} - (static_cast<Bits>(next) >> kSignShift));
    // A zero reached from a negative value is -0 (as std::nextafter has it).
    const Bits zeroFromBelow = (Bits{0} - static_cast<Bits>(next == 0)) & static_cast<Bits>(negative);
    const Bits moved = static_cast<Bits>((next ^ nextNegative) - nextNegative) |
                       ((static_cast<Bits>(nextNegative) | zeroFromBelow) & kSign);
    const Bits kept = Bits{0} - static_cast<Bits>(steps == 0);  // no step: v itself, -0 too
    bits = (bits & kept) | (moved & ~kept);
    std::memcpy(&v, &bits, sizeof bits);
    return v;
}

/// stepBy for a nonzero v (or steps = 0), in three operations: the bits themselves move by
/// `steps`, negated for a negative v (whose bits grow with its magnitude). Past the largest
/// finite value it gives the infinity, and one step toward zero from an infinity the largest
/// finite value; a step onto zero gives the zero of v's sign. From a zero it is wrong: the final
/// rounding of double frames (FastFrame::roundToward) steps a pair's high part only when its low
/// part is nonzero, and then the high part is not zero.
template <class T>
[[nodiscard, gnu::always_inline]] inline T stepFromNonzero(T v, int steps) noexcept {
    using Bits = std::conditional_t<sizeof(T) == sizeof(std::uint32_t), std::uint32_t, std::uint64_t>;
    static_assert(sizeof(Bits) == sizeof(T), "float or double");
    constexpr int kSignShift = 8 * sizeof(Bits) - 1;
    Bits bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    const Bits negative = Bits{0} - (bits >> kSignShift);  // all ones or zero
    bits += (static_cast<Bits>(steps) ^ negative) - negative;
    std::memcpy(&v, &bits, sizeof bits);
    return v;
}

/// The next float or double above (up = true) or below a finite one (stepBy).
template <class T>
[[nodiscard, gnu::always_inline]] inline T stepScalar(T v, bool up) noexcept {
    return stepBy(v, up ? 1 : -1);
}
/// stepScalar on a double.
[[nodiscard]] inline double stepDouble(double v, bool up) noexcept { return stepScalar(v, up); }
/// stepScalar on a float.
[[nodiscard]] inline float stepFloat(float f, bool up) noexcept { return stepScalar(f, up); }

/// The spacing of doubles just above |v|, for any finite v: 2^(exponent(v) - 52) for a normal v
/// whose ulp is normal; the ulp's subnormal bit pattern below that; 2^-1074 for 0 and the
/// subnormals, whose spacing it is. (roundTimeToDouble calls it on quotients its range test keeps
/// far above 2^-970; handling the rest keeps a change of range from wrapping the exponent.)
[[nodiscard]] inline double ulpAbove(double v) noexcept {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    const std::uint64_t field = (bits >> 52) & 0x7ff;  // the biased exponent of |v|
    if (field > 52) {
        bits = (field - 52) << 52;  // a normal ulp
    } else {
        bits = field == 0 ? 1 : std::uint64_t{1} << (field - 1);  // a subnormal ulp: 2^(field - 1075)
    }
    double u = 0;
    std::memcpy(&u, &bits, sizeof bits);
    return u;
}

/// The exact double v rounded to float toward minus infinity (down) or plus infinity (up), without
/// a branch on `up` or on v's bits in float's normal range, [2^-126, 2^128) in magnitude: there a
/// float is a double whose 29 lowest significand bits are zero, so the rounding toward zero clears
/// them, and the rounding away from zero adds one unit at bit 29 to that when any was set (a carry
/// into the exponent is right, and 2^128 converts to the infinity, the rounding up of a value above
/// the largest float). Elsewhere (zero, subnormal floats, beyond 2^128: rare in a game) the nearest
/// float is stepped by stepBy toward v's side, as the arithmetic of the rounding asks.
[[nodiscard, gnu::always_inline]] inline float roundToFloat(double v, bool up) noexcept {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    constexpr std::uint64_t kFloatNormalLeast = 1023 - 126;  // the biased exponent of 2^-126
    constexpr std::uint64_t kFloatBinades = 254;             // 2^-126 to 2^127
    if ((((bits >> 52) & 0x7ff) - kFloatNormalLeast) < kFloatBinades) {
        constexpr std::uint64_t kDropped = (std::uint64_t{1} << 29) - 1;
        const std::uint64_t dropped = bits & kDropped;
        const std::uint64_t negative = bits >> 63;
        // Away from zero when rounding a positive v up or a negative one down, and v is no float.
        const std::uint64_t away =
            (negative ^ static_cast<std::uint64_t>(up)) & static_cast<std::uint64_t>(dropped != 0);
        bits = (bits - dropped) + (away << 29);
        double rounded = 0;
        std::memcpy(&rounded, &bits, sizeof bits);
        return static_cast<float>(rounded);  // exact, or the infinity from 2^128
    }
    const auto f = static_cast<float>(v);
    const auto back = static_cast<double>(f);
    const int below = static_cast<int>(back < v);  // the nearest float is below v: up steps up
    const int above = static_cast<int>(back > v);  // above v: down steps down
    const int upward = static_cast<int>(up);
    return stepBy(f, (upward & below) - ((1 - upward) & above));
}

}  // namespace tilesweep::detail

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

#include <cstdint>
#include <cstring>

namespace tilesweep::detail {

/// The rounding error of p = fl(a*b): a*b - p, exactly (Dekker's TwoProduct with Veltkamp's
/// split; no FMA).
[[nodiscard]] inline double productError(double a, double b, double p) noexcept {
    constexpr double kSplitter = 134217729.0;  // 2^27 + 1: splits 53 bits into 26 + 26
    const double ca = kSplitter * a;
    const double aHigh = ca - (ca - a);
    const double aLow = a - aHigh;
    const double cb = kSplitter * b;
    const double bHigh = cb - (cb - b);
    const double bLow = b - bHigh;
    return ((aHigh * bHigh - p) + aHigh * bLow + aLow * bHigh) + aLow * bLow;
}

/// -1, 0 or 1 as a*b compares with c*d, exactly. `refined` is set when the rounded products
/// were equal and the exact rounding errors had to settle the order.
[[nodiscard]] inline int compareProducts(double a, double b, double c, double d, bool& refined) noexcept {
    const double p = a * b;
    const double q = c * d;
    if (p < q) return -1;  // monotonic rounding: the order of the rounded values is exact
    if (p > q) return 1;
    refined = true;
    const double e = productError(a, b, p);
    const double f = productError(c, d, q);
    return e < f ? -1 : (e > f ? 1 : 0);
}

/// The next float above (up = true) or below a finite float, by its bits; never crosses the
/// largest finite value (the caller's range keeps well inside it).
[[nodiscard]] inline float stepFloat(float f, bool up) noexcept {
    if (f == 0) return up ? 1e-45f : -1e-45f;  // the least subnormal, either sign
    std::uint32_t bits = 0;
    std::memcpy(&bits, &f, sizeof bits);
    const bool away = (f > 0) == up;  // magnitude grows
    bits = away ? bits + 1 : bits - 1;
    std::memcpy(&f, &bits, sizeof bits);
    return f;
}

/// The exact double v rounded to float toward minus infinity (down) or plus infinity. The
/// conversion rounds to nearest, correctly (IEEE 754); one step fixes the direction.
[[nodiscard]] inline float roundToFloat(double v, bool up) noexcept {
    const auto f = static_cast<float>(v);
    const auto back = static_cast<double>(f);
    if (up ? back < v : back > v) return stepFloat(f, up);
    return f;
}

}  // namespace tilesweep::detail

// SPDX-License-Identifier: MIT
#pragma once

// The coordinate arithmetic of the fast path, by type: an exact double (float frames, where the
// range test makes every coordinate and every difference of two an exact double) or an exact
// pair (double frames: a difference of two doubles by TwoSum, exact_double.h). The double
// versions are the plain operations, so the float path compiles to what plain code would.
// The lattice's integers have the same operations (lattice.h), so that the tile test
// (axis_sweep.h) and the frame loop (frame_loop.h) are written once for all three.

#include "exact_double.h"
#include "proof_constants.h"

#include <cmath>
#include <type_traits>

namespace tilesweep::detail {

template <class Coord>
[[nodiscard]] Coord differenceOf(double a, double b) noexcept;
template <>
[[nodiscard]] inline double differenceOf<double>(double a, double b) noexcept {
    return a - b;
}
template <>
[[nodiscard]] inline ExactPair differenceOf<ExactPair>(double a, double b) noexcept {
    return twoSum(a, -b);
}

template <class Coord>
[[nodiscard]] Coord sumOf(double a, double b) noexcept;
template <>
[[nodiscard]] inline double sumOf<double>(double a, double b) noexcept {
    return a + b;
}
template <>
[[nodiscard]] inline ExactPair sumOf<ExactPair>(double a, double b) noexcept {
    return twoSum(a, b);
}

template <class Coord>
[[nodiscard]] Coord coordOf(double a) noexcept;
template <>
[[nodiscard]] inline double coordOf<double>(double a) noexcept {
    return a;
}
template <>
[[nodiscard]] inline ExactPair coordOf<ExactPair>(double a) noexcept {
    return {a, 0};
}

/// -1, 0 or 1 as v compares with d, exactly.
[[nodiscard]] inline int compare(double v, double d) noexcept { return v < d ? -1 : (v > d ? 1 : 0); }
/// The sign of v, exactly (a pair's high part is zero only when the pair is).
[[nodiscard]] inline int signOf(double v) noexcept { return v < 0 ? -1 : (v > 0 ? 1 : 0); }
[[nodiscard]] inline int signOf(ExactPair v) noexcept { return signOf(v.hi); }
/// A double near v, for estimates only: within u|v| of it.
[[nodiscard]] inline double approximate(double v) noexcept { return v; }
[[nodiscard]] inline double approximate(ExactPair v) noexcept { return v.hi; }
/// Whether two coordinates are the same value represented the same way (a sufficient test of
/// equality, for the shortcut in compareTimes).
[[nodiscard]] inline bool identical(double a, double b) noexcept { return a == b; }
[[nodiscard]] inline bool identical(ExactPair a, ExactPair b) noexcept {
    return a.hi == b.hi && a.lo == b.lo;
}

/// Whether a*s > b*t for certain (a, b coordinates, s, t >= 0): false may also mean "equal or
/// could not tell". The walk's early exit; walking on is always harmless.
[[nodiscard]] inline bool certainlyGreater(double a, double s, double b, double t) noexcept {
    return a * s > b * t;  // monotonic rounding: a strictly greater rounded product is exact
}
[[nodiscard]] inline bool certainlyGreater(ExactPair a, double s, ExactPair b, double t) noexcept {
    const double p = a.hi * s;
    const double q = b.hi * t;
    return p - q > kPairProductErrorBound * (std::fabs(p) + std::fabs(q));  // compareProducts' filter
}

}  // namespace tilesweep::detail

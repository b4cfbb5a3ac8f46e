// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>

// Whether a grid line `origin + k*tile` (k any integer, on the map or off it) lies in [low, high),
// where low and high are exact sums of a few floats or doubles: the test of the contract's
// rounding rule ("Positions"), written for the checks on their own, apart from the resolver's
// lattice and the GMP oracle.
//
// A long double estimate decides at once when the nearest line is clearly outside the interval
// (almost always); otherwise the interval is decided exactly, in integers scaled by the lowest
// exponent of the inputs (grid_line.cpp, with Boost.Multiprecision's header-only cpp_int).

namespace tilesweep::checks {

namespace detail {

/// A finite T as mantissa * 2^exponent, with an integer mantissa of at most digits(T) bits.
struct Split {
    std::int64_t mantissa;
    int exponent;
};

template <class T>
[[nodiscard]] Split split(T v) {
    constexpr int p = std::numeric_limits<T>::digits;
    int e = 0;
    const T fraction = std::frexp(v, &e);
    return {static_cast<std::int64_t>(std::ldexp(fraction, p)), e - p};
}

/// The exact test in integers (grid_line.cpp): whether a line origin + k*tile lies in
/// [sum(low), sum(high)), at most four terms each.
[[nodiscard]] bool gridLineInExact(const Split* low, int lowCount, const Split* high, int highCount,
                                   Split origin, Split tile);

}  // namespace detail

/// True when some origin + k*tile (integer k, tile > 0) lies in [sum(low), sum(high)); at most
/// four terms on each side.
template <class T>
[[nodiscard]] bool gridLineIn(std::initializer_list<T> low, std::initializer_list<T> high, T origin, T tile) {
    // The estimate: positions in tiles from the origin, with a margin far above the rounding
    // error of a few long double operations (2^-63 relative each) on terms this size.
    using W = long double;
    const auto wide = [](T v) { return static_cast<W>(v); };
    W lowSum = 0;
    W highSum = 0;
    W largest = std::fabs(wide(origin));
    for (const T v : low) {
        lowSum += wide(v);
        largest = std::max(largest, std::fabs(wide(v)));
    }
    for (const T v : high) {
        highSum += wide(v);
        largest = std::max(largest, std::fabs(wide(v)));
    }
    const W from = (lowSum - wide(origin)) / wide(tile);
    const W to = (highSum - wide(origin)) / wide(tile);
    const W margin = std::ldexp(largest / wide(tile) + std::fabs(from) + std::fabs(to) + 1, -56);
    if (std::fabs(from) < std::ldexp(W(1), 60) && std::ceil(from - margin) > to + margin) return false;

    detail::Split lows[4];
    detail::Split highs[4];
    int lowCount = 0;
    int highCount = 0;
    for (const T v : low)
        if (lowCount < 4) lows[lowCount++] = detail::split(v);
    for (const T v : high)
        if (highCount < 4) highs[highCount++] = detail::split(v);
    return detail::gridLineInExact(lows, lowCount, highs, highCount, detail::split(origin),
                                   detail::split(tile));
}

}  // namespace tilesweep::checks

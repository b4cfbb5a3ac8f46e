// SPDX-License-Identifier: MIT
#pragma once

// Leading and trailing zero counts of nonzero unsigned integers. GCC and Clang get the
// compiler's builtins (one instruction); with TILESWEEP_PORTABLE_INTEGERS defined, or on other
// compilers, a plain binary search that any C++17 compiler builds.

#include <cstdint>

#if !defined(TILESWEEP_PORTABLE_INTEGERS) && (defined(__GNUC__) || defined(__clang__))
#define TILESWEEP_HAVE_BIT_BUILTINS 1
#endif

namespace tilesweep::detail {

/// Zero bits above the highest set bit of x; x must be nonzero.
[[nodiscard]] inline int countLeadingZeros64(std::uint64_t x) noexcept {
#if defined(TILESWEEP_HAVE_BIT_BUILTINS)
    return __builtin_clzll(x);
#else
    int zeros = 0;
    for (int step = 32; step > 0; step /= 2) {
        if ((x >> (64 - step)) == 0) {
            zeros += step;
            x <<= step;
        }
    }
    return zeros;
#endif
}

/// Zero bits below the lowest set bit of x; x must be nonzero.
[[nodiscard]] inline int countTrailingZeros64(std::uint64_t x) noexcept {
#if defined(TILESWEEP_HAVE_BIT_BUILTINS)
    return __builtin_ctzll(x);
#else
    int zeros = 0;
    for (int step = 32; step > 0; step /= 2) {
        if ((x << (64 - step)) == 0) {
            zeros += step;
            x >>= step;
        }
    }
    return zeros;
#endif
}

/// Zero bits above the highest set bit of a nonzero 32-bit x.
[[nodiscard]] inline int countLeadingZeros32(std::uint32_t x) noexcept { return countLeadingZeros64(x) - 32; }

}  // namespace tilesweep::detail

// SPDX-License-Identifier: MIT
#pragma once

// The integer lattice of a frame, and the way back from it to float or double.
//
// Every finite float or double is a dyadic rational m * 2^e. Take E, the lowest exponent of a
// set bit among all the inputs of a frame (box, displacement, map origin and tile size): every
// input, and every tile edge origin + i*tileSize, is then an integer multiple of 2^E. Scaled by
// 2^-E they become integers, and the contract's arithmetic (sums, differences, products of
// distances and displacements, comparisons of times as cross-multiplied fractions) becomes
// integer arithmetic: exact, with no epsilon and no rounding. Times of impact are ratios of two
// lattice integers, so the scale 2^E cancels from them.
//
// The integers need as many bits as the span of exponents (highest minus lowest) plus a few,
// and products twice that; a frame picks the narrowest WideInt that holds them (resolve.cpp).
// Typical game scenes (positions below 2^20, fractions down to 2^-30) take the 128-bit tier.

#include "bit_ops.h"
#include "fault_injection.h"
#include "wide_int.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

namespace tilesweep::detail {

/// A finite float or double as odd * 2^exponent (mantissa 0 for zero): its exact value.
struct Dyadic {
    std::int64_t mantissa;
    int exponent;
};

/// The exact dyadic form of a finite value, read from its bits (no libm call: this runs for
/// every input of every frame).
template <class T>
[[nodiscard]] inline Dyadic decompose(T v) noexcept {
    static_assert(std::numeric_limits<T>::is_iec559, "IEEE 754 binary formats only");
    constexpr int p = std::numeric_limits<T>::digits;               // 24 or 53
    constexpr int bias = std::numeric_limits<T>::max_exponent - 1;  // 127 or 1023
    using Bits = std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>;
    Bits bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    const bool negative = (bits >> (8 * sizeof(T) - 1)) != 0;
    const auto biased = static_cast<int>((bits >> (p - 1)) & ((Bits{1} << (8 * sizeof(T) - p)) - 1));
    auto fraction = static_cast<std::uint64_t>(bits & ((Bits{1} << (p - 1)) - 1));
    int exponent = 1 - bias - (p - 1);  // of a subnormal's last bit
    if (biased != 0) {
        fraction |= std::uint64_t{1} << (p - 1);
        exponent = biased - bias - (p - 1);
    }
    if (fraction == 0) return {0, 0};
    const int zeros = countTrailingZeros64(fraction);
    const auto m = static_cast<std::int64_t>(fraction >> zeros);
    return {negative ? -m : m, exponent + zeros};
}

/// The exponent just above a dyadic's magnitude: |value| < 2^result (very negative for zero).
[[nodiscard]] inline int exponentAbove(Dyadic d) noexcept {
    if (d.mantissa == 0) return std::numeric_limits<int>::min() / 2;  // clz(0) is undefined
    const std::uint64_t mag =
        d.mantissa < 0 ? 0 - static_cast<std::uint64_t>(d.mantissa) : static_cast<std::uint64_t>(d.mantissa);
    return d.exponent + 64 - countLeadingZeros64(mag);
}

/// The lattice integer of a dyadic, d * 2^-latticeExponent (exact: latticeExponent is at most
/// d.exponent).
template <class Num>
[[nodiscard]] inline Num toLattice(Dyadic d, int latticeExponent) noexcept {
    if (d.mantissa == 0) return Num::fromInt(0);
    return Num::fromShifted(d.mantissa, d.exponent - latticeExponent);
}

/// Which way to round a magnitude that is not representable.
enum class MagnitudeRounding : std::uint8_t { TowardZero, AwayFromZero, NearestEven };

/// Rounds (mantissa + f) * 2^exponent to T, where f in [0, 1) is nonzero exactly when `sticky`.
/// When `sticky` is set the mantissa must carry at least digits(T) + 2 bits, so that the bits
/// dropped decide the rounding alone. Subnormal results round at the subnormal spacing.
/// Rounding toward zero never overflows (it clamps at the largest finite value); the other
/// modes give infinity past it, as IEEE does.
template <class T>
[[nodiscard]] inline T roundMagnitude(std::uint64_t mantissa, int exponent, bool sticky,
                                      MagnitudeRounding mode) noexcept {
    constexpr int p = std::numeric_limits<T>::digits;
    constexpr int lowestExponent = std::numeric_limits<T>::min_exponent - p;  // of the least subnormal
    if (mantissa == 0)
        return mode == MagnitudeRounding::AwayFromZero && sticky ? std::numeric_limits<T>::denorm_min()
                                                                 : T(0);
    const int top = 63 - countLeadingZeros64(mantissa);
    int keepFrom = top - (p - 1);  // bit index of the result's least significant bit
    if (keepFrom + exponent < lowestExponent) keepFrom = lowestExponent - exponent;
    std::uint64_t kept = 0;
    bool up = false;
    if (keepFrom <= 0) {
        kept = mantissa << -keepFrom;  // fits: at most p bits
        up = sticky && mode == MagnitudeRounding::AwayFromZero;
        // (A sticky tail with no dropped mantissa bits only happens when the caller broke the
        // precondition; rounding toward zero or to nearest then keeps the mantissa.)
    } else {
        const std::uint64_t dropped =
            keepFrom >= 64 ? mantissa : mantissa & ((std::uint64_t{1} << keepFrom) - 1);
        kept = keepFrom >= 64 ? 0 : mantissa >> keepFrom;
        const bool inexact = dropped != 0 || sticky;
        switch (mode) {
            case MagnitudeRounding::TowardZero:
                up = false;
                break;
            case MagnitudeRounding::AwayFromZero:
                up = inexact;
                break;
            case MagnitudeRounding::NearestEven: {
                const std::uint64_t half = keepFrom > 64 ? 0 : std::uint64_t{1} << (keepFrom - 1);
                if (keepFrom > 64) {
                    up = false;  // below half the least subnormal
                } else if (dropped > half || (dropped == half && sticky)) {
                    up = true;
                } else if (dropped == half) {
#if defined(TILESWEEP_FAULT_TIME_TIES_AWAY)
                    up = true;  // deliberate fault: an exact halfway time rounded away, not to even
#else
                    up = (kept & 1) != 0;
#endif
                }
                break;
            }
        }
    }
    if (up) ++kept;
    const T r = std::ldexp(static_cast<T>(kept), exponent + keepFrom);
    if (mode == MagnitudeRounding::TowardZero && !std::isfinite(r)) return std::numeric_limits<T>::max();
    return r;
}

/// Rounds the lattice integer v (value v * 2^latticeExponent) to T with `mode` on its magnitude.
template <class T, class Num>
[[nodiscard]] inline T roundLattice(const Num& v, int latticeExponent, MagnitudeRounding mode) noexcept {
    const Num mag = v.magnitude();
    const int top = mag.highestBit();
    if (top < 0) return T(0);
    const int from = top > 62 ? top - 62 : 0;
    bool sticky = false;
    const std::uint64_t bits = mag.bitsFrom(from, sticky);
    const T r = roundMagnitude<T>(bits, latticeExponent + from, sticky, mode);
    return v.isNegative() ? -r : r;
}

/// a mod b, floored (in [0, b)), for b > 0, exactly. The quotient is estimated in floating
/// point and taken off a, 40 bits at a time while it is huge, then the last units are settled
/// by exact comparisons. Rarely used: the rounding rule's grid-line test (resolve.cpp).
template <class Num>
[[nodiscard]] inline Num floorModulo(Num a, const Num& b) noexcept {
    for (;;) {
        int ea = 0;
        int eb = 0;
        const double ma = a.approximate(ea);
        const double mb = b.approximate(eb);
        if (ma == 0) return a;
        const double ratio = ma / mb;  // a / b = ratio * 2^shift, |ratio| in (0.5, 2), error < 2^-50
        const int shift = ea - eb;
        if (shift <= 40) {
            // |a / b| < 2^41: the estimate is off by less than one unit.
            a = a - b * static_cast<std::int64_t>(std::floor(std::ldexp(ratio, shift)));
            while (a.isNegative()) a = a + b;
            while (a >= b) a = a - b;
            return a;
        }
        // Take off 40 leading bits of the quotient, truncated: |a| shrinks by 2^38 or more.
        a = a - b * Num::fromShifted(static_cast<std::int64_t>(std::ldexp(ratio, 40)), shift - 40);
    }
}

/// Rounds (num / den) * 2^exponent to T, to nearest (ties to even), for 0 <= num and 0 < den:
/// a frame time (exponent 0), or a lattice coordinate num / den (exponent the lattice's).
template <class T, class Num>
[[nodiscard]] inline T roundRatioToNearest(const Num& num, const Num& den, int exponent = 0) noexcept {
    constexpr int p = std::numeric_limits<T>::digits;
    const int nTop = num.highestBit();
    if (nTop < 0) return T(0);
    const int dTop = den.highestBit();
    // num/den lies in [2^(nTop-dTop-1), 2^(nTop-dTop+1)); scaling num by 2^shift puts the
    // quotient in [2^(p+2), 2^(p+4)): p+2 bits or more, so the dropped bits and the remainder
    // settle the rounding.
    const int shift = p + 3 - (nTop - dTop);
    Num remainder = shift >= 0 ? num.shiftedLeft(shift) : num;
    const Num divisor = shift >= 0 ? den : den.shiftedLeft(-shift);
    std::uint64_t quotient = 0;
    if constexpr (std::is_same<Num, Int128>::value) {
        // The scaled numerator is below 2^(span + 60), and a coordinate's unscaled numerator (a
        // sum of two products) below 2^(2*span + 2): both below 2^127 (bitsNeeded). One division.
        quotient = static_cast<std::uint64_t>(remainder.v / divisor.v);
        remainder = {remainder.v % divisor.v};
        return roundMagnitude<T>(quotient, exponent - shift, !remainder.isZero(),
                                 MagnitudeRounding::NearestEven);
    }
    // Restoring division: the quotient has at most p + 4 bits.
    for (int b = p + 4; b >= 0; --b) {
        const Num step = divisor.shiftedLeft(b);
        if (compare(step, remainder) <= 0) {
            remainder = remainder - step;
            quotient |= std::uint64_t{1} << b;
        }
    }
    return roundMagnitude<T>(quotient, exponent - shift, !remainder.isZero(), MagnitudeRounding::NearestEven);
}

}  // namespace tilesweep::detail

namespace tilesweep::detail {

/// The lattice of a frame: its exponent and the bits its integers span.
struct LatticeShape {
    int exponent;  ///< every input is a multiple of 2^exponent
    int spanBits;  ///< every lattice value of the frame has magnitude below 2^spanBits
};

/// The lattice of a set of dyadics: the lowest exponent among the nonzero ones, and a span that
/// holds every coordinate formed from them, given that none exceeds 2^topExponent.
[[nodiscard]] inline LatticeShape shapeLattice(const Dyadic* values, int count, int topExponent) noexcept {
    int lowest = std::numeric_limits<int>::max();
    for (int k = 0; k < count; ++k)
        if (values[k].mantissa != 0 && values[k].exponent < lowest) lowest = values[k].exponent;
    if (lowest == std::numeric_limits<int>::max()) lowest = 0;
    return {lowest, topExponent - lowest + 1};  // + 1 for the sign
}

/// Bit length of a non-negative count (0 for 0).
[[nodiscard]] inline int bitLength(std::uint64_t n) noexcept {
    return n == 0 ? 0 : 64 - countLeadingZeros64(n);
}

}  // namespace tilesweep::detail

namespace tilesweep::detail {

/// Bits the integers of a frame need: values below 2^span, products of two of them and sums
/// of a few such products below 2^(2*span + 6), and the scaled numerator of a rounded time
/// below 2^(span + 60).
[[nodiscard]] inline int bitsNeeded(const LatticeShape& shape) noexcept {
    const int products = 2 * shape.spanBits + 8;
    const int rounding = shape.spanBits + 64;
    return products > rounding ? products : rounding;
}

/// Calls f(Num{}) with the narrowest of the integer types this library instantiates that holds
/// `bits` signed bits: native __int128 (typical float and integer scenes), 192 or 256 (typical
/// double scenes), 640 (any float scene) or 4480 (any double scene, subnormals to the largest finite).
template <class F>
decltype(auto) withWidth(int bits, F&& f) {
#if defined(TILESWEEP_FAULT_NARROW_TIER)
    if (bits < 192) return f(Int128::fromInt(0));  // deliberate fault: 128 bits where 192 are needed
#endif
    if (bits < 127) return f(Int128::fromInt(0));
    if (bits < 192) return f(WideInt<3>::fromInt(0));
    if (bits < 256) return f(WideInt<4>::fromInt(0));
    if (bits < 640) return f(WideInt<10>::fromInt(0));
    return f(WideInt<70>::fromInt(0));
}

/// The dyadic forms of `count` inputs, in order.
template <class T>
inline void decomposeEach(const T* values, int count, Dyadic* out) noexcept {
    for (int k = 0; k < count; ++k) out[k] = decompose(values[k]);
}

/// The lattice set-up of a frame or of a single tile: the lattice of the inputs `d` (none of the
/// coordinates formed from them reaching 2^topExponent), then f(Num{}, exponent) with the
/// narrowest integers that hold it.
template <class F>
decltype(auto) onLattice(const Dyadic* d, int count, int topExponent, F&& f) {
    const LatticeShape shape = shapeLattice(d, count, topExponent);
    return withWidth(bitsNeeded(shape), [&](auto tag) { return f(tag, shape.exponent); });
}

}  // namespace tilesweep::detail

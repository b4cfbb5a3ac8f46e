// SPDX-License-Identifier: MIT
#pragma once

// A fixed-width signed integer of N 64-bit limbs, two's complement, little-endian limbs.
//
// The resolver scales every input of a frame onto one integer lattice (see lattice.h) and
// decides everything with these integers, so every sum, product and comparison is exact. The
// width is chosen per frame from the span of the inputs' exponents, so that no operation can
// overflow (the caller guarantees it; TILESWEEP_ASSERT-style checks would cost the hot path).
// No allocation: the limbs live in the object.

#include "bit_ops.h"

#include <cmath>
#include <cstdint>

// 128-bit helpers: the compiler's __int128 on GCC and Clang; with TILESWEEP_PORTABLE_INTEGERS
// defined, or on any other compiler (MSVC), two 64-bit limbs with the same operators, so that
// WideInt, Int128 and their callers compile unchanged on any C++17 compiler.
#if !defined(TILESWEEP_PORTABLE_INTEGERS) && (defined(__GNUC__) || defined(__clang__)) && \
    defined(__SIZEOF_INT128__)
#define TILESWEEP_HAVE_NATIVE_INT128 1
#endif

namespace tilesweep::detail {

#if defined(TILESWEEP_HAVE_NATIVE_INT128)
__extension__ typedef unsigned __int128 Uint128;
__extension__ typedef __int128 Int128Native;
#else
/// An unsigned 128-bit integer as two limbs, arithmetic modulo 2^128, with the operators the
/// native unsigned __int128 offers that this library uses. Shifts take 0 <= s < 128.
struct Uint128 {
    std::uint64_t lo = 0;
    std::uint64_t hi = 0;

    constexpr Uint128() noexcept = default;
    constexpr Uint128(std::uint64_t v) noexcept : lo(v) {}  // implicit, as the native type converts
    constexpr Uint128(std::uint64_t high, std::uint64_t low, bool) noexcept : lo(low), hi(high) {}
    explicit constexpr operator std::uint64_t() const noexcept { return lo; }

    /// The full product of two 64-bit values, from 32-bit halves.
    static constexpr Uint128 multiply64(std::uint64_t a, std::uint64_t b) noexcept {
        const std::uint64_t a0 = a & 0xffffffffu, a1 = a >> 32, b0 = b & 0xffffffffu, b1 = b >> 32;
        const std::uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
        const std::uint64_t middle = (p00 >> 32) + (p01 & 0xffffffffu) + (p10 & 0xffffffffu);
        return {p11 + (p01 >> 32) + (p10 >> 32) + (middle >> 32), (p00 & 0xffffffffu) | (middle << 32), true};
    }

    friend constexpr Uint128 operator+(Uint128 a, Uint128 b) noexcept {
        const std::uint64_t low = a.lo + b.lo;
        return {a.hi + b.hi + (low < a.lo ? 1u : 0u), low, true};
    }
    friend constexpr Uint128 operator-(Uint128 a, Uint128 b) noexcept {
        return {a.hi - b.hi - (a.lo < b.lo ? 1u : 0u), a.lo - b.lo, true};
    }
    friend constexpr Uint128 operator*(Uint128 a, Uint128 b) noexcept {
        Uint128 r = multiply64(a.lo, b.lo);
        r.hi += a.lo * b.hi + a.hi * b.lo;
        return r;
    }
    friend constexpr Uint128 operator<<(Uint128 a, int s) noexcept {
        if (s == 0) return a;
        if (s >= 64) return {a.lo << (s - 64), 0, true};
        return {(a.hi << s) | (a.lo >> (64 - s)), a.lo << s, true};
    }
    friend constexpr Uint128 operator>>(Uint128 a, int s) noexcept {
        if (s == 0) return a;
        if (s >= 64) return {0, a.hi >> (s - 64), true};
        return {a.hi >> s, (a.lo >> s) | (a.hi << (64 - s)), true};
    }
    friend constexpr Uint128 operator&(Uint128 a, Uint128 b) noexcept {
        return {a.hi & b.hi, a.lo & b.lo, true};
    }
    friend constexpr Uint128 operator|(Uint128 a, Uint128 b) noexcept {
        return {a.hi | b.hi, a.lo | b.lo, true};
    }
    friend constexpr Uint128 operator~(Uint128 a) noexcept { return {~a.hi, ~a.lo, true}; }
    friend constexpr bool operator==(Uint128 a, Uint128 b) noexcept { return a.hi == b.hi && a.lo == b.lo; }
    friend constexpr bool operator!=(Uint128 a, Uint128 b) noexcept { return !(a == b); }
    friend constexpr bool operator<(Uint128 a, Uint128 b) noexcept {
        return a.hi != b.hi ? a.hi < b.hi : a.lo < b.lo;
    }
    friend constexpr bool operator>(Uint128 a, Uint128 b) noexcept { return b < a; }
    friend constexpr bool operator<=(Uint128 a, Uint128 b) noexcept { return !(b < a); }
    friend constexpr bool operator>=(Uint128 a, Uint128 b) noexcept { return !(a < b); }

    /// Quotient and remainder of a / b, b != 0 (restoring division, one bit a step; a 64-bit
    /// division when both fit).
    static constexpr Uint128 divide(Uint128 a, Uint128 b, Uint128& remainder) noexcept {
        if (a.hi == 0 && b.hi == 0) {
            remainder = Uint128(a.lo % b.lo);
            return Uint128(a.lo / b.lo);
        }
        Uint128 q;
        Uint128 r;
        for (int bit = 127; bit >= 0; --bit) {
            r = (r << 1) | ((a >> bit) & Uint128(1));
            if (r >= b) {
                r = r - b;
                q = q | (Uint128(1) << bit);
            }
        }
        remainder = r;
        return q;
    }

    /// The value rounded to the nearest double (ties to even): the top 64 bits with a sticky
    /// bit for the rest, so the one rounding to 53 bits is the correct one.
    [[nodiscard]] double toDouble() const noexcept {
        if (hi == 0) return static_cast<double>(lo);
        const int shift = 64 - countLeadingZeros64(hi);  // bits of hi, 1..64
        std::uint64_t top = shift == 64 ? hi : (hi << (64 - shift)) | (lo >> shift);
        const std::uint64_t dropped = shift == 64 ? lo : lo << (64 - shift);
        if (dropped != 0) top |= 1;
        return std::ldexp(static_cast<double>(top), shift);
    }
};

/// A signed 128-bit integer, two's complement over Uint128, with the operators the native
/// __int128 offers that this library uses (division truncates toward zero, as in C++).
struct Int128Native {
    Uint128 bits;

    constexpr Int128Native() noexcept = default;
    constexpr Int128Native(std::int64_t v) noexcept  // implicit, as the native type converts
        : bits(v < 0 ? ~std::uint64_t{0} : 0, static_cast<std::uint64_t>(v), true) {}
    explicit constexpr Int128Native(Uint128 u) noexcept : bits(u) {}
    explicit constexpr operator Uint128() const noexcept { return bits; }
    explicit constexpr operator std::uint64_t() const noexcept { return bits.lo; }
    explicit operator double() const noexcept {
        return isNegative() ? -(Uint128{} - bits).toDouble() : bits.toDouble();
    }

    [[nodiscard]] constexpr bool isNegative() const noexcept { return (bits.hi >> 63) != 0; }

    friend constexpr Int128Native operator+(Int128Native a, Int128Native b) noexcept {
        return Int128Native(a.bits + b.bits);
    }
    friend constexpr Int128Native operator-(Int128Native a, Int128Native b) noexcept {
        return Int128Native(a.bits - b.bits);
    }
    friend constexpr Int128Native operator-(Int128Native a) noexcept {
        return Int128Native(Uint128{} - a.bits);
    }
    friend constexpr Int128Native operator*(Int128Native a, Int128Native b) noexcept {
        return Int128Native(a.bits * b.bits);
    }
    friend constexpr Int128Native operator<<(Int128Native a, int s) noexcept {
        return Int128Native(a.bits << s);
    }
    friend constexpr Int128Native operator/(Int128Native a, Int128Native b) noexcept {
        Uint128 r;
        const Uint128 q = Uint128::divide(a.magnitudeBits(), b.magnitudeBits(), r);
        return a.isNegative() != b.isNegative() ? -Int128Native(q) : Int128Native(q);
    }
    friend constexpr Int128Native operator%(Int128Native a, Int128Native b) noexcept {
        Uint128 r;
        Uint128::divide(a.magnitudeBits(), b.magnitudeBits(), r);
        return a.isNegative() ? -Int128Native(r) : Int128Native(r);
    }
    friend constexpr bool operator<(Int128Native a, Int128Native b) noexcept {
        const auto ah = static_cast<std::int64_t>(a.bits.hi);
        const auto bh = static_cast<std::int64_t>(b.bits.hi);
        return ah != bh ? ah < bh : a.bits.lo < b.bits.lo;
    }
    friend constexpr bool operator>(Int128Native a, Int128Native b) noexcept { return b < a; }
    friend constexpr bool operator<=(Int128Native a, Int128Native b) noexcept { return !(b < a); }
    friend constexpr bool operator>=(Int128Native a, Int128Native b) noexcept { return !(a < b); }
    friend constexpr bool operator==(Int128Native a, Int128Native b) noexcept { return a.bits == b.bits; }
    friend constexpr bool operator!=(Int128Native a, Int128Native b) noexcept { return a.bits != b.bits; }

private:
    [[nodiscard]] constexpr Uint128 magnitudeBits() const noexcept {
        return isNegative() ? Uint128{} - bits : bits;
    }
};
#endif

template <int N>
struct WideInt {
    static_assert(N >= 2, "WideInt needs at least two limbs");
    std::uint64_t limb[N];

    static WideInt fromInt(std::int64_t v) noexcept {
        WideInt r;
        r.limb[0] = static_cast<std::uint64_t>(v);
        const std::uint64_t fill = v < 0 ? ~std::uint64_t{0} : 0;
        for (int k = 1; k < N; ++k) r.limb[k] = fill;
        return r;
    }

    /// The value m * 2^shift, for shift >= 0 (shift < 64*N - 64).
    static WideInt fromShifted(std::int64_t m, int shift) noexcept {
        const bool negative = m < 0;
        const std::uint64_t mag =
            negative ? 0 - static_cast<std::uint64_t>(m) : static_cast<std::uint64_t>(m);
        WideInt r = fromInt(0);
        const int word = shift / 64;
        const int bit = shift % 64;
        r.limb[word] = mag << bit;
        if (bit != 0 && word + 1 < N) r.limb[word + 1] = mag >> (64 - bit);
        return negative ? -r : r;
    }

    [[nodiscard]] bool isNegative() const noexcept { return (limb[N - 1] >> 63) != 0; }

    [[nodiscard]] bool isZero() const noexcept {
        for (int k = 0; k < N; ++k)
            if (limb[k] != 0) return false;
        return true;
    }

    /// -1, 0 or 1.
    [[nodiscard]] int sign() const noexcept { return isNegative() ? -1 : (isZero() ? 0 : 1); }

    friend WideInt operator+(const WideInt& a, const WideInt& b) noexcept {
        WideInt r;
        std::uint64_t carry = 0;
        for (int k = 0; k < N; ++k) {
            const Uint128 s = static_cast<Uint128>(a.limb[k]) + b.limb[k] + carry;
            r.limb[k] = static_cast<std::uint64_t>(s);
            carry = static_cast<std::uint64_t>(s >> 64);
        }
        return r;
    }

    friend WideInt operator-(const WideInt& a) noexcept {
        WideInt r;
        std::uint64_t carry = 1;
        for (int k = 0; k < N; ++k) {
            const Uint128 s = static_cast<Uint128>(~a.limb[k]) + carry;
            r.limb[k] = static_cast<std::uint64_t>(s);
            carry = static_cast<std::uint64_t>(s >> 64);
        }
        return r;
    }

    friend WideInt operator-(const WideInt& a, const WideInt& b) noexcept {
        WideInt r;
        std::uint64_t borrow = 0;
        for (int k = 0; k < N; ++k) {
            const Uint128 d = static_cast<Uint128>(a.limb[k]) - b.limb[k] - borrow;
            r.limb[k] = static_cast<std::uint64_t>(d);
            borrow = static_cast<std::uint64_t>(d >> 64) != 0 ? 1 : 0;
        }
        return r;
    }

    /// The magnitude, as a non-negative WideInt (never called on the most negative value).
    [[nodiscard]] WideInt magnitude() const noexcept { return isNegative() ? -*this : *this; }

    friend WideInt operator*(const WideInt& a, const WideInt& b) noexcept {
        const bool negative = a.isNegative() != b.isNegative();
        const WideInt x = a.magnitude();
        const WideInt y = b.magnitude();
        const int xn = x.usedLimbs();
        const int yn = y.usedLimbs();
        WideInt r = fromInt(0);
        for (int i = 0; i < xn; ++i) {
            std::uint64_t carry = 0;
            for (int j = 0; j < yn && i + j < N; ++j) {
                const Uint128 t = static_cast<Uint128>(x.limb[i]) * y.limb[j] + r.limb[i + j] + carry;
                r.limb[i + j] = static_cast<std::uint64_t>(t);
                carry = static_cast<std::uint64_t>(t >> 64);
            }
            if (i + yn < N) r.limb[i + yn] = carry;
        }
        return negative ? -r : r;
    }

    friend WideInt operator*(const WideInt& a, std::int64_t b) noexcept { return a * fromInt(b); }

    /// Three-way signed comparison: -1, 0 or 1.
    friend int compare(const WideInt& a, const WideInt& b) noexcept {
        const bool an = a.isNegative();
        const bool bn = b.isNegative();
        if (an != bn) return an ? -1 : 1;
        for (int k = N - 1; k >= 0; --k)
            if (a.limb[k] != b.limb[k]) return a.limb[k] < b.limb[k] ? -1 : 1;
        return 0;
    }

    friend bool operator<(const WideInt& a, const WideInt& b) noexcept { return compare(a, b) < 0; }
    friend bool operator>(const WideInt& a, const WideInt& b) noexcept { return compare(a, b) > 0; }
    friend bool operator<=(const WideInt& a, const WideInt& b) noexcept { return compare(a, b) <= 0; }
    friend bool operator>=(const WideInt& a, const WideInt& b) noexcept { return compare(a, b) >= 0; }
    friend bool operator==(const WideInt& a, const WideInt& b) noexcept { return compare(a, b) == 0; }
    friend bool operator!=(const WideInt& a, const WideInt& b) noexcept { return compare(a, b) != 0; }

    /// Number of limbs up to the highest nonzero one (of a non-negative value).
    [[nodiscard]] int usedLimbs() const noexcept {
        int n = N;
        while (n > 0 && limb[n - 1] == 0) --n;
        return n;
    }

    /// Index of the highest set bit of a positive value; -1 for zero.
    [[nodiscard]] int highestBit() const noexcept {
        for (int k = N - 1; k >= 0; --k)
            if (limb[k] != 0) return 64 * k + 63 - countLeadingZeros64(limb[k]);
        return -1;
    }

    /// This non-negative value shifted left by `bits` (the result must fit).
    [[nodiscard]] WideInt shiftedLeft(int bits) const noexcept {
        WideInt r = fromInt(0);
        const int word = bits / 64;
        const int bit = bits % 64;
        for (int k = N - 1; k >= word; --k) {
            std::uint64_t v = limb[k - word] << bit;
            if (bit != 0 && k - word - 1 >= 0) v |= limb[k - word - 1] >> (64 - bit);
            r.limb[k] = v;
        }
        return r;
    }

    /// The 64 bits of this non-negative value starting at bit `from` (from >= 0), and whether
    /// any bit below `from` is set.
    [[nodiscard]] std::uint64_t bitsFrom(int from, bool& lowerBitsSet) const noexcept {
        const int word = from / 64;
        const int bit = from % 64;
        lowerBitsSet = false;
        for (int k = 0; k < word && k < N; ++k)
            if (limb[k] != 0) lowerBitsSet = true;
        if (word >= N) return 0;
        if (bit != 0 && (limb[word] << (64 - bit)) != 0) lowerBitsSet = true;
        std::uint64_t v = limb[word] >> bit;
        if (bit != 0 && word + 1 < N) v |= limb[word + 1] << (64 - bit);
        return v;
    }

    /// An approximation m * 2^exponent of the value, with |m| in [0.5, 1) (m = 0 for zero).
    /// Relative error below 2^-52: enough for estimates that are then checked exactly.
    [[nodiscard]] double approximate(int& exponent) const noexcept {
        const WideInt mag = magnitude();
        const int top = mag.highestBit();
        if (top < 0) {
            exponent = 0;
            return 0.0;
        }
        const int from = top >= 63 ? top - 63 : 0;
        bool lower = false;
        const std::uint64_t bits = mag.bitsFrom(from, lower);
        int e = 0;
        const double m = std::frexp(static_cast<double>(bits), &e);
        exponent = e + from;
        return isNegative() ? -m : m;
    }
};

}  // namespace tilesweep::detail

namespace tilesweep::detail {

/// The narrowest tier as one native 128-bit integer: the same interface as WideInt, with the
/// arithmetic done by the compiler's __int128 (a few instructions instead of limb loops), or by
/// the two-limb Int128Native above under TILESWEEP_PORTABLE_INTEGERS.
struct Int128 {
    Int128Native v;

    static Int128 fromInt(std::int64_t x) noexcept { return {x}; }
    static Int128 fromShifted(std::int64_t m, int shift) noexcept {
        return {static_cast<Int128Native>(m) * (static_cast<Int128Native>(1) << shift)};
    }
    [[nodiscard]] bool isNegative() const noexcept { return v < 0; }
    [[nodiscard]] bool isZero() const noexcept { return v == 0; }
    [[nodiscard]] int sign() const noexcept { return v < 0 ? -1 : (v > 0 ? 1 : 0); }
    friend Int128 operator+(Int128 a, Int128 b) noexcept { return {a.v + b.v}; }
    friend Int128 operator-(Int128 a, Int128 b) noexcept { return {a.v - b.v}; }
    friend Int128 operator-(Int128 a) noexcept { return {-a.v}; }
    friend Int128 operator*(Int128 a, Int128 b) noexcept { return {a.v * b.v}; }
    friend Int128 operator*(Int128 a, std::int64_t b) noexcept { return {a.v * b}; }
    friend int compare(Int128 a, Int128 b) noexcept { return a.v < b.v ? -1 : (a.v > b.v ? 1 : 0); }
    friend bool operator<(Int128 a, Int128 b) noexcept { return a.v < b.v; }
    friend bool operator>(Int128 a, Int128 b) noexcept { return a.v > b.v; }
    friend bool operator<=(Int128 a, Int128 b) noexcept { return a.v <= b.v; }
    friend bool operator>=(Int128 a, Int128 b) noexcept { return a.v >= b.v; }
    friend bool operator==(Int128 a, Int128 b) noexcept { return a.v == b.v; }
    friend bool operator!=(Int128 a, Int128 b) noexcept { return a.v != b.v; }
    [[nodiscard]] Int128 magnitude() const noexcept { return {v < 0 ? -v : v}; }
    [[nodiscard]] int highestBit() const noexcept {
        const auto u = static_cast<Uint128>(v);
        const auto hi = static_cast<std::uint64_t>(u >> 64);
        const auto lo = static_cast<std::uint64_t>(u);
        if (hi != 0) return 127 - countLeadingZeros64(hi);
        return lo != 0 ? 63 - countLeadingZeros64(lo) : -1;
    }
    [[nodiscard]] Int128 shiftedLeft(int bits) const noexcept {
        return {static_cast<Int128Native>(static_cast<Uint128>(v) << bits)};
    }
    [[nodiscard]] std::uint64_t bitsFrom(int from, bool& lowerBitsSet) const noexcept {
        const auto u = static_cast<Uint128>(v);
        lowerBitsSet = from > 0 && (u & ((static_cast<Uint128>(1) << from) - 1)) != 0;
        return static_cast<std::uint64_t>(u >> from);
    }
    [[nodiscard]] double approximate(int& exponent) const noexcept {
        return std::frexp(static_cast<double>(v), &exponent);
    }
};

/// a / b for b > 0, approximately (relative error a few ulps of double; saturating at +-1e30).
/// Only ever used as a first guess that exact comparisons then settle.
template <int N>
[[nodiscard]] inline double estimateQuotient(const WideInt<N>& a, const WideInt<N>& b) noexcept {
    int ea = 0;
    int eb = 0;
    const double ma = a.approximate(ea);
    const double mb = b.approximate(eb);
    if (ma == 0) return 0;
    const int shift = ea - eb;
    if (shift > 70) return ma > 0 ? 1e30 : -1e30;
    return std::ldexp(ma / mb, shift);
}

[[nodiscard]] inline double estimateQuotient(Int128 a, Int128 b) noexcept {
    return static_cast<double>(a.v) / static_cast<double>(b.v);
}

}  // namespace tilesweep::detail

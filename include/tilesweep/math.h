// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <type_traits>

// Value types of tilesweep.
//
// Conventions: x grows to the right, y grows downward (screen convention). A box is the
// closed rectangle [pos.x, pos.x + size.x] x [pos.y, pos.y + size.y]; every coordinate is in
// the caller's length unit (pixels, usually). The scalar type T is float or double; an input
// value stands for its exact value, and all decisions are made in exact arithmetic.

namespace tilesweep {

/// A 2D vector in length units (a position, a size or a displacement).
template <class T>
struct Vec2 {
    T x;
    T y;
};

/// An axis-aligned box: the closed rectangle [pos, pos + size]; valid when size > 0 on both axes.
template <class T>
struct Box {
    Vec2<T> pos;
    Vec2<T> size;
};

/// A tile cell of a map: column i (grows right), row j (grows down); row 0 is the top row.
struct Cell {
    std::int32_t i;
    std::int32_t j;
};

/// One of the two axes.
enum class Axis : std::uint8_t { X, Y };

/// A unit normal on one axis: (-1, 0), (1, 0), (0, -1) or (0, 1); landing on a floor is (0, -1).
struct Normal {
    std::int8_t x;
    std::int8_t y;
};

[[nodiscard]] constexpr bool operator==(Cell a, Cell b) noexcept { return a.i == b.i && a.j == b.j; }
[[nodiscard]] constexpr bool operator!=(Cell a, Cell b) noexcept { return !(a == b); }
[[nodiscard]] constexpr bool operator==(Normal a, Normal b) noexcept { return a.x == b.x && a.y == b.y; }
[[nodiscard]] constexpr bool operator!=(Normal a, Normal b) noexcept { return !(a == b); }

template <class T>
[[nodiscard]] constexpr Vec2<T> operator+(Vec2<T> a, Vec2<T> b) noexcept {
    return {a.x + b.x, a.y + b.y};
}
template <class T>
[[nodiscard]] constexpr Vec2<T> operator-(Vec2<T> a, Vec2<T> b) noexcept {
    return {a.x - b.x, a.y - b.y};
}
template <class T>
[[nodiscard]] constexpr bool operator==(Vec2<T> a, Vec2<T> b) noexcept {
    return a.x == b.x && a.y == b.y;
}
template <class T>
[[nodiscard]] constexpr bool operator!=(Vec2<T> a, Vec2<T> b) noexcept {
    return !(a == b);
}

/// v scaled by s, each component rounded once (velocity * dt). The scalar may be any arithmetic
/// type (a `double dt` with a float vector): it is converted to T first, so the result stays a
/// Vec2<T> and no template argument is needed at the call site.
template <class T, class S, class = std::enable_if_t<std::is_arithmetic<S>::value>>
[[nodiscard]] constexpr Vec2<T> operator*(Vec2<T> v, S s) noexcept {
    return {v.x * static_cast<T>(s), v.y * static_cast<T>(s)};
}
template <class T, class S, class = std::enable_if_t<std::is_arithmetic<S>::value>>
[[nodiscard]] constexpr Vec2<T> operator*(S s, Vec2<T> v) noexcept {
    return v * s;
}

/// The component of v on axis a.
template <class T>
[[nodiscard]] constexpr T component(Vec2<T> v, Axis a) noexcept {
    return a == Axis::X ? v.x : v.y;
}

}  // namespace tilesweep

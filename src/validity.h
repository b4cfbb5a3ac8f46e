// SPDX-License-Identifier: MIT
#pragma once

// The cheap value checks every entry point makes before it computes anything (validate.cpp,
// mover.cpp, box_sweep.cpp).

#include "tilesweep/math.h"

#include <cmath>

namespace tilesweep::detail {

/// Both components finite.
template <class T>
[[nodiscard]] bool isFinite(Vec2<T> v) noexcept {
    return std::isfinite(v.x) && std::isfinite(v.y);
}

/// Both components finite and > 0 (a box or tile size).
template <class T>
[[nodiscard]] bool isPositive(Vec2<T> v) noexcept {
    return isFinite(v) && v.x > 0 && v.y > 0;
}

}  // namespace tilesweep::detail

// SPDX-License-Identifier: MIT
#pragma once

// The cheap value checks every entry point makes before it computes anything (validate.cpp,
// mover.cpp, box_sweep.cpp, the zero move and the fast path's range admission), written once.

#include "tilesweep/math.h"
#include "tilesweep/resolve.h"
#include "tilesweep/tile_map.h"

#include <cmath>
#include <cstdint>

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

/// The parts of validity that are not finiteness: box and tile sizes > 0, map dimensions sane,
/// cells present. (The fast path's range tests imply finiteness: a NaN or an infinity has an
/// exponent field of all ones.)
/// The map's half of hasValidShape: tile sizes > 0, dimensions sane, cells present (the range
/// test's map half, range_admission.h, uses it alone).
template <class T>
[[nodiscard]] inline bool mapHasValidShape(const TileMapView<T>& map) noexcept {
    const std::int64_t cells = static_cast<std::int64_t>(map.columns) * map.rows;
    return map.tileSize.x > 0 && map.tileSize.y > 0 && map.columns >= 0 && map.rows >= 0 &&
           cells <= kMaxCells && (cells == 0 || map.solid != nullptr);
}

template <class T>
[[nodiscard]] inline bool hasValidShape(const ResolveInput<T>& in) noexcept {
    return in.box.size.x > 0 && in.box.size.y > 0 && mapHasValidShape(in.map);
}

/// Whether every number of the input is finite, without a libm call: v - v is +0 for a finite v
/// and NaN for an infinity or a NaN, so the sum of them all is zero iff all are finite.
template <class T>
[[nodiscard]] inline bool hasFiniteValues(const ResolveInput<T>& in) noexcept {
    const T x = in.box.pos.x, y = in.box.pos.y, w = in.box.size.x, h = in.box.size.y;
    const T dx = in.displacement.x, dy = in.displacement.y;
    const T ox = in.map.origin.x, oy = in.map.origin.y, tx = in.map.tileSize.x, ty = in.map.tileSize.y;
    const T finite = (((x - x) + (y - y)) + ((w - w) + (h - h))) +
                     (((dx - dx) + (dy - dy)) + ((ox - ox) + (oy - oy))) + ((tx - tx) + (ty - ty));
    return finite == 0;
}

/// isValid (resolve.h): finite values, box size > 0, map header sane.
template <class T>
[[nodiscard]] inline bool isValidInput(const ResolveInput<T>& in) noexcept {
    return hasFiniteValues(in) && hasValidShape(in);
}

}  // namespace tilesweep::detail

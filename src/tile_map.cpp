// SPDX-License-Identifier: MIT
#include "tilesweep/tile_map.h"

#include "exact_double.h"

#include <cmath>

namespace tilesweep {
namespace {

/// Whether a + b is exactly representable in T. Knuth's TwoSum gives the rounding error of
/// s = fl(a + b) exactly (barring overflow, which `s` being finite rules out), so the sum is
/// representable iff that error is zero. No FMA may fuse these lines: -ffp-contract=off.
template <class T>
bool sumIsExact(T a, T b, T& s) noexcept {
    const detail::ExactSum<T> sum = detail::twoSum(a, b);
    s = sum.hi;
    return std::isfinite(s) && sum.lo == 0;
}

/// First k in [1, count] whose edge origin + k*tile is not representable, or -1. Induction:
/// edge k is representable and exact, so edge k+1 = edge k + tile is exact iff that one sum is.
template <class T>
std::int64_t firstUnrepresentableEdge(T origin, T tile, std::int64_t count) noexcept {
    T edge = origin;
    for (std::int64_t k = 1; k <= count; ++k) {
        T next = 0;
        if (!sumIsExact(edge, tile, next)) return k;
        edge = next;
    }
    return -1;
}

}  // namespace

template <class T>
MapError validateTileMap(const TileMapView<T>& map, std::int64_t* firstBadEdge) noexcept {
    if (!std::isfinite(map.origin.x) || !std::isfinite(map.origin.y)) return MapError::NonFiniteOrigin;
    if (!(std::isfinite(map.tileSize.x) && map.tileSize.x > 0 && std::isfinite(map.tileSize.y) &&
          map.tileSize.y > 0))
        return MapError::NonPositiveTileSize;
    if (map.columns < 0 || map.rows < 0) return MapError::NegativeDimensions;
    const std::int64_t cells = static_cast<std::int64_t>(map.columns) * map.rows;
    if (cells > kMaxCells) return MapError::TooLarge;
    if (cells > 0 && map.solid == nullptr) return MapError::NegativeDimensions;
    const std::int64_t badX = firstUnrepresentableEdge(map.origin.x, map.tileSize.x, map.columns);
    if (badX >= 0) {
        if (firstBadEdge != nullptr) *firstBadEdge = badX;
        return MapError::UnrepresentableEdgeX;
    }
    const std::int64_t badY = firstUnrepresentableEdge(map.origin.y, map.tileSize.y, map.rows);
    if (badY >= 0) {
        if (firstBadEdge != nullptr) *firstBadEdge = badY;
        return MapError::UnrepresentableEdgeY;
    }
    // Last, so that a bad map reports its own error first; src/arithmetic_check.cpp says why.
    if (!isArithmeticExact()) return MapError::InexactArithmetic;
    return MapError::None;
}

const char* describe(MapError error) noexcept {
    switch (error) {
        case MapError::None:
            return "valid";
        case MapError::NonFiniteOrigin:
            return "map.origin: non-finite value";
        case MapError::NonPositiveTileSize:
            return "map.tile: tile sizes must be finite and > 0";
        case MapError::NegativeDimensions:
            return "map.rows: dimensions must be >= 0 with cells present";
        case MapError::TooLarge:
            return "map.rows: more cells than kMaxCells";
        case MapError::UnrepresentableEdgeX:
            return "map.tile: a tile edge on x is not representable";
        case MapError::UnrepresentableEdgeY:
            return "map.tile: a tile edge on y is not representable";
        case MapError::NotPrepared:
            return "map: not prepared (a default-constructed PreparedMap; use prepareMap)";
        case MapError::InexactArithmetic:
            return "arithmetic: the floating-point environment is not exact (rounding mode not to "
                   "nearest, fused multiply-add or excess precision); the library refuses every map";
    }
    return "unknown map error";
}

template MapError validateTileMap<float>(const TileMapView<float>&, std::int64_t*) noexcept;
template MapError validateTileMap<double>(const TileMapView<double>&, std::int64_t*) noexcept;

}  // namespace tilesweep

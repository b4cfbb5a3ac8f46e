// SPDX-License-Identifier: MIT
#include "validity.h"

#include "tilesweep/resolve.h"
#include "tilesweep/tile_map.h"

// Validity predicates (box2d's b2IsValid*): the cheap checks every entry point makes before it
// computes anything. Map edge representability is O(columns + rows) and lives in
// validateTileMap (tile_map.cpp), which callers run once per map.

namespace tilesweep {
using detail::isFinite;
using detail::isPositive;

template <class T>
bool isValid(const SweepInput<T>& input) noexcept {
    const TileMapView<T>& map = input.map;
    const std::int64_t cells = static_cast<std::int64_t>(map.columns) * map.rows;
    return isFinite(input.box.pos) && isPositive(input.box.size) && isFinite(input.displacement) &&
           isFinite(map.origin) && isPositive(map.tileSize) && map.columns >= 0 && map.rows >= 0 &&
           cells <= kMaxCells && (cells == 0 || map.solid != nullptr);
}

template bool isValid<float>(const SweepInput<float>&) noexcept;
template bool isValid<double>(const SweepInput<double>&) noexcept;

}  // namespace tilesweep

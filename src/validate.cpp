// SPDX-License-Identifier: MIT
#include "validity.h"

#include "tilesweep/resolve.h"
#include "tilesweep/tile_map.h"

// Validity predicates (box2d's b2IsValid*): the cheap checks every entry point makes before it
// computes anything. Map edge representability is O(columns + rows) and lives in
// validateTileMap (tile_map.cpp), which callers run once per map.

namespace tilesweep {

template <class T>
bool isValid(const ResolveInput<T>& input) noexcept {
    return detail::isValidInput(input);
}

template bool isValid<float>(const ResolveInput<float>&) noexcept;
template bool isValid<double>(const ResolveInput<double>&) noexcept;

}  // namespace tilesweep

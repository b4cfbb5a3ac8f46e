// SPDX-License-Identifier: MIT
// Bad input is rejected with an error, never a result: tile sizes whose multiples are not
// representable. (NaN, infinities and sizes that are not > 0 in every field are the suite's claim
// badInputIsRejected, all_claims.cpp, which `tilesweep check` runs too.)
#include "generators.h"

#include "tilesweep/resolve.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <limits>

namespace tilesweep::properties {
namespace {

// A float map whose tile size is a decimal with no exact float multiples beyond a few columns.
RC_GTEST_PROP(BadInput, unrepresentableTileEdgesAreRejected, ()) {
    const int columns = *rc::gen::inRange(3, 40);
    const int tenths = *rc::gen::element(1, 3, 7, 11);  // 0.1, 0.3, 0.7, 1.1: not dyadic
    const float tile = static_cast<float>(tenths / 10.0);
    std::vector<std::uint8_t> cells(static_cast<std::size_t>(columns), 0);
    std::int64_t badEdge = 0;
    const MapError e = validateTileMap<float>({{0, 0}, {tile, 16}, columns, 1, cells.data()}, &badEdge);
    // Edge k = k * tile is exact only while k * (the tile's odd mantissa) fits 24 bits; the
    // reference: is float(k * tile computed in double) equal to the exact product in double?
    std::int64_t expectedBad = -1;
    for (int k = 1; k <= columns && expectedBad < 0; ++k) {
        const double exact = static_cast<double>(k) * static_cast<double>(tile);  // exact: 24 + 6 bits
        if (static_cast<double>(static_cast<float>(exact)) != exact) expectedBad = k;
    }
    RC_CLASSIFY(expectedBad < 0, "all edges representable");
    if (expectedBad < 0) {
        RC_ASSERT(e == MapError::None);
    } else {
        RC_ASSERT(e == MapError::UnrepresentableEdgeX);
        RC_ASSERT(badEdge == expectedBad);
    }
}

}  // namespace
}  // namespace tilesweep::properties

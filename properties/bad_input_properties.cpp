// SPDX-License-Identifier: MIT
// Bad input is rejected with an error, never a result: NaN and infinities anywhere, sizes that
// are not > 0, tile sizes whose multiples are not representable.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "generators.h"
#include "tilesweep/resolve.h"

namespace tilesweep::properties {
namespace {

template <class T>
void checkCorruptedSceneIsRejected() {
    const GeneratedScene<T> g = *genScene<T>(Family::Mixed);
    Scene<T> s = g.scene;
    const T bad = *rc::gen::element(std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::infinity(),
                                    -std::numeric_limits<T>::infinity(), T(0), T(-1));
    const int field = *rc::gen::inRange(0, 4);
    const bool nonFinite = !std::isfinite(bad);
    RC_PRE(nonFinite || field == 1);  // zero and negative values are only bad as sizes
    RC_CLASSIFY(std::isnan(bad), "nan");
    RC_CLASSIFY(std::isinf(bad), "inf");
    RC_CLASSIFY(!nonFinite, "non-positive size");
    switch (field) {
        case 0: s.box.pos.x = bad; break;
        case 1: s.box.size.y = bad; break;
        case 2: s.moves.back().x = bad; break;
        default: s.box.pos.y = bad; break;
    }
    // The library: InvalidInput, the start position kept, no NaN.
    Contact<T> contacts[8];
    Cell overlaps[8];
    const auto r = resolveMove<T>({s.map.view(), s.box, s.moves.back()}, {contacts, 8, overlaps, 8});
    RC_ASSERT(r.status == Status::InvalidInput);
    RC_ASSERT(r.contactCount == 0);
    RC_ASSERT(!std::isnan(r.position.x) && !std::isnan(r.position.y));
    // The scene reader: an error naming the field. Non-finite values can only be written as
    // strings ("nan", "inf"), which the format refuses; sizes as numbers.
    nlohmann::json line = nlohmann::json::parse(formatScene(g.scene));
    nlohmann::json value = nonFinite ? nlohmann::json(std::isnan(bad) ? "nan" : (bad > 0 ? "inf" : "-inf"))
                                     : nlohmann::json(static_cast<double>(bad));
    switch (field) {
        case 0: line["box"][0] = value; break;
        case 1: line["box"][3] = value; break;
        case 2: line["moves"].back()[0] = value; break;
        default: line["box"][1] = value; break;
    }
    const SceneParse<T> parsed = parseScene<T>(line.dump());
    RC_ASSERT(!parsed.scene.has_value());
    RC_ASSERT(!parsed.error.empty());
    RC_ASSERT(parsed.error.find(field == 2 ? "move" : "box") != std::string::npos);
}

RC_GTEST_PROP(BadInput, corruptedFloatSceneIsRejected, ()) { checkCorruptedSceneIsRejected<float>(); }
RC_GTEST_PROP(BadInput, corruptedDoubleSceneIsRejected, ()) { checkCorruptedSceneIsRejected<double>(); }

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

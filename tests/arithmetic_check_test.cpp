// SPDX-License-Identifier: MIT
// The floating-point environment check (src/arithmetic_check.cpp): this build passes it, and a
// rounding mode other than to-nearest makes validateTileMap refuse every map, in float and double.
#include "tilesweep/mover.h"
#include "tilesweep/tile_map.h"

#include <gtest/gtest.h>

#include <cfenv>
#include <cstdint>

namespace {

using tilesweep::MapError;

const std::uint8_t kCells[] = {0, 1, 0, 0};

TEST(Arithmetic, thisBuildIsExact) {
    EXPECT_TRUE(tilesweep::isArithmeticExact());
    EXPECT_EQ(tilesweep::validateTileMap(tilesweep::TileMapView<float>{{0, 0}, {16, 16}, 2, 2, kCells}),
              MapError::None);
}

/// Sets a rounding mode for one scope and restores to-nearest after it.
class RoundingMode {
public:
    explicit RoundingMode(int mode) { ok_ = std::fesetround(mode) == 0; }
    ~RoundingMode() { std::fesetround(FE_TONEAREST); }
    RoundingMode(const RoundingMode&) = delete;
    RoundingMode& operator=(const RoundingMode&) = delete;
    [[nodiscard]] bool ok() const { return ok_; }

private:
    bool ok_ = false;
};

TEST(Arithmetic, everyDirectedRoundingModeIsRefused) {
    for (const int mode : {FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO}) {
        bool exact = true;
        MapError floatError = MapError::None;
        MapError doubleError = MapError::None;
        tilesweep::PreparedMap<float> prepared;
        {
            RoundingMode scope(mode);
            ASSERT_TRUE(scope.ok()) << "fesetround(" << mode << ")";
            exact = tilesweep::isArithmeticExact();
            floatError =
                tilesweep::validateTileMap(tilesweep::TileMapView<float>{{0, 0}, {16, 16}, 2, 2, kCells});
            doubleError =
                tilesweep::validateTileMap(tilesweep::TileMapView<double>{{0, 0}, {16, 16}, 2, 2, kCells});
            prepared = tilesweep::prepareMap(tilesweep::TileMapView<float>{{0, 0}, {16, 16}, 2, 2, kCells});
        }
        EXPECT_FALSE(exact) << "mode " << mode;
        EXPECT_EQ(floatError, MapError::InexactArithmetic) << "mode " << mode;
        EXPECT_EQ(doubleError, MapError::InexactArithmetic) << "mode " << mode;
        EXPECT_FALSE(prepared.isValid()) << "mode " << mode;
    }
    EXPECT_TRUE(tilesweep::isArithmeticExact());  // restored
}

TEST(Arithmetic, aBadMapReportsItsOwnErrorFirst) {
    RoundingMode scope(FE_UPWARD);
    ASSERT_TRUE(scope.ok());
    EXPECT_EQ(tilesweep::validateTileMap(tilesweep::TileMapView<float>{{0, 0}, {-1, 16}, 2, 2, kCells}),
              MapError::NonPositiveTileSize);
}

}  // namespace

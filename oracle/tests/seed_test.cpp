// SPDX-License-Identifier: MIT
// The seed article's algorithm as written: what it gets right and the flaws it is kept to show.
// Expected values follow the article's formulas step by step (see seed_resolve.h), with inputs
// chosen so that every float operation is exact unless said otherwise.

#include "scene_builder.h"

#include "tilesweep/oracle/exact/exact_resolve.h"
#include "tilesweep/oracle/seed/seed_resolve.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace tilesweep::oracle {
namespace {

using test::makeMap;
using test::makeScene;

TEST(SeedAlgorithm, landsOnAFloorButDoesNotSlideAndReportsAStrayContact) {
    // Box [4, 16] x [16, 28] moving (16, 32); floor row 3 (y 48..64). Swept bounds x [4, 32].
    // (0, 3): distanceX = 0 - 16 = -16, timeX = -1; distanceY = 48 - 28 = 20, timeY = 5/8;
    // time 5/8; disjoint = min(16 - 4, 64 - 16) = 12; 5/8 <= 12: collided. position =
    // (20, 48) - (3/8)(16, 32) = (14, 36); normal on y (timeX < timeY): (0, -1).
    // (1, 3) = [16, 32]: velocity (10, 20); timeX = (16 - 16)/10 = 0, timeY = 20/20 = 1;
    // time 1, not > 1: collided with time 1, moving back by 0. (2, 3) = [32, 48] is outside the
    // swept bounds (32 is not > 32). Final (14, 36); the contract slides on to (20, 36).
    const auto scene =
        makeScene<float>(makeMap<float>({"....", "....", "....", "####"}), {{4, 16}, {12, 12}}, {{16, 32}});
    const std::vector<FrameResult<float>> frames = resolveSceneSeed(scene);
    ASSERT_EQ(frames.size(), 1U);
    EXPECT_EQ(frames[0].position, (Vec2<float>{14, 36}));
    ASSERT_EQ(frames[0].contacts.size(), 2U);
    EXPECT_EQ(frames[0].contacts[0].tile, (Cell{0, 3}));
    EXPECT_EQ(frames[0].contacts[0].normal, (Normal{0, -1}));
    EXPECT_EQ(frames[0].contacts[0].time, 0.625f);
    EXPECT_EQ(frames[0].contacts[1].tile, (Cell{1, 3}));
    EXPECT_EQ(frames[0].contacts[1].time, 1.0f);
    EXPECT_TRUE(frames[0].startOverlaps.empty());
    EXPECT_EQ(resolveSceneExactRounded(scene).at(0).position, (Vec2<float>{20, 36}));
}

TEST(SeedAlgorithm, zeroVelocityAxisDividesByZeroAndTunnels) {
    // Box [4, 18] moving (200, 0) toward tile (5, 1) = [80, 96] x [16, 32]: velocity.y = +0, so
    // distanceY = 32 - 18 = 14 and timeY = 14/0 = +inf > 1: not collided. The box passes the wall.
    const auto scene = makeScene<float>(makeMap<float>({"..........", ".....#....", ".........."}),
                                        {{4, 18}, {10, 10}}, {{200, 0}});
    const FrameResult<float> frame = resolveSceneSeed(scene).at(0);
    EXPECT_EQ(frame.position, (Vec2<float>{204, 18}));
    EXPECT_TRUE(frame.contacts.empty());
}

TEST(SeedAlgorithm, fallingStraightDownFallsThroughTheFloor) {
    // Box [4, 12] x [0, 8] moving (0, 20) onto tile (0, 1) = [0, 16] x [16, 32]: velocity.x = +0,
    // distanceX = 16 - 4 = 12, timeX = +inf: never collided. It ends inside the floor at (4, 20).
    const auto scene = makeScene<float>(makeMap<float>({"...", "###"}), {{4, 0}, {8, 8}}, {{0, 20}});
    EXPECT_EQ(resolveSceneSeed(scene).at(0).position, (Vec2<float>{4, 20}));
}

TEST(SeedAlgorithm, movingLeftPassesThroughWallsBecauseDisjointIsADistance) {
    // Box [40, 48] x [4, 12] moving (-40, 1/2) toward tile (0, 0) = [0, 16]^2. timeX =
    // (16 - 40)/-40 = 3/5, timeY = (0 - 12)/(1/2) = -24: time 3/5. disjointX = 0 - 48 = -48:
    // 3/5 > -48, not collided. The contract stops it at x = 16 at t = 3/5.
    const auto scene = makeScene<float>(makeMap<float>({"#...."}), {{40, 4}, {8, 8}}, {{-40, 0.5f}});
    EXPECT_EQ(resolveSceneSeed(scene).at(0).position, (Vec2<float>{0, 4.5f}));
    EXPECT_EQ(resolveSceneExactRounded(scene).at(0).position.x, 16.0f);
}

TEST(SeedAlgorithm, disjointDistancesLetACornerMissCountAsAHit) {
    // Box [2, 10]^2 moving (60, 7); tile (2, 1) = [32, 48] x [16, 32]. Exactly, x overlaps during
    // (11/30, 23/30) and y from 6/7 on: a corner miss. The article: timeX = 22/60, timeY = 6/7,
    // time 6/7; disjoint = min(48 - 2, 32 - 2) = 30, a distance: 6/7 <= 30, collided. The box is
    // pulled back along the whole velocity: both coordinates end short of (62, 9).
    const auto scene =
        makeScene<float>(makeMap<float>({"......", "..#...", "......"}), {{2, 2}, {8, 8}}, {{60, 7}});
    const FrameResult<float> frame = resolveSceneSeed(scene).at(0);
    ASSERT_EQ(frame.contacts.size(), 1U);
    EXPECT_EQ(frame.contacts[0].tile, (Cell{2, 1}));
    EXPECT_EQ(frame.contacts[0].normal, (Normal{0, -1}));
    EXPECT_EQ(frame.contacts[0].time, 6.0f / 7.0f);
    EXPECT_LT(frame.position.x, 62.0f);
    EXPECT_LT(frame.position.y, 9.0f);
    EXPECT_TRUE(resolveSceneExact(scene).at(0).contacts.empty());
}

TEST(SeedAlgorithm, overflowGivesAnInfinitePositionAndLaterFramesCarryOn) {
    // 2^127 + FLT_MAX overflows float: the article's position becomes +inf, and the next frames
    // compute with it without crashing. The contract rounds toward the start: FLT_MAX.
    constexpr float kMax = std::numeric_limits<float>::max();
    const auto scene =
        makeScene<float>(makeMap<float>({"#"}), {{0x1p127f, 0}, {1, 1}}, {{kMax, 0}, {-1, 0}, {1, 1}});
    const std::vector<FrameResult<float>> frames = resolveSceneSeed(scene);
    ASSERT_EQ(frames.size(), 3U);
    EXPECT_TRUE(std::isinf(frames[0].position.x));
    EXPECT_FALSE(std::isfinite(frames[2].position.x));
    EXPECT_EQ(resolveSceneExactRounded(scene).at(0).position.x, kMax);
}

TEST(SeedAlgorithm, nanInputGivesANanPositionWithoutCrashing) {
    // The scene reader refuses NaN; fed one anyway, velocity.x is NaN, timeX = NaN, std::max
    // keeps the NaN (its first argument), !(NaN > disjoint) is true, and the response writes NaN.
    const auto scene = makeScene<float>(makeMap<float>({"..", "##"}), {{4, 4}, {8, 8}},
                                        {{std::numeric_limits<float>::quiet_NaN(), 8}, {1, 1}});
    const std::vector<FrameResult<float>> frames = resolveSceneSeed(scene);
    ASSERT_EQ(frames.size(), 2U);
    EXPECT_TRUE(std::isnan(frames[0].position.x));
    EXPECT_TRUE(std::isnan(frames[1].position.x));
}

}  // namespace
}  // namespace tilesweep::oracle

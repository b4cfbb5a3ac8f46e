// SPDX-License-Identifier: MIT
// Hand-worked one-way cases of the exact reference. Every expected value below is derived in the
// comment above it from docs/contract.md ("One-way tiles"): a '-' tile blocks only a step with
// r_y > 0 whose box bottom starts at or above the tile's top, and then when I meets (0, 1) and
// entry_y >= entry_x, at entry_y, on y, with normal (0, -1). Tiles are 16 x 16 at the origin
// unless said otherwise, so tile (i, j) is [16i, 16i + 16] x [16j, 16j + 16].

#include "exact_expectations.h"
#include "scene_builder.h"

#include "tilesweep/oracle/exact/exact_resolve.h"
#include "tilesweep/oracle/exact/exact_sweep.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

namespace tilesweep::oracle {
namespace {

using test::makeMap;
using test::makeScene;

using test::expectContacts;
using test::Expected;
using test::expectPosition;
using test::onlyFrame;
using test::ratio;

ExactBox exactBox(std::int64_t x, std::int64_t y, std::int64_t w, std::int64_t h) {
    return {{Rational(x), Rational(y)}, {Rational(w), Rational(h)}};
}

// ---- the map ----------------------------------------------------------------------------------

TEST(ExactOneWayMap, holdsTheScenesCellKindsAndDropsThemOnRequest) {
    // "#-." gives solid, one-way, empty; outside the map is empty. Only '#' is solid (hides a
    // face); withoutOneWay turns '-' into '.' and leaves '#'.
    const ExactTileMap map = toExact(makeMap<float>({"#-."}));
    EXPECT_EQ(map.kind(0, 0), CellKind::Solid);
    EXPECT_EQ(map.kind(1, 0), CellKind::OneWay);
    EXPECT_EQ(map.kind(2, 0), CellKind::Empty);
    EXPECT_EQ(map.kind(-1, 0), CellKind::Empty);
    EXPECT_EQ(map.kind(1, 1), CellKind::Empty);
    EXPECT_TRUE(map.isSolid(0, 0));
    EXPECT_FALSE(map.isSolid(1, 0));
    EXPECT_TRUE(map.isOneWay(1, 0));
    const ExactTileMap dropped = map.withoutOneWay();
    EXPECT_EQ(dropped.kind(0, 0), CellKind::Solid);
    EXPECT_EQ(dropped.kind(1, 0), CellKind::Empty);
}

// ---- one one-way tile, directly ---------------------------------------------------------------

TEST(ExactOneWaySweep, cornerLandingBlocksOnYWhateverTheExposureFlagsSay) {
    // Box [0, 10]^2 moving (20, 20) against [16, 32]^2: x entry (16 - 10)/20 = 3/10, y entry
    // (16 - 10)/20 = 3/10, exits 8/5: I = (3/10, 8/5). entry_y >= entry_x: blocks at 3/10 on y, a
    // tie. A solid tile with only its x face exposed would take x; a one-way tile's top is its
    // only face.
    const ExactSweepInput input{exactBox(0, 0, 10, 10),
                                {Rational(20), Rational(20)},
                                {{Rational(16), Rational(16)}, {Rational(32), Rational(32)}},
                                true,
                                false};
    const ExactSweepOutput solid = sweepTileExact(input);
    ASSERT_EQ(solid.state, ExactSweepState::Blocks);
    EXPECT_EQ(solid.axis, Axis::X);
    const ExactSweepOutput oneWay = sweepOneWayTileExact(input);
    ASSERT_EQ(oneWay.state, ExactSweepState::Blocks);
    EXPECT_EQ(oneWay.axis, Axis::Y);
    EXPECT_TRUE(oneWay.tie);
    EXPECT_EQ(oneWay.time, ratio(3, 10));
}

TEST(ExactOneWaySweep, neverBlocksAMoveUpOrLevelNorABoxStartingInsideIt) {
    const ExactRect tile{{Rational(16), Rational(16)}, {Rational(32), Rational(32)}};
    // Box [18, 28] x [40, 50] moving up 30: y enters at (32 - 40)/-30 = 4/15, x overlaps: a solid
    // tile would block; a move up never does.
    EXPECT_EQ(sweepOneWayTileExact({exactBox(18, 40, 10, 10), {Rational(0), Rational(-30)}, tile}).state,
              ExactSweepState::Misses);
    // Box [0, 10] x [20, 30] moving right 30: x enters at 6/30, y overlaps at all times; level.
    EXPECT_EQ(sweepOneWayTileExact({exactBox(0, 20, 10, 10), {Rational(30), Rational(0)}, tile}).state,
              ExactSweepState::Misses);
    // Box [18, 28] x [20, 30] inside it, moving down: it overlaps at t = 0, its bottom (30) is below
    // the top (16): never blocks, and is not StartsOverlapping either (not a start overlap).
    const ExactSweepOutput inside =
        sweepOneWayTileExact({exactBox(18, 20, 10, 10), {Rational(0), Rational(5)}, tile});
    EXPECT_EQ(inside.state, ExactSweepState::Misses);
    EXPECT_TRUE(inside.overlap.contains(Rational(0)));
}

// ---- one frame through a map ------------------------------------------------------------------

TEST(ExactOneWay, fallingBoxLandsOnAPlatform) {
    // Platform row 2: (1, 2) = [16, 32] x [32, 48], (2, 2) = [32, 48] x [32, 48]. Box [20, 30] x
    // [10, 20] moving (0, 40): bottom 20 <= 32, r_y > 0. x still, overlapping (1, 2): all times;
    // y entry (32 - 20)/40 = 3/10, exit (48 - 10)/40 = 19/20. Blocks at 3/10 on y, normal (0, -1).
    // (2, 2): x [20, 30] does not overlap [32, 48], x still: I empty. p = (20, 22); r = (7/10)(0,
    // 40) with y zeroed = 0. Final (20, 22).
    const ExactFrame frame = onlyFrame(
        makeScene<float>(makeMap<float>({"....", "....", ".--.", "...."}), {{20, 10}, {10, 10}}, {{0, 40}}));
    expectContacts(frame, {{{1, 2}, {0, -1}, ratio(3, 10), 1}});
    EXPECT_FALSE(frame.contacts[0].tie);
    expectPosition(frame, Rational(20), Rational(22));
    EXPECT_TRUE(frame.startOverlaps.empty());
}

TEST(ExactOneWay, diagonalLandingAcrossASeamThenWalksAlongTheTop) {
    // As above moving (16, 40). (1, 2): x entry (16 - 30)/16 = -7/8, exit (32 - 20)/16 = 3/4; y
    // entry 3/10: I = (3/10, 3/4), entry_y >= entry_x: blocks at 3/10. (2, 2): x entry
    // (32 - 30)/16 = 1/8 <= 3/10, exit (48 - 20)/16 = 7/4: I = (3/10, 19/20): blocks at 3/10.
    // H = both, normals (0, -1). p = (20 + 24/5, 22); r = (7/10)(16, 40) -> (56/5, 0). Step 2 is
    // level: no one-way tile blocks it. Final (36, 22).
    const ExactFrame frame = onlyFrame(
        makeScene<float>(makeMap<float>({"....", "....", ".--.", "...."}), {{20, 10}, {10, 10}}, {{16, 40}}));
    expectContacts(frame, {{{1, 2}, {0, -1}, ratio(3, 10), 1}, {{2, 2}, {0, -1}, ratio(3, 10), 1}});
    expectPosition(frame, Rational(36), Rational(22));
}

TEST(ExactOneWay, jumpsUpThroughAPlatformThenLandsOnIt) {
    // Frame 1: box [20, 30] x [50, 60] moving (0, -40): r_y < 0, the platform (1, 2) never blocks.
    // Final (20, 10), no contacts, no start overlaps. Frame 2 from (20, 10) moving (0, 30): bottom
    // 20 <= 32, y entry (32 - 20)/30 = 2/5, x all times: blocks at 2/5; final (20, 22).
    const auto scene = makeScene<float>(makeMap<float>({"....", "....", ".--.", "...."}),
                                        {{20, 50}, {10, 10}}, {{0, -40}, {0, 30}});
    const std::vector<ExactFrame> frames = resolveSceneExact(scene);
    ASSERT_EQ(frames.size(), 2U);
    expectContacts(frames[0], {});
    expectPosition(frames[0], Rational(20), Rational(10));
    EXPECT_TRUE(frames[0].startOverlaps.empty());
    expectContacts(frames[1], {{{1, 2}, {0, -1}, ratio(2, 5), 1}});
    expectPosition(frames[1], Rational(20), Rational(22));
}

TEST(ExactOneWay, jumpThatStopsInsideAPlatformFallsBackThrough) {
    // Box [20, 30] x [30, 40] (bottom 40 below the platform's top 32) moving (0, 10): the bottom is
    // below the top at the step's start, so it never blocks. Final (20, 40); the platform is not a
    // start overlap though the box overlaps it.
    const ExactFrame frame = onlyFrame(
        makeScene<float>(makeMap<float>({"....", "....", ".--.", "...."}), {{20, 30}, {10, 10}}, {{0, 10}}));
    expectContacts(frame, {});
    expectPosition(frame, Rational(20), Rational(40));
    EXPECT_TRUE(frame.startOverlaps.empty());
}

TEST(ExactOneWay, bottomAHairBelowTheTopPassesThroughAndExactlyOnItLands) {
    // Platform (1, 2), top 32. Box height 10 at y = 22 + 2^-19 (the float after 22): bottom
    // 32 + 2^-19 > 32, so moving (0, 10) it passes: final y = 32 + 2^-19 exactly, no contact.
    // At y = 22 exactly the bottom is on the top: y entry 0, x all times: blocks at 0, stays.
    const float hair = 0x1p-19f;
    const auto map = makeMap<float>({"....", "....", ".--.", "...."});
    const ExactFrame below = onlyFrame(makeScene<float>(map, {{20, 22 + hair}, {10, 10}}, {{0, 10}}));
    expectContacts(below, {});
    expectPosition(below, Rational(20), Rational(32) + ratio(1, 1 << 19));
    const ExactFrame on = onlyFrame(makeScene<float>(map, {{20, 22}, {10, 10}}, {{0, 10}}));
    expectContacts(on, {{{1, 2}, {0, -1}, Rational(0), 1}});
    expectPosition(on, Rational(20), Rational(22));
}

TEST(ExactOneWay, boxFallingIntoThePlatformsSideFallsThrough) {
    // Platform (1, 1) = [16, 32] x [16, 32]. Box [0, 10]^2 moving (20, 40): bottom 10 <= 16 and
    // r_y > 0, but x entry (16 - 10)/20 = 3/10 > y entry (16 - 10)/40 = 3/20: it enters through
    // the side. Final (20, 40), no contact. Moving level (30, 0) from [0, 10] x [20, 30] the step
    // is not down: final (30, 20).
    const auto map = makeMap<float>({"....", ".-.."});
    const ExactFrame falling = onlyFrame(makeScene<float>(map, {{0, 0}, {10, 10}}, {{20, 40}}));
    expectContacts(falling, {});
    expectPosition(falling, Rational(20), Rational(40));
    const ExactFrame level = onlyFrame(makeScene<float>(map, {{0, 20}, {10, 10}}, {{30, 0}}));
    expectContacts(level, {});
    expectPosition(level, Rational(30), Rational(20));
}

TEST(ExactOneWay, exactCornerLandingBlocksOnY) {
    // Platform (1, 1); box [0, 10]^2 moving (20, 20): x and y entry both 3/10 (exits 8/5). A tie:
    // blocks on y, normal (0, -1). p = (6, 6); r = (7/10)(20, 20) -> (14, 0); step 2 walks along
    // the top: final (20, 6).
    const ExactFrame frame =
        onlyFrame(makeScene<float>(makeMap<float>({"....", ".-.."}), {{0, 0}, {10, 10}}, {{20, 20}}));
    expectContacts(frame, {{{1, 1}, {0, -1}, ratio(3, 10), 1}});
    EXPECT_TRUE(frame.contacts[0].tie);
    expectPosition(frame, Rational(20), Rational(6));
}

TEST(ExactOneWay, platformBesideASolidTileDoesNotHideItsFace) {
    // Solid (1, 1) = [16, 32]^2 with a platform (1, 0) above it. Box [0, 10]^2 moving (20, 20):
    // the platform: bottom 10 > its top 0, never blocks. (1, 1): x and y entry 3/10, a tie. Its x
    // face's neighbour (0, 1) is empty and its y face's, (1, 0), holds '-', which counts as
    // empty: both exposed, so y, normal (0, -1). (Were '-' to hide the top, only x would be
    // exposed and the axis would be x.) p = (6, 6); r -> (14, 0); final (20, 6).
    const ExactFrame frame =
        onlyFrame(makeScene<float>(makeMap<float>({".-..", ".#.."}), {{0, 0}, {10, 10}}, {{20, 20}}));
    expectContacts(frame, {{{1, 1}, {0, -1}, ratio(3, 10), 1}});
    EXPECT_TRUE(frame.contacts[0].tie);
    expectPosition(frame, Rational(20), Rational(6));

    // The same with '#' above: (1, 0) = [16, 32] x [0, 16] blocks on x at 3/10 (x entry 3/10, y
    // overlapping from -1/2 to 4/5); (1, 1) ties with its y face hidden and its x face exposed: x.
    // Both normals (-1, 0); p = (6, 6); r -> (0, 14); step 2 slides down beside the column:
    // final (6, 20).
    const ExactFrame solidAbove =
        onlyFrame(makeScene<float>(makeMap<float>({".#..", ".#.."}), {{0, 0}, {10, 10}}, {{20, 20}}));
    expectContacts(solidAbove, {{{1, 0}, {-1, 0}, ratio(3, 10), 1}, {{1, 1}, {-1, 0}, ratio(3, 10), 1}});
    expectPosition(solidAbove, Rational(6), Rational(20));
}

TEST(ExactOneWay, startedOverlappingListsSolidTilesOnly) {
    // Box [10, 20] x [4, 12] overlaps the platform (0, 0) = [0, 16]^2 and the solid (1, 0) =
    // [16, 32]^2. Only (1, 0) is a start overlap. Moving (0, 20): the platform's top 0 is above
    // the bottom 12, it never blocks; (1, 0) was overlapped at the start, it never blocks. Final
    // (10, 24). Standing still: the same start overlaps, no contact.
    const auto map = makeMap<float>({"-#", ".."});
    const ExactFrame falling = onlyFrame(makeScene<float>(map, {{10, 4}, {10, 8}}, {{0, 20}}));
    ASSERT_EQ(falling.startOverlaps.size(), 1U);
    EXPECT_EQ(falling.startOverlaps[0], (Cell{1, 0}));
    expectContacts(falling, {});
    expectPosition(falling, Rational(10), Rational(24));
    const ExactFrame still = onlyFrame(makeScene<float>(map, {{10, 4}, {10, 8}}, {{0, 0}}));
    ASSERT_EQ(still.startOverlaps.size(), 1U);
    EXPECT_EQ(still.startOverlaps[0], (Cell{1, 0}));
    // A platform alone, overlapped: no start overlap at all.
    const ExactFrame alone =
        onlyFrame(makeScene<float>(makeMap<float>({"--", ".."}), {{10, 4}, {10, 8}}, {{0, 0}}));
    EXPECT_TRUE(alone.startOverlaps.empty());
}

TEST(ExactOneWay, longFastFallThroughThinPlatformsLandsOnTheFirst) {
    // Tiles 16 x 2: row j is [2j, 2j + 2]. Platforms in rows 10, 20 and 30 (tops 20, 40, 60).
    // Box [18, 28] x [0, 4] moving (0, 1000), 250 platform thicknesses in one frame. x still and
    // inside column 1. Row 10: y entry (20 - 4)/1000 = 2/125; rows 20 and 30 at 9/250 and 7/125,
    // later. s = 2/125, H = {(1, 10)}; p = (18, 16), r -> 0. Frame 2 from there, the same move:
    // bottom 20 on the top 20, y entry 0: blocks at 0, stays.
    std::vector<std::string> rows(40, "...");
    rows[10] = rows[20] = rows[30] = "---";
    const auto scene =
        makeScene<float>(makeMap<float>(rows, {0, 0}, {16, 2}), {{18, 0}, {10, 4}}, {{0, 1000}, {0, 1000}});
    const std::vector<ExactFrame> frames = resolveSceneExact(scene);
    ASSERT_EQ(frames.size(), 2U);
    expectContacts(frames[0], {{{1, 10}, {0, -1}, ratio(2, 125), 1}});
    expectPosition(frames[0], Rational(18), Rational(16));
    expectContacts(frames[1], {{{1, 10}, {0, -1}, Rational(0), 1}});
    expectPosition(frames[1], Rational(18), Rational(16));
}

TEST(ExactOneWay, walkingAlongARowOfPlatformsIsNeverBlockedOnX) {
    // Platforms along row 1 (top 16); box [x, x + 10] x [6, 16] standing on them, moving (6, 3)
    // each frame: from x = 0 it crosses a seam every few frames. Each tile whose x range strictly
    // overlaps [x, x + 10] has y entry (16 - 16)/3 = 0 and an x interval containing 0: it blocks
    // at 0 on y. So does the tile whose left edge the box's right edge touches (16i = x + 10):
    // x entry 0 = y entry, entry_y >= entry_x. The tile the left edge touches has x exit 0: I is
    // empty. Tiles further right have x entry > 0 = y entry: they never block (side entry). H
    // = those tiles at time 0, normal (0, -1); r = (6, 0); step 2 is level: x + 6, y stays 6.
    constexpr int kFrames = 20;
    const auto scene = makeScene<float>(makeMap<float>({std::string(10, '.'), std::string(10, '-')}),
                                        {{0, 6}, {10, 10}}, std::vector<Vec2<float>>(kFrames, {6, 3}));
    const std::vector<ExactFrame> frames = resolveSceneExact(scene);
    ASSERT_EQ(frames.size(), static_cast<std::size_t>(kFrames));
    for (int k = 0; k < kFrames; ++k) {
        SCOPED_TRACE("frame " + std::to_string(k));
        const std::int32_t x = 6 * k;
        std::vector<Expected> expected;
        for (std::int32_t i = 0; i < 10; ++i) {
            if (16 * i <= x + 10 && 16 * i + 16 > x) {
                expected.push_back({{i, 1}, {0, -1}, Rational(0), 1});
            }
        }
        const auto f = static_cast<std::size_t>(k);
        EXPECT_EQ(frames[f].start.x, Rational(x));
        expectContacts(frames[f], expected);
        expectPosition(frames[f], Rational(x + 6), Rational(6));
    }

    // Sunk into the row (bottom 20 below the tops), walking with gravity: no platform blocks at
    // all, and the box falls through as it walks: final (60, 10 + 20).
    const ExactFrame sunk = onlyFrame(makeScene<float>(
        makeMap<float>({std::string(10, '.'), std::string(10, '-')}), {{0, 10}, {10, 10}}, {{60, 20}}));
    expectContacts(sunk, {});
    expectPosition(sunk, Rational(60), Rational(30));
}

TEST(ExactOneWay, droppingThroughIgnoresEveryPlatform) {
    // Standing on the platform (1, 2) (box [20, 30] x [22, 32]) and moving (0, 30): with the
    // platforms it blocks at 0; on map.withoutOneWay() nothing blocks (the floor row 4, top 64,
    // would be reached at (64 - 32)/30 > 1) and it falls to y = 52. The solid floor stays solid:
    // moving (0, 60) it lands at (64 - 32)/60 = 8/15, at y = 54.
    const ExactTileMap map = toExact(makeMap<float>({"....", "....", ".--.", "....", "####"}));
    const ExactBox box = exactBox(20, 22, 10, 10);
    expectContacts(resolveFrameExact(map, box, {Rational(0), Rational(30)}),
                   {{{1, 2}, {0, -1}, Rational(0), 1}});
    const ExactFrame dropped = resolveFrameExact(map.withoutOneWay(), box, {Rational(0), Rational(30)});
    expectContacts(dropped, {});
    expectPosition(dropped, Rational(20), Rational(52));
    const ExactFrame toFloor = resolveFrameExact(map.withoutOneWay(), box, {Rational(0), Rational(60)});
    expectContacts(toFloor, {{{1, 4}, {0, -1}, ratio(8, 15), 1}});
    expectPosition(toFloor, Rational(20), Rational(54));
}

TEST(ExactOneWay, platformAndWallHitAtOnceStopBothAxes) {
    // Platform (1, 1) = [16, 32]^2 and wall (2, 0) = [32, 48] x [0, 16]. Box [12, 22] x [0, 10]
    // moving (20, 20). Platform: bottom 10 <= 16; x overlapping from the start; y entry 6/20 =
    // 3/10: blocks at 3/10 on y. Wall: x entry (32 - 22)/20 = 1/2, later. p = (18, 6); r -> (14,
    // 0). Step 2 from [18, 28] x [6, 16]: the wall's x entry (32 - 28)/14 = 2/7, y overlapping:
    // blocks on x, normal (-1, 0), frame time 3/10 + (2/7)(7/10) = 1/2. p = (22, 6).
    const ExactFrame frame =
        onlyFrame(makeScene<float>(makeMap<float>({"..#.", ".-.."}), {{12, 0}, {10, 10}}, {{20, 20}}));
    expectContacts(frame, {{{1, 1}, {0, -1}, ratio(3, 10), 1}, {{2, 0}, {-1, 0}, ratio(1, 2), 2}});
    expectPosition(frame, Rational(22), Rational(6));
}

}  // namespace
}  // namespace tilesweep::oracle

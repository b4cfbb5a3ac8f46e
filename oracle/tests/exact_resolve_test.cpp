// SPDX-License-Identifier: MIT
// Hand-worked cases of the exact reference. Every expected value below is derived in the comment
// above it from docs/contract.md (per-axis open intervals, I, inf I, the tie rule, the two-step
// frame), not taken from the program's output. Tiles are 16 x 16 at the origin unless said
// otherwise, so tile (i, j) is [16i, 16i + 16] x [16j, 16j + 16].

#include "tilesweep/oracle/exact/exact_resolve.h"

#include "exact_expectations.h"
#include "scene_builder.h"

#include "tilesweep/oracle/exact/exact_sweep.h"
#include "tilesweep/oracle/exact/rational_convert.h"

#include <gtest/gtest.h>

#include <cmath>
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

// ---- one tile, directly ---------------------------------------------------------------------

TEST(ExactSweep, movingAxisGivesTheOpenIntervalBetweenTheTwoEdgeMeetings) {
    // Box [0, 10] moving +20 against [30, 40]: entry (30 - 10)/20 = 1, exit (40 - 0)/20 = 2.
    const TimeInterval forward =
        axisOverlapTimes(Rational(0), Rational(10), Rational(20), Rational(30), Rational(40));
    ASSERT_FALSE(forward.empty);
    EXPECT_EQ(forward.low.value, Rational(1));
    EXPECT_EQ(forward.high.value, Rational(2));
    // The same box at 50 moving -20: entry (40 - 50)/-20 = 1/2, exit (30 - 60)/-20 = 3/2.
    const TimeInterval backward =
        axisOverlapTimes(Rational(50), Rational(10), Rational(-20), Rational(30), Rational(40));
    EXPECT_EQ(backward.low.value, ratio(1, 2));
    EXPECT_EQ(backward.high.value, ratio(3, 2));
}

TEST(ExactSweep, stillAxisIsAllTimesOrNone) {
    const TimeInterval inside =
        axisOverlapTimes(Rational(35), Rational(2), Rational(0), Rational(30), Rational(40));
    EXPECT_FALSE(inside.empty);
    EXPECT_EQ(inside.low.kind, ExtendedTime::Kind::NegativeInfinity);
    EXPECT_EQ(inside.high.kind, ExtendedTime::Kind::PositiveInfinity);
    // Touching [20, 30] against [30, 40] is not overlapping.
    EXPECT_TRUE(axisOverlapTimes(Rational(20), Rational(10), Rational(0), Rational(30), Rational(40)).empty);
}

TEST(ExactSweep, stillBoxNeverBlocks) {
    // Zero displacement: I is all times (overlapping) or empty; neither blocks.
    const ExactSweepInput touching{{{Rational(0), Rational(0)}, {Rational(16), Rational(16)}},
                                   {Rational(0), Rational(0)},
                                   {{Rational(16), Rational(0)}, {Rational(32), Rational(16)}}};
    EXPECT_EQ(sweepTileExact(touching).state, ExactSweepState::Misses);
    ExactSweepInput inside = touching;
    inside.box.pos.x = Rational(8);
    EXPECT_EQ(sweepTileExact(inside).state, ExactSweepState::StartsOverlapping);
}

// ---- one frame through a map ----------------------------------------------------------------

TEST(ExactResolve, fastBoxStopsAtAOneTileWall) {
    // Box [4, 14] x [18, 28] moving (200, 0); tile (5, 1) = [80, 96] x [16, 32]. y does not move
    // and overlaps: all times. x entry (80 - 14)/200 = 33/100, exit (96 - 4)/200 = 23/50.
    // Blocks at 33/100 on x, normal (-1, 0); p = (4 + 66, 18); r = (67/100)(200, 0) with x
    // zeroed is 0, so step 2 moves nothing: final (70, 18).
    const auto scene = makeScene<float>(makeMap<float>({"..........", ".....#....", ".........."}),
                                        {{4, 18}, {10, 10}}, {{200, 0}});
    const ExactFrame frame = onlyFrame(scene);
    expectContacts(frame, {{{5, 1}, {-1, 0}, ratio(33, 100), 1}});
    expectPosition(frame, Rational(70), Rational(18));
    const FrameResult<float> rounded = roundFrame<float>(frame);
    EXPECT_EQ(rounded.position, (Vec2<float>{70, 18}));
    EXPECT_EQ(rounded.contacts.at(0).time, 0.33f);  // 33/100 to nearest, as a float literal rounds
}

TEST(ExactResolve, sweptBoundsOverlapButThePathMissesTheCorner) {
    // Box [2, 10] x [40, 48] moving (60, -9); tile (2, 1) = [32, 48] x [16, 32]. The swept
    // bounds reach y = 31 < 32, so they overlap the tile. x: (22/60, 46/60) = (11/30, 23/30);
    // y moving up: entry (32 - 40)/-9 = 8/9, exit (16 - 48)/-9 = 32/9. 8/9 > 23/30: I is empty.
    const auto scene = makeScene<float>(makeMap<float>({"......", "..#...", "......", "......"}),
                                        {{2, 40}, {8, 8}}, {{60, -9}});
    const ExactFrame frame = onlyFrame(scene);
    expectContacts(frame, {});
    expectPosition(frame, Rational(62), Rational(31));
}

TEST(ExactResolve, pathClippingTheCornerHitsTheBottomFace) {
    // As above with dy = -11: y entry (32 - 40)/-11 = 8/11 < 23/30 = x exit, and 8/11 > 11/30:
    // I = (8/11, 23/30), blocks at 8/11 on y (the later entry), moving up: normal (0, 1).
    // p = (2 + 60*8/11, 32) = (502/11, 32); r = (3/11)(60, -11) with y zeroed = (180/11, 0);
    // step 2 slides along y = 32 (touching the tile's bottom, y does not move): no blocker.
    const auto scene = makeScene<float>(makeMap<float>({"......", "..#...", "......", "......"}),
                                        {{2, 40}, {8, 8}}, {{60, -11}});
    const ExactFrame frame = onlyFrame(scene);
    expectContacts(frame, {{{2, 1}, {0, 1}, ratio(8, 11), 1}});
    expectPosition(frame, Rational(62), Rational(32));
}

TEST(ExactResolve, pathExactlyThroughACornerPointDoesNotBlock) {
    // Box [16, 24] x [48, 56] moving (32, -32); tile (1, 1) = [16, 32] x [16, 32].
    // x: entry (16 - 24)/32 = -1/4, exit (32 - 16)/32 = 1/2. y: entry (32 - 48)/-32 = 1/2,
    // exit (16 - 56)/-32 = 5/4. I = (1/2, 1/2) is empty: at t = 1/2 the box's corner touches
    // the tile's corner (32, 32), and touching is not overlapping.
    const auto scene =
        makeScene<float>(makeMap<float>({"....", ".#..", "....", "...."}), {{16, 48}, {8, 8}}, {{32, -32}});
    const ExactFrame frame = onlyFrame(scene);
    expectContacts(frame, {});
    expectPosition(frame, Rational(48), Rational(16));
}

// Exact corner ties: box [8, 16]^2 moving (32, 32) into tile (2, 2) = [32, 48]^2. Both axes
// enter at (32 - 16)/32 = 1/2. Moving +x the x face's neighbour is (1, 2); moving +y the y
// face's neighbour is (2, 1).
const std::vector<std::string> kTieMapBothExposed{"....", "....", "..#.", "...."};
const std::vector<std::string> kTieMapOnlyXExposed{"....", "..#.", "..#.", "...."};  // (2, 1) solid
const std::vector<std::string> kTieMapOnlyYExposed{"....", "....", ".##.", "...."};  // (1, 2) solid
const std::vector<std::string> kTieMapNoneExposed{"....", "..#.", ".##.", "...."};   // both solid

TEST(ExactResolve, cornerTieWithBothFacesExposedPicksY) {
    // H = {(2, 2)}, tie, both exposed: y, normal (0, -1). p = (24, 24); r = (16, 16) -> (16, 0).
    // Step 2: y range [24, 32] touches the tile's top: no overlap at any time. Final (40, 24).
    const ExactFrame frame =
        onlyFrame(makeScene<float>(makeMap<float>(kTieMapBothExposed), {{8, 8}, {8, 8}}, {{32, 32}}));
    expectContacts(frame, {{{2, 2}, {0, -1}, ratio(1, 2), 1}});
    EXPECT_TRUE(frame.contacts.at(0).tie);
    expectPosition(frame, Rational(40), Rational(24));
}

TEST(ExactResolve, cornerTieWithOnlyTheXFaceExposedPicksX) {
    // (2, 1) = [32, 48] x [16, 32]: x entry 1/2; y entry (16 - 16)/32 = 0, exit (32 - 8)/32 = 3/4:
    // I = (1/2, 3/4), blocks at 1/2 on x (no tie). (2, 2): tie, x face exposed ((1, 2) empty),
    // y face not ((2, 1) solid): x. H = both, by row: (2, 1), (2, 2), normals (-1, 0).
    // p = (24, 24); r = (16, 16) -> (0, 16); step 2: x range [24, 32] touches x = 32: no
    // blocker. Final (24, 40).
    const ExactFrame frame =
        onlyFrame(makeScene<float>(makeMap<float>(kTieMapOnlyXExposed), {{8, 8}, {8, 8}}, {{32, 32}}));
    expectContacts(frame, {{{2, 1}, {-1, 0}, ratio(1, 2), 1}, {{2, 2}, {-1, 0}, ratio(1, 2), 1}});
    expectPosition(frame, Rational(24), Rational(40));
}

TEST(ExactResolve, cornerTieWithOnlyTheYFaceExposedPicksY) {
    // (1, 2) = [16, 32] x [32, 48]: x entry (16 - 16)/32 = 0, exit 3/4; y entry 1/2: blocks at
    // 1/2 on y. (2, 2): tie, x face not exposed ((1, 2) solid), y exposed: y. H by row then
    // column: (1, 2), (2, 2), normals (0, -1). p = (24, 24); r -> (16, 0); final (40, 24).
    const ExactFrame frame =
        onlyFrame(makeScene<float>(makeMap<float>(kTieMapOnlyYExposed), {{8, 8}, {8, 8}}, {{32, 32}}));
    expectContacts(frame, {{{1, 2}, {0, -1}, ratio(1, 2), 1}, {{2, 2}, {0, -1}, ratio(1, 2), 1}});
    expectPosition(frame, Rational(40), Rational(24));
}

TEST(ExactResolve, cornerTieWithNeitherFaceExposedPicksYAndBothAxesStop) {
    // (2, 1) blocks on x at 1/2, (1, 2) on y at 1/2, (2, 2) ties with neither face exposed: y.
    // A = {x, y}: r becomes 0, step 2 moves nothing. Final (24, 24). Order: row 1, then row 2.
    const ExactFrame frame =
        onlyFrame(makeScene<float>(makeMap<float>(kTieMapNoneExposed), {{8, 8}, {8, 8}}, {{32, 32}}));
    expectContacts(frame, {{{2, 1}, {-1, 0}, ratio(1, 2), 1},
                           {{1, 2}, {0, -1}, ratio(1, 2), 1},
                           {{2, 2}, {0, -1}, ratio(1, 2), 1}});
    expectPosition(frame, Rational(24), Rational(24));
}

TEST(ExactResolve, cornerTieMovingUpLeftLooksAtTheRightAndBottomNeighbours) {
    // Box [48, 56]^2 moving (-32, -32) into tile (1, 1) = [16, 32]^2: x entry (32 - 48)/-32 =
    // 1/2, y likewise: a tie. Moving -x the face's neighbour is (2, 1), solid here, so x is not
    // exposed; moving -y it is (1, 2), empty: y, normal (0, 1). (2, 1) = [32, 48] x [16, 32]:
    // x entry (48 - 48)/-32 = 0, exit (32 - 56)/-32 = 3/4; y entry 1/2: blocks at 1/2 on y.
    // p = (32, 32); r = (-16, -16) -> (-16, 0); step 2 slides under the row: final (16, 32).
    const ExactFrame frame = onlyFrame(
        makeScene<float>(makeMap<float>({"....", ".##.", "....", "...."}), {{48, 48}, {8, 8}}, {{-32, -32}}));
    expectContacts(frame, {{{1, 1}, {0, 1}, ratio(1, 2), 1}, {{2, 1}, {0, 1}, ratio(1, 2), 1}});
    expectPosition(frame, Rational(16), Rational(32));
}

TEST(ExactResolve, twoStepsFloorThenWallComposeFrameTimes) {
    // Box [20, 30] x [4, 14] moving (50, 30); floor row 2 (y 32..48), wall column 4 (x 64..80)
    // in rows 0 and 1. Floor y entry (32 - 14)/30 = 3/5 for all of row 2. (1, 2): x exit
    // (32 - 20)/50 < 3/5; (2, 2): x exit (48 - 20)/50 = 14/25 < 3/5: both missed. (3, 2): x
    // (9/25, 22/25): blocks at 3/5 on y. (4, 1) and (4, 2): x entry (64 - 30)/50 = 17/25, later.
    // Step 1: p = (50, 22), r = (2/5)(50, 30) -> (20, 0). Step 2: box [50, 60] x [22, 32];
    // (4, 1) = [64, 80] x [16, 32] overlaps on y; x entry (64 - 60)/20 = 1/5. Frame time
    // 3/5 + (1/5)(2/5) = 17/25. p = (54, 22).
    const ExactFrame frame = onlyFrame(
        makeScene<float>(makeMap<float>({"....#", "....#", "#####"}), {{20, 4}, {10, 10}}, {{50, 30}}));
    expectContacts(frame, {{{3, 2}, {0, -1}, ratio(3, 5), 1}, {{4, 1}, {-1, 0}, ratio(17, 25), 2}});
    expectPosition(frame, Rational(54), Rational(22));
}

TEST(ExactResolve, landingAcrossASeamThenSlidingAlongTheFloor) {
    // Frame 1: box [4, 16] x [20, 32] moving (12, 20); floor row 3 (y 48..64). y entry
    // (48 - 32)/20 = 4/5. (0, 3): x (-1, 1) -> I = (4/5, 1); (1, 3): x (0, 7/3) -> I = (4/5, 7/3);
    // (2, 3): x entry (32 - 16)/12 = 4/3 > 1. H = (0, 3), (1, 3) at 4/5, normals (0, -1).
    // p = (4 + 48/5, 36); r = (12/5, 4) -> (12/5, 0); step 2 slides: final (16, 36).
    //
    // Frames 2..: box [x, x + 12] x [36, 48] resting on the floor, moving (12, 4). Every floor
    // tile whose x range strictly overlaps [x, x + 12] has y entry (48 - 48)/4 = 0 and an x
    // interval containing 0, so it blocks at 0. So does the tile whose left edge the box's
    // right edge touches (16i = x + 12): x entry 0 = y entry, an exact tie, its x face's
    // neighbour (i - 1, 3) is solid and its y face's (i, 2) empty, so y. The tile the trailing
    // edge touches has x exit 0: I is empty. Any other blocks later or not at all. H = those
    // tiles, at time 0, normal (0, -1); r = (12, 0); step 2 moves along the floor: x + 12.
    std::vector<Vec2<float>> moves{{12, 20}};
    constexpr int kSlideFrames = 20;
    for (int k = 0; k < kSlideFrames; ++k) {
        moves.push_back({12, 4});
    }
    const auto scene = makeScene<float>(makeMap<float>({std::string(24, '.'), std::string(24, '.'),
                                                        std::string(24, '.'), std::string(24, '#')}),
                                        {{4, 20}, {12, 12}}, moves);
    const std::vector<ExactFrame> frames = resolveSceneExact(scene);
    ASSERT_EQ(frames.size(), moves.size());
    expectContacts(frames[0], {{{0, 3}, {0, -1}, ratio(4, 5), 1}, {{1, 3}, {0, -1}, ratio(4, 5), 1}});
    expectPosition(frames[0], Rational(16), Rational(36));
    for (int k = 1; k <= kSlideFrames; ++k) {
        const std::int32_t x = 16 + 12 * (k - 1);
        std::vector<Expected> expected;
        for (std::int32_t i = 0; i < 24; ++i) {
            if (16 * i <= x + 12 && 16 * i + 16 > x) {
                expected.push_back({{i, 3}, {0, -1}, Rational(0), 1});
            }
        }
        SCOPED_TRACE("frame " + std::to_string(k));
        const auto frame = static_cast<std::size_t>(k);
        EXPECT_EQ(frames[frame].start.x, Rational(x));
        expectContacts(frames[frame], expected);
        expectPosition(frames[frame], Rational(x + 12), Rational(36));
    }
}

TEST(ExactResolve, restingOnAFloorUnderGravityStaysPutFrameAfterFrame) {
    // Box [10, 22] x [17.5, 32] on the floor row 2 (y 32..48), moving (0, 1/2) each frame.
    // Tiles (0, 2) and (1, 2) overlap it on x (all times, x does not move); y entry
    // (32 - 32)/(1/2) = 0: both block at 0 on y, normal (0, -1). r -> 0; the box stays.
    std::vector<Vec2<float>> moves(50, Vec2<float>{0, 0.5f});
    const auto scene =
        makeScene<float>(makeMap<float>({"....", "....", "####"}), {{10, 17.5f}, {12, 14.5f}}, moves);
    const std::vector<ExactFrame> frames = resolveSceneExact(scene);
    for (const ExactFrame& frame : frames) {
        expectContacts(frame, {{{0, 2}, {0, -1}, Rational(0), 1}, {{1, 2}, {0, -1}, Rational(0), 1}});
        expectPosition(frame, Rational(10), ratio(35, 2));
        EXPECT_TRUE(frame.startOverlaps.empty());
    }
    const std::vector<FrameResult<double>> rounded = resolveSceneExactRounded(
        makeScene<double>(makeMap<double>({"....", "....", "####"}), {{10, 17.5}, {12, 14.5}},
                          std::vector<Vec2<double>>(50, Vec2<double>{0, 0.5})));
    for (const FrameResult<double>& frame : rounded) {
        EXPECT_EQ(frame.position, (Vec2<double>{10, 17.5}));
    }
}

TEST(ExactResolve, zeroDisplacementNeverMovesOrHits) {
    // Box [3, 8] x [4, 16] touching the top of row 1 (y = 16), d = 0: both axes still; the
    // tiles touch without overlapping, so I is empty for all of them.
    const ExactFrame frame =
        onlyFrame(makeScene<float>(makeMap<float>({"..", "##"}), {{3, 4}, {5, 12}}, {{0, 0}}));
    expectContacts(frame, {});
    EXPECT_TRUE(frame.startOverlaps.empty());
    expectPosition(frame, Rational(3), Rational(4));
}

TEST(ExactResolve, zeroXVelocityFallingOntoAnEdgeAlignedTile) {
    // Box [16, 32] x [0, 16] moving (0, 100); tile (1, 2) = [16, 32] x [32, 48]: x still and
    // overlapping; y entry (32 - 16)/100 = 4/25. Blocks on y, normal (0, -1); p = (16, 16).
    const ExactFrame frame =
        onlyFrame(makeScene<float>(makeMap<float>({"...", "...", ".#."}), {{16, 0}, {16, 16}}, {{0, 100}}));
    expectContacts(frame, {{{1, 2}, {0, -1}, ratio(4, 25), 1}});
    expectPosition(frame, Rational(16), Rational(16));
}

TEST(ExactResolve, zeroXVelocityBesideATileTouchingItsSideFallsPast) {
    // Box [0, 16]: x still and touching the tile's [16, 32]: no overlap at any time.
    const ExactFrame frame =
        onlyFrame(makeScene<float>(makeMap<float>({"...", "...", ".#."}), {{0, 0}, {16, 16}}, {{0, 100}}));
    expectContacts(frame, {});
    expectPosition(frame, Rational(0), Rational(100));
}

TEST(ExactResolve, boxExactlyAsWideAsAGapDropsThrough) {
    // Box [16, 32] between tiles (0, 2) = [0, 16] and (2, 2) = [32, 48]: touching both on x, x
    // does not move: neither ever overlaps. Final (16, 4 + 40).
    const ExactFrame frame = onlyFrame(
        makeScene<float>(makeMap<float>({"...", "...", "#.#", "..."}), {{16, 4}, {16, 16}}, {{0, 40}}));
    expectContacts(frame, {});
    expectPosition(frame, Rational(16), Rational(44));
}

TEST(ExactResolve, boxWiderThanTheGapLandsOnBothSides) {
    // Box [15.5, 32.5] overlaps both on x; y entry (32 - 20)/40 = 3/10. Final (15.5, 16).
    const ExactFrame frame = onlyFrame(
        makeScene<float>(makeMap<float>({"...", "...", "#.#", "..."}), {{15.5f, 4}, {17, 16}}, {{0, 40}}));
    expectContacts(frame, {{{0, 2}, {0, -1}, ratio(3, 10), 1}, {{2, 2}, {0, -1}, ratio(3, 10), 1}});
    expectPosition(frame, ratio(31, 2), Rational(16));
}

TEST(ExactResolve, nonDyadicFrameTimeOfOneThird) {
    // Box [0, 16] x [2, 10] moving (144, 0); tile (4, 0) = [64, 80] x [0, 16]: x entry
    // (64 - 16)/144 = 1/3. p = (48, 2). The time rounds to nearest like IEEE 1/3.
    const auto floatScene = makeScene<float>(makeMap<float>({"....#"}), {{0, 2}, {16, 8}}, {{144, 0}});
    const ExactFrame frame = onlyFrame(floatScene);
    expectContacts(frame, {{{4, 0}, {-1, 0}, ratio(1, 3), 1}});
    expectPosition(frame, Rational(48), Rational(2));
    EXPECT_EQ(roundFrame<float>(frame).contacts.at(0).time, 1.0f / 3.0f);
    EXPECT_EQ(roundFrame<double>(frame).contacts.at(0).time, 1.0 / 3.0);
}

TEST(ExactResolve, startedOverlappingTileDoesNotBlockAndIsReported) {
    // Box [20, 28] x [20, 28] inside tile (1, 1) = [16, 32]^2, moving (-20, 0): 0 is in I, so
    // it never blocks; the box leaves to (0, 20). Reported in startOverlaps.
    const ExactFrame frame =
        onlyFrame(makeScene<float>(makeMap<float>({"....", ".#..", "...."}), {{20, 20}, {8, 8}}, {{-20, 0}}));
    expectContacts(frame, {});
    ASSERT_EQ(frame.startOverlaps.size(), 1U);
    EXPECT_EQ(frame.startOverlaps[0], (Cell{1, 1}));
    expectPosition(frame, Rational(0), Rational(20));
}

TEST(ExactResolve, startedOverlappingOneTileStillHitsAnother) {
    // Box [8, 16] x [4, 12] overlaps (0, 0) = [0, 16]^2; moving (20, 0) it reaches (2, 0) =
    // [32, 48]: x entry (32 - 16)/20 = 4/5. p = (24, 4).
    const ExactFrame frame =
        onlyFrame(makeScene<float>(makeMap<float>({"#.#"}), {{8, 4}, {8, 8}}, {{20, 0}}));
    expectContacts(frame, {{{2, 0}, {-1, 0}, ratio(4, 5), 1}});
    ASSERT_EQ(frame.startOverlaps.size(), 1U);
    EXPECT_EQ(frame.startOverlaps[0], (Cell{0, 0}));
    expectPosition(frame, Rational(24), Rational(4));
}

TEST(ExactResolve, farFromTheOrigin) {
    // Origin (10^6, 2*10^6); floor row 2 at y = 2000032. Box [1000003.25, +10] x [2000004.5, +10]
    // moving (7.75, 30): y entry (2000032 - 2000014.5)/30 = 7/12. At 7/12 the box's x range is
    // [1000003.25 + 217/48, ...] = [1000007.77.., 1000017.77..], overlapping tiles (0, 2)
    // (x up to 1000016) and (1, 2) (x entry (1000016 - 1000013.25)/7.75 = 11/31 < 7/12).
    // Both on y. Step 2 slides the remaining x: final (1000003.25 + 7.75, 2000022).
    const auto scene = makeScene<float>(makeMap<float>({"......", "......", "######"}, {1000000, 2000000}),
                                        {{1000003.25f, 2000004.5f}, {10, 10}}, {{7.75f, 30}});
    const ExactFrame frame = onlyFrame(scene);
    expectContacts(frame, {{{0, 2}, {0, -1}, ratio(7, 12), 1}, {{1, 2}, {0, -1}, ratio(7, 12), 1}});
    expectPosition(frame, Rational(1000011), Rational(2000022));
    EXPECT_EQ(roundFrame<float>(frame).position, (Vec2<float>{1000011, 2000022}));
}

TEST(ExactResolve, tinyMoveRoundsTowardTheStartAndTheNextFrameStartsThere) {
    // At x = 65540 the float spacing is 2^-7; 65540 + 0.001f lies strictly between 65540 and
    // 65540 + 2^-7, so rounding toward the start gives 65540, and every later frame starts
    // from 65540 again. In double the spacing is 2^-36: the result is the largest double <=
    // the exact sum.
    const auto scene = makeScene<float>(makeMap<float>({"....", "####"}, {65536, 0}, {32, 32}),
                                        {{65540, 10}, {8, 8}}, {{0.001f, 0}, {0.001f, 0}, {0.001f, 0}});
    const std::vector<ExactFrame> frames = resolveSceneExact(scene);
    for (const ExactFrame& frame : frames) {
        EXPECT_EQ(frame.start.x, Rational(65540));
        EXPECT_EQ(frame.position.x, Rational(65540) + toRational(0.001f));
        EXPECT_EQ(roundFrame<float>(frame).position.x, 65540.0f);
    }
    const auto doubleScene = makeScene<double>(makeMap<double>({"....", "####"}, {65536, 0}, {32, 32}),
                                               {{65540, 10}, {8, 8}}, {{0.001, 0}});
    const double x = resolveSceneExactRounded(doubleScene).at(0).position.x;
    const Rational exact = Rational(65540) + toRational(0.001);
    EXPECT_LE(toRational(x), exact);
    EXPECT_GT(toRational(std::nextafter(x, 1e9)), exact);
}

TEST(ExactResolve, contactPositionRoundsToTheFreeSideOfTheFace) {
    // Box x = 0.1f, width 12.3f, moving 60.7f toward tile (3, 1) = [48, 64] x [16, 32] (the box's
    // y range [10.3f, 10.3f + 9.9f] reaches past 16). It stops touching: exact x = 48 - 12.3f,
    // which needs 2^-20 resolution while floats near 35.7 are spaced 2^-18, so the float is the
    // largest one below it: less than one ulp short, never inside the tile.
    const auto scene =
        makeScene<float>(makeMap<float>({"....", "...#"}), {{0.1f, 10.3f}, {12.3f, 9.9f}}, {{60.7f, 0}});
    const ExactFrame frame = onlyFrame(scene);
    const Rational touching = Rational(48) - toRational(12.3f);
    ASSERT_EQ(frame.contacts.size(), 1U);
    EXPECT_EQ(frame.contacts[0].tile, (Cell{3, 1}));
    EXPECT_EQ(frame.contacts[0].normal, (Normal{-1, 0}));
    EXPECT_EQ(frame.contacts[0].time, (touching - toRational(0.1f)) / toRational(60.7f));
    EXPECT_EQ(frame.position.x, touching);
    const float x = roundFrame<float>(frame).position.x;
    EXPECT_LT(toRational(x), touching);
    EXPECT_GT(toRational(std::nextafter(x, 100.0f)), touching);
    EXPECT_EQ(roundFrame<float>(frame).position.y, 10.3f);
}

TEST(ExactResolve, doubleAndFloatScenesGiveTheSameDecisions) {
    // Dyadic inputs are the same numbers in float and double, so the exact frames agree.
    const auto f =
        makeScene<float>(makeMap<float>({"....#", "....#", "#####"}), {{20, 4}, {10, 10}}, {{50, 30}});
    const auto d =
        makeScene<double>(makeMap<double>({"....#", "....#", "#####"}), {{20, 4}, {10, 10}}, {{50, 30}});
    const ExactFrame ef = resolveSceneExact(f).at(0);
    const ExactFrame ed = resolveSceneExact(d).at(0);
    ASSERT_EQ(ef.contacts.size(), ed.contacts.size());
    for (std::size_t k = 0; k < ef.contacts.size(); ++k) {
        EXPECT_EQ(ef.contacts[k].tile, ed.contacts[k].tile);
        EXPECT_EQ(ef.contacts[k].time, ed.contacts[k].time);
    }
    EXPECT_EQ(ef.position.x, ed.position.x);
}

}  // namespace
}  // namespace tilesweep::oracle

// SPDX-License-Identifier: MIT
// The substep oracles: the exact one brackets the exact time of impact whenever the overlap
// window is wider than one substep, and never reports a hit the contract does not have; the
// game-style float one tunnels and misses corners, as a baseline should.

#include "scene_builder.h"

#include "tilesweep/oracle/exact/exact_resolve.h"
#include "tilesweep/oracle/exact/exact_sweep.h"
#include "tilesweep/oracle/substep/substep_float.h"
#include "tilesweep/oracle/substep/substep_oracle.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <iostream>
#include <random>
#include <string>
#include <vector>

namespace tilesweep::oracle {
namespace {

using test::makeMap;
using test::makeScene;

Rational ratio(std::int64_t a, std::int64_t b) { return Rational(a) / Rational(b); }

// ---- hand-worked ----------------------------------------------------------------------------

TEST(SubstepOracle, clippedCornerNeedsSubstepsFinerThanItsWindow) {
    // Box [2, 10] x [40, 48] moving (60, -11) clips tile (2, 1)'s corner during I = (8/11, 23/30),
    // a window of 13/330 < 1/10. N = 10 samples 0.7 and 0.8, both outside: nothing found.
    // N = 100: 73/100 is the first sample inside, and the bracket [72/100, 73/100) holds 8/11.
    const ExactTileMap map = toExact(makeMap<float>({"......", "..#...", "......", "......"}));
    const ExactBox box{{Rational(2), Rational(40)}, {Rational(8), Rational(8)}};
    const ExactVec2 d{Rational(60), Rational(-11)};
    EXPECT_FALSE(findFirstOverlapExact(map, box, d, 10).found());
    const SubstepOverlap fine = findFirstOverlapExact(map, box, d, 100);
    ASSERT_TRUE(fine.found());
    EXPECT_EQ(fine.firstOverlap, 73);
    ASSERT_EQ(fine.tiles.size(), 1U);
    EXPECT_EQ(fine.tiles[0], (Cell{2, 1}));
    EXPECT_LE(fine.bracketLow(), ratio(8, 11));
    EXPECT_LT(ratio(8, 11), fine.bracketHigh());
}

TEST(SubstepOracle, impactExactlyOnASubstepIsSeenAtTheNextOne) {
    // Box [0, 16] x [2, 10] moving (144, 0) against tile (4, 0) = [64, 80]: I = (1/3, 5/9). With
    // N = 6, k = 2 puts the box at [48, 64], touching (not an overlap); k = 3 at [72, 88],
    // overlapping: bracket [1/3, 1/2). With N = 3, k = 1 touches and k = 2 is already past the
    // tile ([96, 112]): the window 2/9 is narrower than 1/3 and the tile is missed.
    const ExactTileMap map = toExact(makeMap<float>({"....#"}));
    const ExactBox box{{Rational(0), Rational(2)}, {Rational(16), Rational(8)}};
    const ExactVec2 d{Rational(144), Rational(0)};
    const SubstepOverlap overlap = findFirstOverlapExact(map, box, d, 6);
    EXPECT_EQ(overlap.firstOverlap, 3);
    EXPECT_EQ(overlap.bracketLow(), ratio(1, 3));
    EXPECT_FALSE(findFirstOverlapExact(map, box, d, 3).found());
}

TEST(SubstepOracle, tilesOverlappedAtTheStartAreNeverReported) {
    // Box inside (1, 1), moving left out of it: nothing else is in the way.
    const ExactTileMap map = toExact(makeMap<float>({"....", ".#..", "...."}));
    const SubstepOverlap overlap = findFirstOverlapExact(
        map, {{Rational(20), Rational(20)}, {Rational(8), Rational(8)}}, {Rational(-20), Rational(0)}, 50);
    EXPECT_FALSE(overlap.found());
    ASSERT_EQ(overlap.startOverlaps.size(), 1U);
    EXPECT_EQ(overlap.startOverlaps[0], (Cell{1, 1}));
}

TEST(SubstepOracle, refusesZeroSubsteps) {
    const ExactTileMap map = toExact(makeMap<float>({"#"}));
    EXPECT_THROW((void)findFirstOverlapExact(map, {{Rational(0), Rational(0)}, {Rational(1), Rational(1)}},
                                             {Rational(1), Rational(1)}, 0),
                 std::invalid_argument);
}

TEST(SubstepResolver, stopsAtTheLastClearSubstepWithAGuessedNormal) {
    // Box [4, 14] x [18, 28] moving (200, 0), N = 20: substep k puts it at 4 + 10k. At k = 7 it is
    // [74, 84], overlapping tile (5, 1) = [80, 96]; at k = 6 it was [64, 74], separated on x only:
    // normal (-1, 0), time 7/20, position of k = 6: (64, 18). (The exact time 33/100 lies in
    // [6/20, 7/20).)
    const auto scene = makeScene<float>(makeMap<float>({"..........", ".....#....", ".........."}),
                                        {{4, 18}, {10, 10}}, {{200, 0}});
    const std::vector<SubstepFrame<float>> frames = resolveSceneSubstep(scene, 20);
    ASSERT_EQ(frames.size(), 1U);
    EXPECT_EQ(frames[0].firstOverlap, 7);
    EXPECT_EQ(frames[0].frame.position, (Vec2<float>{64, 18}));
    ASSERT_EQ(frames[0].frame.contacts.size(), 1U);
    EXPECT_EQ(frames[0].frame.contacts[0].tile, (Cell{5, 1}));
    EXPECT_EQ(frames[0].frame.contacts[0].normal, (Normal{-1, 0}));
    EXPECT_EQ(frames[0].frame.contacts[0].time, 7.0f / 20.0f);
}

TEST(SubstepResolver, freeMotionEndsAtStartPlusDisplacementRoundedTowardTheStart) {
    // Nothing solid: all N substeps are clear; the end is start + d exactly, rounded toward the
    // start: 65540 + 0.001f rounds back to 65540 in float.
    const auto scene = makeScene<float>(makeMap<float>({"...."}, {65536, 0}, {32, 32}), {{65540, 10}, {8, 8}},
                                        {{0.001f, 0}});
    const std::vector<SubstepFrame<float>> frames = resolveSceneSubstep(scene, 7);
    EXPECT_EQ(frames[0].firstOverlap, 0);
    EXPECT_EQ(frames[0].frame.position, (Vec2<float>{65540, 10}));
}

TEST(SubstepFloat, coarseSubstepsTunnelThroughAThinWall) {
    // Box [4, 14] moving 200 toward tile (5, 1) = [80, 96]. N = 4: steps of 50 put it at 54, 104,
    // 154, 204: [54, 64] and [104, 114] both miss [80, 96]; it tunnels to 204. N = 20: steps of
    // 10 (exact in float), [74, 84] overlaps at k = 7: it stops at 64.
    const auto scene = makeScene<float>(makeMap<float>({"..........", ".....#....", ".........."}),
                                        {{4, 18}, {10, 10}}, {{200, 0}});
    const auto coarse = resolveSceneSubstepFloat(scene, 4);
    EXPECT_EQ(coarse[0].firstOverlap, 0);
    EXPECT_EQ(coarse[0].frame.position, (Vec2<float>{204, 18}));
    const auto fine = resolveSceneSubstepFloat(scene, 20);
    EXPECT_EQ(fine[0].firstOverlap, 7);
    EXPECT_EQ(fine[0].frame.position, (Vec2<float>{64, 18}));
}

TEST(SubstepFloat, coarseSubstepsMissAClippedCorner) {
    // The clipped corner of above (window 13/330) with N = 10: samples at 0.7 and 0.8 miss it,
    // and the box ends at start + d although the contract hits the tile at 8/11.
    const auto scene = makeScene<float>(makeMap<float>({"......", "..#...", "......", "......"}),
                                        {{2, 40}, {8, 8}}, {{60, -11}});
    const auto frames = resolveSceneSubstepFloat(scene, 10);
    EXPECT_EQ(frames[0].firstOverlap, 0);
    EXPECT_TRUE(frames[0].frame.contacts.empty());
    EXPECT_EQ(resolveSceneExact(scene).at(0).contacts.size(), 1U);
}

// ---- one-way tiles, hand-worked ---------------------------------------------------------------

TEST(SubstepOracle, landingOnAPlatformIsBracketed) {
    // Platform (1, 2) = [16, 32] x [32, 48]; box [20, 30] x [10, 20] moving (0, 40): the exact
    // landing is at 3/10. N = 10: k = 3 puts the bottom at 32, on the top (no overlap); k = 4 at
    // 36, overlapping, and at k = 3 the box was over the platform on x with its bottom at the
    // top: it stops at k = 4, bracket [3/10, 4/10). The resolver stops at k = 3, (20, 22), normal
    // (0, -1).
    const auto scene =
        makeScene<float>(makeMap<float>({"....", "....", ".--.", "...."}), {{20, 10}, {10, 10}}, {{0, 40}});
    const SubstepOverlap overlap =
        findFirstOverlapExact(toExact(scene.map), toExact(scene.box), {Rational(0), Rational(40)}, 10);
    ASSERT_TRUE(overlap.found());
    EXPECT_EQ(overlap.firstOverlap, 4);
    ASSERT_EQ(overlap.tiles.size(), 1U);
    EXPECT_EQ(overlap.tiles[0], (Cell{1, 2}));
    const std::vector<SubstepFrame<float>> frames = resolveSceneSubstep(scene, 10);
    EXPECT_EQ(frames[0].frame.position, (Vec2<float>{20, 22}));
    ASSERT_EQ(frames[0].frame.contacts.size(), 1U);
    EXPECT_EQ(frames[0].frame.contacts[0].normal, (Normal{0, -1}));
    EXPECT_TRUE(frames[0].frame.startOverlaps.empty());
}

TEST(SubstepOracle, jumpingUpOrEnteringThroughTheSideNeverStops) {
    const ExactTileMap map = toExact(makeMap<float>({"....", ".-..", "...."}));
    // Box [18, 28] x [34, 44] moving (0, -40) up through the platform (1, 1) = [16, 32]^2.
    EXPECT_FALSE(findFirstOverlapExact(map, {{Rational(18), Rational(34)}, {Rational(10), Rational(10)}},
                                       {Rational(0), Rational(-40)}, 64)
                     .found());
    // Box [0, 10]^2 moving (20, 40): it reaches the top's height (3/20) before the platform's x
    // range (3/10), so it comes in through the side: at every sample before the overlap it was
    // beside the platform. The same tile solid stops it.
    const ExactBox box{{Rational(0), Rational(0)}, {Rational(10), Rational(10)}};
    const ExactVec2 d{Rational(20), Rational(40)};
    EXPECT_FALSE(findFirstOverlapExact(map, box, d, 100).found());
    EXPECT_TRUE(
        findFirstOverlapExact(toExact(makeMap<float>({"....", ".#..", "...."})), box, d, 100).found());
    // Inside the platform (bottom below its top) moving down: it falls through, and the platform
    // is not a start overlap.
    const SubstepOverlap inside = findFirstOverlapExact(
        map, {{Rational(18), Rational(20)}, {Rational(10), Rational(10)}}, {Rational(0), Rational(10)}, 16);
    EXPECT_FALSE(inside.found());
    EXPECT_TRUE(inside.startOverlaps.empty());
}

TEST(SubstepOracle, exactCornerLandingFallsBetweenTheSamples) {
    // Box [0, 10]^2 moving (20, 20) onto the platform (1, 1): the exact reference lands at 3/10
    // (a tie, on y). At every sample up to 3/10 the box is not yet over the platform on x (its
    // right edge reaches 16 at 3/10 exactly), and after it the bottom is below the top: the
    // substeps never see a landing. This is the documented limit, not a false hit.
    const ExactTileMap map = toExact(makeMap<float>({"....", ".-.."}));
    const ExactBox box{{Rational(0), Rational(0)}, {Rational(10), Rational(10)}};
    const ExactVec2 d{Rational(20), Rational(20)};
    ASSERT_EQ(resolveFrameExact(map, box, d).contacts.size(), 1U);
    for (const std::int64_t n : {10, 100, 1000}) {
        EXPECT_FALSE(findFirstOverlapExact(map, box, d, n).found()) << "N = " << n;
    }
}

TEST(SubstepFloat, coarseSubstepsFallThroughThinPlatforms) {
    // Tiles 16 x 2; platforms in rows 10, 20 and 30 (tops 20, 40, 60). Box [18, 28] x [0, 4]
    // moving (0, 1000). N = 10: steps of 100 put the box at y = 100, 200, ...: no sample overlaps
    // a platform; it ends at y = 1000. N = 1000: steps of 1; at k = 16 the bottom is 20, on the
    // top of row 10; at k = 17 it overlaps: it stops at y = 16, normal (0, -1).
    std::vector<std::string> rows(40, "...");
    rows[10] = rows[20] = rows[30] = "---";
    const auto scene =
        makeScene<float>(makeMap<float>(rows, {0, 0}, {16, 2}), {{18, 0}, {10, 4}}, {{0, 1000}});
    const auto coarse = resolveSceneSubstepFloat(scene, 10);
    EXPECT_EQ(coarse[0].firstOverlap, 0);
    EXPECT_EQ(coarse[0].frame.position, (Vec2<float>{18, 1000}));
    const auto fine = resolveSceneSubstepFloat(scene, 1000);
    EXPECT_EQ(fine[0].firstOverlap, 17);
    EXPECT_EQ(fine[0].frame.position, (Vec2<float>{18, 16}));
    ASSERT_EQ(fine[0].frame.contacts.size(), 1U);
    EXPECT_EQ(fine[0].frame.contacts[0].tile, (Cell{1, 10}));
    EXPECT_EQ(fine[0].frame.contacts[0].normal, (Normal{0, -1}));
}

TEST(SubstepFloat, platformsLetABoxJumpUpAndWalkInFromTheSide) {
    // The float loop, N = 50: up through the platform (1, 1) from [18, 28] x [34, 44] by -40; in
    // through its side from [0, 10]^2 by (20, 40). Neither stops.
    const auto map = makeMap<float>({"....", ".-..", "...."});
    EXPECT_EQ(
        resolveSceneSubstepFloat(makeScene<float>(map, {{18, 34}, {10, 10}}, {{0, -40}}), 50)[0].firstOverlap,
        0);
    EXPECT_EQ(
        resolveSceneSubstepFloat(makeScene<float>(map, {{0, 0}, {10, 10}}, {{20, 40}}), 50)[0].firstOverlap,
        0);
}

// ---- the bracket, over generated scenes -----------------------------------------------------

// A random dyadic coordinate: a multiple of 1/4 in [lo, hi].
Rational quarter(std::mt19937_64& random, int lo, int hi) {
    std::uniform_int_distribution<int> pick(4 * lo, 4 * hi);
    return Rational(pick(random)) / Rational(4);
}

// The exact decision for one tile of the straight move, by its kind.
ExactSweepOutput sweepByKind(const ExactTileMap& map, Cell cell, const ExactBox& box, const ExactVec2& d) {
    const ExactSweepInput input{box, d, map.tileRect(cell.i, cell.j)};
    return map.isOneWay(cell.i, cell.j) ? sweepOneWayTileExact(input) : sweepTileExact(input);
}

// Whether the one-way rule, not the geometry, decides some tile: a solid tile in its place would
// block the straight move and the platform does not (a jump up through it, a box inside it, an
// entry through a side).
bool oneWayRuleLetsPass(const ExactTileMap& map, const ExactBox& box, const ExactVec2& d) {
    for (std::int32_t j = 0; j < map.rows; ++j) {
        for (std::int32_t i = 0; i < map.columns; ++i) {
            if (!map.isOneWay(i, j)) continue;
            const ExactSweepInput input{box, d, map.tileRect(i, j)};
            if (sweepTileExact(input).state == ExactSweepState::Blocks &&
                sweepOneWayTileExact(input).state != ExactSweepState::Blocks) {
                return true;
            }
        }
    }
    return false;
}

// The claims of substep_oracle.h, against the exact reference's first step on random maps of '#',
// '-' and '.':
//   - a reported substep k means the earliest exact impact s satisfies s < k/N, and every tile
//     reported there blocks the straight move by itself, earlier than k/N (so a platform the box
//     jumps through, starts in or enters from the side is never reported);
//   - if the earliest-hit tiles include one whose window (s, min(exit, 1)) is longer than 1/N
//     (and, for a one-way tile, that the box overlapped on x at the sample before s: entry_x < 0
//     or s - entry_x >= 1/N), the substep oracle reports some k, and (k-1)/N <= s < k/N.
TEST(SubstepOracle, bracketHoldsTheExactTimeWheneverTheWindowIsWiderThanOneSubstep) {
    std::mt19937_64 random(20240611);
    std::discrete_distribution<int> cellKind({60, 20, 20});  // '.', '#', '-'
    const char kCells[] = {'.', '#', '-'};
    const std::int64_t substepCounts[] = {1, 2, 7, 16, 64};
    int hits = 0;
    int bracketed = 0;
    int narrowWindows = 0;
    int oneWayHits = 0;       // the first step's contacts include a '-' tile
    int oneWayBracketed = 0;  // the bracket was asserted through a '-' tile
    int oneWayPasses = 0;     // a '-' tile let the box through where '#' would have blocked
    for (int n = 0; n < 3000; ++n) {
        std::vector<std::string> rows(6, std::string(6, '.'));
        for (std::string& row : rows) {
            for (char& c : row) {
                c = kCells[cellKind(random)];
            }
        }
        const ExactTileMap map = toExact(makeMap<float>(rows));
        const ExactBox box{{quarter(random, 0, 90), quarter(random, 0, 90)},
                           {quarter(random, 1, 20), quarter(random, 1, 20)}};
        const ExactVec2 d{quarter(random, -60, 60), quarter(random, -60, 60)};
        const ExactFrame frame = resolveFrameExact(map, box, d);
        const std::int64_t substeps = substepCounts[n % 5];
        const Rational sampleGap = Rational(1) / Rational(substeps);
        const SubstepOverlap overlap = findFirstOverlapExact(map, box, d, substeps);

        const bool blocks = !frame.contacts.empty();
        const Rational s = blocks ? frame.contacts.front().time : Rational(0);
        if (oneWayRuleLetsPass(map, box, d)) ++oneWayPasses;
        if (overlap.found()) {
            ASSERT_TRUE(blocks) << "substep " << overlap.firstOverlap << " of " << substeps
                                << " without a hit";
            ASSERT_LT(s, overlap.bracketHigh());
            for (const Cell& cell : overlap.tiles) {
                const ExactSweepOutput sweep = sweepByKind(map, cell, box, d);
                ASSERT_EQ(sweep.state, ExactSweepState::Blocks)
                    << "tile (" << cell.i << ", " << cell.j << ") reported at substep "
                    << overlap.firstOverlap;
                ASSERT_LT(sweep.time, overlap.bracketHigh());
            }
        }
        if (!blocks) {
            continue;
        }
        ++hits;
        // The widest usable window among the tiles hit first (all hit at s; step 1 is the
        // straight move).
        Rational widest(0);
        bool widestIsOneWay = false;
        bool anyOneWay = false;
        for (const ExactContact& c : frame.contacts) {
            if (c.step != 1) {
                continue;
            }
            const bool oneWay = map.isOneWay(c.tile.i, c.tile.j);
            anyOneWay = anyOneWay || oneWay;
            const ExactSweepOutput sweep = sweepByKind(map, c.tile, box, d);
            ASSERT_EQ(sweep.state, ExactSweepState::Blocks);
            const Rational end = (sweep.overlap.high.isFinite() && sweep.overlap.high.value < 1)
                                     ? sweep.overlap.high.value
                                     : Rational(1);
            Rational window = end - s;
            if (oneWay) {
                // The sample before s must see the box over the platform on x.
                const ExtendedTime& entryX = sweep.xTimes.low;
                const bool overOnXEarlyEnough =
                    entryX < Rational(0) || !(Rational(s - entryX.value) < sampleGap);
                if (!overOnXEarlyEnough) window = 0;
            }
            if (window > widest) {
                widest = window;
                widestIsOneWay = oneWay;
            }
        }
        if (anyOneWay) ++oneWayHits;
        if (widest > sampleGap) {
            ++bracketed;
            if (widestIsOneWay) ++oneWayBracketed;
            ASSERT_TRUE(overlap.found()) << "window " << toString(widest) << " missed with N = " << substeps;
            ASSERT_LE(overlap.bracketLow(), s);
            ASSERT_LT(s, overlap.bracketHigh());
        } else {
            ++narrowWindows;
        }
    }
    // Coverage, so that the run shows it exercised each case, one-way tiles included.
    RecordProperty("hits", hits);
    RecordProperty("bracketed", bracketed);
    RecordProperty("narrowWindows", narrowWindows);
    RecordProperty("oneWayHits", oneWayHits);
    RecordProperty("oneWayBracketed", oneWayBracketed);
    RecordProperty("oneWayPasses", oneWayPasses);
    std::cout << "cross-check: " << hits << " hits, " << bracketed << " bracketed, " << narrowWindows
              << " narrow windows; one-way: " << oneWayHits << " hits, " << oneWayBracketed
              << " bracketed through a platform, " << oneWayPasses << " let through by the one-way rule\n";
    EXPECT_GT(hits, 600);
    EXPECT_GT(bracketed, 400);
    EXPECT_GT(narrowWindows, 20);
    EXPECT_GT(oneWayHits, 150);
    EXPECT_GT(oneWayBracketed, 75);
    EXPECT_GT(oneWayPasses, 150);
}

}  // namespace
}  // namespace tilesweep::oracle

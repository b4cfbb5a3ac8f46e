// SPDX-License-Identifier: MIT
// The safety checker on frames whose start overlaps are listed in another order than tilesweep's
// (the contract leaves the order of started_overlapping free), or with a cell left out, listed
// twice or replaced: only the order is free.
#include "frame_safety.h"

#include "tilesweep/resolve.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace tilesweep::checks {
namespace {

/// A 4 x 3 map of 16 px tiles whose top two rows and first three columns are solid, and a box
/// 40 x 24 px at (4, 4) that overlaps all six of those tiles at the start: (0..2, 0..1).
struct Fixture {
    std::vector<std::uint8_t> solid = {1, 1, 1, 0,  //
                                       1, 1, 1, 0,  //
                                       0, 0, 0, 0};
    TileMapView<float> map{{0, 0}, {16, 16}, 4, 3, solid.data()};
    MapEdges<float> edges = computeEdges(map);
    Box<float> box{{4, 4}, {40, 24}};
    Vec2<float> move{6, 0};  // right, into the empty column: nothing blocks
    Contact<float> contacts[8];
    Cell overlaps[16];
    ResolveResult<float> result = resolveMove<float>({map, box, move}, {contacts, 8, overlaps, 16});

    /// The checker's verdict on the frame with `listed` as its start overlaps.
    SafetyViolation check(std::vector<Cell> listed) {
        ResolveResult<float> r = result;
        r.startOverlapCount = static_cast<std::int32_t>(listed.size());
        SafetyScratch scratch;
        return checkFrameSafety<float>({map, box, move, r, contacts, listed.data()}, edges, scratch);
    }

    std::vector<Cell> exact() const { return {overlaps, overlaps + result.startOverlapCount}; }
};

TEST(FrameSafety, startOverlapsAreTheBoxsTilesInTheResolversOrder) {
    Fixture f;
    ASSERT_EQ(f.result.status, ResolveStatus::Moved);
    const std::vector<Cell> expected = {{0, 0}, {1, 0}, {2, 0}, {0, 1}, {1, 1}, {2, 1}};
    EXPECT_EQ(f.exact(), expected);
    EXPECT_FALSE(f.check(f.exact())) << f.check(f.exact()).detail;
}

TEST(FrameSafety, acceptsStartOverlapsInAnyOrder) {
    Fixture f;
    std::vector<Cell> reversed = f.exact();
    std::reverse(reversed.begin(), reversed.end());
    EXPECT_FALSE(f.check(reversed)) << f.check(reversed).detail;
    // By column, then row: the order a checker sorting by (i, j) would expect.
    std::vector<Cell> byColumn = f.exact();
    std::sort(byColumn.begin(), byColumn.end(),
              [](Cell a, Cell b) { return a.i != b.i ? a.i < b.i : a.j < b.j; });
    ASSERT_NE(byColumn, f.exact());
    EXPECT_FALSE(f.check(byColumn)) << f.check(byColumn).detail;
    std::vector<Cell> rotated = f.exact();
    std::rotate(rotated.begin(), rotated.begin() + 2, rotated.end());
    EXPECT_FALSE(f.check(rotated)) << f.check(rotated).detail;
}

TEST(FrameSafety, refusesStartOverlapsWithACellMissingTwiceOrWrong) {
    Fixture f;
    std::vector<Cell> reversed = f.exact();
    std::reverse(reversed.begin(), reversed.end());

    std::vector<Cell> missing = reversed;
    missing.pop_back();
    EXPECT_EQ(f.check(missing).rule, SafetyRule::StartOverlaps);
    EXPECT_EQ(f.check({}).rule, SafetyRule::StartOverlaps);

    std::vector<Cell> extraTwice = reversed;  // every cell, and one of them again
    extraTwice.push_back(reversed.front());
    EXPECT_EQ(f.check(extraTwice).rule, SafetyRule::StartOverlaps);

    // As many cells as the exact list, every one of them a tile the box overlaps, but one twice
    // and another left out: a membership test alone would pass it.
    std::vector<Cell> twiceInPlace = reversed;
    twiceInPlace.back() = twiceInPlace.front();
    EXPECT_EQ(f.check(twiceInPlace).rule, SafetyRule::StartOverlaps);

    std::vector<Cell> wrong = reversed;
    wrong[1] = {3, 2};  // an empty cell of the map
    EXPECT_EQ(f.check(wrong).rule, SafetyRule::StartOverlaps);
}

TEST(FrameSafety, sameCellsInAnyOrderReusesItsStorage) {
    Fixture f;
    const std::vector<Cell> exact = f.exact();
    std::vector<Cell> reversed = exact;
    std::reverse(reversed.begin(), reversed.end());
    std::vector<Cell> sorted;
    ASSERT_TRUE(sameCellsInAnyOrder(exact, reversed.data(), reversed.size(), sorted));
    const Cell* storage = sorted.data();
    for (int k = 0; k < 3; ++k)
        EXPECT_TRUE(sameCellsInAnyOrder(exact, reversed.data(), reversed.size(), sorted));
    EXPECT_EQ(sorted.data(), storage);  // no allocation once it holds the longest list
    EXPECT_TRUE(sameCellsInAnyOrder({}, nullptr, 0, sorted));
    EXPECT_FALSE(sameCellsInAnyOrder(exact, reversed.data(), 0, sorted));
}

}  // namespace
}  // namespace tilesweep::checks

// SPDX-License-Identifier: MIT
// Hand-worked cases of the contract (docs/contract.md) and the seed article. Every expected
// value below is derived in the comment above it from the contract's rules, not copied from the
// program's output.
#include "tilesweep/resolve.h"
#include "tilesweep/tile_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace tilesweep {
namespace {

template <class T>
struct Level {
    std::vector<std::uint8_t> cells;
    TileMapView<T> map;

    Level(const std::vector<std::string>& rows, Vec2<T> origin = {0, 0}, Vec2<T> tile = {16, 16}) {
        for (const std::string& row : rows)
            for (char c : row) cells.push_back(c == '#' ? 1 : 0);
        map = {origin, tile, static_cast<std::int32_t>(rows.empty() ? 0 : rows[0].size()),
               static_cast<std::int32_t>(rows.size()), cells.data()};
    }
};

template <class T>
struct Frame {
    ResolveResult<T> result;
    std::vector<Contact<T>> contacts;
    std::vector<Cell> overlaps;
};

template <class T>
Frame<T> resolve(const Level<T>& level, Box<T> box, Vec2<T> move) {
    Frame<T> f;
    f.contacts.resize(64);
    f.overlaps.resize(64);
    f.result = resolveMove<T>({level.map, box, move}, {f.contacts.data(), 64, f.overlaps.data(), 64});
    f.contacts.resize(static_cast<std::size_t>(std::min(f.result.contactCount, 64)));
    f.overlaps.resize(static_cast<std::size_t>(std::min(f.result.startOverlapCount, 64)));
    return f;
}

template <class T>
void expectContact(const Contact<T>& c, Cell tile, Normal normal, T time) {
    EXPECT_EQ(c.tile.i, tile.i);
    EXPECT_EQ(c.tile.j, tile.j);
    EXPECT_EQ(c.normal.x, normal.x);
    EXPECT_EQ(c.normal.y, normal.y);
    EXPECT_EQ(c.time, time);
}

template <class T>
class Resolve : public ::testing::Test {};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(Resolve, Scalars);

// Seed picture 1. Box x in [4, 14] moving +200 toward tile (5, 1) = [80, 96]: entry time
// (80 - 14) / 200 = 0.33, it stops touching at x = 80 - 10 = 70; y is static and overlaps.
TYPED_TEST(Resolve, fastBoxStopsAtThinWall) {
    using T = TypeParam;
    Level<T> level({"..........", ".....#....", ".........."});
    const Frame<T> f = resolve<T>(level, {{4, 18}, {10, 10}}, {200, 0});
    EXPECT_EQ(f.result.status, ResolveStatus::Blocked);
    EXPECT_EQ(f.result.position.x, T(70));
    EXPECT_EQ(f.result.position.y, T(18));
    ASSERT_EQ(f.contacts.size(), 1u);
    expectContact<T>(f.contacts[0], {5, 1}, {-1, 0}, static_cast<T>(0.33L));
}

// The same wall at a million pixels per frame: no tunnelling; t = 66 / 1e6.
TYPED_TEST(Resolve, neverTunnelsAtAnySpeed) {
    using T = TypeParam;
    Level<T> level({"..........", ".....#....", ".........."});
    const Frame<T> f = resolve<T>(level, {{4, 18}, {10, 10}}, {1e6, 0});
    EXPECT_EQ(f.result.position.x, T(70));
    ASSERT_EQ(f.contacts.size(), 1u);
    expectContact<T>(f.contacts[0], {5, 1}, {-1, 0}, static_cast<T>(66.0L / 1e6L));
}

// Seed picture 2. Tile (2, 1) = [32, 48] x [16, 32]; box [2, 10] x [40, 48] moving (60, -9).
// x overlaps for t in (22/60, 46/60), y from t > 8/9: 8/9 > 46/60, the intervals are disjoint
// although the swept bounds overlap the tile. No hit; the box ends at (62, 31).
TYPED_TEST(Resolve, rejectsCornerMissInsideSweptBounds) {
    using T = TypeParam;
    Level<T> level({"......", "..#...", "......", "......"});
    const Frame<T> f = resolve<T>(level, {{2, 40}, {8, 8}}, {60, -9});
    EXPECT_EQ(f.result.status, ResolveStatus::Moved);
    EXPECT_TRUE(f.contacts.empty());
    EXPECT_EQ(f.result.position.x, T(62));
    EXPECT_EQ(f.result.position.y, T(31));
}

// The same with dy = -11: y enters at 8/11 < 46/60, so the box clips the corner, on y (8/11 >
// 22/60). It stops at y = 32 (touching the tile's bottom), normal (0, 1), and slides on to x = 62.
TYPED_TEST(Resolve, catchesClippedCorner) {
    using T = TypeParam;
    Level<T> level({"......", "..#...", "......", "......"});
    const Frame<T> f = resolve<T>(level, {{2, 40}, {8, 8}}, {60, -11});
    EXPECT_EQ(f.result.position.x, T(62));
    EXPECT_EQ(f.result.position.y, T(32));
    ASSERT_EQ(f.contacts.size(), 1u);
    expectContact<T>(f.contacts[0], {2, 1}, {0, 1}, static_cast<T>(8.0L / 11.0L));
}

// Box [16, 24] x [48, 56] moving (32, -32) past tile (1, 1) = [16, 32]^2: x overlaps while
// t < 1/2, y from t > 1/2: the path passes exactly through the corner point: touch, no hit.
TYPED_TEST(Resolve, pathThroughCornerPointDoesNotBlock) {
    using T = TypeParam;
    Level<T> level({"....", ".#..", "....", "...."});
    const Frame<T> f = resolve<T>(level, {{16, 48}, {8, 8}}, {32, -32});
    EXPECT_TRUE(f.contacts.empty());
    EXPECT_EQ(f.result.position.x, T(48));
    EXPECT_EQ(f.result.position.y, T(16));
}

// One ulp more of upward speed and the path clips that corner: y enters at 16/|dy| < 1/2. The
// hit is on y (x has overlapped since before t = 0), the box touches y = 32 and slides to x = 48.
// One ulp less and it misses: y ends at 48 - |dy| = 16 + ulp/2 of 32, which is representable.
TYPED_TEST(Resolve, oneUlpDecidesCornerClipExactly) {
    using T = TypeParam;
    Level<T> level({"....", ".#..", "....", "...."});
    const T faster = std::nextafter(T(32), T(64));
    const Frame<T> clip = resolve<T>(level, {{16, 48}, {8, 8}}, {32, -faster});
    ASSERT_EQ(clip.contacts.size(), 1u);
    expectContact<T>(clip.contacts[0], {1, 1}, {0, 1},
                     static_cast<T>(16.0L / static_cast<long double>(faster)));
    EXPECT_EQ(clip.result.position.x, T(48));
    EXPECT_EQ(clip.result.position.y, T(32));

    const T slower = std::nextafter(T(32), T(0));
    const Frame<T> miss = resolve<T>(level, {{16, 48}, {8, 8}}, {32, -slower});
    EXPECT_TRUE(miss.contacts.empty());
    EXPECT_EQ(miss.result.position.y, T(48) - slower);
    EXPECT_EQ(miss.result.position.y, T(16) + (T(32) - slower));
}

// Exact corner tie: box [8, 16]^2 moving (32, 32) toward tile (2, 2) = [32, 48]^2: both axes
// enter at t = 1/2. The face across which the box comes on x has neighbour (1, 2), on y (2, 1).
// Both exposed: y. The box stops at y = 32 - 8 = 24 and slides on x to 40.
TYPED_TEST(Resolve, cornerTieWithBothFacesExposedTakesY) {
    using T = TypeParam;
    Level<T> level({"....", "....", "..#.", "...."});
    const Frame<T> f = resolve<T>(level, {{8, 8}, {8, 8}}, {32, 32});
    ASSERT_EQ(f.contacts.size(), 1u);
    expectContact<T>(f.contacts[0], {2, 2}, {0, -1}, T(0.5));
    EXPECT_EQ(f.result.position.x, T(40));
    EXPECT_EQ(f.result.position.y, T(24));
}

// Only the x face exposed: (2, 1) is solid. It is hit at 1/2 too (x enters at 1/2; y overlaps
// it for t in (0, 3/4)), on x; the tie of (2, 2) goes to x. The box stops at x = 24 and slides
// down to y = 8 + 32 = 40 along the wall. Contacts by row: (2, 1), then (2, 2).
TYPED_TEST(Resolve, cornerTieWithOnlyXFaceExposedTakesX) {
    using T = TypeParam;
    Level<T> level({"....", "..#.", "..#.", "...."});
    const Frame<T> f = resolve<T>(level, {{8, 8}, {8, 8}}, {32, 32});
    ASSERT_EQ(f.contacts.size(), 2u);
    expectContact<T>(f.contacts[0], {2, 1}, {-1, 0}, T(0.5));
    expectContact<T>(f.contacts[1], {2, 2}, {-1, 0}, T(0.5));
    EXPECT_EQ(f.result.position.x, T(24));
    EXPECT_EQ(f.result.position.y, T(40));
}

// Only the y face exposed: (1, 2) is solid and hit on y at 1/2; the tie of (2, 2) goes to y.
// The box lands at y = 24 and slides on to x = 40. Contacts: (1, 2), then (2, 2).
TYPED_TEST(Resolve, cornerTieWithOnlyYFaceExposedTakesY) {
    using T = TypeParam;
    Level<T> level({"....", "....", ".##.", "...."});
    const Frame<T> f = resolve<T>(level, {{8, 8}, {8, 8}}, {32, 32});
    ASSERT_EQ(f.contacts.size(), 2u);
    expectContact<T>(f.contacts[0], {1, 2}, {0, -1}, T(0.5));
    expectContact<T>(f.contacts[1], {2, 2}, {0, -1}, T(0.5));
    EXPECT_EQ(f.result.position.x, T(40));
    EXPECT_EQ(f.result.position.y, T(24));
}

// Neither face exposed: (2, 1) is hit on x, (1, 2) on y, and the tie of (2, 2) goes to y. Both
// axes are contact axes: the box stops at (24, 24) with three contacts at 1/2.
TYPED_TEST(Resolve, cornerTieWithNoFaceExposedStopsBothAxes) {
    using T = TypeParam;
    Level<T> level({"....", "..#.", ".##.", "...."});
    const Frame<T> f = resolve<T>(level, {{8, 8}, {8, 8}}, {32, 32});
    ASSERT_EQ(f.contacts.size(), 3u);
    expectContact<T>(f.contacts[0], {2, 1}, {-1, 0}, T(0.5));
    expectContact<T>(f.contacts[1], {1, 2}, {0, -1}, T(0.5));
    expectContact<T>(f.contacts[2], {2, 2}, {0, -1}, T(0.5));
    EXPECT_EQ(f.result.position.x, T(24));
    EXPECT_EQ(f.result.position.y, T(24));
}

// A 12x12 box at (4, 20) falls by (12, 20) onto the floor row 3 (y = 48): it touches at
// t = (48 - 32) / 20 = 0.8, straddling the seam x = 16 (box x in [13.6, 25.6] then), so both
// (0, 3) and (1, 3) are hit; then it slides to x = 16. Every later frame of (12, 4) touches the
// floor at t = 0 and slides exactly 12 along it: never a snag on any seam, y fixed at 36.
TYPED_TEST(Resolve, landsAcrossSeamAndSlidesWithoutSnagging) {
    using T = TypeParam;
    Level<T> level({std::string(64, '.'), std::string(64, '.'), std::string(64, '.'), std::string(64, '#')});
    Box<T> box{{4, 20}, {12, 12}};
    Frame<T> f = resolve<T>(level, box, {12, 20});
    ASSERT_EQ(f.contacts.size(), 2u);
    expectContact<T>(f.contacts[0], {0, 3}, {0, -1}, static_cast<T>(0.8L));
    expectContact<T>(f.contacts[1], {1, 3}, {0, -1}, static_cast<T>(0.8L));
    EXPECT_EQ(f.result.position.x, T(16));
    EXPECT_EQ(f.result.position.y, T(36));
    box.pos = f.result.position;
    for (int frame = 1; frame <= 60; ++frame) {
        f = resolve<T>(level, box, {12, 4});
        const T x = T(16 + 12 * frame);
        ASSERT_EQ(f.result.position.x, x) << "frame " << frame;
        ASSERT_EQ(f.result.position.y, T(36)) << "frame " << frame;
        // Floor tiles under the box's open x span at the start of the frame, plus the one
        // whose top-left corner the box's bottom-right corner touches (when start + 12 is a
        // multiple of 16): that is an exact corner tie at t = 0, and with the x face covered
        // by the floor tile before it, only the y face is exposed, so it is a floor contact.
        const int start = 16 + 12 * (frame - 1);
        std::vector<int> under;
        for (int i = 0; i < 64; ++i)
            if (16 * i <= start + 12 && 16 * (i + 1) > start) under.push_back(i);
        ASSERT_EQ(f.contacts.size(), under.size()) << "frame " << frame;
        for (std::size_t k = 0; k < under.size(); ++k)
            expectContact<T>(f.contacts[k], {under[k], 3}, {0, -1}, T(0));
        box.pos = f.result.position;
    }
}

// A box resting on the floor (bottom at y = 32) under gravity: each frame it touches at t = 0,
// y is zeroed and nothing moves. Bit for bit the same position for 500 frames.
TYPED_TEST(Resolve, restingContactIsStable) {
    using T = TypeParam;
    Level<T> level({"....", "....", "####"});
    Box<T> box{{10, T(17.5)}, {12, T(14.5)}};
    for (int frame = 0; frame < 500; ++frame) {
        const Frame<T> f = resolve<T>(level, box, {0, T(0.5)});
        ASSERT_EQ(f.result.position.x, T(10));
        ASSERT_EQ(f.result.position.y, T(17.5));
        ASSERT_EQ(f.contacts.size(), 2u);
        expectContact<T>(f.contacts[0], {0, 2}, {0, -1}, T(0));
        expectContact<T>(f.contacts[1], {1, 2}, {0, -1}, T(0));
        box.pos = f.result.position;
    }
}

// Zero displacement: nothing moves, no contact, even touching the floor.
TYPED_TEST(Resolve, zeroDisplacementChangesNothing) {
    using T = TypeParam;
    Level<T> level({"..", "##"});
    const Frame<T> f = resolve<T>(level, {{3, 4}, {5, 12}}, {0, 0});
    EXPECT_EQ(f.result.status, ResolveStatus::Moved);
    EXPECT_TRUE(f.contacts.empty());
    EXPECT_TRUE(f.overlaps.empty());
    EXPECT_EQ(f.result.position.x, T(3));
    EXPECT_EQ(f.result.position.y, T(4));
}

// dx = 0, aligned with tile (1, 2) = [16, 32] x [32, 48]: lands at t = 16/100 at y = 16.
// Beside it (x in [0, 16]) the box only touches the tile's side: it falls through to y = 100.
TYPED_TEST(Resolve, zeroVelocityAxisOverlapsOrNeverDoes) {
    using T = TypeParam;
    Level<T> level({"...", "...", ".#."});
    const Frame<T> on = resolve<T>(level, {{16, 0}, {16, 16}}, {0, 100});
    ASSERT_EQ(on.contacts.size(), 1u);
    expectContact<T>(on.contacts[0], {1, 2}, {0, -1}, static_cast<T>(0.16L));
    EXPECT_EQ(on.result.position.y, T(16));
    const Frame<T> beside = resolve<T>(level, {{0, 0}, {16, 16}}, {0, 100});
    EXPECT_TRUE(beside.contacts.empty());
    EXPECT_EQ(beside.result.position.x, T(0));
    EXPECT_EQ(beside.result.position.y, T(100));
}

// A box exactly as wide as a one-tile gap (x in [16, 32]) only touches both sides: it drops
// through. Half a unit wider on each side it lands on both tiles at t = (32 - 20) / 40 = 0.3.
TYPED_TEST(Resolve, boxAsWideAsGapDropsThrough) {
    using T = TypeParam;
    Level<T> level({"...", "...", "#.#", "..."});
    const Frame<T> through = resolve<T>(level, {{16, 4}, {16, 16}}, {0, 40});
    EXPECT_TRUE(through.contacts.empty());
    EXPECT_EQ(through.result.position.y, T(44));
    const Frame<T> lands = resolve<T>(level, {{T(15.5), 4}, {17, 16}}, {0, 40});
    ASSERT_EQ(lands.contacts.size(), 2u);
    expectContact<T>(lands.contacts[0], {0, 2}, {0, -1}, static_cast<T>(0.3L));
    expectContact<T>(lands.contacts[1], {2, 2}, {0, -1}, static_cast<T>(0.3L));
    EXPECT_EQ(lands.result.position.y, T(16));
}

// Far from the origin: map at x = 1e6 (16-pixel tiles, every edge representable in float since
// ulp(1e6) = 1/16). Box x in [1e6 + 3.25, 1e6 + 13.25] moving +100 at wall column 5 (x = 1e6+80):
// entry (80 - 13.25) / 100 = 0.6675, stop at 1e6 + 70.
TYPED_TEST(Resolve, farFromOriginStaysExact) {
    using T = TypeParam;
    Level<T> level({"......", ".....#"}, {T(1e6), 0});
    ASSERT_EQ(validateTileMap(level.map), MapError::None);
    const Frame<T> f = resolve<T>(level, {{T(1e6) + T(3.25), 18}, {10, 10}}, {100, 0});
    ASSERT_EQ(f.contacts.size(), 1u);
    expectContact<T>(f.contacts[0], {5, 1}, {-1, 0}, static_cast<T>(0.6675L));
    EXPECT_EQ(f.result.position.x, T(1e6) + T(70));
}

// Non-dyadic time: box x in [0, 16] moving +144 at the wall x = 64: t = 48/144 = 1/3, rounded to
// nearest in T.
TYPED_TEST(Resolve, nonDyadicTimeRoundsToNearest) {
    using T = TypeParam;
    Level<T> level({"....#"});
    const Frame<T> f = resolve<T>(level, {{0, 2}, {16, 8}}, {144, 0});
    ASSERT_EQ(f.contacts.size(), 1u);
    expectContact<T>(f.contacts[0], {4, 0}, {-1, 0}, static_cast<T>(1.0L / 3.0L));
    EXPECT_EQ(f.result.position.x, T(48));
}

// A move far below one ulp of the position (65540 has ulp 1/128 in float): the exact end
// 65540 + dx rounds toward the start, to the largest T not above it. TwoSum gives the exact
// rounding error of the nearest sum, which says on which side of the exact value it fell.
TYPED_TEST(Resolve, subUlpMoveRoundsTowardStart) {
    using T = TypeParam;
    Level<T> level({"....", "####"}, {65536, 0}, {32, 32});
    const T dx = static_cast<T>(0.001);
    const Frame<T> f = resolve<T>(level, {{65540, 10}, {8, 8}}, {dx, 0});
    const T a = 65540;
    const T nearest = a + dx;
    const T error = (a - (nearest - (nearest - a))) + (dx - (nearest - a));  // exact: a + dx - nearest
    const T expected = error < 0 ? std::nextafter(nearest, T(0)) : nearest;
    EXPECT_EQ(f.result.position.x, expected);
    if (std::is_same<T, float>::value) {
        EXPECT_EQ(f.result.position.x, T(65540));
    } else {
        EXPECT_GT(f.result.position.x, T(65540));
    }
}

// Non-representable box values: x = 0.1, w = 12.3 (rounded once to T), moving 60.7 at the wall
// x = 48: the contact position is 48 - w exactly, which lies strictly between two T values; it
// rounds toward the start, so the box ends short of the wall, never inside it.
TYPED_TEST(Resolve, contactPositionRoundsTowardStart) {
    using T = TypeParam;
    Level<T> level({"....", "...#"});
    const T w = static_cast<T>(12.3);
    const Frame<T> f =
        resolve<T>(level, {{static_cast<T>(0.1), static_cast<T>(10.3)}, {w, static_cast<T>(9.9)}},
                   {static_cast<T>(60.7), 0});
    ASSERT_EQ(f.contacts.size(), 1u);
    const long double touch = 48.0L - static_cast<long double>(w);  // exact
    const T x = f.result.position.x;
    EXPECT_LE(static_cast<long double>(x), touch);
    EXPECT_GT(static_cast<long double>(std::nextafter(x, T(64))), touch);
    EXPECT_LE(static_cast<long double>(x) + static_cast<long double>(w), 48.0L);
}

// A box that starts inside tile (1, 1) may leave it: the tile is reported, never blocks.
TYPED_TEST(Resolve, startOverlapIsReportedAndNeverBlocks) {
    using T = TypeParam;
    Level<T> level({"....", ".#..", "...."});
    const Frame<T> f = resolve<T>(level, {{20, 20}, {8, 8}}, {-20, 0});
    EXPECT_TRUE(f.contacts.empty());
    ASSERT_EQ(f.overlaps.size(), 1u);
    EXPECT_EQ(f.overlaps[0].i, 1);
    EXPECT_EQ(f.overlaps[0].j, 1);
    EXPECT_EQ(f.result.position.x, T(0));
}

// Diagonal into an inside corner: floor (y = 32) first at t = (32 - 14) / 30 = 0.6 on tile
// (3, 2) (box x in [50, 60] then); y stops at 22; x moves on and meets the wall x = 64 at frame
// time (64 - 30) / 50 = 0.68, stopping at 54.
TYPED_TEST(Resolve, diagonalIntoCornerHitsFloorThenWall) {
    using T = TypeParam;
    Level<T> level({"....#", "....#", "#####"});
    const Frame<T> f = resolve<T>(level, {{20, 4}, {10, 10}}, {50, 30});
    ASSERT_EQ(f.contacts.size(), 2u);
    expectContact<T>(f.contacts[0], {3, 2}, {0, -1}, static_cast<T>(0.6L));
    expectContact<T>(f.contacts[1], {4, 1}, {-1, 0}, static_cast<T>(0.68L));
    EXPECT_EQ(f.result.position.x, T(54));
    EXPECT_EQ(f.result.position.y, T(22));
}

// Bad input never yields a result: NaN, infinities, non-positive sizes.
// The sign of zero (the oracle's rule, oracle/README.md): an axis whose exact end equals its start
// gives the start's own bits, so a box at x = -0 that moves on y alone stays at -0; any other zero
// end is +0 (1 - 1 = +0 exactly, below the start: rounded toward it, the zero itself).
TYPED_TEST(Resolve, keepsTheStartsSignOfZeroOnAStillAxis) {
    using T = TypeParam;
    Level<T> level({"....", "....", "...."});
    const Frame<T> still = resolve<T>(level, {{-T(0), 5}, {4, 4}}, {0, 3});
    EXPECT_EQ(still.result.status, ResolveStatus::Moved);
    EXPECT_EQ(still.result.position.x, T(0));
    EXPECT_TRUE(std::signbit(still.result.position.x));
    EXPECT_EQ(still.result.position.y, T(8));
    const Frame<T> stillY = resolve<T>(level, {{5, -T(0)}, {4, 4}}, {-2, 0});
    EXPECT_TRUE(std::signbit(stillY.result.position.y));
    EXPECT_EQ(stillY.result.position.x, T(3));
    const Frame<T> toZero = resolve<T>(level, {{1, 5}, {4, 4}}, {-1, 1});
    EXPECT_EQ(toZero.result.position.x, T(0));
    EXPECT_FALSE(std::signbit(toZero.result.position.x));
}

TYPED_TEST(Resolve, rejectsInvalidInput) {
    using T = TypeParam;
    Level<T> level({"..", ".."});
    const T nan = std::numeric_limits<T>::quiet_NaN();
    const T inf = std::numeric_limits<T>::infinity();
    const Box<T> good{{1, 1}, {4, 4}};
    const std::vector<std::pair<Box<T>, Vec2<T>>> bad = {{good, {nan, 1}},
                                                         {good, {1, inf}},
                                                         {{{nan, 1}, {4, 4}}, {1, 1}},
                                                         {{{1, 1}, {0, 4}}, {1, 1}},
                                                         {{{1, 1}, {4, -4}}, {1, 1}},
                                                         {{{1, -inf}, {4, 4}}, {1, 1}}};
    for (const auto& [box, move] : bad) {
        const Frame<T> f = resolve<T>(level, box, move);
        EXPECT_EQ(f.result.status, ResolveStatus::InvalidInput);
        EXPECT_EQ(f.result.contactCount, 0);
        EXPECT_FALSE(std::isnan(f.result.position.x) || std::isnan(f.result.position.y));
    }
    Level<T> badTile({".."}, {0, 0}, {0, 16});
    EXPECT_EQ(resolve<T>(badTile, good, {1, 1}).result.status, ResolveStatus::InvalidInput);
}

// Map edges: 0.1 as a float is 13421773 * 2^-27; 2 * 0.1f is exact, 3 * 0.1f needs 26 bits.
TEST(TileMap, rejectsUnrepresentableEdges) {
    const std::uint8_t cells[4] = {};
    std::int64_t bad = 0;
    EXPECT_EQ(validateTileMap<float>({{0, 0}, {0.1f, 16}, 2, 1, cells}), MapError::None);
    EXPECT_EQ(validateTileMap<float>({{0, 0}, {0.1f, 16}, 4, 1, cells}, &bad),
              MapError::UnrepresentableEdgeX);
    EXPECT_EQ(bad, 3);
    EXPECT_EQ(validateTileMap<double>({{0, 0}, {16, 0.1}, 1, 4, cells}, &bad),
              MapError::UnrepresentableEdgeY);
    EXPECT_EQ(bad, 3);
    // 2^24 + 16k is representable in float for every k here; 2^24 + 1 is not.
    EXPECT_EQ(validateTileMap<float>({{16777216.0f, 0}, {16, 16}, 4, 1, cells}), MapError::None);
    EXPECT_EQ(validateTileMap<float>({{16777216.0f, 0}, {1, 16}, 4, 1, cells}),
              MapError::UnrepresentableEdgeX);
    EXPECT_EQ(validateTileMap<float>({{0, 0}, {-16, 16}, 4, 1, cells}), MapError::NonPositiveTileSize);
}

}  // namespace
}  // namespace tilesweep

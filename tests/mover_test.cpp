// SPDX-License-Identifier: MIT
// The game-loop API (tilesweep/mover.h): hand-worked frames, and properties over random scenes
// that hold moveAndSlide to resolveMove bit for bit and the resolver to maxContacts.
// TILESWEEP_PROPERTY_CASES sets the cases per property (default 3000); the seed is fixed.
#include "tilesweep/mover.h"

#include "property_cases.h"

#include "tilesweep/resolve.h"
#include "tilesweep/scenarios/mover_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace tilesweep {
namespace {

template <class T>
class Mover : public ::testing::Test {};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(Mover, Scalars);

// A 12x16 box falling 5 from y = 14 (bottom 30) onto the floor at y = 32: hits at 2/5, stops
// at y = 16, normal (0, -1): on the ground, blocked on y only.
TYPED_TEST(Mover, landingSetsOnGround) {
    using T = TypeParam;
    scenarios::Level<T> level({"....", "....", "####"});
    const PreparedMap<T> map = prepareMap(level.view());
    ASSERT_TRUE(map.isValid());
    const MoveResult<T> r = moveAndSlide(map, {{{4, 14}, {12, 16}}, {0, 5}});
    EXPECT_EQ(r.status, MoveStatus::Blocked);
    EXPECT_EQ(r.position.y, T(16));
    EXPECT_TRUE(r.onGround);
    EXPECT_TRUE(r.blockedY);
    EXPECT_FALSE(r.onWall);
    EXPECT_FALSE(r.blockedX);
    EXPECT_FALSE(r.onCeiling);
    EXPECT_EQ(r.contactCount, 1);
}

// Walking right into tile (2, 0) = [32, 48] from x = 10 (right edge 30) by 8: touches at 32,
// normal (-1, 0): a wall on the right.
TYPED_TEST(Mover, wallSetsOnWallWithItsSide) {
    using T = TypeParam;
    scenarios::Level<T> level({"..#.", "....", "...."});
    const PreparedMap<T> map = prepareMap(level.view());
    Contact<T> contacts[8];
    const MoveResult<T> r = moveAndSlide(map, {{{10, 2}, {20, 10}}, {8, 0}}, contacts, 8);
    EXPECT_EQ(r.position.x, T(12));
    EXPECT_TRUE(r.onWall);
    EXPECT_TRUE(r.blockedX);
    EXPECT_EQ(r.wallNormalX, -1);
    ASSERT_EQ(r.contactCount, 1);
    EXPECT_EQ(contacts[0].tile, (Cell{2, 0}));
}

// Jumping up into the ceiling row 0 (bottom at 16) from y = 20 by -10: normal (0, 1).
TYPED_TEST(Mover, ceilingSetsOnCeiling) {
    using T = TypeParam;
    scenarios::Level<T> level({"####", "....", "...."});
    const PreparedMap<T> map = prepareMap(level.view());
    const MoveResult<T> r = moveAndSlide(map, {{{4, 20}, {8, 8}}, {0, -10}});
    EXPECT_EQ(r.position.y, T(16));
    EXPECT_TRUE(r.onCeiling);
    EXPECT_FALSE(r.onGround);
}

// velocity * dt with a double dt compiles with a float vector, and with a float dt.
TEST(Mover, scalarProductTakesAnyArithmeticScalar) {
    const Vec2<float> v{3, -2};
    const double dt = 0.5;
    const Vec2<float> a = v * dt;
    const Vec2<float> b = 0.5f * v;
    const Vec2<double> c = Vec2<double>{1, 2} * 2;
    EXPECT_EQ(a, (Vec2<float>{1.5f, -1}));
    EXPECT_EQ(b, (Vec2<float>{1.5f, -1}));
    EXPECT_EQ(c, (Vec2<double>{2, 4}));
}

TYPED_TEST(Mover, badInputIsRefusedNotResolved) {
    using T = TypeParam;
    scenarios::Level<T> level({"....", "####"});
    const PreparedMap<T> map = prepareMap(level.view());
    const T nan = std::numeric_limits<T>::quiet_NaN();
    EXPECT_EQ(moveAndSlide(map, {{{0, 0}, {4, 4}}, {nan, 0}}).status, MoveStatus::InvalidInput);
    EXPECT_EQ(moveAndSlide(map, {{{0, 0}, {0, 4}}, {1, 0}}).status, MoveStatus::InvalidInput);
    const MoveResult<T> r = moveAndSlide(map, {{{1, 2}, {-1, 4}}, {1, 0}});
    EXPECT_EQ(r.position, (Vec2<T>{1, 2}));
    TileMapView<T> bad = level.view();
    bad.tileSize = {0, 16};
    const PreparedMap<T> refused = prepareMap(bad);
    EXPECT_FALSE(refused.isValid());
    EXPECT_EQ(refused.error(), MapError::NonPositiveTileSize);
    EXPECT_EQ(moveAndSlide(refused, {{{0, 0}, {4, 4}}, {1, 0}}).status, MoveStatus::InvalidInput);
    EXPECT_EQ(moveAndSlide(PreparedMap<T>{}, {{{0, 0}, {4, 4}}, {1, 0}}).status, MoveStatus::InvalidInput);
    EXPECT_EQ(PreparedMap<T>{}.error(), MapError::NotPrepared);
    EXPECT_STREQ(describe(MapError::NotPrepared),
                 "map: not prepared (a default-constructed PreparedMap; use prepareMap)");
}

// A box 100 tiles wide has maxContacts 104 + 3 > kInlineContacts: with no buffer the frame is
// still resolved, flags and all, with no contacts stored; with a buffer of maxContacts entries
// it stores all 101 floor tiles it lands on.
TYPED_TEST(Mover, wideBoxGetsItsFlagsWithoutABuffer) {
    using T = TypeParam;
    std::vector<std::string> rows{std::string(120, '.'), std::string(120, '#')};
    scenarios::Level<T> level(rows);
    const PreparedMap<T> map = prepareMap(level.view());
    const MoveInput<T> in{{{8, 0}, {1600, 8}}, {0, 16}};
    const std::int32_t bound = maxContacts(in.box.size, level.view().tileSize);
    EXPECT_EQ(bound, 102 + 2);
    const MoveResult<T> bare = moveAndSlide(map, in);
    EXPECT_EQ(bare.status, MoveStatus::Blocked);
    EXPECT_EQ(bare.contactCount, 101);
    EXPECT_FALSE(bare.contactsStored);
    EXPECT_TRUE(bare.onGround && bare.blockedY && !bare.onWall && !bare.onCeiling);
    EXPECT_EQ(bare.position.y, T(8));
    std::vector<Contact<T>> shortBuffer(100);
    const MoveResult<T> cut = moveAndSlide(map, in, shortBuffer.data(), 100);
    EXPECT_FALSE(cut.contactsStored);
    EXPECT_EQ(cut.position, bare.position);
    std::vector<Contact<T>> contacts(static_cast<std::size_t>(bound));
    const MoveResult<T> r = moveAndSlide(map, in, contacts.data(), bound);
    EXPECT_EQ(r.status, MoveStatus::Blocked);
    EXPECT_EQ(r.contactCount, 101);
    EXPECT_TRUE(r.contactsStored);
    EXPECT_TRUE(r.onGround);
    EXPECT_EQ(r.position.y, T(8));
    EXPECT_EQ(contacts[100].tile, (Cell{100, 1}));
}

// Jumping into a ceiling while walking into a wall: both blocked components go, clipVelocity
// zeroes exactly those, and the clipped displacement keeps nothing of them.
TYPED_TEST(Mover, clipVelocityZeroesWhatPushesIntoTheFacesHit) {
    using T = TypeParam;
    // Tile (1, 0) = [16, 32] x [0, 16] above; tile (3, 1) = [48, 64] x [16, 32] to the right.
    scenarios::Level<T> level({".#..", "...#", "...."});
    const PreparedMap<T> map = prepareMap(level.view());
    // A 10x10 box at (20, 20) moving up 8: its top (20) hits the ceiling's bottom (16) at 1/2.
    const MoveResult<T> up = moveAndSlide(map, {{{20, 20}, {10, 10}}, {0, -8}});
    EXPECT_TRUE(up.onCeiling && up.blockedY && !up.onGround && !up.onWall);
    EXPECT_EQ(up.position.y, T(16));
    EXPECT_EQ(clipVelocity(Vec2<T>{3, -5}, up), (Vec2<T>{3, 0}));
    EXPECT_EQ(clipVelocity(Vec2<T>{3, 5}, up), (Vec2<T>{3, 5}));  // falling away is kept
    EXPECT_EQ(up.clippedDisplacement, (Vec2<T>{0, 0}));
    // Moving right 12 and down 2 from (30, 18) (right edge 40): the wall at 48 stops x at 2/3.
    const MoveResult<T> right = moveAndSlide(map, {{{30, 18}, {10, 10}}, {12, 2}});
    EXPECT_TRUE(right.onWall && right.blockedX && !right.blockedY);
    EXPECT_EQ(right.wallNormalX, -1);
    EXPECT_EQ(right.position.x, T(38));
    EXPECT_EQ(right.clippedDisplacement, (Vec2<T>{0, 2}));
    EXPECT_EQ(clipVelocity(Vec2<T>{6, 1}, right), (Vec2<T>{0, 1}));
    EXPECT_EQ(clipVelocity(Vec2<T>{-6, 1}, right), (Vec2<T>{-6, 1}));  // walking away is kept
    const MoveResult<T> free = moveAndSlide(map, {{{0, 34}, {4, 4}}, {3, 1}});
    EXPECT_EQ(free.status, MoveStatus::Moved);
    EXPECT_EQ(free.clippedDisplacement, (Vec2<T>{3, 1}));
    EXPECT_EQ(clipVelocity(Vec2<T>{6, 1}, free), (Vec2<T>{6, 1}));
}

TEST(Mover, resolveMoveOnAMapNotPreparedIsInvalidInput) {
    const std::uint8_t cells[4] = {0, 0, 0, 1};
    const TileMapView<float> view{{0, 0}, {16, 16}, 2, 2, cells};
    const ResolveResult<float> unprepared = resolveMove(PreparedMap<float>{}, {{{1, 2}, {4, 4}}, {3, 3}}, {});
    EXPECT_EQ(unprepared.status, ResolveStatus::InvalidInput);
    EXPECT_EQ(unprepared.position, (Vec2<float>{1, 2}));
    const ResolveResult<float> moved = resolveMove(prepareMap(view), {{{1, 2}, {4, 4}}, {3, 3}}, {});
    EXPECT_EQ(moved.status, ResolveStatus::Moved);
    EXPECT_EQ(moved.position, (Vec2<float>{4, 5}));
}

TEST(Mover, maxContactsOfInvalidSizesIsZero) {
    EXPECT_EQ(maxContacts(Vec2<float>{0, 1}, Vec2<float>{16, 16}), 0);
    EXPECT_EQ(maxContacts(Vec2<double>{1, 1}, Vec2<double>{std::nan(""), 16}), 0);
    EXPECT_EQ(maxContacts(Vec2<float>{16, 16}, Vec2<float>{16, 16}), 6);
    EXPECT_EQ(maxContacts(Vec2<double>{1e300, 1}, Vec2<double>{1e-300, 1}),
              std::numeric_limits<std::int32_t>::max());
}

// ---- Properties over random scenes (tilesweep/scenarios/mover_scenes.h) ----

template <class T>
void expectSameAsResolveMove(const scenarios::RandomScene<T>& scene, std::uint64_t caseIndex) {
    const PreparedMap<T> map = prepareMap(scene.view());
    ASSERT_TRUE(map.isValid());
    std::vector<Contact<T>> expected(4096);
    const ResolveResult<T> s =
        resolveMove<T>({scene.view(), scene.box, scene.move}, {expected.data(), 4096, nullptr, 0});
    const std::int32_t bound = maxContacts(scene.box.size, scene.view().tileSize);
    const std::string where = "case " + std::to_string(caseIndex) + ": " + scene.describe();

    // resolveMove through the prepared map: the same frame, bit for bit, start overlaps too.
    {
        std::vector<Cell> overlaps(4096);
        const ResolveResult<T> v = resolveMove<T>({scene.view(), scene.box, scene.move},
                                                  {expected.data(), 4096, overlaps.data(), 4096});
        std::vector<Contact<T>> contacts(4096);
        std::vector<Cell> preparedOverlaps(4096);
        const ResolveResult<T> p =
            resolveMove(map, {scene.box, scene.move}, {contacts.data(), 4096, preparedOverlaps.data(), 4096});
        EXPECT_EQ(std::memcmp(&p.position, &v.position, sizeof p.position), 0) << where << " prepared";
        EXPECT_EQ(p.status, v.status) << where << " prepared";
        EXPECT_EQ(p.blockedX, v.blockedX) << where << " prepared";
        EXPECT_EQ(p.blockedY, v.blockedY) << where << " prepared";
        ASSERT_EQ(p.contactCount, v.contactCount) << where << " prepared";
        ASSERT_EQ(p.startOverlapCount, v.startOverlapCount) << where << " prepared";
        for (std::int32_t k = 0; k < std::min<std::int32_t>(p.contactCount, 4096); ++k) {
            const auto& a = contacts[static_cast<std::size_t>(k)];
            const auto& b = expected[static_cast<std::size_t>(k)];
            EXPECT_TRUE(a.tile == b.tile && a.normal == b.normal &&
                        std::memcmp(&a.time, &b.time, sizeof a.time) == 0 &&
                        std::memcmp(&a.position, &b.position, sizeof a.position) == 0)
                << where << " prepared contact " << k;
        }
        for (std::int32_t k = 0; k < std::min<std::int32_t>(p.startOverlapCount, 4096); ++k)
            EXPECT_EQ(preparedOverlaps[static_cast<std::size_t>(k)], overlaps[static_cast<std::size_t>(k)])
                << where << " prepared start overlap " << k;
    }
    // The documented bound: a buffer of maxContacts never truncates.
    ASSERT_LE(s.contactCount, bound) << where;

    std::vector<Contact<T>> got(static_cast<std::size_t>(bound) + 1);
    const MoveResult<T> r = moveAndSlide(map, {scene.box, scene.move}, got.data(), bound);
    ASSERT_NE(r.status, MoveStatus::InvalidInput) << where;
    EXPECT_EQ(std::memcmp(&r.position, &s.position, sizeof r.position), 0)
        << where << " moveAndSlide " << r.position.x << "," << r.position.y << " resolveMove " << s.position.x
        << "," << s.position.y;
    EXPECT_EQ(r.status == MoveStatus::Blocked, s.status == ResolveStatus::Blocked) << where;
    ASSERT_EQ(r.contactCount, s.contactCount) << where;
    EXPECT_EQ(r.startOverlapCount, s.startOverlapCount) << where;
    bool ground = false, ceiling = false, wall = false;
    for (std::int32_t k = 0; k < s.contactCount; ++k) {
        const auto& a = got[static_cast<std::size_t>(k)];
        const auto& b = expected[static_cast<std::size_t>(k)];
        EXPECT_TRUE(a.tile == b.tile && a.normal == b.normal &&
                    std::memcmp(&a.time, &b.time, sizeof a.time) == 0 &&
                    std::memcmp(&a.position, &b.position, sizeof a.position) == 0)
            << where << " contact " << k;
        ground = ground || b.normal.y == -1;
        ceiling = ceiling || b.normal.y == 1;
        wall = wall || b.normal.x != 0;
    }
    EXPECT_EQ(r.onGround, ground) << where;
    EXPECT_EQ(r.onCeiling, ceiling) << where;
    EXPECT_EQ(r.onWall, wall) << where;
    EXPECT_EQ(r.blockedX, wall) << where;
    EXPECT_EQ(r.blockedY, ground || ceiling) << where;

    // The solver's blocked axes are those of the contacts' normals.
    EXPECT_EQ(s.blockedX, wall) << where;
    EXPECT_EQ(s.blockedY, ground || ceiling) << where;
    EXPECT_TRUE(r.contactsStored) << where;
    EXPECT_EQ(r.wallNormalX, wall ? static_cast<std::int8_t>(scene.move.x > 0 ? -1 : 1) : 0) << where;

    // With no buffer, and with a buffer one short of the count: the same frame and flags for a
    // box of any size, nothing stored in the short one (never half-filled).
    const MoveResult<T> bare = moveAndSlide(map, {scene.box, scene.move});
    EXPECT_EQ(bare.status, r.status) << where;
    EXPECT_EQ(std::memcmp(&bare.position, &r.position, sizeof r.position), 0) << where;
    EXPECT_EQ(bare.onGround, r.onGround) << where;
    EXPECT_EQ(bare.onCeiling, r.onCeiling) << where;
    EXPECT_EQ(bare.onWall, r.onWall) << where;
    EXPECT_EQ(bare.wallNormalX, r.wallNormalX) << where;
    EXPECT_EQ(bare.contactCount, r.contactCount) << where;
    EXPECT_FALSE(bare.contactsStored) << where;
    if (s.contactCount > 0) {
        std::vector<Contact<T>> shortBuffer(static_cast<std::size_t>(s.contactCount));
        for (auto& c : shortBuffer) c.tile = {-7, -7};
        const MoveResult<T> cut =
            moveAndSlide(map, {scene.box, scene.move}, shortBuffer.data(), s.contactCount - 1);
        EXPECT_EQ(cut.contactCount, s.contactCount) << where;
        EXPECT_FALSE(cut.contactsStored) << where;
        for (const auto& c : shortBuffer) EXPECT_EQ(c.tile, (Cell{-7, -7})) << where << " half-filled";
    }
}

TYPED_TEST(Mover, matchesResolveMoveBitForBitAndNeverExceedsMaxContacts) {
    using T = TypeParam;
    std::mt19937_64 rng(0x5eed12);
    const std::uint64_t cases = test::propertyCases(3000);
    for (std::uint64_t k = 0; k < cases && !::testing::Test::HasFailure(); ++k) {
        const scenarios::RandomScene<T> scene = scenarios::randomScene<T>(rng);
        expectSameAsResolveMove(scene, k);
    }
}

}  // namespace
}  // namespace tilesweep

// SPDX-License-Identifier: MIT
// Many movers at once (tilesweep/batch.h): a batch on 1, 2 and 3 threads gives every mover
// exactly what moveAndSlide and resolveMove give it alone, bit for bit, over random maps and
// movers (tests/mover_scenes.h). TILESWEEP_PROPERTY_CASES sets the number of maps (default 300,
// 500 movers each).
#include "tilesweep/batch.h"

#include "mover_scenes.h"

#include "tilesweep/resolve.h"

#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

namespace tilesweep {
namespace {

template <class T>
class Batch : public ::testing::Test {};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(Batch, Scalars);

template <class T>
bool sameResult(const MoveResult<T>& a, const MoveResult<T>& b) {
    return std::memcmp(&a.position, &b.position, sizeof a.position) == 0 && a.status == b.status &&
           a.blockedX == b.blockedX && a.blockedY == b.blockedY && a.onGround == b.onGround &&
           a.onCeiling == b.onCeiling && a.onWall == b.onWall && a.wallNormalX == b.wallNormalX &&
           a.contactCount == b.contactCount && a.startOverlapCount == b.startOverlapCount &&
           std::memcmp(&a.clippedDisplacement, &b.clippedDisplacement, sizeof a.clippedDisplacement) == 0 &&
           a.contactsStored == b.contactsStored;
}

TYPED_TEST(Batch, givesEveryMoverWhatResolveMoveGivesItAlone) {
    using T = TypeParam;
    std::mt19937_64 rng(0xba7c4);
    BatchPool one(1);
    BatchPool two(2);
    BatchPool three(3);
    EXPECT_EQ(one.threadCount(), 1);
    EXPECT_EQ(two.threadCount(), 2);
    const std::uint64_t maps = test::propertyCases(3000) / 10 + 1;
    constexpr std::size_t kMovers = 500;
    std::vector<MoveInput<T>> inputs(kMovers);
    std::vector<MoveResult<T>> alone(kMovers), byOne(kMovers), byTwo(kMovers), byThree(kMovers),
        inline_(kMovers);
    std::vector<Contact<T>> contacts(4096);
    for (std::uint64_t m = 0; m < maps && !::testing::Test::HasFailure(); ++m) {
        const test::RandomScene<T> level = test::randomScene<T>(rng);
        const PreparedMap<T> map = prepareMap(level.view());
        ASSERT_TRUE(map.isValid());
        for (auto& in : inputs) test::randomMover(rng, level, in.box, in.displacement);
        for (std::size_t k = 0; k < kMovers; ++k) alone[k] = moveAndSlide(map, inputs[k]);
        moveAndSlideBatch(map, inputs.data(), byOne.data(), kMovers, &one);
        moveAndSlideBatch(map, inputs.data(), byTwo.data(), kMovers, &two);
        moveAndSlideBatch(map, inputs.data(), byThree.data(), kMovers, &three);
        moveAndSlideBatch(map, inputs.data(), inline_.data(), kMovers);
        for (std::size_t k = 0; k < kMovers; ++k) {
            ASSERT_TRUE(sameResult(alone[k], byOne[k]) && sameResult(alone[k], byTwo[k]) &&
                        sameResult(alone[k], byThree[k]) && sameResult(alone[k], inline_[k]))
                << "map " << m << " mover " << k;
            // And the core resolver, with a buffer large enough for any of these frames.
            const SweepResult<T> s = resolveMove<T>({level.view(), inputs[k].box, inputs[k].displacement},
                                                    {contacts.data(), 4096, nullptr, 0});
            ASSERT_EQ(std::memcmp(&s.position, &byTwo[k].position, sizeof s.position), 0)
                << "map " << m << " mover " << k;
            ASSERT_EQ(s.contactCount, byTwo[k].contactCount);
            ASSERT_EQ(s.startOverlapCount, byTwo[k].startOverlapCount);
        }
    }
}

TEST(Batch, emptyAndNullBatchesDoNothing) {
    test::Level<float> level({"....", "####"});
    const PreparedMap<float> map = prepareMap(level.view());
    BatchPool pool(2);
    MoveResult<float> result{};
    result.contactCount = 7;
    moveAndSlideBatch(map, nullptr, &result, 1, &pool);
    moveAndSlideBatch(map, nullptr, nullptr, 0, &pool);
    EXPECT_EQ(result.contactCount, 7);
}

// A pool outlives many batches, and a large batch is split across its threads (chunks of 256).
TEST(Batch, poolRunsEveryIndexExactlyOnce) {
    BatchPool pool(3);
    for (int round = 0; round < 50; ++round) {
        std::vector<int> hits(10007, 0);
        pool.run(
            hits.size(), 64,
            [](void* ctx, std::size_t b, std::size_t e) {
                auto& h = *static_cast<std::vector<int>*>(ctx);
                for (std::size_t k = b; k < e; ++k) ++h[k];
            },
            &hits);
        for (int h : hits) ASSERT_EQ(h, 1);
    }
}

}  // namespace
}  // namespace tilesweep

// SPDX-License-Identifier: MIT
// The single box-against-tile sweep. Expected values are worked out from docs/contract.md.
#include "tilesweep/box_sweep.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace tilesweep {
namespace {

template <class T>
class BoxSweep : public ::testing::Test {};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(BoxSweep, Scalars);

// Tile [32, 48]^2 throughout. Box [0, 8] x [36, 44] moving +40 on x: entry (32 - 8)/40 = 0.6.
TYPED_TEST(BoxSweep, headOnHitEntersAtLaterAxis) {
    using T = TypeParam;
    const auto out = sweepBox<T>({{{0, 36}, {8, 8}}, {40, 0}, {32, 32}, {48, 48}});
    EXPECT_EQ(out.status, BoxSweepStatus::Blocks);
    EXPECT_EQ(out.axis, Axis::X);
    EXPECT_EQ(out.time, static_cast<T>(0.6L));
}

// Reaching the face exactly at t = 1 is not a block (I must meet the open (0, 1)).
TYPED_TEST(BoxSweep, touchingAtEndOfMoveIsNotAHit) {
    using T = TypeParam;
    const auto out = sweepBox<T>({{{0, 36}, {8, 8}}, {24, 0}, {32, 32}, {48, 48}});
    EXPECT_EQ(out.status, BoxSweepStatus::Misses);
}

// Touching at t = 0 and moving in: blocks at time 0 (resting contact).
TYPED_TEST(BoxSweep, touchingAtStartAndMovingInBlocksAtZero) {
    using T = TypeParam;
    const auto out = sweepBox<T>({{{24, 36}, {8, 8}}, {5, 0}, {32, 32}, {48, 48}});
    EXPECT_EQ(out.status, BoxSweepStatus::Blocks);
    EXPECT_EQ(out.time, T(0));
    const auto away = sweepBox<T>({{{24, 36}, {8, 8}}, {-5, 0}, {32, 32}, {48, 48}});
    EXPECT_EQ(away.status, BoxSweepStatus::Misses);
}

// Static y axis that only touches the tile (box y in [24, 32]): never overlaps, never blocks.
TYPED_TEST(BoxSweep, slidingAlongFaceNeverBlocks) {
    using T = TypeParam;
    const auto out = sweepBox<T>({{{0, 24}, {8, 8}}, {100, 0}, {32, 32}, {48, 48}});
    EXPECT_EQ(out.status, BoxSweepStatus::Misses);
}

// Box [24, 32]^2 moving (16, 16) touches the tile's corner point at t = 0 and moves into it:
// x and y both enter at t = 0 exactly, a tie settled by the exposure flags.
TYPED_TEST(BoxSweep, exactTieFollowsExposedFace) {
    using T = TypeParam;
    BoxSweepInput<T> in{{{24, 24}, {8, 8}}, {16, 16}, {32, 32}, {48, 48}};
    in.xFaceExposed = true;
    in.yFaceExposed = true;
    EXPECT_EQ(sweepBox<T>(in).axis, Axis::Y);
    in.yFaceExposed = false;
    EXPECT_EQ(sweepBox<T>(in).axis, Axis::X);
    in.xFaceExposed = false;
    EXPECT_EQ(sweepBox<T>(in).axis, Axis::Y);
    in.xFaceExposed = false;
    in.yFaceExposed = true;
    const auto out = sweepBox<T>(in);
    EXPECT_EQ(out.status, BoxSweepStatus::Blocks);
    EXPECT_EQ(out.axis, Axis::Y);
    EXPECT_EQ(out.time, T(0));
}

TYPED_TEST(BoxSweep, startOverlapNeverBlocks) {
    using T = TypeParam;
    const auto out = sweepBox<T>({{{30, 30}, {8, 8}}, {10, 10}, {32, 32}, {48, 48}});
    EXPECT_EQ(out.status, BoxSweepStatus::StartsOverlapping);
}

// A denormal displacement on one axis still moves that axis: box [0, 8] at x, tile from 8:
// touching, so entry time 0 on x; y static overlapping: blocks at 0 on x.
TYPED_TEST(BoxSweep, subnormalDisplacementIsExact) {
    using T = TypeParam;
    const T tiny = std::numeric_limits<T>::denorm_min();
    const auto out = sweepBox<T>({{{0, 36}, {8, 8}}, {tiny, 0}, {8, 32}, {48, 48}});
    EXPECT_EQ(out.status, BoxSweepStatus::Blocks);
    EXPECT_EQ(out.axis, Axis::X);
    EXPECT_EQ(out.time, T(0));
    // One denormal short of touching: entry time 1 exactly -> no block.
    const auto short1 = sweepBox<T>({{{-tiny, 36}, {8, 8}}, {tiny, 0}, {8, 32}, {48, 48}});
    EXPECT_EQ(short1.status, BoxSweepStatus::Misses);
}

TYPED_TEST(BoxSweep, invalidInputNeverGivesNaN) {
    using T = TypeParam;
    const T nan = std::numeric_limits<T>::quiet_NaN();
    const auto out = sweepBox<T>({{{0, 36}, {8, 8}}, {nan, 0}, {32, 32}, {48, 48}});
    EXPECT_EQ(out.status, BoxSweepStatus::InvalidInput);
    EXPECT_FALSE(std::isnan(out.time));
    const auto inverted = sweepBox<T>({{{0, 36}, {8, 8}}, {1, 0}, {48, 32}, {32, 48}});
    EXPECT_EQ(inverted.status, BoxSweepStatus::InvalidInput);
}

}  // namespace
}  // namespace tilesweep

// SPDX-License-Identifier: MIT
// The names before the one naming scheme (<Op>Input, <Op>Result, <Op>Status) still compile for
// one release, as the same types, and so does the umbrella header's old name, tilesweep/sweep.h
// (now tilesweep/tilesweep.hpp), so that a game can upgrade and then rename. Built with -w:
// everywhere else a use of them warns.
#include "tilesweep/sweep.h"  // the only include: it still brings every header of the core library

#include <gtest/gtest.h>

#include <type_traits>

namespace {

static_assert(std::is_same<tilesweep::SweepInput<float>, tilesweep::ResolveInput<float>>::value);
static_assert(std::is_same<tilesweep::SweepResult<double>, tilesweep::ResolveResult<double>>::value);
static_assert(std::is_same<tilesweep::Status, tilesweep::ResolveStatus>::value);
static_assert(std::is_same<tilesweep::BoxSweepOutput<float>, tilesweep::BoxSweepResult<float>>::value);
static_assert(std::is_same<tilesweep::BoxSweepState, tilesweep::BoxSweepStatus>::value);

TEST(DeprecatedNames, codeWrittenWithTheOldNamesStillResolves) {
    const std::uint8_t cells[] = {0, 0, 1, 1};  // 2 x 2 tiles of 16, the bottom row solid
    const tilesweep::TileMapView<float> map{{0, 0}, {16, 16}, 2, 2, cells};
    const tilesweep::SweepInput<float> input{map, {{2, 2}, {10, 10}}, {0, 8}};  // bottom 12 -> 16
    const tilesweep::SweepResult<float> r = tilesweep::resolveMove(input, tilesweep::ResolveOutput<float>{});
    EXPECT_EQ(r.status, tilesweep::Status::Blocked);
    EXPECT_EQ(r.position.y, 6.0f);
    const tilesweep::BoxSweepOutput<float> s =
        tilesweep::sweepBox<float>({{{2, 2}, {10, 10}}, {0, 8}, {0, 16}, {16, 32}});
    EXPECT_EQ(s.status, tilesweep::BoxSweepState::Blocks);
}

TEST(DeprecatedNames, theOldUmbrellaHeaderStillBringsTheGameLoop) {
    const std::uint8_t cells[] = {0, 0, 1, 1};
    const tilesweep::TileMapView<float> map{{0, 0}, {16, 16}, 2, 2, cells};
    const tilesweep::PreparedMap<float> prepared = tilesweep::prepareMap(map);  // mover.h
    EXPECT_TRUE(prepared.isValid());
    const tilesweep::MoveResult<float> r = tilesweep::moveAndSlide(prepared, {{{2, 2}, {10, 10}}, {0, 8}});
    EXPECT_TRUE(r.onGround);
    EXPECT_EQ(r.position.y, 6.0f);
}

}  // namespace

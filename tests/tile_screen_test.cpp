// SPDX-License-Identifier: MIT
// The tile screen of double frames (FastFrame<double>::testTile, src/fast_frame.h), which
// decides from the high parts of the four distances and defers to the exact test whenever that
// test would read a low part, against the exact test itself (axis_sweep.h's testTile on the
// frame's own axes): the same verdict and the same time on every tile near the box's path. The
// draws are built to sit where the high parts alone cannot decide: far edges that are not
// doubles (a nonzero low part), paths exactly through a tile's corner (an exact tie of the two
// entries, the Tie verdict, or of one axis's entry and the other's exit, a miss) and one ulp
// either side of it (inside the product filter's band), and near-ties on tiles whose distances
// are rounded. Half the random frames lie on a map far from the origin, where every distance is
// an exact double (FastFrame::distancesExact) and the screen needs no filter; every tile of that
// map lies where Sterbenz's lemma holds for them, so all of them are compared, as on the other
// map, whose frames never take that way.
#include "axis_sweep.h"
#include "fast_frame.h"
#include "range_admission.h"

#include "tilesweep/resolve.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <vector>

namespace tilesweep::detail {
namespace {

constexpr std::int32_t kCells = 12;

/// A random double in [low, high).
double randomIn(std::mt19937_64& rng, double low, double high) {
    return std::uniform_real_distribution<double>(low, high)(rng);
}

struct Tally {
    int tiles = 0;
    int ties = 0;
    int blocks = 0;
    int startsOverlapping = 0;
    int farEdgeNotADouble = 0;
    int exactFrames = 0;       ///< frames whose tile distances are all exact doubles
    int exactFrameBlocks = 0;  ///< tiles of those frames that block (or tie)
};

/// Every tile of the map against the frame: the screened test's verdict and time are the
/// exact test's.
void expectScreenMatchesExactTest(const ResolveInput<double>& in, Tally& tally) {
    const MapRange range = doubleMapRange(in.map);
    ASSERT_TRUE(admitDoubleFrame(in, range));
    FastFrame<double> frame(in, range);
    FastFrame<double> exactFrame(in, range);
    const auto& mx = exactFrame.axis(0);
    const auto& my = exactFrame.axis(1);
    tally.farEdgeNotADouble += (mx.highLow != 0) + (my.highLow != 0);
    tally.exactFrames += frame.distancesExact();
    for (std::int64_t j = -1; j <= kCells; ++j) {
        for (std::int64_t i = -1; i <= kCells; ++i) {
            bool refined = false;
            const auto exact =
                testTile(mx, my, mx.edge(i), mx.edge(i + 1), my.edge(j), my.edge(j + 1), refined);
            const auto screened = frame.testTile(i, j);
            ++tally.tiles;
            ASSERT_EQ(static_cast<int>(screened.verdict), static_cast<int>(exact.verdict))
                << "tile (" << i << ", " << j << ") of box (" << in.box.pos.x << ", " << in.box.pos.y
                << ") size (" << in.box.size.x << ", " << in.box.size.y << ") moving (" << in.displacement.x
                << ", " << in.displacement.y << ")";
            if (exact.verdict == TileVerdict::Misses || exact.verdict == TileVerdict::StartsOverlapping) {
                tally.startsOverlapping += exact.verdict == TileVerdict::StartsOverlapping;
                continue;
            }
            EXPECT_EQ(screened.time.num.hi, exact.time.num.hi);
            EXPECT_EQ(screened.time.num.lo, exact.time.num.lo);
            EXPECT_EQ(screened.time.den, exact.time.den);
            tally.ties += exact.verdict == TileVerdict::Tie;
            tally.blocks += exact.verdict != TileVerdict::Tie;
            tally.exactFrameBlocks += frame.distancesExact();
        }
    }
}

struct Grid {
    explicit Grid(Vec2<double> origin = {-3.25, 1.5})
        : view{origin, {0.75, 1.25}, kCells, kCells, solid.data()} {}
    std::vector<std::uint8_t> solid = std::vector<std::uint8_t>(kCells * kCells, 0);
    TileMapView<double> view;
};

TEST(TileScreen, agreesWithTheExactTestOnRandomFrames) {
    const Grid grid;
    const Grid farGrid({96.75, 201.5});  // 9 by 15 units, some 100 from the origin
    std::mt19937_64 rng(19);
    Tally tally;
    for (int draw = 0; draw < 800; ++draw) {
        ResolveInput<double> in{grid.view, {}, {}};
        if (draw % 2 == 0) {
            // On the far map: sizes of whole quarters (far edges that are doubles: the frame's
            // distances are exact doubles) or arbitrary ones (far edges that are pairs).
            in.map = farGrid.view;
            in.box.pos = {randomIn(rng, 99.0, 103.0), randomIn(rng, 204.0, 212.0)};
            std::uniform_int_distribution<int> quarters(1, 8);
            if (draw % 4 == 0) {
                in.box.size = {0.25 * quarters(rng), 0.25 * quarters(rng)};
            } else {
                in.box.size = {randomIn(rng, 0.1, 2.0), randomIn(rng, 0.1, 2.0)};
            }
        } else {
            in.box.pos = {randomIn(rng, -2.0, 4.0), randomIn(rng, 2.0, 12.0)};
            in.box.size = {randomIn(rng, 0.1, 2.0), randomIn(rng, 0.1, 2.0)};
        }
        in.displacement = {randomIn(rng, -4.0, 4.0), randomIn(rng, -4.0, 4.0)};
        expectScreenMatchesExactTest(in, tally);
    }
    EXPECT_GT(tally.blocks, 400);
    EXPECT_GT(tally.startsOverlapping, 100);
    EXPECT_GT(tally.farEdgeNotADouble, 400);
    EXPECT_GT(tally.exactFrames, 150);
    EXPECT_GT(tally.exactFrameBlocks, 200);
}

TEST(TileScreen, agreesWithTheExactTestOnNearTiesWhereDistancesAreRounded) {
    // A box of full precision, its far edges doubles (x in [1, 1.5) with w = 0.5, y in [2, 3.5)
    // with h = 0.5: each sum stays in its binade), and a tile whose near corner (X, Y) lies
    // beyond twice the box's near edge on both axes, where Sterbenz's lemma does not hold: its
    // distances to the box, X - (x + w) and Y - (y + h), need one bit more than a double has
    // about a third of the time. The displacement reaches the corner on both axes at nearly the
    // same time (dx from the rounded ratio, then nudged by up to 4 ulps either way), so which
    // face the box enters first is decided within the rounding of those distances: only the
    // filter and the exact test decide it right.
    const Grid grid;
    std::mt19937_64 rng(21);
    Tally tally;
    int draws = 0;
    int roundedDistances = 0;
    for (int draw = 0; draw < 20000 && draws < 400; ++draw) {
        const double x = randomIn(rng, 1.0, 1.5);
        const double y = randomIn(rng, 2.0, 3.5);
        const std::int64_t ci = std::uniform_int_distribution<std::int64_t>(0, kCells - 1)(rng);
        const std::int64_t cj = std::uniform_int_distribution<std::int64_t>(0, kCells - 1)(rng);
        const double cornerX = grid.view.origin.x + static_cast<double>(ci) * grid.view.tileSize.x;
        const double cornerY = grid.view.origin.y + static_cast<double>(cj) * grid.view.tileSize.y;
        // Beyond twice the box's coordinates, within four times them.
        if (!(cornerX > 2 * x && cornerX + grid.view.tileSize.x <= 4 * x)) continue;
        if (!(cornerY > 2 * y && cornerY + grid.view.tileSize.y <= 4 * y)) continue;
        ++draws;
        const ExactPair gapX = twoSum(cornerX, -(x + 0.5));
        const ExactPair gapY = twoSum(cornerY, -(y + 0.5));
        roundedDistances += gapX.lo != 0 || gapY.lo != 0;
        const double dy = gapY.hi * randomIn(rng, 1.2, 3.0);
        const double dx = gapX.hi * dy / gapY.hi;
        for (int nudge = -4; nudge <= 4; ++nudge) {
            ResolveInput<double> in{grid.view, {}, {}};
            in.box.pos = {x, y};
            in.box.size = {0.5, 0.5};
            double nudged = dx;
            for (int k = 0; k < std::abs(nudge); ++k) nudged = std::nextafter(nudged, nudge > 0 ? 1e9 : -1e9);
            in.displacement = {nudged, dy};
            expectScreenMatchesExactTest(in, tally);
            if (::testing::Test::HasFatalFailure()) return;
        }
    }
    EXPECT_GE(draws, 400);
    EXPECT_GT(roundedDistances, 80);
    EXPECT_EQ(tally.exactFrames, 0);
    EXPECT_GT(tally.blocks, 2000);
}

TEST(TileScreen, agreesWithTheExactTestOnPathsThroughACorner) {
    // The far corner (x + w, y + h) reaches the corner (X, Y) of tile (ci, cj) at t = 1/2 on
    // both axes: X - (x + w) and Y - (y + h) are doubles D, E (retried until they are), and the
    // displacement is (2D, 2E), so both entries are exactly 1/2 (a Tie). The position nudged by
    // one ulp either way puts the two entries a hair apart, inside the product filter's band.
    const Grid grid;
    std::mt19937_64 rng(20);
    Tally tally;
    int corners = 0;
    for (int draw = 0; draw < 4000 && corners < 300; ++draw) {
        const std::int64_t ci = std::uniform_int_distribution<std::int64_t>(3, kCells - 2)(rng);
        const std::int64_t cj = std::uniform_int_distribution<std::int64_t>(3, kCells - 2)(rng);
        const double cornerX = grid.view.origin.x + static_cast<double>(ci) * grid.view.tileSize.x;
        const double cornerY = grid.view.origin.y + static_cast<double>(cj) * grid.view.tileSize.y;
        const double w = randomIn(rng, 0.1, 1.0);
        const double h = randomIn(rng, 0.1, 1.0);
        const double x = cornerX - w - randomIn(rng, 0.05, 1.0);
        const double y = cornerY - h - randomIn(rng, 0.05, 1.0);
        const ExactPair gapX = twoSum(cornerX - x, -w);  // cornerX - x is exact (Sterbenz)
        const ExactPair gapY = twoSum(cornerY - y, -h);
        if (gapX.lo != 0 || gapY.lo != 0 || !(gapX.hi > 0 && gapY.hi > 0)) continue;
        ++corners;
        for (int nudge = -1; nudge <= 1; ++nudge) {
            ResolveInput<double> in{grid.view, {}, {}};
            const double nudgedX = nudge == 0 ? x : std::nextafter(x, nudge > 0 ? 1e9 : -1e9);
            in.box.pos = {nudgedX, y};
            in.box.size = {w, h};
            in.displacement = {2 * gapX.hi, 2 * gapY.hi};
            expectScreenMatchesExactTest(in, tally);
            if (::testing::Test::HasFatalFailure()) return;
            // Grazing: the box starts level with tile (ci, cj - 1), whose top edge is Y, and its
            // corner (x + w, y) passes exactly through (X, Y) at t = 1/2, so that the x entry
            // equals the y exit (E == X: a miss, decided only by an exact comparison).
            const double grazeY = cornerY - randomIn(rng, 0.05, 0.9 * h);
            const double gapUp = cornerY - grazeY;  // exact (Sterbenz)
            in.box.pos = {nudgedX, grazeY};
            in.displacement = {2 * gapX.hi, 2 * gapUp};
            expectScreenMatchesExactTest(in, tally);
            if (::testing::Test::HasFatalFailure()) return;
        }
    }
    EXPECT_GE(corners, 300);
    EXPECT_GE(tally.ties, 250);
    EXPECT_GT(tally.farEdgeNotADouble, 100);
}

}  // namespace
}  // namespace tilesweep::detail

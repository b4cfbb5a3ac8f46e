// SPDX-License-Identifier: MIT
// The zero move (src/zero_move.h) against the exact reference: frames whose displacement is
// (0, 0), with box edges on grid lines, one rounding away from them and far from them, at far
// origins, huge and tiny magnitudes, float subnormals and tile sizes that are not powers of two.
// Each case asserts the whole answer of resolveMove (position bit for bit, no contact, the start
// overlaps in order), that the early exit either declines or gives that same answer, and, where
// the early exit is meant to settle a case (edges on lines: the frames of a resting game), that
// it does. Counts of the frames the estimate and the settlement decided keep the random cases
// from being vacuous. Invalid input must reach the ordinary path and come back InvalidInput.
#include "zero_move.h"

#include "tilesweep/mover.h"
#include "tilesweep/oracle/exact/exact_resolve.h"
#include "tilesweep/resolve.h"
#include "tilesweep/scene/scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace tilesweep {
namespace {

template <class T>
bool sameBits(T a, T b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

/// What the early exit did with a frame.
enum class Exit { Declined, Estimated, Settled };

template <class T>
struct Checked {
    Exit exit = Exit::Declined;
    std::string failure;  ///< empty when the frame's answer is the exact reference's
};

template <class T>
std::string describe(const TileMap<T>& map, Box<T> box) {
    char text[400];
    std::snprintf(text, sizeof text, "origin (%a, %a) tile (%a, %a) %dx%d box (%a, %a) size (%a, %a)",
                  static_cast<double>(map.origin.x), static_cast<double>(map.origin.y),
                  static_cast<double>(map.tileSize.x), static_cast<double>(map.tileSize.y), map.columns,
                  map.rows, static_cast<double>(box.pos.x), static_cast<double>(box.pos.y),
                  static_cast<double>(box.size.x), static_cast<double>(box.size.y));
    return text;
}

/// One zero-move frame through resolveMove and through the early exit alone, both compared with
/// the exact reference. The map and box must be valid.
template <class T>
Checked<T> checkZeroMove(const TileMap<T>& map, Box<T> box) {
    Checked<T> c;
    const oracle::ExactFrame exact = oracle::resolveFrameExact(oracle::toExact(map), oracle::toExact(box),
                                                               {oracle::Rational(0), oracle::Rational(0)});
    const ResolveInput<T> in{map.view(), box, {T(0), T(0)}};
    std::vector<Cell> overlaps(64);
    std::vector<Contact<T>> contacts(8);
    const ResolveOutput<T> out{contacts.data(), 8, overlaps.data(), 64};
    const auto matches = [&](const ResolveResult<T>& r, const char* who) -> std::string {
        std::string why;
        if (r.status != ResolveStatus::Moved)
            why = "status";
        else if (!sameBits(r.position.x, box.pos.x) || !sameBits(r.position.y, box.pos.y))
            why = "position";
        else if (r.contactCount != 0)
            why = "contacts";
        else if (r.startOverlapCount != static_cast<std::int32_t>(exact.startOverlaps.size()))
            why = "overlap count";
        else
            for (std::size_t k = 0; k < exact.startOverlaps.size() && k < 64; ++k)
                if (overlaps[k].i != exact.startOverlaps[k].i || overlaps[k].j != exact.startOverlaps[k].j)
                    why = "overlapped cells";
        return why.empty()
                   ? why
                   : std::string(who) + ": " + why + " differ from the exact reference's, " +
                         describe(map, box) + " (exact count " + std::to_string(exact.startOverlaps.size()) +
                         ", got " + std::to_string(r.startOverlapCount) + ")";
    };
    c.failure = matches(resolveMove(in, out), "resolveMove");
    if (!c.failure.empty()) return c;
    const auto estimated1 = [](T x, T w, T o, T t) {
        const double a = static_cast<double>(x) - static_cast<double>(o);
        detail::CellRange range{};
        return detail::estimateZeroMoveRange(a / static_cast<double>(t),
                                             (a + static_cast<double>(w)) / static_cast<double>(t), range);
    };
    const bool estimated = estimated1(box.pos.x, box.size.x, map.origin.x, map.tileSize.x) &&
                           estimated1(box.pos.y, box.size.y, map.origin.y, map.tileSize.y);
    ResolveResult<T> early;
    if (detail::resolveZeroMove(detail::FrameInput<T>(in), out, early)) {
        c.exit = estimated ? Exit::Estimated : Exit::Settled;
        c.failure = matches(early, "resolveZeroMove");
    }
    return c;
}

template <class T>
TileMap<T> makeMap(Vec2<T> origin, Vec2<T> tile, std::int32_t columns, std::int32_t rows,
                   std::uint32_t seed) {
    TileMap<T> map;
    map.origin = origin;
    map.tileSize = tile;
    map.columns = columns;
    map.rows = rows;
    std::mt19937 rng(seed);
    map.solid.resize(static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows));
    for (auto& s : map.solid) s = (rng() % 3 == 0) ? 0 : 1;  // mostly solid: every miss shows
    return map;
}

/// The grid line o + k*t rounded to T, and its neighbours one and two representable values away.
template <class T>
T nearLine(T origin, T tile, double k, int step) {
    T v = static_cast<T>(static_cast<double>(origin) + k * static_cast<double>(tile));
    const T toward = step > 0 ? std::numeric_limits<T>::infinity() : -std::numeric_limits<T>::infinity();
    for (int s = 0; s < std::abs(step); ++s) v = std::nextafter(v, toward);
    return v;
}

template <class T>
class ZeroMove : public ::testing::Test {};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(ZeroMove, Scalars);

// Hand-worked: a 16-px map with every cell solid, so each overlapped cell is reported.
//   - A box (16, 16) 16x16 lies exactly on cell (1, 1): its interior meets that cell only (its
//     edges touch cells 0 and 2 on both axes, which touching does not overlap).
//   - The same box one representable value left of 16 also meets column 0, and one value right
//     of 32 at its far edge also meets column 2.
TYPED_TEST(ZeroMove, boxOnGridLinesOverlapsOnlyTheCellsItsInteriorMeets) {
    using T = TypeParam;
    const TileMap<T> map = makeMap<T>({0, 0}, {16, 16}, 4, 4, 1);
    TileMap<T> full = map;
    for (auto& s : full.solid) s = 1;
    const ResolveInput<T> in{full.view(), {{16, 16}, {16, 16}}, {0, 0}};
    Cell overlaps[8];
    ResolveResult<T> early;
    ASSERT_TRUE(detail::resolveZeroMove(detail::FrameInput<T>(in), {nullptr, 0, overlaps, 8}, early))
        << "a box on lines stays on the exit";
    ASSERT_EQ(early.startOverlapCount, 1);
    EXPECT_EQ(overlaps[0].i, 1);
    EXPECT_EQ(overlaps[0].j, 1);
    const ResolveInput<T> left{full.view(), {{std::nextafter(T(16), T(0)), 16}, {16, 16}}, {0, 0}};
    const ResolveResult<T> l = resolveMove(left, {nullptr, 0, overlaps, 8});
    ASSERT_EQ(l.startOverlapCount, 2);  // (0, 1) and (1, 1)
    EXPECT_EQ(overlaps[0].i, 0);
    EXPECT_EQ(overlaps[1].i, 1);
    const ResolveInput<T> wide{full.view(), {{16, 16}, {std::nextafter(T(16), T(32)), 16}}, {0, 0}};
    const ResolveResult<T> w = resolveMove(wide, {nullptr, 0, overlaps, 8});
    ASSERT_EQ(w.startOverlapCount, 2);  // (1, 1) and (2, 1)
    EXPECT_EQ(overlaps[0].i, 1);
    EXPECT_EQ(overlaps[1].i, 2);
}

// The frames of a resting game: a box standing exactly on a floor (far edge on a line), snapped
// against a wall (low edge on a line), or both, at several origins and tile sizes (exact
// multiples), must be settled by the early exit, with the exact reference's answer.
TYPED_TEST(ZeroMove, restingBoxesAreSettledOnTheEarlyExit) {
    using T = TypeParam;
    const T origins[] = {T(0), T(-64), T(1048576), T(0.5)};
    const T tiles[] = {T(16), T(24), T(12.5), T(1)};
    int settled = 0;
    for (T o : origins)
        for (T t : tiles) {
            const TileMap<T> map = makeMap<T>({o, o}, {t, t}, 6, 5, 7);
            for (int k = 0; k <= 6; ++k) {
                // Low edge on column line k; far edge on row line 3 (standing on row 3).
                const Box<T> box{{static_cast<T>(o + T(k) * t), static_cast<T>(o + T(3) * t - T(0.75) * t)},
                                 {static_cast<T>(t / 2), static_cast<T>(T(0.75) * t)}};
                const Checked<T> c = checkZeroMove(map, box);
                ASSERT_TRUE(c.failure.empty()) << c.failure;
                EXPECT_NE(c.exit, Exit::Declined)
                    << "a resting box left the early exit: " << describe(map, box);
                settled += c.exit == Exit::Settled;
            }
        }
    EXPECT_GE(settled, 50) << "the settlement decided too few resting boxes";
}

// An origin far below the ulp of the box's coordinates: x - o rounds onto the grid line, so the
// rounded quotient is a whole number while the exact one is not. The low edge 16 with origin
// 2^-100 lies just below line 1 (cell 0 is overlapped); the far edge 16 with origin -2^-100
// lies just past line 1 (cell 1 is overlapped).
TYPED_TEST(ZeroMove, edgesARoundingAwayFromALineAreDecidedExactly) {
    using T = TypeParam;
    const T tiny = static_cast<T>(std::ldexp(1.0, -100));
    const TileMap<T> below = makeMap<T>({tiny, 0}, {16, 16}, 4, 4, 3);
    TileMap<T> full = below;
    for (auto& s : full.solid) s = 1;
    Checked<T> c = checkZeroMove(full, Box<T>{{16, 20}, {8, 8}});
    EXPECT_TRUE(c.failure.empty()) << c.failure;
    full.origin = {-tiny, 0};
    c = checkZeroMove(full, Box<T>{{4, 20}, {12, 8}});
    EXPECT_TRUE(c.failure.empty()) << c.failure;
    c = checkZeroMove(full, Box<T>{{16, 20}, {8, 8}});
    EXPECT_TRUE(c.failure.empty()) << c.failure;
}

// A box of width 2^-100 whose low edge is on line 1 (16, 16 px tiles): x + w rounds back onto
// the line, so the rounded quotient of the far edge is whole while the exact one lies past it,
// and cell 1 is overlapped.
TYPED_TEST(ZeroMove, aFarEdgeThatRoundsOntoALineIsDecidedExactly) {
    using T = TypeParam;
    TileMap<T> full = makeMap<T>({0, 0}, {16, 16}, 4, 4, 3);
    for (auto& s : full.solid) s = 1;
    const Checked<T> c = checkZeroMove(full, Box<T>{{16, 20}, {static_cast<T>(std::ldexp(1.0, -100)), 8}});
    EXPECT_TRUE(c.failure.empty()) << c.failure;
}

// Double frames where the two roundings of x - o and of the sum carry the rounded far-edge
// coordinate an ulp or two past a whole number k, or short of it, while the exact one lies on
// the other side (found by search with exact rationals): the estimate must leave them to the
// settlement (its band covers the error), which leaves them to the ordinary path.
TEST(ZeroMoveDouble, roundingsThatCrossALineAreNotTakenAsDecided) {
    struct Case {
        double x, w, o, t;
    };
    const Case cases[] = {
        {0x1.01b68582127ddp+2, 0x1.6c4eff1b3f6dap+0, 0x1.6bfea4f65c85ep-63, 0x1.d10db1b68321ap+0},
        {0x1.f2a941583e3fep+2, 0x1.6213785690984p+0, 0x1.787f6188b2623p-69, 0x1.d5be7f8b1b84cp+0},
        {0x1.2c2a615b0c77cp+3, 0x1.bf7304b6b5f18p-1, 0x1.c7e9d4cad256cp-52, 0x1.b58217889fc92p+0},
        {0x1.3e32b8fcd0781p+3, 0x1.b922a0be03cbbp+0, -0x1.5e3da88dc6818p-52, 0x1.f1c966c616976p+0},
        {0x1.3a4fa58aa84d5p+3, 0x1.d0167e25493a8p-1, 0x1.5d69463a20e7ep-70, 0x1.c9c1673bfbd6ap+0},
        {0x1.4346b0689aabcp+1, 0x1.d6642e06eb15cp-2, 0x1.04266ed85cae3p-62, 0x1.fd6ef2e1f568ap-1},
    };
    for (const Case& k : cases) {
        TileMap<double> full = makeMap<double>({k.o, 0}, {k.t, 1}, 8, 2, 1);
        for (auto& s : full.solid) s = 1;
        const Checked<double> c = checkZeroMove(full, Box<double>{{k.x, 0.25}, {k.w, 0.5}});
        EXPECT_TRUE(c.failure.empty()) << c.failure;
    }
}

// Double tile sizes where k * t rounds: the rounded product p = fl(k*t) is x exactly (low edge)
// or x + w exactly (far edge), and p / t rounds to k, but the exact quotient lies below k (the
// low edge is just inside cell k - 1) or above it (the far edge reaches into cell k).
TEST(ZeroMoveDouble, gridLinesThatRoundAreNotTakenAsExact) {
    const double lowTile = 0x1.b6c1bfd8e4be3p-1;   // fl(3t) < 3t
    const double highTile = 0x1.0e10129bf7213p+0;  // fl(5t) > 5t
    TileMap<double> low = makeMap<double>({0, 0}, {lowTile, 1}, 8, 2, 1);
    for (auto& s : low.solid) s = 1;
    Checked<double> c = checkZeroMove(low, Box<double>{{3 * lowTile, 0.25}, {0.5, 0.5}});
    EXPECT_TRUE(c.failure.empty()) << c.failure;
    TileMap<double> high = makeMap<double>({0, 0}, {highTile, 1}, 8, 2, 1);
    for (auto& s : high.solid) s = 1;
    c = checkZeroMove(high, Box<double>{{5 * highTile - 1, 0.25}, {1, 0.5}});
    EXPECT_TRUE(c.failure.empty()) << c.failure;
}

// Random frames next to grid lines and away from them, against the exact reference.
TYPED_TEST(ZeroMove, matchesTheExactReferenceNearAndOnGridLines) {
    using T = TypeParam;
    const bool isFloat = sizeof(T) == sizeof(float);
    const std::vector<double> origins = {
        0.0, -37.25, 1048576.0, -3.0e7, 1.0e-30, std::ldexp(1.0, -100), isFloat ? 1.0e30 : 1.0e200, 0.1};
    const std::vector<double> tiles = {
        16.0, 1.0 / 3.0, 0.1, 24.0, 3.0, std::ldexp(1.0, -60), 1.0e20, isFloat ? 1.0e-38 : 1.0e-300};
    std::mt19937_64 rng(20261202);
    int counts[3] = {0, 0, 0};
    for (double o : origins)
        for (double t : tiles) {
            const T ot = static_cast<T>(o);
            const T tt = static_cast<T>(t);
            if (!(tt > 0) || !std::isfinite(ot)) continue;
            const TileMap<T> map = makeMap<T>({ot, ot}, {tt, tt}, 5, 4, static_cast<std::uint32_t>(rng()));
            for (int n = 0; n < 60; ++n) {
                Box<T> box{};
                T* low[2] = {&box.pos.x, &box.pos.y};
                T* size[2] = {&box.size.x, &box.size.y};
                for (int a = 0; a < 2; ++a) {
                    const double k = static_cast<double>(static_cast<int>(rng() % 8) - 1);
                    const int kind = static_cast<int>(rng() % 4);
                    const double frac = kind == 3 ? std::uniform_real_distribution<double>(0, 1)(rng) : 0.0;
                    *low[a] = nearLine(ot, tt, k + frac, kind == 3 ? 0 : static_cast<int>(rng() % 5) - 2);
                    const double cellsWide = static_cast<double>(rng() % 3) + (rng() % 2 ? 0.5 : 1.0);
                    const T far = nearLine(ot, tt, k + frac + cellsWide, static_cast<int>(rng() % 5) - 2);
                    *size[a] = static_cast<T>(far - *low[a]);
                    if (!(*size[a] > 0) || !std::isfinite(*size[a])) *size[a] = tt;
                }
                if (!std::isfinite(box.pos.x) || !std::isfinite(box.pos.y)) continue;
                const Checked<T> c = checkZeroMove(map, box);
                ASSERT_TRUE(c.failure.empty()) << c.failure;
                ++counts[static_cast<int>(c.exit)];
            }
        }
    EXPECT_GE(counts[static_cast<int>(Exit::Estimated)], 100) << "too few frames decided by the estimate";
    EXPECT_GE(counts[static_cast<int>(Exit::Settled)], 300) << "too few frames decided by the settlement";
    EXPECT_GE(counts[static_cast<int>(Exit::Declined)], 20) << "too few frames left to the ordinary path";
}

// Float subnormals and the smallest normals as box, origin and tile values.
TEST(ZeroMoveFloat, matchesTheExactReferenceOnSubnormals) {
    const float denorm = std::numeric_limits<float>::denorm_min();
    const float values[] = {denorm, 3 * denorm, 1024 * denorm, std::numeric_limits<float>::min(), 1.0f};
    for (float t : values)
        for (float o : {0.0f, -denorm, 5 * denorm})
            for (float x : values)
                for (float w : values) {
                    const TileMap<float> map = makeMap<float>({o, o}, {t, t}, 3, 3, 11);
                    const Checked<float> c = checkZeroMove(map, Box<float>{{x, o + t}, {w, t}});
                    ASSERT_TRUE(c.failure.empty()) << c.failure;
                }
}

// The same frames on a prepared map (resolveMove on a PreparedMap), where the early exit skips
// the header and tile-size tests prepareMap made: the answers are the bare call's, bit for bit,
// and a box size that is not finite and > 0 still comes back InvalidInput.
TYPED_TEST(ZeroMove, aPreparedMapGivesTheBareCallsAnswers) {
    using T = TypeParam;
    const TileMap<T> map = makeMap<T>({-32, 8}, {16, 16}, 6, 5, 9);
    const PreparedMap<T> prepared = prepareMap(map.view());
    ASSERT_TRUE(prepared.isValid());
    Cell bare[16];
    Cell onPrepared[16];
    for (int k = -2; k <= 14; ++k) {
        const T x = static_cast<T>(-32 + 8 * k);
        for (const Box<T> box : {Box<T>{{x, 24}, {16, 16}}, Box<T>{{x + T(0.5), 40}, {12, 32}},
                                 Box<T>{{x, T(7.75)}, {T(20.5), T(40.25)}}}) {
            const ResolveResult<T> a =
                resolveMove(ResolveInput<T>{map.view(), box, {0, 0}}, {nullptr, 0, bare, 16});
            const ResolveResult<T> b = resolveMove(prepared, {box, {0, 0}}, {nullptr, 0, onPrepared, 16});
            ASSERT_EQ(a.status, b.status) << describe(map, box);
            ASSERT_TRUE(sameBits(a.position.x, b.position.x) && sameBits(a.position.y, b.position.y));
            ASSERT_EQ(a.startOverlapCount, b.startOverlapCount) << describe(map, box);
            for (std::int32_t n = 0; n < a.startOverlapCount && n < 16; ++n) {
                EXPECT_EQ(bare[n].i, onPrepared[n].i);
                EXPECT_EQ(bare[n].j, onPrepared[n].j);
            }
        }
    }
    for (T v : {T(0), -T(0), T(-8), std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::infinity()})
        for (int axis = 0; axis < 2; ++axis) {
            Box<T> box{{8, 24}, {16, 16}};
            (axis == 0 ? box.size.x : box.size.y) = v;
            const ResolveResult<T> r = resolveMove(prepared, {box, {0, 0}}, {nullptr, 0, onPrepared, 16});
            EXPECT_EQ(r.status, ResolveStatus::InvalidInput)
                << "size " << static_cast<double>(v) << " on axis " << axis;
        }
}

// Invalid input: every non-finite value, every size <= 0, a bad map header. The early exit must
// decline, and resolveMove must report InvalidInput with the start position ((0, 0) when
// that is not finite).
TYPED_TEST(ZeroMove, invalidInputLeavesTheEarlyExitAndIsReported) {
    using T = TypeParam;
    const T inf = std::numeric_limits<T>::infinity();
    const T nan = std::numeric_limits<T>::quiet_NaN();
    const TileMap<T> map = makeMap<T>({0, 0}, {16, 16}, 4, 4, 5);
    const ResolveInput<T> good{map.view(), {{18, 20}, {8, 8}}, {0, 0}};
    std::vector<ResolveInput<T>> bad;
    for (T v : {inf, -inf, nan}) {
        for (int field = 0; field < 8; ++field) {
            ResolveInput<T> in = good;
            T* fields[8] = {&in.box.pos.x,    &in.box.pos.y,    &in.box.size.x,     &in.box.size.y,
                            &in.map.origin.x, &in.map.origin.y, &in.map.tileSize.x, &in.map.tileSize.y};
            *fields[field] = v;
            bad.push_back(in);
        }
    }
    for (T v : {T(0), -T(0), T(-8)}) {
        for (int field = 0; field < 4; ++field) {
            ResolveInput<T> in = good;
            T* fields[4] = {&in.box.size.x, &in.box.size.y, &in.map.tileSize.x, &in.map.tileSize.y};
            *fields[field] = v;
            bad.push_back(in);
        }
    }
    ResolveInput<T> in = good;
    in.map.columns = -1;
    bad.push_back(in);
    in = good;
    in.map.rows = -4;
    bad.push_back(in);
    in = good;
    in.map.columns = 65536;
    in.map.rows = 65536;  // 2^32 cells: past kMaxCells
    bad.push_back(in);
    in = good;
    in.map.solid = nullptr;
    bad.push_back(in);
    Cell overlaps[8];
    for (std::size_t k = 0; k < bad.size(); ++k) {
        const ResolveOutput<T> out{nullptr, 0, overlaps, 8};
        ResolveResult<T> early;
        EXPECT_FALSE(detail::resolveZeroMove(detail::FrameInput<T>(bad[k]), out, early)) << "case " << k;
        const ResolveResult<T> r = resolveMove(bad[k], out);
        EXPECT_EQ(r.status, ResolveStatus::InvalidInput) << "case " << k;
        const bool finite = std::isfinite(bad[k].box.pos.x) && std::isfinite(bad[k].box.pos.y);
        const Vec2<T> start = finite ? bad[k].box.pos : Vec2<T>{0, 0};  // as resolve.h says
        EXPECT_TRUE(sameBits(r.position.x, start.x) && sameBits(r.position.y, start.y)) << "case " << k;
    }
}

}  // namespace
}  // namespace tilesweep

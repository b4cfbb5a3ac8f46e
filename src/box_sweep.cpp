// SPDX-License-Identifier: MIT
#include "tilesweep/box_sweep.h"

#include "axis_sweep.h"
#include "fast_frame.h"
#include "lattice.h"
#include "validity.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <type_traits>

// One box against one tile: the same exact test the resolver applies to every candidate tile
// (axis_sweep.h), on the lattice of this one pair.

namespace tilesweep {
using detail::isFinite;

namespace {

/// The state and contact axis of a verdict (the time is the caller's); true when it blocks.
template <class T>
bool recordVerdict(detail::TileVerdict verdict, const BoxSweepInput<T>& in, BoxSweepOutput<T>& out) noexcept {
    switch (verdict) {
        case detail::TileVerdict::Misses:
            out.state = BoxSweepState::Misses;
            return false;
        case detail::TileVerdict::StartsOverlapping:
            out.state = BoxSweepState::StartsOverlapping;
            return false;
        case detail::TileVerdict::BlocksOnX:
            out.axis = Axis::X;
            break;
        case detail::TileVerdict::BlocksOnY:
            out.axis = Axis::Y;
            break;
        case detail::TileVerdict::Tie:
            out.axis = detail::settleTie(in.xFaceExposed, in.yFaceExposed);
            break;
    }
    out.state = BoxSweepState::Blocks;
    return true;
}

template <class T, class Num>
BoxSweepOutput<T> sweepOnLattice(const BoxSweepInput<T>& in, const detail::Dyadic* d, int exponent) noexcept {
    const auto lat = [exponent](detail::Dyadic v) { return detail::toLattice<Num>(v, exponent); };
    const auto mx = detail::makeAxisMotion(lat(d[0]), lat(d[2]), lat(d[4]));
    const auto my = detail::makeAxisMotion(lat(d[1]), lat(d[3]), lat(d[5]));
    const auto test = detail::testTile(mx, my, lat(d[6]), lat(d[8]), lat(d[7]), lat(d[9]));
    BoxSweepOutput<T> out;
    if (!recordVerdict(test.verdict, in, out)) return out;
    out.time = detail::roundRatioToNearest<T>(test.time.num, test.time.den);
    return out;
}

/// Whether the fast path holds every value of this float pair exactly: as admitFloatFrame
/// (fast_frame.h), with the box's edges (sums of three inputs) and the tile's bounds as the
/// coordinates. All nonzero inputs normal; every coordinate below 2^C, every difference of two
/// below 2^(C+1), all multiples of 2^G; (C + 1) - G <= 53.
bool admitFloatPair(const BoxSweepInput<float>& in) noexcept {
    const float values[10] = {in.box.pos.x,      in.box.pos.y,      in.box.size.x, in.box.size.y,
                              in.displacement.x, in.displacement.y, in.tileMin.x,  in.tileMin.y,
                              in.tileMax.x,      in.tileMax.y};
    int lowest = 255;
    int boxTop = 0;
    int tileTop = 0;
    for (int k = 0; k < 10; ++k) {
        std::uint32_t bits = 0;
        std::memcpy(&bits, &values[k], sizeof bits);
        const int f = static_cast<int>((bits >> 23) & 0xff);  // |v| in [2^(f-127), 2^(f-126))
        if ((bits & 0x7fffffff) == 0) continue;
        if (f == 0) return false;  // subnormal
        lowest = std::min(lowest, f);
        if (k < 6)
            boxTop = std::max(boxTop, f);
        else
            tileTop = std::max(tileTop, f);
    }
    const int top = std::max(boxTop + 2, tileTop);  // coordinates below 2^(top - 126)
    int span = (top - 126 + 1) - (lowest - 150);
#if defined(TILESWEEP_FAULT_FAST_RANGE_TOO_WIDE)
    --span;  // deliberate fault: the range test one binade too generous
#endif
#if defined(TILESWEEP_FAULT_FAST_RANGE_FAR_TOO_WIDE)
    span -= 6;  // deliberate fault: six binades too generous, past the test's slack
#endif
    return span <= detail::kFastSpanBits && top - 126 <= 120;
}

/// The pair on exact doubles (fast_frame.h): the verdict by testTileFast, the time rounded by
/// roundTimeToFloat; false when the time needs the lattice's rounding.
bool sweepFast(const BoxSweepInput<float>& in, BoxSweepOutput<float>& out) noexcept {
    const auto axis = [](float pos, float size, float disp) {
        const auto d = static_cast<double>(disp);
        const auto p = static_cast<double>(pos);
        const auto w = static_cast<double>(size);
        return detail::FastAxis{p, p + w, d, std::fabs(d), d > 0 ? 1 : (d < 0 ? -1 : 0), 0, 1, 0, 1, w};
    };
    const detail::FastAxis mx = axis(in.box.pos.x, in.box.size.x, in.displacement.x);
    const detail::FastAxis my = axis(in.box.pos.y, in.box.size.y, in.displacement.y);
    bool refined = false;
    const detail::FastTileTest<> test =
        detail::testTileFast(mx, my, static_cast<double>(in.tileMin.x), static_cast<double>(in.tileMax.x),
                             static_cast<double>(in.tileMin.y), static_cast<double>(in.tileMax.y), refined);
    if (!recordVerdict(test.verdict, in, out)) return true;
    return detail::roundTimeToFloat(test.time, refined, out.time);
}

}  // namespace

template <class T>
BoxSweepOutput<T> sweepBox(const BoxSweepInput<T>& in) noexcept {
    if (!isFinite(in.box.pos) || !isFinite(in.box.size) || !(in.box.size.x > 0 && in.box.size.y > 0) ||
        !isFinite(in.displacement) || !isFinite(in.tileMin) || !isFinite(in.tileMax) ||
        !(in.tileMin.x < in.tileMax.x && in.tileMin.y < in.tileMax.y))
        return {};
    if constexpr (std::is_same<T, float>::value) {
        BoxSweepOutput<T> out;
        if (admitFloatPair(in) && sweepFast(in, out)) return out;
    }
    using detail::decompose;
    const detail::Dyadic d[10] = {decompose(in.box.pos.x),      decompose(in.box.pos.y),
                                  decompose(in.box.size.x),     decompose(in.box.size.y),
                                  decompose(in.displacement.x), decompose(in.displacement.y),
                                  decompose(in.tileMin.x),      decompose(in.tileMin.y),
                                  decompose(in.tileMax.x),      decompose(in.tileMax.y)};
    // Box edges are sums of three inputs (2 bits above the largest); tile edges are inputs.
    int top = 0;
    for (int k = 0; k < 10; ++k) top = std::max(top, detail::exponentAbove(d[k]) + 2);
    const detail::LatticeShape shape = detail::shapeLattice(d, 10, top);
    return detail::withWidth(detail::bitsNeeded(shape), [&](auto tag) {
        return sweepOnLattice<T, decltype(tag)>(in, d, shape.exponent);
    });
}

template BoxSweepOutput<float> sweepBox<float>(const BoxSweepInput<float>&) noexcept;
template BoxSweepOutput<double> sweepBox<double>(const BoxSweepInput<double>&) noexcept;

}  // namespace tilesweep

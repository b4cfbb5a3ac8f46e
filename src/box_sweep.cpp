// SPDX-License-Identifier: MIT
#include "tilesweep/box_sweep.h"

#include "axis_sweep.h"
#include "fast_axis.h"
#include "lattice.h"
#include "range_admission.h"
#include "time_rounding.h"
#include "validity.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <type_traits>

// One box against one tile: the same exact test the resolver applies to every candidate tile
// (axis_sweep.h), on the lattice of this one pair.

namespace tilesweep {
using detail::isFinite;

namespace {

/// The state and contact axis of a verdict (the time is the caller's); true when it blocks.
template <class T>
bool recordVerdict(detail::TileVerdict verdict, const BoxSweepInput<T>& in, BoxSweepResult<T>& out) noexcept {
    switch (verdict) {
        case detail::TileVerdict::Misses:
            out.status = BoxSweepStatus::Misses;
            return false;
        case detail::TileVerdict::StartsOverlapping:
            out.status = BoxSweepStatus::StartsOverlapping;
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
    out.status = BoxSweepStatus::Blocks;
    return true;
}

template <class T, class Num>
BoxSweepResult<T> sweepOnLattice(const BoxSweepInput<T>& in, const detail::Dyadic* d, int exponent) noexcept {
    const auto lat = [exponent](detail::Dyadic v) { return detail::toLattice<Num>(v, exponent); };
    const auto mx = detail::makeAxisMotion(lat(d[0]), lat(d[2]), lat(d[4]));
    const auto my = detail::makeAxisMotion(lat(d[1]), lat(d[3]), lat(d[5]));
    bool refined = false;  // integers need no refinement
    const auto test = detail::testTile(mx, my, lat(d[6]), lat(d[8]), lat(d[7]), lat(d[9]), refined);
    BoxSweepResult<T> out;
    if (!recordVerdict(test.verdict, in, out)) return out;
    out.time = detail::roundRatioToNearest<T>(test.time.num, test.time.den);
    return out;
}

/// The pair on exact doubles (fast_axis.h), admitted by admitFloatPair (range_admission.h): the
/// verdict by the one tile test (axis_sweep.h), the time rounded by roundTimeToFloat; false when
/// the time needs the lattice's rounding.
bool sweepFast(const BoxSweepInput<float>& in, BoxSweepResult<float>& out) noexcept {
    const auto axis = [](float pos, float size, float disp) {
        const auto d = static_cast<double>(disp);
        const auto p = static_cast<double>(pos);
        const auto w = static_cast<double>(size);
        return detail::FastAxis<double>{p, p + w, d, std::fabs(d), d > 0 ? 1 : (d < 0 ? -1 : 0), 0, 1,
                                        0, 1,     w};
    };
    const detail::FastAxis<double> mx = axis(in.box.pos.x, in.box.size.x, in.displacement.x);
    const detail::FastAxis<double> my = axis(in.box.pos.y, in.box.size.y, in.displacement.y);
    bool refined = false;
    const auto test =
        detail::testTile(mx, my, static_cast<double>(in.tileMin.x), static_cast<double>(in.tileMax.x),
                         static_cast<double>(in.tileMin.y), static_cast<double>(in.tileMax.y), refined);
    if (!recordVerdict(test.verdict, in, out)) return true;
    return detail::roundTimeToFloat(test.time, refined, out.time);
}

}  // namespace

template <class T>
BoxSweepResult<T> sweepBox(const BoxSweepInput<T>& in) noexcept {
    if (!isFinite(in.box.pos) || !isFinite(in.box.size) || !(in.box.size.x > 0 && in.box.size.y > 0) ||
        !isFinite(in.displacement) || !isFinite(in.tileMin) || !isFinite(in.tileMax) ||
        !(in.tileMin.x < in.tileMax.x && in.tileMin.y < in.tileMax.y))
        return {};
    if constexpr (std::is_same<T, float>::value) {
        BoxSweepResult<T> out;
        if (detail::admitFloatPair(in) && sweepFast(in, out)) return out;
    }
    const T values[10] = {in.box.pos.x,      in.box.pos.y, in.box.size.x, in.box.size.y, in.displacement.x,
                          in.displacement.y, in.tileMin.x, in.tileMin.y,  in.tileMax.x,  in.tileMax.y};
    detail::Dyadic d[10];
    detail::decomposeEach(values, 10, d);
    // Box edges are sums of three inputs (2 bits above the largest); tile edges are inputs.
    int top = 0;
    for (int k = 0; k < 10; ++k) top = std::max(top, detail::exponentAbove(d[k]) + 2);
    return detail::onLattice(d, 10, top, [&](auto tag, int exponent) {
        return sweepOnLattice<T, decltype(tag)>(in, d, exponent);
    });
}

template BoxSweepResult<float> sweepBox<float>(const BoxSweepInput<float>&) noexcept;
template BoxSweepResult<double> sweepBox<double>(const BoxSweepInput<double>&) noexcept;

}  // namespace tilesweep

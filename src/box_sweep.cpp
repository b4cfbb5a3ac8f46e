// SPDX-License-Identifier: MIT
#include "tilesweep/box_sweep.h"

#include <algorithm>
#include <cmath>

#include "axis_sweep.h"
#include "lattice.h"

// One box against one tile: the same exact test the resolver applies to every candidate tile
// (axis_sweep.h), on the lattice of this one pair.

namespace tilesweep {
namespace {

template <class T>
bool isFinite(Vec2<T> v) noexcept { return std::isfinite(v.x) && std::isfinite(v.y); }

template <class T, class Num>
BoxSweepOutput<T> sweepOnLattice(const BoxSweepInput<T>& in, const detail::Dyadic* d, int exponent) noexcept {
    const auto lat = [exponent](detail::Dyadic v) { return detail::toLattice<Num>(v, exponent); };
    const auto mx = detail::makeAxisMotion(lat(d[0]), lat(d[2]), lat(d[4]));
    const auto my = detail::makeAxisMotion(lat(d[1]), lat(d[3]), lat(d[5]));
    const auto test = detail::testTile(mx, my, lat(d[6]), lat(d[8]), lat(d[7]), lat(d[9]));
    BoxSweepOutput<T> out;
    switch (test.verdict) {
        case detail::TileVerdict::Misses: out.state = BoxSweepState::Misses; return out;
        case detail::TileVerdict::StartsOverlapping: out.state = BoxSweepState::StartsOverlapping; return out;
        case detail::TileVerdict::BlocksOnX: out.axis = Axis::X; break;
        case detail::TileVerdict::BlocksOnY: out.axis = Axis::Y; break;
        case detail::TileVerdict::Tie: out.axis = detail::settleTie(in.xFaceExposed, in.yFaceExposed); break;
    }
    out.state = BoxSweepState::Blocks;
    out.time = detail::roundRatioToNearest<T>(test.time.num, test.time.den);
    return out;
}

}  // namespace

template <class T>
BoxSweepOutput<T> sweepBox(const BoxSweepInput<T>& in) noexcept {
    if (!isFinite(in.box.pos) || !isFinite(in.box.size) || !(in.box.size.x > 0 && in.box.size.y > 0) ||
        !isFinite(in.displacement) || !isFinite(in.tileMin) || !isFinite(in.tileMax) ||
        !(in.tileMin.x < in.tileMax.x && in.tileMin.y < in.tileMax.y))
        return {};
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

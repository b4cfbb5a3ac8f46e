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
BoxSweepOutput<T> sweepOnLattice(const BoxSweepInput<T>& in, int exponent) noexcept {
    const auto lat = [exponent](T v) { return detail::toLattice<Num>(v, exponent); };
    const auto mx = detail::makeAxisMotion(lat(in.box.pos.x), lat(in.box.size.x), lat(in.displacement.x));
    const auto my = detail::makeAxisMotion(lat(in.box.pos.y), lat(in.box.size.y), lat(in.displacement.y));
    const auto test = detail::testTile(mx, my, lat(in.tileMin.x), lat(in.tileMax.x), lat(in.tileMin.y),
                                       lat(in.tileMax.y));
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
    const T values[] = {in.box.pos.x, in.box.pos.y, in.box.size.x, in.box.size.y, in.displacement.x,
                        in.displacement.y, in.tileMin.x, in.tileMin.y, in.tileMax.x, in.tileMax.y};
    using Wide = long double;
    const auto mag = [](T v) { return static_cast<Wide>(std::fabs(v)); };
    const Wide bound = std::max({mag(in.box.pos.x) + mag(in.box.size.x) + mag(in.displacement.x),
                                 mag(in.box.pos.y) + mag(in.box.size.y) + mag(in.displacement.y),
                                 mag(in.tileMin.x), mag(in.tileMax.x), mag(in.tileMin.y), mag(in.tileMax.y)});
    const detail::LatticeShape shape = detail::shapeLattice(values, 10, bound);
    return detail::withWidth(detail::bitsNeeded(shape), [&](auto tag) {
        return sweepOnLattice<T, decltype(tag)>(in, shape.exponent);
    });
}

template BoxSweepOutput<float> sweepBox<float>(const BoxSweepInput<float>&) noexcept;
template BoxSweepOutput<double> sweepBox<double>(const BoxSweepInput<double>&) noexcept;

}  // namespace tilesweep

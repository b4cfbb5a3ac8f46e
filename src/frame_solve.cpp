// SPDX-License-Identifier: MIT
#include "frame_solve.h"

#include "fast_frame.h"
#include "frame_loop.h"
#include "lattice.h"
#include "lattice_frame.h"

#include <algorithm>
#include <cstdint>

namespace tilesweep::detail {

template <class T>
bool solveFast(const SweepInput<T>& input, const ResolveOutput<T>& output, SweepResult<T>& result,
               bool& refined) noexcept {
    FastFrame<T> frame(input);
    const bool solved = FrameLoop<FastFrame<T>>(frame).run(output, result);
    refined = frame.refined();
    return solved;
}

template <class T>
SweepResult<T> solveOnLattice(const SweepInput<T>& in, const ResolveOutput<T>& out) noexcept {
    const T values[10] = {in.box.pos.x,      in.box.pos.y,      in.box.size.x,   in.box.size.y,
                          in.displacement.x, in.displacement.y, in.map.origin.x, in.map.origin.y,
                          in.map.tileSize.x, in.map.tileSize.y};
    Dyadic d[10];
    decomposeEach(values, 10, d);
    // Every coordinate the frame forms is below 2^top: box edges at the start and the end (a sum
    // of three inputs, so 2 bits above the largest) and tile edges from one cell before the map
    // to one past it (origin + k*tile with |k| <= cells + 2).
    int top = 0;
    for (int k = 0; k < 6; ++k) top = std::max(top, exponentAbove(d[k]) + 2);
    const int cellBits[2] = {bitLength(static_cast<std::uint64_t>(in.map.columns) + 2),
                             bitLength(static_cast<std::uint64_t>(in.map.rows) + 2)};
    for (int a = 0; a < 2; ++a)
        top = std::max(top, std::max(exponentAbove(d[6 + a]), exponentAbove(d[8 + a]) + cellBits[a]) + 1);
    return onLattice(d, 10, top, [&](auto tag, int exponent) {
        LatticeFrame<T, decltype(tag)> frame(in, d, exponent);
        SweepResult<T> result;
        (void)FrameLoop<LatticeFrame<T, decltype(tag)>>(frame).run(out, result);  // never undecided
        return result;
    });
}

template bool solveFast<float>(const SweepInput<float>&, const ResolveOutput<float>&, SweepResult<float>&,
                               bool&) noexcept;
template bool solveFast<double>(const SweepInput<double>&, const ResolveOutput<double>&, SweepResult<double>&,
                                bool&) noexcept;
template SweepResult<float> solveOnLattice<float>(const SweepInput<float>&, const ResolveOutput<float>&) noexcept;
template SweepResult<double> solveOnLattice<double>(const SweepInput<double>&,
                                                    const ResolveOutput<double>&) noexcept;

}  // namespace tilesweep::detail

// SPDX-License-Identifier: MIT
#include "tilesweep/resolve.h"

#include "frame_solve.h"

// Move-and-slide over the tile grid: the entry point. A frame goes to the first of these that
// settles it: the zero move (zero_move.h), the fast path on exact doubles or pairs
// (fast_frame.h) when the range test admits it (range_admission.h), and the exact lattice
// (lattice_frame.h). The last two run the same frame loop (frame_loop.h).

namespace tilesweep {

template <class T>
ResolveResult<T> resolveMove(const ResolveInput<T>& input, const ResolveOutput<T>& output) noexcept {
    return detail::resolveFrame(input.map, MoveInput<T>{input.box, input.displacement}, output,
                                detail::ContactPositions::Placed, nullptr);
}

template ResolveResult<float> resolveMove<float>(const ResolveInput<float>&,
                                                 const ResolveOutput<float>&) noexcept;
template ResolveResult<double> resolveMove<double>(const ResolveInput<double>&,
                                                   const ResolveOutput<double>&) noexcept;

ResolveResult<float> resolveMove(const ResolveInput<float>& input,
                                 const ResolveOutput<float>& output) noexcept {
    return resolveMove<float>(input, output);
}
ResolveResult<double> resolveMove(const ResolveInput<double>& input,
                                  const ResolveOutput<double>& output) noexcept {
    return resolveMove<double>(input, output);
}

}  // namespace tilesweep

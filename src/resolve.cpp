// SPDX-License-Identifier: MIT
#include "tilesweep/resolve.h"

#include "frame_solve.h"
#include "zero_move.h"

// Move-and-slide over the tile grid: the entry point. A frame goes to the first of these that
// settles it: the zero move (zero_move.h), the fast path on exact doubles or pairs
// (fast_frame.h) when the range test admits it (range_admission.h), and the exact lattice
// (lattice_frame.h). The last two run the same frame loop (frame_loop.h).

namespace tilesweep {

namespace detail {

template <class T>
ResolveResult<T> resolveFrame(const ResolveInput<T>& input, const ResolveOutput<T>& output,
                              ContactPositions positions, const MapRange* prepared) noexcept {
    // A zero move: the start overlaps alone, from the cells under the box (zero_move.h).
    if (input.displacement.x == 0 && input.displacement.y == 0) {
        ResolveResult<T> result;
        if (resolveZeroMove(input, output, result)) {
            recordPath(output, DecisionPath::Fast);
            return result;
        }
    }
    return resolveMovingFrame(input, output, positions, prepared);
}

template ResolveResult<float> resolveFrame<float>(const ResolveInput<float>&, const ResolveOutput<float>&,
                                                  ContactPositions, const MapRange*) noexcept;
template ResolveResult<double> resolveFrame<double>(const ResolveInput<double>&, const ResolveOutput<double>&,
                                                    ContactPositions, const MapRange*) noexcept;

}  // namespace detail

template <class T>
ResolveResult<T> resolveMove(const ResolveInput<T>& input, const ResolveOutput<T>& output) noexcept {
    return detail::resolveFrame(input, output, detail::ContactPositions::Placed, nullptr);
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

// SPDX-License-Identifier: MIT
#include "tilesweep/resolve.h"

#include "frame_solve.h"
#include "zero_move.h"

// Move-and-slide over the tile grid: the entry point. A frame goes to the first of these that
// settles it: the zero move (zero_move.h), the fast path on exact doubles or pairs
// (fast_frame.h) when the range test admits it (range_admission.h), and the exact lattice
// (lattice_frame.h). The last two run the same frame loop (frame_loop.h).

namespace tilesweep {

template <class T>
SweepResult<T> resolveMove(const SweepInput<T>& input, const ResolveOutput<T>& output) noexcept {
    // A zero move: the start overlaps alone, from the cells under the box (zero_move.h).
    if (input.displacement.x == 0 && input.displacement.y == 0) {
        SweepResult<T> result;
        if (detail::resolveZeroMove(input, output, result)) {
            detail::recordPath(output, DecisionPath::Fast);
            return result;
        }
    }
    return detail::resolveMovingFrame(input, output);
}

template SweepResult<float> resolveMove<float>(const SweepInput<float>&,
                                               const ResolveOutput<float>&) noexcept;
template SweepResult<double> resolveMove<double>(const SweepInput<double>&,
                                                 const ResolveOutput<double>&) noexcept;

SweepResult<float> resolveMove(const SweepInput<float>& input, const ResolveOutput<float>& output) noexcept {
    return resolveMove<float>(input, output);
}
SweepResult<double> resolveMove(const SweepInput<double>& input,
                                const ResolveOutput<double>& output) noexcept {
    return resolveMove<double>(input, output);
}

}  // namespace tilesweep

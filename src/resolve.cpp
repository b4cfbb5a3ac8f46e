// SPDX-License-Identifier: MIT
#include "tilesweep/resolve.h"

#include "frame_solve.h"
#include "range_admission.h"
#include "zero_move.h"

#include <algorithm>
#include <cmath>
#include <type_traits>

// Move-and-slide over the tile grid: the entry point. A frame goes to the first of these that
// settles it: the zero move (zero_move.h), the fast path on exact doubles or pairs
// (fast_frame.h) when the range test admits it (range_admission.h), and the exact lattice
// (lattice_frame.h). The last two run the same frame loop (frame_loop.h).

namespace tilesweep {
namespace {

/// Records the path that decided the frame when the caller asked for it (frame_stats.h).
template <class T>
void recordPath(const ResolveOutput<T>& output, DecisionPath path) noexcept {
    if (output.stats != nullptr) output.stats->path = path;
}

/// Every frame but the zero moves resolveZeroMove settles: out of line, so that the early exit
/// pays for none of its stack frame.
template <class T>
#if defined(__GNUC__)
__attribute__((noinline))
#endif
SweepResult<T>
resolveMoving(const SweepInput<T>& input, const ResolveOutput<T>& output) noexcept {
    // The fast path, when the range test admits the frame (fast_frame.h): float frames on exact
    // doubles, double frames on exact pairs under a certified filter. The range test implies
    // the frame is valid, so isValid only runs for the frames it turns away.
    bool admitted = false;
    if constexpr (std::is_same<T, float>::value) {
        admitted = detail::admitFloatFrame(input);
    } else {
        admitted = detail::admitDoubleFrame(input);
    }
    if (admitted) {
        SweepResult<T> result;
        bool refined = false;
        if (detail::solveFast(input, output, result, refined)) {
            recordPath(output, refined ? DecisionPath::Filtered : DecisionPath::Fast);
            return result;
        }
    } else if (!isValid(input)) {
        SweepResult<T> invalid;
        invalid.status = Status::InvalidInput;
        invalid.position = input.box.pos;
        if (!std::isfinite(invalid.position.x) || !std::isfinite(invalid.position.y))
            invalid.position = {0, 0};
        recordPath(output, DecisionPath::Exact);
        return invalid;
    }
    recordPath(output, DecisionPath::Exact);
    return detail::solveOnLattice(input, output);
}

}  // namespace

template <class T>
SweepResult<T> resolveMove(const SweepInput<T>& input, const ResolveOutput<T>& output) noexcept {
    // A zero move: the start overlaps alone, from the cells under the box (zero_move.h).
    if (input.displacement.x == 0 && input.displacement.y == 0) {
        SweepResult<T> result;
        if (detail::resolveZeroMove(input, output, result)) {
            recordPath(output, DecisionPath::Fast);
            return result;
        }
    }
    return resolveMoving(input, output);
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

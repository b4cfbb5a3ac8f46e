// SPDX-License-Identifier: MIT
#pragma once

// One frame, solved: a zero move by resolveZeroMove when it settles it (zero_move.h); otherwise
// the fast path when the range test admits the frame, else (or when the fast path answers
// "undecided") the exact lattice. Both are the one frame loop (frame_loop.h) on a different
// arithmetic. resolveMovingFrame is defined in frame_solve.cpp, instantiated there for float
// and double, so that the fast path inlines into it there.

#include "zero_move.h"

#include "tilesweep/detail/map_range.h"
#include "tilesweep/resolve.h"

#include <cstdint>

namespace tilesweep::detail {

/// Records the path that decided the frame when the caller asked for it (frame_stats.h).
template <class T>
inline void recordPath(const ResolveOutput<T>& output, DecisionPath path) noexcept {
    if (output.stats != nullptr) output.stats->path = path;
}

/// Whether a frame writes its stored contacts' positions (Contact::position). resolveMove always
/// does; the game-loop calls (mover.cpp) skip them when the caller will not receive the
/// contacts, so that a frame resolved into their inline buffer pays nothing for them.
enum class ContactPositions : std::uint8_t { Placed, Skipped };

/// resolveMove for every frame but the zero moves resolveZeroMove settles (frame_solve.cpp), into
/// `result`, which must be as default-initialized.
template <class T>
void resolveMovingFrame(const ResolveInput<T>& input, const ResolveOutput<T>& output,
                        ContactPositions positions, const MapRange* prepared,
                        ResolveResult<T>& result) noexcept;

/// resolveMove, with the choice above: the zero moves resolveZeroMove settles (zero_move.h), then
/// resolveMovingFrame. `prepared` is the map's range test (range_admission.h) when the map was
/// prepared (PreparedMap), or null: it is then computed for the frame. Inline, so that each entry
/// point (resolve.cpp, mover.cpp) goes straight to the zero move or to resolveMovingFrame.
///
/// One result object, written in place by whichever path settles the frame and returned by name
/// on every path, so that it is the caller's (NRVO): a copy at the end would read whole vectors
/// of a struct just written field by field, which stalls the store forwarding.
template <class T>
[[nodiscard]] inline ResolveResult<T> resolveFrame(const ResolveInput<T>& input,
                                                   const ResolveOutput<T>& output, ContactPositions positions,
                                                   const MapRange* prepared) noexcept {
    ResolveResult<T> result;
    // A zero move: the start overlaps alone, from the cells under the box (zero_move.h).
    if (input.displacement.x == 0 && input.displacement.y == 0 &&
        resolveZeroMove(input, output, result, prepared != nullptr)) {  // prepared: a valid map
        recordPath(output, DecisionPath::Fast);
        return result;
    }
    resolveMovingFrame(input, output, positions, prepared, result);
    return result;
}

extern template void resolveMovingFrame<float>(const ResolveInput<float>&, const ResolveOutput<float>&,
                                               ContactPositions, const MapRange*,
                                               ResolveResult<float>&) noexcept;
extern template void resolveMovingFrame<double>(const ResolveInput<double>&, const ResolveOutput<double>&,
                                                ContactPositions, const MapRange*,
                                                ResolveResult<double>&) noexcept;

}  // namespace tilesweep::detail

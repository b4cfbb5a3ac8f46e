// SPDX-License-Identifier: MIT
#pragma once

// A moving frame, solved: the fast path when the range test admits the frame, else (or when the
// fast path answers "undecided") the exact lattice. Both are the one frame loop (frame_loop.h)
// on a different arithmetic. Defined in frame_solve.cpp, instantiated there for float and
// double, so that the fast path inlines into its caller there.

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

/// resolveMove, with the choice above (resolve.cpp): the zero moves resolveZeroMove settles, then
/// resolveMovingFrame. `prepared` is the map's range test (range_admission.h) when the map was
/// prepared (PreparedMap), or null: it is then computed for the frame.
template <class T>
[[nodiscard]] ResolveResult<T> resolveFrame(const ResolveInput<T>& input, const ResolveOutput<T>& output,
                                            ContactPositions positions, const MapRange* prepared) noexcept;

/// resolveMove for every frame but the zero moves resolveZeroMove settles (resolve.cpp).
template <class T>
[[nodiscard]] ResolveResult<T> resolveMovingFrame(const ResolveInput<T>& input,
                                                  const ResolveOutput<T>& output, ContactPositions positions,
                                                  const MapRange* prepared) noexcept;

extern template ResolveResult<float> resolveFrame<float>(const ResolveInput<float>&,
                                                         const ResolveOutput<float>&, ContactPositions,
                                                         const MapRange*) noexcept;
extern template ResolveResult<double> resolveFrame<double>(const ResolveInput<double>&,
                                                           const ResolveOutput<double>&, ContactPositions,
                                                           const MapRange*) noexcept;
extern template ResolveResult<float> resolveMovingFrame<float>(const ResolveInput<float>&,
                                                               const ResolveOutput<float>&, ContactPositions,
                                                               const MapRange*) noexcept;
extern template ResolveResult<double> resolveMovingFrame<double>(const ResolveInput<double>&,
                                                                 const ResolveOutput<double>&,
                                                                 ContactPositions, const MapRange*) noexcept;

}  // namespace tilesweep::detail

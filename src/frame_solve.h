// SPDX-License-Identifier: MIT
#pragma once

// The two solvers of a moving frame, both the one frame loop (frame_loop.h) on a different
// arithmetic; defined in frame_solve.cpp, instantiated there for float and double.

#include "tilesweep/resolve.h"

namespace tilesweep::detail {

/// Solves an admitted frame (range_admission.h) on the fast path into `result`; false when it
/// meets a case it hands to the lattice. `refined` is set when some predicate needed its exact
/// refinement (DecisionPath::Filtered).
template <class T>
[[nodiscard]] bool solveFast(const SweepInput<T>& input, const ResolveOutput<T>& output, SweepResult<T>& result,
                             bool& refined) noexcept;

/// Solves a valid frame exactly: scaled onto its lattice, with integers wide enough for it.
template <class T>
[[nodiscard]] SweepResult<T> solveOnLattice(const SweepInput<T>& input, const ResolveOutput<T>& output) noexcept;

extern template bool solveFast<float>(const SweepInput<float>&, const ResolveOutput<float>&, SweepResult<float>&,
                                      bool&) noexcept;
extern template bool solveFast<double>(const SweepInput<double>&, const ResolveOutput<double>&,
                                       SweepResult<double>&, bool&) noexcept;
extern template SweepResult<float> solveOnLattice<float>(const SweepInput<float>&,
                                                         const ResolveOutput<float>&) noexcept;
extern template SweepResult<double> solveOnLattice<double>(const SweepInput<double>&,
                                                           const ResolveOutput<double>&) noexcept;

}  // namespace tilesweep::detail

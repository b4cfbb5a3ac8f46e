// SPDX-License-Identifier: MIT
#pragma once

// Which path decided the last frame resolved on this thread: for the verification suite (it
// tags generated cases and holds the exact fallback to a coverage floor), never for users.
// Internal header, not installed. The record is one thread_local byte written once per frame.

#include <cstdint>

namespace tilesweep::detail {

/// How resolveMove decided a frame.
enum class DecisionPath : std::uint8_t {
    /// The fast path (fast_frame.h) decided every predicate of the frame with rounded double
    /// arithmetic alone: each comparison of two products was settled by the order of the
    /// rounded products (exact by monotonic rounding), and every contact time's rounding was
    /// certain from the rounded quotient.
    Fast,
    /// The fast path decided the frame, but at least one predicate lay inside its error band
    /// (two products rounded to the same double, or a rounded contact time landed exactly on a
    /// rounding midpoint) and was settled by an exact refinement within the fast path (the
    /// rounding errors by TwoProduct, exact_double.h).
    Filtered,
    /// The exact lattice solver decided the frame: the range test did not admit it (scalar type,
    /// magnitudes, subnormals, map size), or the fast path met a case it does not refine (a
    /// contact time in float's subnormal range) and handed the whole frame over. Invalid input
    /// is recorded as Exact too.
    Exact,
};

/// The path that decided the last resolveMove on the calling thread (Exact before any);
/// defined in resolve.cpp, which records it.
[[nodiscard]] DecisionPath lastDecisionPath() noexcept;

}  // namespace tilesweep::detail

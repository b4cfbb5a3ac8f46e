// SPDX-License-Identifier: MIT
#pragma once

// How resolveMove decided a frame, for callers that ask (the verification suite tags generated
// cases with it and holds the exact fallback to a coverage floor; a game has no use for it).
// Opt-in: pass a FrameStats in ResolveOutput::stats and the resolve fills it in; leave it null
// and nothing is recorded. The library keeps no state of its own between calls.

#include <cstdint>

namespace tilesweep {

/// The path that decided a frame, from the cheapest to the most exact.
enum class DecisionPath : std::uint8_t {
    /// The fast path decided every predicate of the frame from rounded double arithmetic alone:
    /// each comparison of two products by the order of the rounded products (exact by monotonic
    /// rounding), each contact time's rounding from the rounded quotient, and each contact
    /// position's from a rounded estimate outside its certified error bound.
    Fast,
    /// The fast path decided the frame, but some predicate lay inside its error band (two
    /// products rounded to the same double, a rounded contact time exactly on a rounding
    /// midpoint, a contact position next to one) and an exact refinement inside the fast path
    /// settled it (TwoProduct, exact expansions).
    Filtered,
    /// The exact lattice solver decided the frame: the range test did not admit it (scalar type,
    /// magnitudes, subnormals, map size), or the fast path met a case it does not refine and
    /// handed the whole frame over. Invalid input is recorded as Exact too.
    Exact,
};

/// What a resolve reports about how it worked, when the caller passes one.
struct FrameStats {
    DecisionPath path = DecisionPath::Exact;  ///< the path that decided the frame
};

}  // namespace tilesweep

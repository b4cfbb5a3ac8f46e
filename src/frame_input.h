// SPDX-License-Identifier: MIT
#pragma once

// A frame's inputs as the solver reads them: the map, the box and the displacement by
// reference, where the caller keeps them. ResolveInput (resolve.h) holds the same three by value,
// and building one from a prepared map's view and a MoveInput copies 12 words a frame, a
// noticeable share of a zero move's work; a FrameInput copies none.

#include "tilesweep/resolve.h"

namespace tilesweep::detail {

template <class T>
struct FrameInput {
    const TileMapView<T>& map;
    const Box<T>& box;
    const Vec2<T>& displacement;

    FrameInput(const TileMapView<T>& m, const Box<T>& b, const Vec2<T>& d) noexcept
        : map(m), box(b), displacement(d) {}
    /// A ResolveInput's fields, by reference: it must outlive the FrameInput.
    FrameInput(const ResolveInput<T>& in) noexcept  // NOLINT(google-explicit-constructor): a view of it
        : map(in.map), box(in.box), displacement(in.displacement) {}
};

}  // namespace tilesweep::detail

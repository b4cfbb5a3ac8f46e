// SPDX-License-Identifier: MIT
#pragma once

// A game-loop result (MoveResult, tilesweep/mover.h) from a resolved frame (ResolveResult): the
// one conversion behind moveAndSlide (mover.cpp) and the batch (move_range.cpp).

#include "tilesweep/mover.h"
#include "tilesweep/resolve.h"

#include <cstdint>

namespace tilesweep::detail {

/// The result of a move refused with `status`: the box stays where it was.
template <class T>
[[nodiscard, gnu::always_inline]] inline MoveResult<T> refusedMove(const MoveInput<T>& input,
                                                                   MoveStatus status) noexcept {
    MoveResult<T> r;
    r.position = input.box.pos;
    r.status = status;
    return r;
}

/// The MoveResult of frame `s` of a move by `d`, which resolved (not InvalidInput); contactsStored
/// is left to the caller, which knows where the contacts went. Every contact of an axis has the
/// normal against that axis's motion (a frame moves one way on each axis), so the blocked axes
/// and the motion's signs give every flag.
template <class T>
[[nodiscard, gnu::always_inline]] inline MoveResult<T> moveResultOf(const ResolveResult<T>& s,
                                                                    Vec2<T> d) noexcept {
    MoveResult<T> r;
    r.position = s.position;
    r.status = s.status == ResolveStatus::Blocked ? MoveStatus::Blocked : MoveStatus::Moved;
    r.contactCount = s.contactCount;
    r.startOverlapCount = s.startOverlapCount;
    r.blockedX = s.blockedX;
    r.blockedY = s.blockedY;
    r.onWall = s.blockedX;
    // A blocked axis moved (a tile blocks only motion toward it), so its sign is -1 or 1.
    r.wallNormalX = static_cast<std::int8_t>(s.blockedX ? (d.x < 0) - (d.x > 0) : 0);
    r.onGround = s.blockedY & (d.y > 0);
    r.onCeiling = s.blockedY & (d.y < 0);
    r.clippedDisplacement = {s.blockedX ? T(0) : d.x, s.blockedY ? T(0) : d.y};
    return r;
}

}  // namespace tilesweep::detail

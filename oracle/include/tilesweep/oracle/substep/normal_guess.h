// SPDX-License-Identifier: MIT
#pragma once

#include "tilesweep/math.h"

#include <cstdint>

// The normal the substep resolvers report. A substep method sees only "separated at substep
// k-1, overlapping at substep k"; it has no entry times, so the contact axis is a guess.

namespace tilesweep::oracle {

/// The guessed normal of a tile first overlapped at a substep: the axis on which the box was
/// still separated from the tile at the previous substep when exactly one was (that axis closed
/// last), otherwise the dominant axis of the motion (`xDominant`: |dx| > |dy|); the normal points
/// against the motion on that axis (`signX`, `signY` in {-1, 0, 1}).
[[nodiscard]] inline Normal guessNormal(bool separatedX, bool separatedY, int signX, int signY,
                                        bool xDominant) {
    const bool useX = (separatedX != separatedY) ? separatedX : xDominant;
    return useX ? Normal{static_cast<std::int8_t>(-signX), 0} : Normal{0, static_cast<std::int8_t>(-signY)};
}

}  // namespace tilesweep::oracle

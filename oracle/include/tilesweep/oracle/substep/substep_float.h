// SPDX-License-Identifier: MIT
#pragma once

#include "tilesweep/oracle/substep/substep_oracle.h"
#include "tilesweep/scene/scene.h"

#include <cstdint>
#include <vector>

// The game-style substep loop a tutorial would write, kept as a baseline that is known to be
// wrong: everything in T. The step d/N is rounded once, the position is accumulated with
// p += step (one rounding per substep, so after N substeps it need not equal start + d), each
// box edge p + size is rounded, and overlap is tested in T against tile edges computed in T as
// origin + i*tileSize. It misses corners whose overlap window falls between two substeps and
// tunnels through tiles thinner than one substep of motion; rounding can also make it see or
// miss a touch the exact rules decide the other way. A one-way tile is handled as a tutorial
// would: tested only on a move down that starts with the box's bottom at or above its top (in T),
// it stops the box at the first substep that overlaps it if, a substep before, the box overlapped
// it on x with its bottom at or above the top.
//
// It reports like resolveSceneSubstep: the position of the last substep before the first
// overlap (as accumulated, no further rounding), the tiles overlapped at the first overlapping
// substep k with time k/N (computed in T) and the guessed normal of guessNormal, and the tiles
// overlapped (in T) at the frame's start, which are never tested.

namespace tilesweep::oracle {

/// Runs every frame of a scene through the game-style T substep loop, usable as
/// `--resolver substep-float:N`. Throws std::invalid_argument when substeps < 1.
template <class T>
[[nodiscard]] std::vector<SubstepFrame<T>> resolveSceneSubstepFloat(const Scene<T>& scene,
                                                                    std::int64_t substeps);

extern template std::vector<SubstepFrame<float>> resolveSceneSubstepFloat<float>(const Scene<float>&,
                                                                                 std::int64_t);
extern template std::vector<SubstepFrame<double>> resolveSceneSubstepFloat<double>(const Scene<double>&,
                                                                                   std::int64_t);

}  // namespace tilesweep::oracle

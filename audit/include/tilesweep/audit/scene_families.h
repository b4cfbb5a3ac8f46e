// SPDX-License-Identifier: MIT
#pragma once

#include "tilesweep/scenarios/drawn_families.h"
#include "tilesweep/scenarios/families.h"
#include "tilesweep/scene/scene.h"

#include <cstdint>
#include <string>
#include <vector>

// The columns of the audit, over the scenario library (scenarios/): its drawn families, the
// same scenes translated far from the origin, and every family of the property suite, so that
// the audit measures the population the properties check and a new family lands here too. One
// scene per (seed, family, case index, scalar), so that any case is regenerated from those four
// numbers (the worst scenes are written that way, after the run).

namespace tilesweep::audit {

/// What a family builds; the "far" families are a mix of the first four, translated.
enum class FamilyKind : std::uint8_t {
    Uniform,     ///< random maps, boxes and moves, 1 to 3 frames
    NearCorner,  ///< a corner grazed exactly, or clipped or missed by 1 to 4 ulps
    Tie,         ///< both axes enter at the same time (an exact corner hit), sometimes 1 ulp off
    Seam,        ///< landings across floor seams and long slides resting on a floor
    Tiny,        ///< displacements below one ulp of the position, free or against a face
    HighSpeed,   ///< 1 to 100 tiles per frame through thin walls (the property family high-speed)
    Far,         ///< uniform, near-corner, tie and seam scenes translated by `magnitude`
    Suite,       ///< a family of the property suite (`suite`), drawn from a seed (scenarios::buildScene)
};

/// One column of the report.
struct Family {
    std::string name;  ///< "uniform", "near-corner", ..., "far-1e6"
    FamilyKind kind = FamilyKind::Uniform;
    double magnitude = 0;  ///< the translation of the scene (rounded down to whole tiles)
    bool floatToo = true;  ///< false: only the double implementations run it (beyond 2^23)
    scenarios::Family suite = scenarios::Family::Mixed;  ///< for FamilyKind::Suite
};

/// Every family of the audit, in report order.
[[nodiscard]] std::vector<Family> auditFamilies();

/// The scene of one case, regenerated identically from the same four values.
template <class T>
[[nodiscard]] Scene<T> generateScene(const Family& family, std::uint64_t seed, std::uint64_t caseIndex);

extern template Scene<float> generateScene<float>(const Family&, std::uint64_t, std::uint64_t);
extern template Scene<double> generateScene<double>(const Family&, std::uint64_t, std::uint64_t);

}  // namespace tilesweep::audit

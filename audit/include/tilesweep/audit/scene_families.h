// SPDX-License-Identifier: MIT
#pragma once

#include "tilesweep/scenarios/families.h"
#include "tilesweep/scene/scene.h"

#include <cstdint>
#include <string>
#include <vector>

// The columns of the audit, over the scenario library (scenarios/): every family of the property
// suite, and the same scenes built far from the origin, so that the audit measures the
// population the properties check and a new family lands here too. One scene per (seed, family,
// case index, scalar), so that any case is regenerated from those four numbers (the worst scenes
// are written that way, after the run).

namespace tilesweep::audit {

/// What a column builds.
enum class FamilyKind : std::uint8_t {
    Suite,  ///< a family of the property suite (`suite`), drawn from a seed (scenarios::buildScene)
    Far,    ///< the families of kFarFamilies in turn, built at `magnitude`
};

/// The families of the far columns, case by case in turn: solid tiles, then one-way platforms
/// (landed on, jumped through, walked along), so that every claim is measured by distance.
inline constexpr scenarios::Family kFarFamilies[] = {
    scenarios::Family::Random,      scenarios::Family::CornerPass,      scenarios::Family::CornerTie,
    scenarios::Family::SeamLanding, scenarios::Family::PlatformLanding, scenarios::Family::PlatformJump,
    scenarios::Family::PlatformWalk};

/// One column of the report.
struct Family {
    std::string name;  ///< the suite family's name ("random", "corner-tie", ...), or "far-1e6"
    FamilyKind kind = FamilyKind::Suite;
    double magnitude = 0;  ///< where a far scene's map origin lies (rounded down to whole tiles)
    bool floatToo = true;  ///< false: only the double implementations run it (beyond 2^23)
    scenarios::Family suite = scenarios::Family::Mixed;  ///< for FamilyKind::Suite
};

/// The column of one property family.
[[nodiscard]] Family suiteFamily(scenarios::Family suite);

/// Every family of the audit, in report order.
[[nodiscard]] std::vector<Family> auditFamilies();

/// The scene of one case, regenerated identically from the same four values.
template <class T>
[[nodiscard]] Scene<T> generateScene(const Family& family, std::uint64_t seed, std::uint64_t caseIndex);

extern template Scene<float> generateScene<float>(const Family&, std::uint64_t, std::uint64_t);
extern template Scene<double> generateScene<double>(const Family&, std::uint64_t, std::uint64_t);

}  // namespace tilesweep::audit

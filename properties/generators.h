// SPDX-License-Identifier: MIT
#pragma once

// The property suite's scenes are the scenario library's families (scenarios/, one definition
// for the suite, the audit, the benchmarks and the soak); the suite names them as its own.

#include "tilesweep/scenarios/families.h"

namespace tilesweep::properties {

using scenarios::allFamilies;
using scenarios::buildScene;
using scenarios::Family;
using scenarios::familyName;
using scenarios::GeneratedScene;
using scenarios::genScene;

}  // namespace tilesweep::properties

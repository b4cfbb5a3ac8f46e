// SPDX-License-Identifier: MIT
#pragma once

// The benchmarks' frames come from the scenario library (tilesweep/scenarios/frames.h).

#include "tilesweep/scenarios/frames.h"

namespace tilesweep::bench {

using scenarios::FrameKind;
using scenarios::FrameScenario;
using scenarios::kFarOrigin;
using scenarios::kFrameCount;
using scenarios::kFrameMapSize;
using scenarios::kFrameTile;
using scenarios::kSideBySideScenarios;
using scenarios::makeFrameScenario;
using scenarios::nameOf;
using scenarios::SideBySideScenario;

}  // namespace tilesweep::bench

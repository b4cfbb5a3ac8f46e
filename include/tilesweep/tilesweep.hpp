// SPDX-License-Identifier: MIT
#pragma once

// The C++ umbrella header of the tilesweep core library (target tilesweep::tilesweep): includes
// its headers, declares nothing. The batch (batch.h, target tilesweep::batch) and the C API
// (tilesweep.h, target tilesweep::c) are included on their own.

#include "tilesweep/box_sweep.h"
#include "tilesweep/frame_stats.h"
#include "tilesweep/math.h"
#include "tilesweep/mover.h"
#include "tilesweep/resolve.h"
#include "tilesweep/tile_map.h"

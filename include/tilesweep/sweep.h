// SPDX-License-Identifier: MIT
#pragma once

// Umbrella header of the tilesweep core library (target tilesweep::tilesweep): includes its
// headers, declares nothing. The batch (batch.h, tilesweep::batch) and the C API (tilesweep.h)
// are included on their own.

#include "tilesweep/box_sweep.h"
#include "tilesweep/frame_stats.h"
#include "tilesweep/math.h"
#include "tilesweep/mover.h"
#include "tilesweep/resolve.h"
#include "tilesweep/tile_map.h"

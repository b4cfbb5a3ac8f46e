// SPDX-License-Identifier: MIT
#pragma once

// Umbrella header of the tilesweep core library: includes the others, declares nothing.

#include "tilesweep/box_sweep.h"
#include "tilesweep/math.h"
#include "tilesweep/resolve.h"
#include "tilesweep/tile_map.h"

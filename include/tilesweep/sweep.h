// SPDX-License-Identifier: MIT
#pragma once

// Deprecated: the C++ umbrella header is tilesweep/tilesweep.hpp, and this one only includes it.
// It is kept for one release, as the names before the one naming scheme are (resolve.h), and
// warns where it is included.

#if defined(_MSC_VER)
#pragma message("tilesweep/sweep.h is deprecated: include tilesweep/tilesweep.hpp")
#elif defined(__GNUC__)
#pragma GCC warning "tilesweep/sweep.h is deprecated: include tilesweep/tilesweep.hpp"
#endif

#include "tilesweep/tilesweep.hpp"

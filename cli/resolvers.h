// SPDX-License-Identifier: MIT
#pragma once

// The implementations `tilesweep resolve --resolver NAME` chooses among, all driven by the same
// scene files and printing the same output format:
//
//   core             the production resolver in --scalar (the default)
//   float, double    the production resolver in that scalar type (sets --scalar)
//   exact            the exact rational reference, rounded under --scalar's rule
//   substep:N        the exact fine-substep oracle with N substeps
//   substep-float:N  the game-style substep loop, positions accumulated in --scalar
//   seed             the seed article's algorithm as written (a baseline, not a reference)
//   twin, grid       the game-style swept-AABB baselines of baselines/ (plain T, lean)
//   lib:PATH         a user's resolver in a shared library (include/tilesweep/resolver_lib.h)

#include "tilesweep/scene/scene.h"

#include <functional>
#include <string>
#include <vector>

namespace tilesweep::cli {

/// Runs every frame of one scene.
template <class T>
using Resolver = std::function<std::vector<FrameResult<T>>(const Scene<T>&)>;

/// The resolver a name selects, or an empty function for an unknown name.
template <class T>
[[nodiscard]] Resolver<T> findResolver(const std::string& name);

/// Empty when `name` is a resolver this build knows, otherwise why not (for CLI11's checks).
[[nodiscard]] std::string checkResolverName(const std::string& name);

/// The scalar a resolver name forces ("float" or "double"), or empty.
[[nodiscard]] std::string scalarForcedBy(const std::string& name);

}  // namespace tilesweep::cli

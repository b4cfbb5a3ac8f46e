// SPDX-License-Identifier: MIT
#pragma once

// The names of every resolver behind the seam (scene_resolver.h), one table for every command
// of the tool (resolve, check, replay, audit, merge):
//
//   core             tilesweep's production resolver (float, double: the same, and the scalar forced)
//   exact            the exact rational reference, rounded under the contract's rule
//   substep:N        the exact fine-substep oracle with N substeps (1 <= N <= 2^20)
//   substep-float:N  the game-style substep loop, positions accumulated in the scalar type
//   seed             the seed article's algorithm as written (a baseline, not a reference)
//   twin, grid       the game-style swept-AABB baselines (baselines/)
//   lib:PATH         a user's resolver in a shared library (include/tilesweep/resolver_lib.h)
//   cmd:COMMAND      an outside process speaking `tilesweep resolve`'s protocol (outside_resolver.h)
//
//     std::string error;
//     auto twin = makeResolver("twin", error);        // nullptr, with `error` naming why, if unknown

#include "tilesweep/resolvers/scene_resolver.h"

#include <memory>
#include <string>

namespace tilesweep::resolvers {

/// How an outside process (cmd:COMMAND) is run.
struct OutsideOptions {
    double timeoutSeconds = 10;  ///< without an answer before the process counts as hung
};

/// The resolver `name` selects, or nullptr with `error` saying why (an unknown name, a library
/// that cannot be loaded).
[[nodiscard]] std::unique_ptr<SceneResolver> makeResolver(const std::string& name, std::string& error,
                                                          const OutsideOptions& outside = {});

/// Empty when `name` is a resolver this build knows (a library is loaded to see), else why not.
[[nodiscard]] std::string checkResolverName(const std::string& name);

/// The scalar type a name forces ("float" or "double"), or empty.
[[nodiscard]] std::string scalarForcedBy(const std::string& name);

/// The prefixes of the names that carry an argument.
inline constexpr const char* kLibraryPrefix = "lib:";
inline constexpr const char* kCommandPrefix = "cmd:";

}  // namespace tilesweep::resolvers

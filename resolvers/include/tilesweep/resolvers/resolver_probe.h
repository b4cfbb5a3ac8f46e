// SPDX-License-Identifier: MIT
#pragma once

// Whether an outside resolver can be checked at all, asked before a run starts its workers: one
// known scene (a box falling onto a floor) in each scalar type the run uses, sent in one batch.
// A resolver that cannot start, exits, hangs past the timeout, prints a line that is not a result
// line, or answers the valid scene with an error line is unusable, and the reason names it with
// its exit status and the tail of its standard error. The answer's values are not judged here:
// an inexact resolver is usable, the claims judge it.
//
//     const std::string why = probeResolver("adapters/godot/run.sh", 10.0, true, false);
//     if (!why.empty()) { print "resolver unusable: " + why; exit 2; }

#include <string>

namespace tilesweep::resolvers {

/// The known scene's line (every number a hexfloat, so the same scene in float and in double).
[[nodiscard]] std::string knownSceneLine();

/// Empty when `command` answers the known scene in float (when `inFloat`) and in double (when
/// `inDouble`) with a readable result line; else why not.
[[nodiscard]] std::string probeResolver(const std::string& command, double timeoutSeconds, bool inFloat,
                                        bool inDouble);

}  // namespace tilesweep::resolvers

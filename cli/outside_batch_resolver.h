// SPDX-License-Identifier: MIT
#pragma once

// An outside resolver (a command speaking `tilesweep resolve`'s protocol, in pipe or file mode:
// properties/resolver_process.h) as a batch resolver for the engine rates (audit/engine_rates.h):
// every batch goes to the process at once, and each answer is read back as frames of the run's
// scalar type (float, or double for resolveDouble). A
// crash, a hang, an error line or a malformed answer is that scene's failure, with the
// engine's output tail; the batch goes on.

#include "tilesweep/audit/engine_rates.h"

#include <memory>
#include <string>

namespace tilesweep::cli {

/// A batch resolver that runs `command` (sh -c), `timeoutSeconds` a batch at most.
[[nodiscard]] std::unique_ptr<audit::BatchResolver> makeOutsideBatchResolver(const std::string& command,
                                                                             double timeoutSeconds);

}  // namespace tilesweep::cli

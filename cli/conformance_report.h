// SPDX-License-Identifier: MIT
#pragma once

// The conformance report (docs/conformance.md): for each resolver checked, every property's
// verdict, cases run, failure rate and smallest counterexample with its picture. Written by
// `tilesweep audit --resolver-cmd ...` (several resolvers) and `tilesweep check --report`.

#include "check_command.h"

#include <string>
#include <vector>

namespace tilesweep::cli {

/// One resolver's check, as the report shows it.
struct ConformanceEntry {
    std::string label;     ///< a short name ("tilesweep", "twin", "box2d")
    CheckOptions options;  ///< what was run (command, claims, scalar, cases, seed, budget)
    CheckRun run;
};

/// Writes the Markdown report to `file` and each smallest counterexample's picture into
/// `pictureDir` (as <label>-<property>.svg, linked relative to the report); `rates`, when not
/// empty, is the engine rates section (audit/engine_rates.h, ratesMarkdown), placed after the
/// summary. Throws std::runtime_error when a file cannot be written.
void writeConformanceReport(const std::vector<ConformanceEntry>& entries, const std::string& file,
                            const std::string& pictureDir, const std::string& rates = {});

}  // namespace tilesweep::cli

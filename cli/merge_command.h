// SPDX-License-Identifier: MIT
#pragma once

// `tilesweep merge`: adds up the reports of shards (`tilesweep check --shard K/N --json` and
// `tilesweep audit --resolver-cmd ... --shard K/N`'s rates.json) into one conformance report,
// with the shards' regression files gathered in one corpus.

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace tilesweep::cli {

/// The options of `tilesweep merge`.
struct MergeOptions {
    std::vector<std::string> files;  ///< check JSON and rates JSON files, any order
    std::string outDir = "merged";   ///< conformance.md, rates.json, check-*.json, corpus/
};

/// Declares the subcommand and its options.
CLI::App* addMergeCommand(CLI::App& app, MergeOptions& options);

/// Runs it; returns the exit status (0 merged, 1 some resolver broke a claim, 2 bad input).
int runMergeCommand(const MergeOptions& options);

}  // namespace tilesweep::cli

// SPDX-License-Identifier: MIT
#pragma once

// `tilesweep replay`: regression files (corpus scenes) replayed against every claim that
// applies, through tilesweep's own resolver or an outside one (replay_command.cpp). What a team
// runs in its own CI to keep the counterexamples `tilesweep check --resolver-cmd` found.

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace tilesweep::cli {

/// The options of `tilesweep replay`.
struct ReplayOptions {
    std::vector<std::string> paths;  ///< files (.jsonl) or directories of them
    std::string resolver = "core";   ///< the resolver under test, by registry name
    std::string resolverCmd;         ///< outside resolver (sh -c): the same as resolver "cmd:" + it
    double resolverTimeout = 10;     ///< seconds without an answer before the process counts as hung
    std::string claims = "all";      ///< "all" or "safety"
};

/// Declares the subcommand and its options.
CLI::App* addReplayCommand(CLI::App& app, ReplayOptions& options);

/// Runs it; returns the exit status.
int runReplayCommand(const ReplayOptions& options);

}  // namespace tilesweep::cli

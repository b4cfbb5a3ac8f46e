// SPDX-License-Identifier: MIT
#pragma once

// `tilesweep check`: the property suite from the command line (check_command.cpp).

#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>

namespace tilesweep::cli {

/// The options of `tilesweep check`.
struct CheckOptions {
    int cases = 1000;                 ///< cases per property per round
    double seconds = 60;              ///< keep running rounds until this budget is spent
    std::uint64_t seed = 20261122;    ///< seed of the first round
    std::string property;             ///< substring filter on property names; empty: all
    int jobs = 0;                     ///< worker processes; 0: all cores
    std::string corpusDir = "properties/corpus";  ///< where failing cases are written
};

/// Declares the subcommand and its options.
CLI::App* addCheckCommand(CLI::App& app, CheckOptions& options);

/// Runs it; returns the exit status.
int runCheckCommand(const CheckOptions& options);

}  // namespace tilesweep::cli

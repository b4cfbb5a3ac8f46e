// SPDX-License-Identifier: MIT
#pragma once
// The options that check, replay and audit share for an outside resolver, declared once so that
// their spelling, checks, defaults and help stay the same in every command.
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace tilesweep::cli {

/// --resolver-timeout SECONDS: how long an outside resolver may go without answering (a line in
/// pipe mode, its answer file growing in file mode) before it counts as hung.
inline void addResolverTimeoutOption(CLI::App* command, double& seconds, const std::string& helpPrefix = "") {
    command
        ->add_option(
            "--resolver-timeout", seconds,
            helpPrefix + "Seconds an outside resolver may go without answering before it counts as hung")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
}

/// --claims all|safety: every claim, or leave out the bit-for-bit ones.
inline void addClaimsOption(CLI::App* command, std::string& claims, const std::string& helpPrefix = "") {
    command->add_option("--claims", claims, helpPrefix + "all, or safety: leave out the bit-for-bit claims")
        ->check(CLI::IsMember(std::vector<std::string>{"all", "safety"}))
        ->capture_default_str();
}

}  // namespace tilesweep::cli

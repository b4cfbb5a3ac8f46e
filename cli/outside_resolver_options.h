// SPDX-License-Identifier: MIT
#pragma once
// The options that check, replay and audit share for the resolver under test, declared once so
// that their spelling, checks, defaults and help stay the same in every command.
#include "tilesweep/resolvers/resolver_registry.h"

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

/// --resolver NAME: any resolver of the registry (tilesweep/resolvers/resolver_registry.h).
inline void addResolverOption(CLI::App* command, std::string& name) {
    command
        ->add_option(
            "--resolver", name,
            "The resolver under test, by name: core, exact, seed, substep:N, substep-float:N, twin,\n"
            "grid, lib:PATH (a shared library) or cmd:COMMAND (the same as --resolver-cmd)")
        ->check(CLI::Validator(resolvers::checkResolverName, "NAME", "resolver"))
        ->capture_default_str();
}

/// The registry name of the resolver under test: the --resolver-cmd command when one is given,
/// else the --resolver name.
[[nodiscard]] inline std::string resolverUnderTest(const std::string& name, const std::string& command) {
    return command.empty() ? name : std::string(resolvers::kCommandPrefix) + command;
}

/// Whether a resolver name is tilesweep's own production resolver, held to every claim (the
/// others are held to the claims about results only).
[[nodiscard]] inline bool isTilesweepItself(const std::string& name) {
    return name == "core" || name == "float" || name == "double";
}

/// --claims all|safety: every claim, or leave out the bit-for-bit ones.
inline void addClaimsOption(CLI::App* command, std::string& claims, const std::string& helpPrefix = "") {
    command->add_option("--claims", claims, helpPrefix + "all, or safety: leave out the bit-for-bit claims")
        ->check(CLI::IsMember(std::vector<std::string>{"all", "safety"}))
        ->capture_default_str();
}

}  // namespace tilesweep::cli

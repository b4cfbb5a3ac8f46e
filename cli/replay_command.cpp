// SPDX-License-Identifier: MIT
// `tilesweep replay`: every scene of the regression files named, against every claim that
// applies to the resolver (all of them for tilesweep's own; those about results for an outside
// one, or only the safety ones with --claims safety). One line per scene; exit status 1 when a
// claim fails, so a team's CI keeps its counterexamples fixed.
#include "replay_command.h"

#include "all_claims.h"
#include "outside_resolver_options.h"

#include "tilesweep/resolvers/resolver_registry.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

namespace tilesweep::cli {
namespace {

std::vector<std::string> expandPaths(const std::vector<std::string>& paths) {
    std::vector<std::string> files;
    for (const std::string& p : paths) {
        if (!std::filesystem::is_directory(p)) {
            files.push_back(p);
            continue;
        }
        std::vector<std::string> inside;
        for (const auto& entry : std::filesystem::directory_iterator(p))
            if (entry.path().extension() == ".jsonl") inside.push_back(entry.path().string());
        std::sort(inside.begin(), inside.end());
        files.insert(files.end(), inside.begin(), inside.end());
    }
    return files;
}

/// Replays one scene line in T; prints its verdict; returns whether every claim held.
template <class T>
bool replayLine(const std::string& where, const std::string& line, resolvers::SceneResolver& resolver,
                bool outside, bool safetyOnly) {
    const SceneParse<T> parsed = parseScene<T>(line);
    if (!parsed.scene) {
        std::printf("FAILED %s: not a scene: %s\n", where.c_str(), parsed.error.c_str());
        return false;
    }
    int checked = 0;
    bool ok = true;
    for (const properties::Claim<T>& claim : properties::allClaims<T>()) {
        const bool applies = outside ? properties::appliesToOutside(claim.scope, safetyOnly)
                                     : !(safetyOnly && claim.scope == properties::ClaimScope::BitForBit);
        if (!applies) continue;
        ++checked;
        const std::string why = properties::checkClaim(claim, *parsed.scene, resolver);
        if (why.empty()) continue;
        ok = false;
        std::printf("FAILED %s: %s: %s\n", where.c_str(), claim.name, why.c_str());
    }
    if (ok) std::printf("ok     %s (%d claims)\n", where.c_str(), checked);
    return ok;
}

}  // namespace

CLI::App* addReplayCommand(CLI::App& app, ReplayOptions& options) {
    CLI::App* command =
        app.add_subcommand("replay", "Replay regression files against every claim that applies");
    command->add_option("PATH", options.paths, "Regression files (.jsonl), or directories of them")
        ->required();
    addResolverOption(command, options.resolver);
    command
        ->add_option(
            "--resolver-cmd", options.resolverCmd,
            "Replay against an outside resolver (a shell command speaking `tilesweep resolve`'s protocol)")
        ->type_name("CMD");
    addResolverTimeoutOption(command, options.resolverTimeout);
    addClaimsOption(command, options.claims);
    command->footer(
        "Each scene line is read in the scalar its \"scalar\" field names (float when absent), as\n"
        "`tilesweep check` writes them. Exit status: 0 every claim held on every scene; 1 some claim\n"
        "failed or a line is not a scene; 2 bad arguments or a file could not be read.");
    return command;
}

int runReplayCommand(const ReplayOptions& options) {
    const std::string name = resolverUnderTest(options.resolver, options.resolverCmd);
    const bool outside = !isTilesweepItself(name);
    const bool safetyOnly = options.claims == "safety";
    std::string error;
    const std::unique_ptr<resolvers::SceneResolver> resolver =
        resolvers::makeResolver(name, error, {options.resolverTimeout});
    if (!resolver) {
        std::fprintf(stderr, "tilesweep replay: --resolver %s: %s\n", name.c_str(), error.c_str());
        return 2;
    }
    int scenes = 0;
    int failed = 0;
    for (const std::string& file : expandPaths(options.paths)) {
        std::ifstream in(file);
        if (!in) {
            std::fprintf(stderr, "tilesweep replay: cannot read '%s'\n", file.c_str());
            return 2;
        }
        std::string line;
        for (int number = 1; std::getline(in, line); ++number) {
            if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
            const auto json = nlohmann::json::parse(line, nullptr, false);
            const std::string scalar =
                json.is_object() && json.contains("scalar") && json["scalar"].is_string()
                    ? json["scalar"].get<std::string>()
                    : "float";
            const std::string where = file + ":" + std::to_string(number);
            const bool ok = scalar == "double"
                                ? replayLine<double>(where, line, *resolver, outside, safetyOnly)
                                : replayLine<float>(where, line, *resolver, outside, safetyOnly);
            ++scenes;
            failed += ok ? 0 : 1;
        }
    }
    std::printf("\n%d scene%s replayed, %d failed\n", scenes, scenes == 1 ? "" : "s", failed);
    return failed == 0 ? 0 : 1;
}

}  // namespace tilesweep::cli

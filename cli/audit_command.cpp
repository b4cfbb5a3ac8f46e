// SPDX-License-Identifier: MIT
// `tilesweep audit`: runs the tolerance audit (audit/audit.h) with progress on stderr, writes the
// report into --out and prints where it is and the headline figures. The exit status is 1 when a
// production row (core-float, core-double) is not zero: that is a bug in the core.
#include "audit_command.h"

#include <chrono>
#include <cstdio>
#include <exception>
#include <iostream>
#include <string>

#include "audit/audit.h"

namespace tilesweep::cli {

CLI::App* addAuditCommand(CLI::App& app, AuditOptions& options) {
    CLI::App* command = app.add_subcommand(
        "audit", "Hold every implementation against the exact reference over scenario families; write a report");
    command->add_option("--cases", options.cases, "Scenes per family per scalar type")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    command->add_option("--seed", options.seed, "The seed every scene derives from")->capture_default_str();
    command->add_option("--out", options.outDir, "Directory for report.md, report.json, the SVG plots and worst/")
        ->type_name("DIR")
        ->capture_default_str();
    command->add_option("--jobs", options.jobs, "Worker threads (default: all cores)")->check(CLI::PositiveNumber);
    command->footer(
        "Implementations: core-float, core-double (tilesweep::runScene), twin-* and grid-* (game-style\n"
        "swept AABB, bench/), seed-float, seed-double (the seed\n"
        "article as written), substep{4,16,256}-float (the game-style substep loop). Families: uniform,\n"
        "near-corner, tie, seam, tiny, high-speed, and far-<magnitude> (the same scenes translated by whole\n"
        "tiles; float up to 2^23, double up to 2^52). The figures depend only on --cases and --seed.\n"
        "\n"
        "Exit status: 0 the production rows read zero everywhere; 1 they do not (the report names the\n"
        "scenes); 2 bad arguments or the report could not be written.");
    return command;
}

int runAuditCommand(const AuditOptions& options) {
    audit::AuditConfig config;
    config.cases = options.cases;
    config.seed = options.seed;
    config.jobs = options.jobs;
    config.commandLine = options.commandLine.empty()
                             ? "tilesweep audit --cases " + std::to_string(options.cases) + " --seed " +
                                   std::to_string(options.seed)
                             : options.commandLine;
    const auto started = std::chrono::steady_clock::now();
    config.progress = [started](std::uint64_t done, std::uint64_t total) {
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
        const double share = total == 0 ? 1.0 : static_cast<double>(done) / static_cast<double>(total);
        const double left = share > 0 ? elapsed / share - elapsed : 0.0;
        std::fprintf(stderr, "\rtilesweep audit: %llu/%llu cases (%3.0f%%), %.0f s, about %.0f s left   ",
                     static_cast<unsigned long long>(done), static_cast<unsigned long long>(total), 100.0 * share,
                     elapsed, left);
        if (done == total) std::fprintf(stderr, "\n");
        std::fflush(stderr);
    };
    std::fprintf(stderr, "tilesweep audit: %llu scenes per family per scalar type, %zu families, seed %llu -> %s\n",
                 static_cast<unsigned long long>(options.cases), audit::auditFamilies().size(),
                 static_cast<unsigned long long>(options.seed), options.outDir.c_str());
    const audit::AuditResult result = audit::runAudit(config);
    try {
        audit::writeAuditReport(result, options.outDir);
    } catch (const std::exception& error) {
        std::cerr << "tilesweep audit: " << error.what() << '\n';
        return 2;
    }

    // Headline: per implementation, over all families.
    std::printf("%-18s %10s %10s %10s %14s\n", "implementation", "decision", "tunnel", "inside", "max pos ulps");
    bool productionClean = true;
    for (std::size_t i = 0; i < result.implementations.size(); ++i) {
        std::uint64_t scenes = 0, decision = 0, tunnel = 0, inside = 0, worstUlps = 0;
        bool anyFailure = false;
        for (const audit::CellStats& cell : result.cells[i]) {
            scenes += cell.scenes;
            decision += cell.failures[static_cast<std::size_t>(audit::Metric::Decision)];
            tunnel += cell.failures[static_cast<std::size_t>(audit::Metric::Tunnel)];
            inside += cell.failures[static_cast<std::size_t>(audit::Metric::Inside)];
            if (!cell.positionUlps.empty() && cell.positionUlps.back() > worstUlps) worstUlps = cell.positionUlps.back();
            for (const std::uint64_t f : cell.failures) anyFailure = anyFailure || f > 0;
        }
        auto pct = [&](std::uint64_t n) { return scenes == 0 ? 0.0 : 100.0 * static_cast<double>(n) / static_cast<double>(scenes); };
        const std::string ulps = worstUlps == audit::kNonFiniteUlps ? std::string("inf") : std::to_string(worstUlps);
        std::printf("%-18s %9.2f%% %9.2f%% %9.2f%% %14s\n", result.implementations[i].name.c_str(), pct(decision),
                    pct(tunnel), pct(inside), ulps.c_str());
        if (result.implementations[i].kind == audit::ImplementationKind::Core && anyFailure) productionClean = false;
    }
    std::printf("\n%s\nreport: %s/report.md (%.1f s, %d thread%s)\n",
                productionClean ? "production rows: zero everywhere"
                                : "PRODUCTION ROWS ARE NOT ZERO: see report.md and worst/core-*",
                options.outDir.c_str(), result.seconds, result.jobs, result.jobs == 1 ? "" : "s");
    return productionClean ? 0 : 1;
}

}  // namespace tilesweep::cli

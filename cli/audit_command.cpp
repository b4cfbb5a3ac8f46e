// SPDX-License-Identifier: MIT
// `tilesweep audit`: runs the tolerance audit (audit/audit.h) with progress on stderr, writes the
// report into --out and prints where it is and the headline figures. The exit status is 1 when a
// production row (core-float, core-double) is not zero: that is a bug in the core.
#include "audit_command.h"

#include "audit/audit.h"

#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <string>
#include <unistd.h>
#if TILESWEEP_HAVE_CHECK
#include "check_command.h"
#include "conformance_report.h"
#endif

namespace tilesweep::cli {

CLI::App* addAuditCommand(CLI::App& app, AuditOptions& options) {
    CLI::App* command = app.add_subcommand(
        "audit",
        "Hold every implementation against the exact reference over scenario families; write a report");
    command->add_option("--cases", options.cases, "Scenes per family per scalar type")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    command->add_option("--seed", options.seed, "The seed every scene derives from")->capture_default_str();
    command
        ->add_option(
            "--out", options.outDir,
            "Directory for report.md, report.json and worst/ (scripts/plots.py audit DIR draws the charts)")
        ->type_name("DIR")
        ->capture_default_str();
    command->add_option("--jobs", options.jobs, "Worker threads (default: all cores)")
        ->check(CLI::PositiveNumber);
    command
        ->add_option("--resolver-cmd", options.resolverCmds,
                     "Conformance mode: hold this outside resolver (repeatable) to every claim about\n"
                     "results, instead of the tolerance audit; writes --report")
        ->type_name("CMD");
    command->add_option("--resolver-name", options.resolverNames, "A label per --resolver-cmd, in order");
    command->add_option("--report", options.report, "Conformance mode: the Markdown report")
        ->capture_default_str();
    command->add_option("--pictures", options.pictures, "Conformance mode: where counterexample pictures go")
        ->capture_default_str();
    command
        ->add_option("--seconds", options.secondsPerResolver, "Conformance mode: check budget per resolver")
        ->check(CLI::NonNegativeNumber)
        ->capture_default_str();
    command
        ->add_option("--property-cases", options.propertyCases,
                     "Conformance mode: cases per property per round")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    command
        ->add_option("--claims", options.claims, "Conformance mode: all, or safety (no bit-for-bit claims)")
        ->check(CLI::IsMember(std::vector<std::string>{"all", "safety"}))
        ->capture_default_str();
    command->add_option("--scalar", options.scalar, "Conformance mode: the resolvers' scalar type")
        ->check(CLI::IsMember(std::vector<std::string>{"float", "double"}))
        ->capture_default_str();
    command->add_option("--resolver-timeout", options.resolverTimeout, "Conformance mode: seconds per batch")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    command->footer(
        "Implementations: core-float, core-double (tilesweep::runScene), twin-* and grid-* (game-style\n"
        "swept AABB, bench/), seed-float, seed-double (the seed\n"
        "article as written), substep{4,16,256}-float (the game-style substep loop). Families: uniform,\n"
        "near-corner, tie, seam, tiny, high-speed, and far-<magnitude> (the same scenes translated by whole\n"
        "tiles; float up to 2^23, double up to 2^52), and suite:<family>, every family of the property\n"
        "suite but extreme (scenarios/). The figures depend only on --cases and --seed.\n"
        "\n"
        "Exit status: 0 the production rows read zero everywhere; 1 they do not (the report names the\n"
        "scenes); 2 bad arguments or the report could not be written.");
    return command;
}

#if TILESWEEP_HAVE_CHECK
namespace {

/// Conformance mode: one check per outside resolver, every run kept going for the whole budget
/// so that failure rates mean something, and one report.
int runConformance(const AuditOptions& options) {
    std::vector<ConformanceEntry> entries;
    bool allHeld = true;
    for (std::size_t k = 0; k < options.resolverCmds.size(); ++k) {
        ConformanceEntry entry;
        entry.label = k < options.resolverNames.size() ? options.resolverNames[k] : options.resolverCmds[k];
        CheckOptions& check = entry.options;
        check.resolverCmd = options.resolverCmds[k];
        check.resolverTimeout = options.resolverTimeout;
        check.claims = options.claims;
        check.scalar = options.scalar;
        check.cases = options.propertyCases;
        check.seconds = options.secondsPerResolver;
        check.seed = options.seed;
        check.jobs = options.jobs;
        check.keepGoing = true;
        check.quiet = true;
        check.corpusDir = (std::filesystem::temp_directory_path() /
                           ("tilesweep-conformance-" + std::to_string(getpid()) + "-" + std::to_string(k)))
                              .string();
        std::fprintf(stderr, "tilesweep audit: checking %s (%s) for %.0f s\n", entry.label.c_str(),
                     check.resolverCmd.c_str(), check.seconds);
        entry.run = runChecks(check);
        int failed = 0;
        for (const CheckRow& r : entry.run.rows) failed += r.failures > 0 ? 1 : 0;
        std::printf("%-24s %3zu properties, %3d failed\n", entry.label.c_str(), entry.run.rows.size(),
                    failed);
        allHeld = allHeld && failed == 0;
        entries.push_back(std::move(entry));
    }
    writeConformanceReport(entries, options.report, options.pictures);
    for (const ConformanceEntry& e : entries) {
        std::error_code ignored;
        std::filesystem::remove_all(e.options.corpusDir, ignored);
    }
    std::printf("report: %s\n", options.report.c_str());
    return allHeld ? 0 : 1;
}

}  // namespace
#endif

int runAuditCommand(const AuditOptions& options) {
#if TILESWEEP_HAVE_CHECK
    if (!options.resolverCmds.empty()) return runConformance(options);
#endif
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
        const double elapsed =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
        const double share = total == 0 ? 1.0 : static_cast<double>(done) / static_cast<double>(total);
        const double left = share > 0 ? elapsed / share - elapsed : 0.0;
        std::fprintf(stderr, "\rtilesweep audit: %llu/%llu cases (%3.0f%%), %.0f s, about %.0f s left   ",
                     static_cast<unsigned long long>(done), static_cast<unsigned long long>(total),
                     100.0 * share, elapsed, left);
        if (done == total) std::fprintf(stderr, "\n");
        std::fflush(stderr);
    };
    std::fprintf(stderr,
                 "tilesweep audit: %llu scenes per family per scalar type, %zu families, seed %llu -> %s\n",
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
    std::printf("%-18s %10s %10s %10s %14s\n", "implementation", "decision", "tunnel", "inside",
                "max pos ulps");
    bool productionClean = true;
    for (std::size_t i = 0; i < result.implementations.size(); ++i) {
        std::uint64_t scenes = 0, decision = 0, tunnel = 0, inside = 0, worstUlps = 0;
        bool anyFailure = false;
        for (const audit::CellStats& cell : result.cells[i]) {
            scenes += cell.scenes;
            decision += cell.failures[static_cast<std::size_t>(audit::Metric::Decision)];
            tunnel += cell.failures[static_cast<std::size_t>(audit::Metric::Tunnel)];
            inside += cell.failures[static_cast<std::size_t>(audit::Metric::Inside)];
            if (!cell.positionUlps.empty() && cell.positionUlps.back() > worstUlps)
                worstUlps = cell.positionUlps.back();
            for (const std::uint64_t f : cell.failures) anyFailure = anyFailure || f > 0;
        }
        auto pct = [&](std::uint64_t n) {
            return scenes == 0 ? 0.0 : 100.0 * static_cast<double>(n) / static_cast<double>(scenes);
        };
        const std::string ulps =
            worstUlps == audit::kNonFiniteUlps ? std::string("inf") : std::to_string(worstUlps);
        std::printf("%-18s %9.2f%% %9.2f%% %9.2f%% %14s\n", result.implementations[i].name.c_str(),
                    pct(decision), pct(tunnel), pct(inside), ulps.c_str());
        if (result.implementations[i].kind == audit::ImplementationKind::Core && anyFailure)
            productionClean = false;
    }
    std::printf("\n%s\nreport: %s/report.md (%.1f s, %d thread%s)\n",
                productionClean ? "production rows: zero everywhere"
                                : "PRODUCTION ROWS ARE NOT ZERO: see report.md and worst/core-*",
                options.outDir.c_str(), result.seconds, result.jobs, result.jobs == 1 ? "" : "s");
    return productionClean ? 0 : 1;
}

}  // namespace tilesweep::cli

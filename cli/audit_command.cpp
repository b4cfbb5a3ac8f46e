// SPDX-License-Identifier: MIT
// `tilesweep audit`: runs the tolerance audit (audit/audit.h) with progress on stderr, writes the
// report into --out and prints where it is and the headline figures. The exit status is 1 when a
// production row (core-float, core-double) is not zero: that is a bug in the core.
#include "audit_command.h"

#include "outside_resolver_options.h"
#include "progress_line.h"
#include "shard.h"

#include "tilesweep/audit/audit.h"
#include "tilesweep/resolvers/outside_resolver.h"
#include "tilesweep/resolvers/resolver_probe.h"
#include "tilesweep/resolvers/resolver_registry.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <unistd.h>
#if TILESWEEP_HAVE_CHECK
#include "check_command.h"
#include "conformance_report.h"

#include "tilesweep/audit/engine_rates.h"

#include <fstream>
#include <sstream>
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
    addClaimsOption(command, options.claims, "Conformance mode: ");
    command
        ->add_option("--scalar", options.scalar,
                     "Conformance mode: the resolvers' scalar type (the checks' and the rates' scenes)")
        ->check(CLI::IsMember(std::vector<std::string>{"float", "double"}))
        ->capture_default_str();
    addResolverTimeoutOption(command, options.resolverTimeout);
    command
        ->add_option("--rates-cases", options.ratesCases,
                     "Conformance mode: scenes per family for the engine rates and tolerances (0: none)")
        ->capture_default_str();
    command
        ->add_option("--resolver-tolerance", options.resolverTolerances,
                     "Conformance mode: an engine's own tolerance, by its --resolver-name, in pixels, then\n"
                     "what it is (\"godot=0.08 safe margin\"); set beside the measured tolerances")
        ->type_name("\"NAME=PX [NOTE]\"");
    command
        ->add_option("--compare", options.compare,
                     "Conformance mode: tilesweep's in-process implementations measured on the same scenes\n"
                     "(comma-separated: tilesweep, twin, grid; empty: none)")
        ->capture_default_str();
    command->add_option(
        "--rates-json", options.ratesJson,
        "Conformance mode: the rates file (default: <pictures>/rates.json; `tilesweep merge`\n"
        "adds shards' files up)");
    command->add_flag("--rates-only", options.ratesOnly,
                      "Conformance mode: only the rates, no property checks");
    command
        ->add_option(
            "--shard", options.shard,
            "K/N: run only slice K (from 0) of N of the seeds and cases; merge with `tilesweep merge`")
        ->capture_default_str();
    command->footer(
        "Implementations: core-float, core-double (tilesweep::runScene), twin-* and grid-* (game-style\n"
        "swept AABB, bench/), seed-float, seed-double (the seed\n"
        "article as written), substep{4,16,256}-float (the game-style substep loop). Families: every\n"
        "family of the property suite but extreme (scenarios/), and far-<magnitude>: random, corner-pass,\n"
        "corner-tie, seam-landing and one-way platform scenes built with their map origin there (float up\n"
        "to 2^23, double\n"
        "up to 2^52). The figures depend only on --cases and --seed.\n"
        "\n"
        "Exit status: 0 the production rows read zero everywhere; 1 they do not (the report names the\n"
        "scenes); 2 bad arguments or the report could not be written.");
    return command;
}

#if TILESWEEP_HAVE_CHECK
namespace {

/// The in-process implementations `--compare` names, as rate engines.
std::vector<audit::EngineSpec> comparedEngines(const std::string& list, const std::string& scalar) {
    std::vector<audit::EngineSpec> engines;
    std::stringstream names(list);
    for (std::string name; std::getline(names, name, ',');) {
        if (name.empty()) continue;
        const std::string implementation = (name == "tilesweep" ? "core" : name) + "-" + scalar;
        bool found = false;
        for (const audit::Implementation& impl : audit::auditImplementations()) {
            if (impl.name != implementation) continue;
            const std::string resolver = audit::resolverName(impl);
            engines.push_back({name,
                               [resolver] {
                                   std::string error;
                                   return resolvers::makeResolver(resolver, error);
                               },
                               0, ""});
            found = true;
        }
        if (!found)
            throw std::invalid_argument("--compare: unknown implementation '" + name +
                                        "' (tilesweep, twin, grid)");
    }
    return engines;
}

/// An engine's documented tolerance: "godot=0.08 safe margin" -> godot, 0.08, "safe margin".
struct DocumentedTolerance {
    std::string name;
    double pixels = 0;
    std::string note;
};

/// Parses NAME=PIXELS [NOTE]; throws std::invalid_argument naming the option.
DocumentedTolerance parseTolerance(const std::string& text) {
    const std::size_t equals = text.find('=');
    const std::string usage =
        "--resolver-tolerance: expected NAME=PIXELS then a note, as \"godot=0.08 safe margin\", got '";
    if (equals == std::string::npos || equals == 0) throw std::invalid_argument(usage + text + "'");
    const char* number = text.c_str() + equals + 1;
    char* end = nullptr;
    const double value = std::strtod(number, &end);
    if (end == number || !(value >= 0) || !std::isfinite(value))
        throw std::invalid_argument(usage + text + "'");
    std::string note = end;
    while (!note.empty() && note.front() == ' ') note.erase(0, 1);
    return {text.substr(0, equals), value, note};
}

/// Conformance mode: one check per outside resolver, every run kept going for the whole budget
/// so that failure rates mean something; then the engine rates of every resolver over the same
/// scenes; one report.
int runConformance(const AuditOptions& options) {
    Shard shard;
    std::string shardError;
    if (!parseShard(options.shard, shard, shardError)) {
        std::cerr << "tilesweep audit: " << shardError << '\n';
        return 2;
    }
    std::vector<audit::EngineSpec> engines;
    try {
        engines = comparedEngines(options.compare, options.scalar);
        std::vector<DocumentedTolerance> tolerances;
        for (const std::string& text : options.resolverTolerances) tolerances.push_back(parseTolerance(text));
        const auto labelOf = [&options](std::size_t k) {
            return k < options.resolverNames.size() ? options.resolverNames[k] : options.resolverCmds[k];
        };
        for (const DocumentedTolerance& t : tolerances) {
            bool named = false;
            for (std::size_t k = 0; k < options.resolverCmds.size(); ++k)
                named = named || labelOf(k) == t.name;
            if (!named)
                throw std::invalid_argument("--resolver-tolerance: no --resolver-name '" + t.name + "'");
        }
        for (std::size_t k = 0; k < options.resolverCmds.size(); ++k) {
            const std::string label = labelOf(k);
            double tolerance = 0;
            std::string note;
            for (const DocumentedTolerance& t : tolerances)
                if (t.name == label) {
                    tolerance = t.pixels;
                    note = t.note;
                }
            const std::string command = options.resolverCmds[k];
            const double timeout = options.resolverTimeout;
            const bool inDouble = options.scalar == "double";
            if (const std::string why = resolvers::probeResolver(command, timeout, !inDouble, inDouble);
                !why.empty()) {
                std::cerr << "tilesweep audit: resolver unusable: " << command
                          << "\n  it did not answer the known scene (a box falling onto a floor): " << why
                          << '\n';
                return 2;
            }
            engines.push_back({label,
                               [command, timeout] {
                                   return std::make_unique<resolvers::OutsideResolver>(command, timeout);
                               },
                               tolerance, note});
        }
    } catch (const std::invalid_argument& error) {
        std::cerr << "tilesweep audit: " << error.what() << '\n';
        return 2;
    }

    std::vector<ConformanceEntry> entries;
    bool allHeld = true;
    for (std::size_t k = 0; k < options.resolverCmds.size() && !options.ratesOnly; ++k) {
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
        check.shard = options.shard;
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

    std::string rates;
    if (options.ratesCases > 0 && !engines.empty()) {
        audit::RatesConfig config;
        config.cases = options.ratesCases;
        config.seed = options.seed;
        config.jobs = options.jobs;
        config.scalar = options.scalar;
        config.shardIndex = shard.index;
        config.shardCount = shard.count;
        ProgressLine progress("tilesweep audit: rates", "scenes");
        config.progress = [&progress](std::uint64_t done, std::uint64_t total) {
            if (done == total)
                progress.finish(total);
            else
                progress.update(done, total);
        };
        std::fprintf(stderr,
                     "tilesweep audit: rates of %zu resolvers, %llu %s scenes per family, shard %d/%d\n",
                     engines.size(), static_cast<unsigned long long>(options.ratesCases),
                     options.scalar.c_str(), shard.index, shard.count);
        const audit::RatesResult result = audit::measureRates(config, engines);
        const std::string jsonPath = options.ratesJson.empty()
                                         ? (std::filesystem::path(options.pictures) / "rates.json").string()
                                         : options.ratesJson;
        const std::filesystem::path jsonDir = std::filesystem::path(jsonPath).parent_path();
        if (!jsonDir.empty()) std::filesystem::create_directories(jsonDir);
        std::ofstream(jsonPath) << audit::ratesJson(result);
        std::printf("rates: %s (%.1f s)\n", jsonPath.c_str(), result.seconds);
        rates = "Written by `" + options.commandLine + "`.\n\n" + audit::ratesMarkdown(result);
        for (std::size_t e = 0; e < result.engines.size(); ++e) {
            audit::RateCell all;
            for (const audit::RateCell& c : result.cells[e]) all.merge(c);
            std::uint64_t broken = 0;
            for (const audit::Metric m : audit::kRateMetrics)
                broken += all.failures[static_cast<std::size_t>(m)];
            std::printf("%-24s %8llu scenes, tunnels %llu, ends inside %llu, no answer %llu\n",
                        result.engines[e].c_str(), static_cast<unsigned long long>(all.scenes),
                        static_cast<unsigned long long>(
                            all.failures[static_cast<std::size_t>(audit::Metric::Tunnel)]),
                        static_cast<unsigned long long>(
                            all.failures[static_cast<std::size_t>(audit::Metric::Inside)]),
                        static_cast<unsigned long long>(
                            all.failures[static_cast<std::size_t>(audit::Metric::NoAnswer)]));
            const bool outside = e >= result.engines.size() - options.resolverCmds.size();
            if (outside) allHeld = allHeld && broken == 0;
        }
    }
    writeConformanceReport(entries, options.report, options.pictures, rates);
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
    ProgressLine progress("tilesweep audit");
    config.progress = [&progress](std::uint64_t done, std::uint64_t total) {
        if (done == total)
            progress.finish(total);
        else
            progress.update(done, total);
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

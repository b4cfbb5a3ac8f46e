// SPDX-License-Identifier: MIT
#pragma once

// `tilesweep audit`: every implementation against the exact reference, as a report
// (audit_command.cpp; the work is in audit/).

#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace tilesweep::cli {

/// The options of `tilesweep audit`.
struct AuditOptions {
    std::uint64_t cases = 5000;           ///< scenes per family per scalar type
    std::uint64_t seed = 20261122;        ///< every scene derives from it
    std::string outDir = "audit-report";  ///< where report.md, report.json, the plots and worst/ go
    int jobs = 0;                         ///< worker threads; 0: all cores
    std::string commandLine;              ///< the command as typed, recorded in the report
    // Conformance mode (--resolver-cmd): the property suite against outside resolvers, one
    // `tilesweep check` per command, written as one report (conformance_report.h).
    std::vector<std::string> resolverCmds;       ///< outside resolvers; empty: the tolerance audit
    std::vector<std::string> resolverNames;      ///< a label per command (default: the command)
    std::string report = "docs/conformance.md";  ///< the conformance report
    std::string pictures = "docs/conformance";   ///< its pictures and regression files
    double secondsPerResolver = 60;              ///< check budget per resolver
    int propertyCases = 200;                     ///< cases per property per round
    std::string claims = "all";                  ///< "all" or "safety"
    std::string scalar = "float";                ///< the scalar type the resolvers work in
    double resolverTimeout = 10;  ///< seconds without an answer before a resolver counts as hung
    // Engine rates (audit/engine_rates.h), in conformance mode after the checks.
    std::uint64_t ratesCases = 2000;              ///< scenes per family; 0: no rates
    std::vector<std::string> resolverTolerances;  ///< "NAME=PIXELS [what it is]", by --resolver-name
    std::string compare = "tilesweep,twin,grid";  ///< in-process implementations measured beside them
    std::string ratesJson;                        ///< the rates file; empty: <pictures>/rates.json
    bool ratesOnly = false;                       ///< no property checks, only the rates
    std::string shard = "0/1";                    ///< K/N: this run's slice of the seeds and cases
};

/// Declares the subcommand and its options.
CLI::App* addAuditCommand(CLI::App& app, AuditOptions& options);

/// Runs it; returns the exit status.
int runAuditCommand(const AuditOptions& options);

}  // namespace tilesweep::cli

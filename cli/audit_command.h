// SPDX-License-Identifier: MIT
#pragma once

// `tilesweep audit`: every implementation against the exact reference, as a report
// (audit_command.cpp; the work is in audit/).

#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>

namespace tilesweep::cli {

/// The options of `tilesweep audit`.
struct AuditOptions {
    std::uint64_t cases = 5000;            ///< scenes per family per scalar type
    std::uint64_t seed = 20261122;        ///< every scene derives from it
    std::string outDir = "audit-report";  ///< where report.md, report.json, the plots and worst/ go
    int jobs = 0;                         ///< worker threads; 0: all cores
    std::string commandLine;              ///< the command as typed, recorded in the report
};

/// Declares the subcommand and its options.
CLI::App* addAuditCommand(CLI::App& app, AuditOptions& options);

/// Runs it; returns the exit status.
int runAuditCommand(const AuditOptions& options);

}  // namespace tilesweep::cli

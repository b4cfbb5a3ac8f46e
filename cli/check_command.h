// SPDX-License-Identifier: MIT
#pragma once

// `tilesweep check`: the property suite from the command line (check_command.cpp), against
// tilesweep's own resolver or, with --resolver-cmd, an outside process that speaks
// `tilesweep resolve`'s protocol.

#include <CLI/CLI.hpp>

#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace tilesweep::cli {

/// The options of `tilesweep check`.
struct CheckOptions {
    int cases = 1000;               ///< cases per property per round
    double seconds = 60;            ///< keep running rounds until this budget is spent
    std::uint64_t seed = 20261122;  ///< seed of the first round
    std::string property;           ///< substring filter on property names; empty: all
    int jobs = 0;                   ///< worker processes; 0: all cores
    std::string corpusDir;          ///< where failing cases are written; empty: the default
                                    ///< (properties/corpus, or resolver-corpus for an outside resolver)
    std::string resolver = "core";  ///< the resolver under test by registry name (resolver_registry.h)
    std::string resolverCmd;        ///< outside resolver (sh -c); empty: tilesweep's own
    std::string resolverLib;        ///< a user's resolver library: run as the command libraryCommand gives
    double resolverTimeout = 10;    ///< seconds without an answer before the process counts as hung
    std::string claims = "all";     ///< "all" or "safety" (leaves out the bit-for-bit claims)
    std::string scalar;             ///< "float" or "double"; empty: both (built-in), float (outside)
    std::string report;             ///< a conformance report (Markdown) to write; empty: none
    bool keepGoing = false;         ///< keep running rounds after a failure (failure rates)
    double shrinkSeconds = -1;      ///< per counterexample; < 0: 10 s with --resolver-cmd, else no limit
    bool noShrink = false;          ///< never shrink: every round counts its failures (throughput)
    std::string shard = "0/1";      ///< K/N: round r runs seed + r*N + K (shard.h)
    std::string json;               ///< the run as JSON, for `tilesweep merge`; empty: none
    bool quiet = false;             ///< no per-run progress lines
};

/// What one property did over all its runs.
struct CheckRow {
    std::string property;
    std::string claim;
    int runs = 0;
    int cases = 0;     ///< cases that passed
    int failures = 0;  ///< runs that ended in a (shrunk) counterexample
    /// Runs whose claim held but whose coverage fell certainly short of a floor: the suite's
    /// generator's shortfall, not the resolver's (properties/coverage_judgement.h).
    int coverageShortfalls = 0;
    std::vector<std::string> coverageMessages;
    double seconds = 0;
    double secondsToFirstFailure = 0;  ///< run time of the first failing run (generation + shrinking)
    std::map<std::string, int> tags;
    std::vector<std::string> messages;
    std::string smallestScene;    ///< the shortest shrunk counterexample seen (scene line)
    std::string smallestFailure;  ///< the claim's message on it
    std::string smallestCorpus;   ///< its regression file
    std::string smallestPicture;  ///< its picture
    /// The first failing case seen, before shrinking: the counterexample of a run the budget
    /// stopped while it shrank (then `runs` is 0).
    std::string firstFailure;
    std::string firstFailureScene;
};

/// A whole check: one row per property, in suite order.
struct CheckRun {
    std::vector<CheckRow> rows;
    bool workerFailed = false;
    int jobs = 1;
    double wallSeconds = 0;
    /// With an outside resolver: the workers were stopped at --seconds plus --resolver-timeout;
    /// a row with no run did not finish one.
    bool stoppedAtBudget = false;
    /// With an outside resolver: how often it failed a scene (crash, hang, extra output), and
    /// the first of those reasons.
    int resolverFailures = 0;
    std::vector<std::string> resolverFailureMessages;
};

/// The outside resolver failed the known scene before the run (tilesweep/resolvers/resolver_probe.h):
/// `tilesweep check` says why and exits with status 2.
struct ResolverUnusable : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// Declares the subcommand and its options.
CLI::App* addCheckCommand(CLI::App& app, CheckOptions& options);

/// Runs the properties the options select; prints progress unless `options.quiet`. Throws
/// std::invalid_argument when no property matches, and ResolverUnusable when the outside
/// resolver does not answer the known scene.
[[nodiscard]] CheckRun runChecks(const CheckOptions& options);

/// Runs it; returns the exit status.
int runCheckCommand(const CheckOptions& options);

/// The outside resolver command that serves a --resolver-lib library: this executable's
/// `resolve --resolver lib:PATH --scalar SCALAR` (exec: a signal that kills it is seen as
/// such), every word quoted for sh.
[[nodiscard]] std::string libraryCommand(const std::string& library, const std::string& scalar);

/// This executable's `resolve --resolver RESOLVER --scalar SCALAR` as an outside resolver command
/// (exec, every word quoted for sh): how `check --resolver NAME` holds any resolver of the
/// registry other than tilesweep's own, in a child process.
[[nodiscard]] std::string resolveCommand(const std::string& resolver, const std::string& scalar);

/// A check run as JSON (`tilesweep check --json`), and back; readCheckJson throws
/// std::runtime_error on a malformed file.
[[nodiscard]] std::string checkJson(const CheckOptions& options, const CheckRun& run);
[[nodiscard]] CheckRun readCheckJson(const std::string& text, CheckOptions& options);

/// Adds up the runs of shards (rows matched by property name); throws std::invalid_argument
/// when the shards' properties differ.
[[nodiscard]] CheckRun mergeCheckRuns(const std::vector<CheckRun>& runs);

}  // namespace tilesweep::cli

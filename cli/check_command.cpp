// SPDX-License-Identifier: MIT
// `tilesweep check`: the property suite as the main job. Runs every property (or the ones
// named) on all cores, shows progress while it runs, and prints a table: property, verdict,
// cases, failures, cases per second, coverage of each class, time. On a failure the shrunk
// scene is written to the regression corpus with its picture, and the exit status is 1.
//
// With --resolver-cmd (or --resolver-lib, or --resolver NAME for any other resolver of the
// registry) the claims about results run against an outside process instead
// (tilesweep/resolvers/outside_resolver.h): each worker starts the command once and keeps it; a
// round draws its cases, sends every scene they ask for in one batch, judges them, and shrinks a
// failure live, asking the process for each step's candidates; a crash or a hang fails the scene
// it was given and the process is restarted. Before any worker starts, the command is sent one
// known scene (tilesweep/resolvers/resolver_probe.h): a resolver that cannot answer it ends the
// run at once with status 2. The workers are stopped at --seconds plus one
// --resolver-timeout whatever the resolver does, and every failure of the resolver itself is
// shown as it happens.
//
// RapidCheck keeps its state in process-wide statics, so the parallelism is processes: the
// parent forks one worker per job before it starts any thread; each worker runs its share of
// the properties and reports one JSON line per finished run through a pipe.
#include "check_command.h"

#include "conformance_report.h"
#include "outside_resolver_options.h"
#include "property_suite.h"
#include "shard.h"

#include "tilesweep/resolvers/outside_resolver.h"
#include "tilesweep/resolvers/resolver_probe.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <poll.h>
#include <stdexcept>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace tilesweep::cli {
namespace {

using properties::Property;
using properties::PropertyOutcome;

/// How long shrinking one counterexample may take with an outside resolver, by default: every
/// candidate is a request (a process run, in file mode).
constexpr double kOutsideShrinkSeconds = 10;

/// How many failure messages a property keeps for the summary (the first ones: the shrunk
/// counterexample, then counting rounds).
constexpr std::size_t kMessagesPerProperty = 3;

/// How many of the outside resolver's own failures are shown as they happen and kept for the
/// summary (the rest are counted).
constexpr int kResolverFailuresShown = 5;

/// The coverage classes shown in the table, in order.
const std::vector<std::string> kTableTags = {"hit",      "miss", "tie",        "touch-at-0",
                                             "two-step", "seam", "far-origin", "family:corner-pass"};

std::vector<const Property*> selectProperties(const CheckOptions& options) {
    const bool outside = !options.resolverCmd.empty();
    const bool safetyOnly = options.claims == "safety";
    const std::string scalar = options.scalar.empty() && outside ? "float" : options.scalar;
    std::vector<const Property*> selected;
    for (const Property& p : properties::allProperties()) {
        if (!options.property.empty() && p.name.find(options.property) == std::string::npos) continue;
        if (!scalar.empty() && p.scalar != scalar) continue;
        if (outside && !properties::appliesToOutside(p.scope, safetyOnly)) continue;
        if (!outside && safetyOnly && p.scope == properties::ClaimScope::BitForBit) continue;
        selected.push_back(&p);
    }
    return selected;
}

std::string corpusDirOf(const CheckOptions& options) {
    if (!options.corpusDir.empty()) return options.corpusDir;
    return options.resolverCmd.empty() ? "properties/corpus" : "resolver-corpus";
}

/// Writes one report line to the parent; a parent gone ends the worker.
void sendLine(int out, const nlohmann::json& report) {
    const std::string line = report.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
    if (write(out, line.data(), line.size()) < 0) _exit(3);
}

/// A worker stopped by the parent (the budget) or by the terminal (^C) takes its resolvers with it:
/// they run in process groups of their own, which no signal to ours reaches.
extern "C" void stopWorker(int signal) {
    resolvers::killLiveResolverProcesses();
    _exit(128 + signal);
}

/// A worker's rounds: properties index % jobs == worker, round after round with a new seed each
/// round, until the deadline (at least one round), each run reported on `out`.
void runRounds(const std::vector<const Property*>& work, int worker, int jobs, const CheckOptions& options,
               const Shard& shard, int out) {
    // The outside resolver, one process per worker, for float and double scenes alike.
    std::unique_ptr<resolvers::OutsideResolver> outside;
    if (!options.resolverCmd.empty()) {
        outside = std::make_unique<resolvers::OutsideResolver>(options.resolverCmd, options.resolverTimeout);
        outside->process().onFailure([out](const std::string& why) {
            sendLine(out, {{"resolver_failure", why}});
        });
    }
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(options.seconds);
    // A property's first counterexample is shrunk; later rounds count failures without shrinking
    // again (with an outside resolver each shrinking step is a request: the rates would measure
    // shrinking, not the resolver).
    std::vector<bool> shrunk(work.size(), false);
    for (int round = 0;; ++round) {
        bool anyFailed = false;
        for (std::size_t k = 0; k < work.size(); ++k) {
            if (static_cast<int>(k % static_cast<std::size_t>(jobs)) != worker) continue;
            if (round > 0 && std::chrono::steady_clock::now() >= deadline) break;
            properties::RunOptions run;
            run.seed = options.seed +
                       static_cast<std::uint64_t>(round) * static_cast<std::uint64_t>(shard.count) +
                       static_cast<std::uint64_t>(shard.index);
            run.cases = options.cases;
            run.resolver = outside.get();
            run.shrink = !shrunk[k] && !options.noShrink;
            run.shrinkSeconds = options.shrinkSeconds >= 0    ? options.shrinkSeconds
                                : options.resolverCmd.empty() ? 0.0
                                                              : kOutsideShrinkSeconds;
            if (run.shrink) run.corpusDir = corpusDirOf(options);  // one regression file a property
            run.onFirstFailure = [out, k](const std::string& message, const std::string& scene) {
                sendLine(out, {{"first_failure", message}, {"index", k}, {"scene", scene}});
            };
            const PropertyOutcome o = work[k]->run(run);
            if (!o.passed && !o.sceneLine.empty()) shrunk[k] = true;
            anyFailed = anyFailed || !o.passed;
            sendLine(out, {{"index", k},
                           {"passed", o.passed},
                           {"cases", o.cases},
                           {"failed_cases", o.failedCases},
                           {"tags", o.tagCounts},
                           {"message", o.message},
                           {"coverage", o.coverageShortfall},
                           {"corpus", o.corpusFile},
                           {"picture", o.pictureFile},
                           {"seconds", o.seconds},
                           {"seed", run.seed},
                           {"scene", o.sceneLine},
                           {"failure", o.failure}});
        }
        if ((anyFailed && !options.keepGoing) || std::chrono::steady_clock::now() >= deadline) break;
    }
}

[[noreturn]] void runWorker(const std::vector<const Property*>& work, int worker, int jobs,
                            const CheckOptions& options, const Shard& shard, int out) {
    std::signal(SIGTERM, stopWorker);
    std::signal(SIGINT, stopWorker);
    runRounds(work, worker, jobs, options, shard, out);  // its destructors stop the outside process
    close(out);
    _exit(0);
}

void printTable(const CheckRun& run) {
    std::printf("\n%-52s %-7s %9s %5s %9s", "property", "verdict", "cases", "fail", "cases/s");
    for (const std::string& tag : kTableTags) std::printf(" %8.8s", tag.c_str());
    std::printf(" %8s\n", "time s");
    for (const CheckRow& r : run.rows) {
        std::printf("%-52s %-7s %9d %5d %9.0f", r.property.c_str(),
                    r.failures > 0             ? "FAILED"
                    : r.runs == 0              ? "unrun"
                    : r.coverageShortfalls > 0 ? "coverage"
                                               : "ok",
                    r.cases, r.failures, r.seconds > 0 ? r.cases / r.seconds : 0.0);
        for (const std::string& tag : kTableTags) {
            const auto it = r.tags.find(tag);
            const double share = r.cases > 0 && it != r.tags.end() ? 100.0 * it->second / r.cases : 0.0;
            std::printf(" %7.1f%%", share);
        }
        std::printf(" %8.1f\n", r.seconds);
    }
}

}  // namespace

CLI::App* addCheckCommand(CLI::App& app, CheckOptions& options) {
    CLI::App* command =
        app.add_subcommand("check", "Run the property suite: every claim against the oracles");
    command->add_option("--cases", options.cases, "Cases per property per round")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    command->add_option("--seconds", options.seconds, "Keep running rounds (new seed each) for this long")
        ->check(CLI::NonNegativeNumber)
        ->capture_default_str();
    command->add_option("--seed", options.seed, "RapidCheck seed of the first round")->capture_default_str();
    command->add_option("--property", options.property, "Run only properties whose name contains this");
    command->add_option("--jobs", options.jobs, "Worker processes (default: all cores)")
        ->check(CLI::PositiveNumber);
    command->add_option("--corpus", options.corpusDir,
                        "Where a failing case's regression file and picture go (default: properties/corpus;\n"
                        "resolver-corpus with --resolver-cmd)");
    command
        ->add_option("--resolver-cmd", options.resolverCmd,
                     "Check an outside resolver: a shell command that reads scene lines on stdin and writes\n"
                     "one result line per scene, as `tilesweep resolve` does")
        ->type_name("CMD");
    CLI::Option* library =
        command
            ->add_option("--resolver-lib", options.resolverLib,
                         "Check your resolver in a shared library exporting ts_user_resolve_f (and _d for\n"
                         "--scalar double; include/tilesweep/resolver_lib.h), run in a child process")
            ->type_name("PATH.so")
            ->check(CLI::ExistingFile)
            ->excludes("--resolver-cmd");
    addResolverOption(command, options.resolver);
    command->get_option("--resolver")->excludes("--resolver-cmd")->excludes(library);
    addResolverTimeoutOption(command, options.resolverTimeout);
    addClaimsOption(command, options.claims);
    command
        ->add_option("--scalar", options.scalar,
                     "Only the properties in this scalar type (default: both; float with --resolver-cmd)")
        ->check(CLI::IsMember(std::vector<std::string>{"float", "double"}));
    command->add_option("--report", options.report, "Also write a conformance report (Markdown) to this file")
        ->type_name("FILE.md");
    command->add_flag("--keep-going", options.keepGoing,
                      "Keep running rounds after a failure, to measure failure rates over the whole budget");
    command
        ->add_option("--shrink-seconds", options.shrinkSeconds,
                     "Stop shrinking a counterexample after this long, keeping the smallest found (default:\n"
                     "10 with --resolver-cmd, no limit otherwise)")
        ->check(CLI::NonNegativeNumber);
    command->add_flag("--no-shrink", options.noShrink,
                      "Never shrink: report each failure as found and count every failing case (throughput)");
    command
        ->add_option("--shard", options.shard,
                     "K/N: run slice K (from 0) of N: round r uses seed + r*N + K, so N runs cover\n"
                     "disjoint seeds; `tilesweep merge` adds their --json files up")
        ->capture_default_str();
    command->add_option("--json", options.json, "Also write the run as JSON (for `tilesweep merge`)")
        ->type_name("FILE.json");
    command->footer(
        "Each property runs --cases cases per round; rounds repeat with seed+1, seed+2, ... until\n"
        "--seconds have passed (one round at least). A property fails when a case falsifies it.\n"
        "Coverage floors are judged statistically: a run draws more cases until each class's share\n"
        "is certainly above or below its floor (error rate 1e-9); one certainly below is reported\n"
        "as insufficient coverage (the suite's scenes, not the resolver), apart from failures and\n"
        "without changing the exit status. A falsified property shrinks, and the minimal\n"
        "scene is written to --corpus as <property>-<hash>.jsonl (every number a hexfloat, with the\n"
        "property and seed) with its picture beside it; corpus_test replays every such file.\n"
        "\n"
        "With --resolver-cmd CMD, the claims about results (not the ones about tilesweep's internals)\n"
        "run against CMD, started once per worker with sh -c. A crash, a hang past --resolver-timeout,\n"
        "a malformed line or the wrong number of lines fails that scene, and CMD is restarted. The\n"
        "corpus file then also holds \"resolver_cmd\", \"resolver_answer\" and \"exact_answer\";\n"
        "`tilesweep replay --resolver-cmd CMD FILE...` replays it.\n"
        "\n"
        "Exit status: 0 every property held; 1 some property failed; 2 bad arguments.");
    return command;
}

CheckRun runChecks(const CheckOptions& options) {
    const auto begun = std::chrono::steady_clock::now();
    Shard shard;
    std::string shardError;
    if (!parseShard(options.shard, shard, shardError)) throw std::invalid_argument(shardError);
    const std::vector<const Property*> work = selectProperties(options);
    if (work.empty()) throw std::invalid_argument("no property matches '" + options.property + "'");
    // A corpus that cannot be a directory would end each worker at its first failure.
    if (const std::string corpus = corpusDirOf(options);
        std::filesystem::exists(corpus) && !std::filesystem::is_directory(corpus))
        throw std::invalid_argument("--corpus: '" + corpus + "' exists and is not a directory");
    int jobs = options.jobs > 0 ? options.jobs : static_cast<int>(std::thread::hardware_concurrency());
    if (jobs < 1) jobs = 1;
    if (jobs > static_cast<int>(work.size())) jobs = static_cast<int>(work.size());
    CheckRun run;
    run.jobs = jobs;
    for (const Property* p : work) {
        CheckRow row;
        row.property = p->name;
        row.claim = p->claim;
        run.rows.push_back(row);
    }
    if (!options.quiet) {
        std::printf(
            "tilesweep check: %zu properties, %d cases each per round, seed %llu, %d job%s, %.0f s "
            "budget%s%s\n",
            work.size(), options.cases, static_cast<unsigned long long>(options.seed), jobs,
            jobs == 1 ? "" : "s", options.seconds,
            options.resolverCmd.empty() ? "" : ", resolver: ", options.resolverCmd.c_str());
        std::fflush(stdout);
    }
    const bool outside = !options.resolverCmd.empty();
    if (outside) {
        const auto inScalar = [&](const char* scalar) {
            return std::any_of(work.begin(), work.end(),
                               [&](const Property* p) { return p->scalar == scalar; });
        };
        const std::string why = resolvers::probeResolver(options.resolverCmd, options.resolverTimeout,
                                                         inScalar("float"), inScalar("double"));
        if (!why.empty()) throw ResolverUnusable(why);
    }

    std::vector<int> pipes;
    std::vector<pid_t> children;
    for (int w = 0; w < jobs; ++w) {
        int fds[2];
        if (pipe(fds) != 0) throw std::runtime_error("pipe failed");
        const pid_t pid = fork();
        if (pid < 0) throw std::runtime_error("fork failed");
        if (pid == 0) {
            close(fds[0]);
            for (int fd : pipes) close(fd);
            runWorker(work, w, jobs, options, shard, fds[1]);
        }
        close(fds[1]);
        pipes.push_back(fds[0]);
        children.push_back(pid);
    }

    std::vector<std::string> pending(pipes.size());
    const auto started = std::chrono::steady_clock::now();
    const auto elapsed = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    };
    // An outside resolver may hang or crawl: the workers are stopped at the budget plus one
    // timeout (SIGTERM; SIGKILL a second later for one that does not go), whatever it does.
    const auto budgetEnd =
        begun + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                    std::chrono::duration<double>(options.seconds + options.resolverTimeout));
    int stopSignal = 0;
    auto stopAt = budgetEnd;
    int runsDone = 0;
    std::size_t open = pipes.size();
    while (open > 0) {
        std::vector<pollfd> fds;
        for (int fd : pipes)
            if (fd >= 0) fds.push_back({fd, POLLIN, 0});
        int waitMs = -1;
        if (outside && stopSignal != SIGKILL) {
            const auto left =
                std::chrono::ceil<std::chrono::milliseconds>(stopAt - std::chrono::steady_clock::now());
            waitMs = static_cast<int>(std::max<long long>(0, left.count()));
        }
        const int ready = poll(fds.data(), fds.size(), waitMs);
        if (ready < 0 && errno == EINTR) continue;
        if (ready < 0) break;
        if (ready == 0) {
            stopSignal = stopSignal == 0 ? SIGTERM : SIGKILL;
            for (std::size_t w = 0; w < children.size(); ++w)
                if (pipes[w] >= 0) kill(children[w], stopSignal);
            run.stoppedAtBudget = true;
            stopAt = std::chrono::steady_clock::now() + std::chrono::seconds(1);
            if (!options.quiet && stopSignal == SIGTERM) {
                std::printf(
                    "[%6.1f s] stopping the workers: --seconds %g plus --resolver-timeout %g have passed\n",
                    elapsed(), options.seconds, options.resolverTimeout);
                std::fflush(stdout);
            }
            continue;
        }
        for (const pollfd& p : fds) {
            if (!(p.revents & (POLLIN | POLLHUP))) continue;
            char buffer[65536];
            const ssize_t n = read(p.fd, buffer, sizeof buffer);
            const std::size_t w =
                static_cast<std::size_t>(std::find(pipes.begin(), pipes.end(), p.fd) - pipes.begin());
            if (n <= 0) {
                close(p.fd);
                pipes[w] = -1;
                --open;
                continue;
            }
            pending[w].append(buffer, static_cast<std::size_t>(n));
            std::size_t end;
            while ((end = pending[w].find('\n')) != std::string::npos) {
                const nlohmann::json r = nlohmann::json::parse(pending[w].substr(0, end));
                pending[w].erase(0, end + 1);
                if (r.contains("resolver_failure")) {
                    const std::string why = r["resolver_failure"].get<std::string>();
                    if (++run.resolverFailures <= kResolverFailuresShown) {
                        run.resolverFailureMessages.push_back(why);
                        if (!options.quiet) {
                            std::printf("[%6.1f s] resolver failure: %s\n", elapsed(), why.c_str());
                            if (run.resolverFailures == kResolverFailuresShown)
                                std::printf("[%6.1f s] (further resolver failures are counted, not shown)\n",
                                            elapsed());
                            std::fflush(stdout);
                        }
                    }
                    continue;
                }
                if (r.contains("first_failure")) {  // a run's first counterexample, before it shrinks
                    CheckRow& row = run.rows[r["index"].get<std::size_t>()];
                    if (row.firstFailure.empty()) {
                        row.firstFailure = r["first_failure"].get<std::string>();
                        row.firstFailureScene = r["scene"].get<std::string>();
                    }
                    continue;
                }
                CheckRow& row = run.rows[r["index"].get<std::size_t>()];
                ++row.runs;
                ++runsDone;
                row.cases += r["cases"].get<int>();
                row.seconds += r["seconds"].get<double>();
                for (const auto& [tag, count] : r["tags"].items()) row.tags[tag] += count.get<int>();
                const bool passed = r["passed"].get<bool>();
                const std::string coverage = r.value("coverage", std::string());
                if (passed && !coverage.empty()) {
                    ++row.coverageShortfalls;
                    row.coverageMessages.push_back(coverage);
                }
                if (!passed) {
                    if (row.failures == 0) row.secondsToFirstFailure = r["seconds"].get<double>();
                    // A run that shrank stopped at its first failure; a counting run judged every
                    // case (RunOptions::shrink): the failures are cases either way.
                    row.failures += std::max(1, r.value("failed_cases", 1));
                    const std::string corpus = r["corpus"].get<std::string>();
                    if (row.messages.size() < kMessagesPerProperty)
                        row.messages.push_back(r["message"].get<std::string>() +
                                               (corpus.empty()
                                                    ? std::string()
                                                    : "\n  regression file: " + corpus +
                                                          "\n  picture: " + r["picture"].get<std::string>()));
                    const std::string scene = r["scene"].get<std::string>();
                    if (!scene.empty() &&
                        (row.smallestScene.empty() || scene.size() < row.smallestScene.size())) {
                        row.smallestScene = scene;
                        row.smallestFailure = r["failure"].get<std::string>();
                        row.smallestCorpus = corpus;
                        row.smallestPicture = r["picture"].get<std::string>();
                    }
                    if (row.smallestScene.empty() && row.smallestFailure.empty())
                        row.smallestFailure = r["message"].get<std::string>();  // a coverage shortfall
                }
                if (!options.quiet) {
                    std::printf("[%6.1f s] %-52s %s  %d cases  (run %d)\n", elapsed(), row.property.c_str(),
                                passed ? (coverage.empty() ? "ok    " : "coverage") : "FAILED",
                                r["cases"].get<int>(), runsDone);
                    std::fflush(stdout);
                }
            }
        }
    }
    for (pid_t pid : children) {
        int status = 0;
        waitpid(pid, &status, 0);
        const bool clean = WIFEXITED(status) && WEXITSTATUS(status) == 0;
        const bool stoppedByUs =
            run.stoppedAtBudget && ((WIFEXITED(status) && WEXITSTATUS(status) == 128 + SIGTERM) ||
                                    (WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL));
        run.workerFailed = run.workerFailed || !(clean || stoppedByUs);
    }
    // A run the budget stopped while it shrank keeps its first counterexample, unshrunk.
    for (CheckRow& row : run.rows) {
        if (row.runs > 0 || row.firstFailure.empty()) continue;
        row.failures = 1;
        row.messages.push_back(row.firstFailure + "\n(not shrunk: the budget ended while it shrank) scene: " +
                               row.firstFailureScene);
        row.smallestScene = row.firstFailureScene;
        row.smallestFailure = row.firstFailure;
    }
    run.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return run;
}

std::string resolveCommand(const std::string& resolver, const std::string& scalar) {
    const auto quoted = [](const std::string& text) {
        std::string q = "'";
        for (const char c : text) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
        return q + "'";
    };
    std::error_code ignored;
    const std::string self = std::filesystem::read_symlink("/proc/self/exe", ignored).string();
    return "exec " + quoted(self.empty() ? std::string("tilesweep") : self) + " resolve --resolver " +
           quoted(resolver) + " --scalar " + scalar;
}

std::string libraryCommand(const std::string& library, const std::string& scalar) {
    return resolveCommand(resolvers::kLibraryPrefix + std::filesystem::absolute(library).string(), scalar);
}

int runCheckCommand(const CheckOptions& given) {
    CheckOptions options = given;
    // Every resolver but tilesweep's own runs in a child process (a crash costs a scene, not the
    // run): a library or a registry name as this executable's `resolve --resolver NAME`.
    const std::string forced = resolvers::scalarForcedBy(options.resolver);
    if (!forced.empty() && options.scalar.empty()) options.scalar = forced;
    const std::string scalar = options.scalar.empty() ? "float" : options.scalar;
    const std::string& resolver = options.resolver;
    if (!options.resolverLib.empty()) {
        options.resolverCmd = libraryCommand(options.resolverLib, scalar);
    } else if (resolver.rfind(resolvers::kCommandPrefix, 0) == 0) {
        options.resolverCmd = resolver.substr(std::string(resolvers::kCommandPrefix).size());
    } else if (resolver.rfind(resolvers::kLibraryPrefix, 0) == 0) {
        options.resolverCmd =
            libraryCommand(resolver.substr(std::string(resolvers::kLibraryPrefix).size()), scalar);
    } else if (!isTilesweepItself(resolver)) {
        options.resolverCmd = resolveCommand(resolver, scalar);
    }
    CheckRun run;
    try {
        run = runChecks(options);
    } catch (const std::invalid_argument& error) {
        std::cerr << "tilesweep check: " << error.what() << '\n';
        return 2;
    } catch (const ResolverUnusable& error) {
        std::cerr << "tilesweep check: resolver unusable: " << options.resolverCmd
                  << "\n  it did not answer the known scene (a box falling onto a floor): " << error.what()
                  << '\n';
        return 2;
    }
    printTable(run);
    if (!options.json.empty()) {
        std::ofstream(options.json) << checkJson(options, run);
        std::printf("json: %s\n", options.json.c_str());
    }
    int failures = 0;
    int failedProperties = 0;
    for (const CheckRow& row : run.rows) {
        failedProperties += row.failures > 0 ? 1 : 0;
        for (const std::string& m : row.messages) {
            ++failures;
            std::printf("\nFAILED %s:\n  %s\n", row.property.c_str(), m.c_str());
        }
    }
    for (const CheckRow& row : run.rows)
        for (const std::string& m : row.coverageMessages)
            std::printf(
                "\nINSUFFICIENT COVERAGE %s (the suite's scenes, not the resolver; the claim held):\n  %s\n",
                row.property.c_str(), m.c_str());
    if (run.workerFailed) std::printf("\na worker process died; its properties are incomplete\n");
    if (run.resolverFailures > 0) {
        std::printf(
            "\nthe resolver itself failed %d time%s (each fails the scenes it was asked); the first:\n",
            run.resolverFailures, run.resolverFailures == 1 ? "" : "s");
        for (const std::string& why : run.resolverFailureMessages) std::printf("  %s\n", why.c_str());
    }
    std::vector<std::string> unrun;
    for (const CheckRow& row : run.rows)
        if (row.runs == 0 && row.firstFailure.empty()) unrun.push_back(row.property);
    if (!unrun.empty()) {
        std::printf(
            "\n%zu propert%s did not finish a round within --seconds %g plus --resolver-timeout %g "
            "(give more --seconds):\n",
            unrun.size(), unrun.size() == 1 ? "y" : "ies", options.seconds, options.resolverTimeout);
        for (const std::string& name : unrun) std::printf("  %s\n", name.c_str());
    }
    int cases = 0;  // every case judged: passed or failed
    for (const CheckRow& row : run.rows) cases += row.cases + row.failures;
    std::printf("\n%d cases in %.1f s on %d job%s: %.0f cases/s\n", cases, run.wallSeconds, run.jobs,
                run.jobs == 1 ? "" : "s", run.wallSeconds > 0 ? cases / run.wallSeconds : 0.0);
    if (!options.report.empty()) {
        ConformanceEntry entry;
        entry.label = options.resolverCmd.empty() ? "tilesweep (built-in)" : options.resolverCmd;
        entry.options = options;
        entry.run = run;
        const std::string dir = std::filesystem::path(options.report).parent_path().string();
        writeConformanceReport({entry}, options.report,
                               (dir.empty() ? std::string(".") : dir) + "/conformance");
        std::printf("report: %s\n", options.report.c_str());
    }
    const bool ok = failures == 0 && !run.workerFailed && unrun.empty();
    const int total = static_cast<int>(run.rows.size());
    // A worker that died without a failing property still fails the run: count it as one.
    const int failed = ok ? 0 : std::max(failedProperties, unrun.empty() ? 1 : 0);
    const int unrunCount = static_cast<int>(unrun.size());
    std::printf("\n%d passed, %d failed", total - failed - unrunCount, failed);
    if (unrunCount > 0) std::printf(", %d unrun", unrunCount);
    std::printf("\n");
    return ok ? 0 : 1;
}

std::string checkJson(const CheckOptions& options, const CheckRun& run) {
    nlohmann::ordered_json j;
    j["kind"] = "tilesweep-check";
    j["resolver_cmd"] = options.resolverCmd;
    j["claims"] = options.claims;
    j["scalar"] = options.scalar;
    j["cases"] = options.cases;
    j["seconds"] = options.seconds;
    j["seed"] = options.seed;
    j["shard"] = options.shard;
    j["corpus"] = corpusDirOf(options);
    j["jobs"] = run.jobs;
    j["wall_seconds"] = run.wallSeconds;
    j["worker_failed"] = run.workerFailed;
    for (const CheckRow& r : run.rows)
        j["rows"].push_back({{"property", r.property},
                             {"claim", r.claim},
                             {"runs", r.runs},
                             {"cases", r.cases},
                             {"failures", r.failures},
                             {"seconds", r.seconds},
                             {"seconds_to_first_failure", r.secondsToFirstFailure},
                             {"tags", r.tags},
                             {"messages", r.messages},
                             {"coverage_shortfalls", r.coverageShortfalls},
                             {"coverage_messages", r.coverageMessages},
                             {"smallest_scene", r.smallestScene},
                             {"smallest_failure", r.smallestFailure},
                             {"smallest_corpus", r.smallestCorpus},
                             {"smallest_picture", r.smallestPicture}});
    return j.dump(1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

CheckRun readCheckJson(const std::string& text, CheckOptions& options) {
    const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
    if (j.is_discarded() || !j.is_object() || j.value("kind", "") != "tilesweep-check")
        throw std::runtime_error("not a check file (tilesweep check --json writes one)");
    try {
        options.resolverCmd = j.at("resolver_cmd").get<std::string>();
        options.claims = j.at("claims").get<std::string>();
        options.scalar = j.at("scalar").get<std::string>();
        options.cases = j.at("cases").get<int>();
        options.seconds = j.at("seconds").get<double>();
        options.seed = j.at("seed").get<std::uint64_t>();
        options.shard = j.at("shard").get<std::string>();
        options.corpusDir = j.at("corpus").get<std::string>();
        CheckRun run;
        run.jobs = j.at("jobs").get<int>();
        run.wallSeconds = j.at("wall_seconds").get<double>();
        run.workerFailed = j.at("worker_failed").get<bool>();
        for (const auto& r : j.at("rows")) {
            CheckRow row;
            row.property = r.at("property").get<std::string>();
            row.claim = r.at("claim").get<std::string>();
            row.runs = r.at("runs").get<int>();
            row.cases = r.at("cases").get<int>();
            row.failures = r.at("failures").get<int>();
            row.seconds = r.at("seconds").get<double>();
            row.secondsToFirstFailure = r.at("seconds_to_first_failure").get<double>();
            row.tags = r.at("tags").get<std::map<std::string, int>>();
            row.messages = r.at("messages").get<std::vector<std::string>>();
            row.coverageShortfalls = r.at("coverage_shortfalls").get<int>();
            row.coverageMessages = r.at("coverage_messages").get<std::vector<std::string>>();
            row.smallestScene = r.at("smallest_scene").get<std::string>();
            row.smallestFailure = r.at("smallest_failure").get<std::string>();
            row.smallestCorpus = r.at("smallest_corpus").get<std::string>();
            row.smallestPicture = r.at("smallest_picture").get<std::string>();
            run.rows.push_back(std::move(row));
        }
        return run;
    } catch (const nlohmann::json::exception& e) {
        throw std::runtime_error(std::string("malformed check file: ") + e.what());
    }
}

CheckRun mergeCheckRuns(const std::vector<CheckRun>& runs) {
    if (runs.empty()) throw std::invalid_argument("nothing to merge");
    CheckRun merged = runs.front();
    for (std::size_t k = 1; k < runs.size(); ++k) {
        const CheckRun& other = runs[k];
        if (other.rows.size() != merged.rows.size())
            throw std::invalid_argument("check file " + std::to_string(k + 1) + " ran other properties");
        for (std::size_t r = 0; r < merged.rows.size(); ++r) {
            CheckRow& into = merged.rows[r];
            const CheckRow& row = other.rows[r];
            if (row.property != into.property)
                throw std::invalid_argument("check file " + std::to_string(k + 1) + " ran other properties");
            if (row.failures > 0 &&
                (into.failures == 0 || row.secondsToFirstFailure < into.secondsToFirstFailure))
                into.secondsToFirstFailure = row.secondsToFirstFailure;
            into.runs += row.runs;
            into.cases += row.cases;
            into.failures += row.failures;
            into.seconds += row.seconds;
            for (const auto& [tag, count] : row.tags) into.tags[tag] += count;
            into.messages.insert(into.messages.end(), row.messages.begin(), row.messages.end());
            into.coverageShortfalls += row.coverageShortfalls;
            into.coverageMessages.insert(into.coverageMessages.end(), row.coverageMessages.begin(),
                                         row.coverageMessages.end());
            if (!row.smallestScene.empty() &&
                (into.smallestScene.empty() || row.smallestScene.size() < into.smallestScene.size())) {
                into.smallestScene = row.smallestScene;
                into.smallestFailure = row.smallestFailure;
                into.smallestCorpus = row.smallestCorpus;
                into.smallestPicture = row.smallestPicture;
            }
        }
        merged.workerFailed = merged.workerFailed || other.workerFailed;
        merged.wallSeconds = std::max(merged.wallSeconds, other.wallSeconds);  // shards run side by side
        merged.jobs += other.jobs;
    }
    return merged;
}

}  // namespace tilesweep::cli

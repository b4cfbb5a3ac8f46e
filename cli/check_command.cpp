// SPDX-License-Identifier: MIT
// `tilesweep check`: the property suite as the main job. Runs every property (or the ones
// named) on all cores, shows progress while it runs, and prints a table: property, cases,
// failures, coverage of each class, time. On a failure the shrunk scene is written to the
// regression corpus with its picture, and the exit status is 1.
//
// RapidCheck keeps its state in process-wide statics, so the parallelism is processes: the
// parent forks one worker per job before it starts any thread; each worker runs its share of
// the properties and reports one JSON line per finished run through a pipe.
#include "check_command.h"

#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "property_suite.h"

namespace tilesweep::cli {
namespace {

using properties::Property;
using properties::PropertyOutcome;

/// The coverage classes shown in the table, in order.
const std::vector<std::string> kTableTags = {"hit", "miss", "tie", "touch-at-0", "two-step", "seam", "far-origin",
                                              "family:corner-pass"};

std::vector<const Property*> selectProperties(const std::string& filter) {
    std::vector<const Property*> selected;
    for (const Property& p : properties::allProperties())
        if (filter.empty() || p.name.find(filter) != std::string::npos) selected.push_back(&p);
    return selected;
}

/// A worker: runs properties index % jobs == worker, round after round with a new seed each
/// round, until the deadline (at least one round), and reports each run on `out`.
[[noreturn]] void runWorker(const std::vector<const Property*>& work, int worker, int jobs,
                            const CheckOptions& options, int out) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(options.seconds);
    for (int round = 0;; ++round) {
        bool anyFailed = false;
        for (std::size_t k = 0; k < work.size(); ++k) {
            if (static_cast<int>(k % static_cast<std::size_t>(jobs)) != worker) continue;
            properties::RunOptions run;
            run.seed = options.seed + static_cast<std::uint64_t>(round);
            run.cases = options.cases;
            run.corpusDir = options.corpusDir;
            const PropertyOutcome o = work[k]->run(run);
            anyFailed = anyFailed || !o.passed;
            const nlohmann::json report = {{"index", k},        {"passed", o.passed},   {"cases", o.cases},
                                           {"tags", o.tagCounts}, {"message", o.message}, {"corpus", o.corpusFile},
                                           {"picture", o.pictureFile}, {"seconds", o.seconds}, {"seed", run.seed}};
            const std::string line = report.dump() + "\n";
            if (write(out, line.data(), line.size()) < 0) _exit(3);
        }
        if (anyFailed || std::chrono::steady_clock::now() >= deadline) break;
    }
    close(out);
    _exit(0);
}

struct Row {
    int runs = 0;
    int cases = 0;
    int failures = 0;
    double seconds = 0;
    std::map<std::string, int> tags;
    std::vector<std::string> messages;
};

void printTable(const std::vector<const Property*>& work, const std::vector<Row>& rows) {
    std::printf("\n%-52s %9s %5s", "property", "cases", "fail");
    for (const std::string& tag : kTableTags) std::printf(" %8.8s", tag.c_str());
    std::printf(" %8s\n", "time s");
    for (std::size_t k = 0; k < work.size(); ++k) {
        const Row& r = rows[k];
        std::printf("%-52s %9d %5d", work[k]->name.c_str(), r.cases, r.failures);
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
    CLI::App* command = app.add_subcommand("check", "Run the property suite: every claim against the oracles");
    command->add_option("--cases", options.cases, "Cases per property per round")->check(CLI::PositiveNumber)->capture_default_str();
    command->add_option("--seconds", options.seconds, "Keep running rounds (new seed each) for this long")
        ->check(CLI::NonNegativeNumber)
        ->capture_default_str();
    command->add_option("--seed", options.seed, "RapidCheck seed of the first round")->capture_default_str();
    command->add_option("--property", options.property, "Run only properties whose name contains this");
    command->add_option("--jobs", options.jobs, "Worker processes (default: all cores)")->check(CLI::PositiveNumber);
    command->add_option("--corpus", options.corpusDir, "Where a failing case's regression file and picture go")
        ->capture_default_str();
    command->footer(
        "Each property runs --cases cases per round; rounds repeat with seed+1, seed+2, ... until\n"
        "--seconds have passed (one round at least). A property fails when a case falsifies it or\n"
        "when a coverage class falls below its floor. A falsified property shrinks, and the minimal\n"
        "scene is written to --corpus as <property>-<hash>.jsonl (every number a hexfloat, with the\n"
        "property and seed) with its picture beside it; corpus_test replays every such file.\n"
        "\n"
        "Exit status: 0 every property held; 1 some property failed; 2 bad arguments.");
    return command;
}

int runCheckCommand(const CheckOptions& options) {
    const std::vector<const Property*> work = selectProperties(options.property);
    if (work.empty()) {
        std::cerr << "tilesweep check: no property matches '" << options.property << "'\n";
        return 2;
    }
    int jobs = options.jobs > 0 ? options.jobs : static_cast<int>(std::thread::hardware_concurrency());
    if (jobs < 1) jobs = 1;
    if (jobs > static_cast<int>(work.size())) jobs = static_cast<int>(work.size());
    std::printf("tilesweep check: %zu properties, %d cases each per round, seed %llu, %d job%s, %.0f s budget\n",
                work.size(), options.cases, static_cast<unsigned long long>(options.seed), jobs, jobs == 1 ? "" : "s",
                options.seconds);
    std::fflush(stdout);

    std::vector<int> pipes;
    std::vector<pid_t> children;
    for (int w = 0; w < jobs; ++w) {
        int fds[2];
        if (pipe(fds) != 0) {
            std::perror("tilesweep check: pipe");
            return 2;
        }
        const pid_t pid = fork();
        if (pid < 0) {
            std::perror("tilesweep check: fork");
            return 2;
        }
        if (pid == 0) {
            close(fds[0]);
            runWorker(work, w, jobs, options, fds[1]);
        }
        close(fds[1]);
        pipes.push_back(fds[0]);
        children.push_back(pid);
    }

    std::vector<Row> rows(work.size());
    std::vector<std::string> pending(pipes.size());
    const auto started = std::chrono::steady_clock::now();
    int runsDone = 0;
    std::size_t open = pipes.size();
    while (open > 0) {
        std::vector<pollfd> fds;
        for (int fd : pipes)
            if (fd >= 0) fds.push_back({fd, POLLIN, 0});
        if (poll(fds.data(), fds.size(), -1) < 0) break;
        for (const pollfd& p : fds) {
            if (!(p.revents & (POLLIN | POLLHUP))) continue;
            char buffer[65536];
            const ssize_t n = read(p.fd, buffer, sizeof buffer);
            const std::size_t w = static_cast<std::size_t>(std::find(pipes.begin(), pipes.end(), p.fd) - pipes.begin());
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
                Row& row = rows[r["index"].get<std::size_t>()];
                ++row.runs;
                ++runsDone;
                row.cases += r["cases"].get<int>();
                row.seconds += r["seconds"].get<double>();
                for (const auto& [tag, count] : r["tags"].items()) row.tags[tag] += count.get<int>();
                const bool passed = r["passed"].get<bool>();
                if (!passed) {
                    ++row.failures;
                    row.messages.push_back(r["message"].get<std::string>() +
                                           (r["corpus"].get<std::string>().empty()
                                                ? std::string()
                                                : "\n  regression file: " + r["corpus"].get<std::string>() +
                                                      "\n  picture: " + r["picture"].get<std::string>()));
                }
                const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
                std::printf("[%6.1f s] %-52s %s  %d cases  (run %d)\n", elapsed,
                            work[r["index"].get<std::size_t>()]->name.c_str(), passed ? "ok    " : "FAILED",
                            r["cases"].get<int>(), runsDone);
                std::fflush(stdout);
            }
        }
    }
    bool workerFailed = false;
    for (pid_t pid : children) {
        int status = 0;
        waitpid(pid, &status, 0);
        workerFailed = workerFailed || !WIFEXITED(status) || WEXITSTATUS(status) != 0;
    }

    printTable(work, rows);
    int failures = 0;
    for (std::size_t k = 0; k < work.size(); ++k)
        for (const std::string& m : rows[k].messages) {
            ++failures;
            std::printf("\nFAILED %s:\n  %s\n", work[k]->name.c_str(), m.c_str());
        }
    if (workerFailed) std::printf("\na worker process died; its properties are incomplete\n");
    const bool ok = failures == 0 && !workerFailed;
    std::printf("\n%d passed, %d failed\n", static_cast<int>(work.size()) - (ok ? 0 : std::max(failures, 1)),
                ok ? 0 : std::max(failures, 1));
    return ok ? 0 : 1;
}

}  // namespace tilesweep::cli

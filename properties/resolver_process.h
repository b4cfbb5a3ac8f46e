// SPDX-License-Identifier: MIT
#pragma once

// An outside resolver as a process: `sh -c COMMAND`, fed scene lines on its standard input and
// answering one result line per scene on its standard output, in order (the protocol of
// `tilesweep resolve`, CONTRACT.md). The process is started on first use and kept for the
// next batch; a crash, a hang past the timeout, or output that does not come as one line per
// scene fails the scene it was working on, and the process is killed and restarted for the
// scenes after it.
//
//     ResolverProcess process("build/dev/cli/tilesweep resolve --scalar float", 10.0);
//     auto replies = process.exchange({sceneLine1, sceneLine2});
//     for (auto& r : replies) if (!r.failure.empty()) ... else parseResultLine<float>(r.line, ...);
//
// Not thread-safe: one per worker. POSIX only (fork, pipes, poll).

#include <string>
#include <sys/types.h>
#include <vector>

namespace tilesweep::properties {

/// One scene's answer from the process.
struct ResolverReply {
    std::string line;     ///< the result line, without its newline (when `failure` is empty)
    std::string failure;  ///< why there is no line: crash, hang, extra output; empty when answered
};

/// A long-lived outside resolver process speaking JSON Lines over pipes.
class ResolverProcess {
public:
    /// @param command a shell command line, run by /bin/sh -c in its own process group
    /// @param timeoutSeconds how long one batch may take before the process counts as hung
    ResolverProcess(std::string command, double timeoutSeconds);
    ~ResolverProcess();
    ResolverProcess(const ResolverProcess&) = delete;
    ResolverProcess& operator=(const ResolverProcess&) = delete;

    /// Sends every line (each one scene, without a newline) and returns one reply per line, in
    /// order. Lines are written while answers are read, so a batch of any size cannot deadlock
    /// on full pipes. Never throws for the process's misbehaviour: that is in the replies.
    [[nodiscard]] std::vector<ResolverReply> exchange(const std::vector<std::string>& lines);

    /// The command line, as given.
    [[nodiscard]] const std::string& command() const noexcept { return command_; }
    /// How many times the process was started (1 after the first batch when all went well).
    [[nodiscard]] int starts() const noexcept { return starts_; }
    /// Kills the process (and its process group) if it runs; the next batch starts a new one.
    void stop() noexcept;

private:
    bool start(std::string& why);
    /// Exchanges lines[from..] with the running process; fills replies; returns the index of
    /// the first line not answered (== lines.size() when all were), with its failure set.
    std::size_t exchangeFrom(const std::vector<std::string>& lines, std::size_t from,
                             std::vector<ResolverReply>& replies);
    std::string exitDescription();
    [[nodiscard]] std::string errorTail() const;  ///< "; its standard error ends: ..." or empty

    std::string command_;
    double timeoutSeconds_;
    pid_t pid_ = -1;
    int in_ = -1;            ///< the process's standard input (we write)
    int out_ = -1;           ///< its standard output (we read)
    int err_ = -1;           ///< its standard error (we keep the tail, for messages)
    std::string pending_;    ///< output read but not yet a whole line
    std::string errorTail_;  ///< the last bytes of its standard error
    int starts_ = 0;
};

}  // namespace tilesweep::properties

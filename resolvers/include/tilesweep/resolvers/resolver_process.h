// SPDX-License-Identifier: MIT
#pragma once

// An outside resolver as a process speaking the protocol of `tilesweep resolve` (docs/contract.md):
// scene lines in, one result line per scene out, in order. Two transports:
//
//   pipe mode (the default): `sh -c COMMAND`, fed the scene lines on its standard input, answers
//     on its standard output. The process is started on first use and kept for the next batch.
//   file mode, when COMMAND contains both `{in}` and `{out}`: per batch, the scene lines are
//     written to a file, `sh -c COMMAND` runs once with `{in}` and `{out}` replaced by the paths
//     of that file and of an answer file, and the answers are read from the answer file when it
//     exits. For engines that are slow to start or cannot read a pipe (Godot 3).
//
// Either way a crash, or output that does not come as one line per scene, fails the scene it
// was working on (the first one not answered), and a fresh process takes the scenes after it:
// an engine's bad output is a per-scene result, never the end of the run. A hang past the
// timeout fails every scene of the batch not yet answered (a fresh process would most likely
// hang again, one timeout per scene), and the next batch gets a fresh process.
//
// A batch is one exchange: `tilesweep check` sends every scene a property round asks for in one
// (properties/answer_cache.h), so an engine sees one batch per round, not one request per case.
//
//     ResolverProcess process("build/plain/cli/tilesweep resolve --scalar float", 10.0);
//     auto replies = process.exchange({sceneLine1, sceneLine2});
//     for (auto& r : replies) if (!r.failure.empty()) ... else parseResultLine<float>(r.line, ...);
//
// Not thread-safe: one per worker. POSIX only (fork, pipes, poll).

#include <cstdint>
#include <functional>
#include <string>
#include <sys/types.h>
#include <vector>

namespace tilesweep::resolvers {

/// One scene's answer from the process.
struct ResolverReply {
    std::string line;     ///< the result line, without its newline (when `failure` is empty)
    std::string failure;  ///< why there is no line: crash, hang, extra output; empty when answered
};

/// Kills (SIGKILL) the process group of every resolver process this process has running, and
/// those of file-mode runs under way. Async-signal-safe: for a SIGTERM or SIGINT handler, since a
/// resolver runs in its own process group and a signal to ours does not reach it.
void killLiveResolverProcesses() noexcept;

/// A long-lived outside resolver process speaking JSON Lines over pipes.
class ResolverProcess {
public:
    /// @param command a shell command line, run by /bin/sh -c in its own process group
    /// @param timeoutSeconds how long the process may go without answering (pipe mode: a line;
    ///        file mode: the answer file growing) before it counts as hung
    ResolverProcess(std::string command, double timeoutSeconds);
    ~ResolverProcess();
    ResolverProcess(const ResolverProcess&) = delete;
    ResolverProcess& operator=(const ResolverProcess&) = delete;

    /// Sends every line (each one scene, without a newline) and returns one reply per line, in
    /// order. Lines are written while answers are read, so a batch of any size cannot deadlock
    /// on full pipes. Never throws for the process's misbehaviour: that is in the replies.
    [[nodiscard]] std::vector<ResolverReply> exchange(const std::vector<std::string>& lines);

    /// Scenes sent to the resolver so far, and batches they went in.
    [[nodiscard]] std::uint64_t scenesSent() const noexcept { return scenesSent_; }
    [[nodiscard]] std::uint64_t batchesSent() const noexcept { return batchesSent_; }
    /// True when the command has `{in}` and `{out}`: one run per batch, through files.
    [[nodiscard]] bool fileMode() const noexcept { return fileMode_; }

    /// The command line, as given.
    [[nodiscard]] const std::string& command() const noexcept { return command_; }
    /// How many times the process was started (1 after the first batch when all went well).
    [[nodiscard]] int starts() const noexcept { return starts_; }
    /// Kills the process (and its process group) if it runs; the next batch starts a new one.
    void stop() noexcept;
    /// Pipe mode: sends `line`, a scene the resolver answers, before and after every batch. A
    /// scene that prints more than one line puts the second barrier answer out of step with the
    /// first, whenever in the batch it prints it, and then that scene fails: every time, not
    /// only when the extra line happens to arrive before the batch ends.
    void setBarrier(std::string line) { barrier_ = std::move(line); }
    /// Called with the reason each time the process fails a scene (crash, hang, extra output,
    /// cannot start), so that a run can say what the resolver does as it happens.
    void onFailure(std::function<void(const std::string&)> observer) { observer_ = std::move(observer); }

private:
    /// Sends the lines to the resolver, one reply per line; in pipe mode with a barrier, between
    /// two barriers.
    std::vector<ResolverReply> send(const std::vector<std::string>& lines);
    /// Sends the lines as they are.
    std::vector<ResolverReply> sendPlain(const std::vector<std::string>& lines);
    /// After a batch came back out of step: each scene again with the barrier after it, so that
    /// the scenes that print more than one line fail and the others keep their answers.
    std::vector<ResolverReply> attributeStrayLines(const std::vector<std::string>& lines,
                                                   const std::string& barrierAnswer);
    /// File mode: runs the command once on lines[from..]; fills their replies; returns the index
    /// of the first line not answered (== lines.size() when all were), with its failure set.
    std::size_t runFileBatch(const std::vector<std::string>& lines, std::size_t from,
                             std::vector<ResolverReply>& replies);
    bool start(std::string& why);
    /// Exchanges lines[from..] with the running process; fills replies; returns the index of
    /// the first line not answered (== lines.size() when all were), with its failure set.
    std::size_t exchangeFrom(const std::vector<std::string>& lines, std::size_t from,
                             std::vector<ResolverReply>& replies);
    std::string exitDescription();
    /// Fails lines[from..] after a hang on lines[from]: it gets `why`, the others say so.
    void failAfterHang(std::vector<ResolverReply>& replies, std::size_t from, const std::string& why);
    void report(const std::string& why) const;
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
    bool fileMode_ = false;
    std::string directory_;  ///< file mode: a private temporary directory for the two files
    std::uint64_t scenesSent_ = 0;
    std::uint64_t batchesSent_ = 0;
    std::function<void(const std::string&)> observer_;
    bool hung_ = false;    ///< the last exchange hung: the rest of its batch is failed
    std::string barrier_;  ///< pipe mode: the scene sent around every batch; empty: none
};

}  // namespace tilesweep::resolvers

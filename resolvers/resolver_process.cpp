// SPDX-License-Identifier: MIT
#include "tilesweep/resolvers/resolver_process.h"

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <poll.h>
#include <signal.h>
#include <sstream>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <utility>

namespace tilesweep::resolvers {
namespace {

/// How much of the process's standard error a failure message quotes (its tail), in bytes.
constexpr std::size_t kErrorTailBytes = 600;
/// How long a process that closed its output gets to exit before it is killed, in milliseconds.
constexpr int kExitGraceMs = 200;

void closeFd(int& fd) noexcept {
    if (fd >= 0) close(fd);
    fd = -1;
}

void setNonBlocking(int fd) noexcept { fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) | O_NONBLOCK); }

std::string describeStatus(int status) {
    if (WIFEXITED(status)) return "exited with status " + std::to_string(WEXITSTATUS(status));
    if (WIFSIGNALED(status)) {
        const int s = WTERMSIG(status);
        const char* name = strsignal(s);
        return "was killed by signal " + std::to_string(s) +
               (name ? std::string(" (") + name + ")" : std::string());
    }
    return "stopped";
}

/// The placeholders that put a command in file mode.
constexpr const char* kInPlaceholder = "{in}";
constexpr const char* kOutPlaceholder = "{out}";

/// `text` as one word for sh: single quotes, with each single quote closed, escaped, reopened.
std::string shellQuote(const std::string& text) {
    std::string quoted = "'";
    for (const char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

/// `command` with every `placeholder` replaced by `value`.
std::string replaceAll(std::string command, const std::string& placeholder, const std::string& value) {
    for (std::size_t at = 0; (at = command.find(placeholder, at)) != std::string::npos; at += value.size())
        command.replace(at, placeholder.size(), value);
    return command;
}

/// The process groups of the resolvers running now (0: a free slot), for
/// killLiveResolverProcesses. A worker runs one or two resolvers at a time; the slots are many.
constexpr std::size_t kLiveSlots = 64;
std::atomic<pid_t> liveGroups[kLiveSlots];
static_assert(std::atomic<pid_t>::is_always_lock_free, "read from a signal handler");

void noteLive(pid_t group) noexcept {
    for (std::atomic<pid_t>& slot : liveGroups) {
        pid_t free = 0;
        if (slot.compare_exchange_strong(free, group)) return;
    }
}

void noteGone(pid_t group) noexcept {
    for (std::atomic<pid_t>& slot : liveGroups) {
        pid_t expected = group;
        if (slot.compare_exchange_strong(expected, 0)) return;
    }
}

std::string secondsText(double seconds) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", seconds);
    return text;
}

void keepTail(std::string& tail, const char* data, std::size_t size) {
    tail.append(data, size);
    if (tail.size() > kErrorTailBytes) tail.erase(0, tail.size() - kErrorTailBytes);
}

}  // namespace

void killLiveResolverProcesses() noexcept {
    for (std::atomic<pid_t>& slot : liveGroups) {
        const pid_t group = slot.load();
        if (group > 0) kill(-group, SIGKILL);
    }
}

ResolverProcess::ResolverProcess(std::string command, double timeoutSeconds)
    : command_(std::move(command)), timeoutSeconds_(timeoutSeconds) {
    // A resolver that dies while we write to it must be a failure to report, not our death.
    signal(SIGPIPE, SIG_IGN);
    fileMode_ = command_.find(kInPlaceholder) != std::string::npos &&
                command_.find(kOutPlaceholder) != std::string::npos;
    if (fileMode_) {
        const char* base = std::getenv("TMPDIR");
        std::string pattern = std::string(base && *base ? base : "/tmp") + "/tilesweep-resolver-XXXXXX";
        if (mkdtemp(pattern.data()) != nullptr) directory_ = pattern;
    }
}

ResolverProcess::~ResolverProcess() {
    // Polite first: end of input lets a well-behaved resolver exit by itself.
    closeFd(in_);
    if (pid_ > 0) {
        for (int waited = 0; waited < kExitGraceMs; waited += 5) {
            int status = 0;
            if (waitpid(pid_, &status, WNOHANG) == pid_) {
                noteGone(pid_);
                pid_ = -1;
                break;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
    }
    stop();
    if (!directory_.empty()) {
        std::error_code ignored;
        std::filesystem::remove_all(directory_, ignored);
    }
}

bool ResolverProcess::start(std::string& why) {
    int inPipe[2], outPipe[2], errPipe[2];
    if (pipe2(inPipe, O_CLOEXEC) != 0) {
        why = std::string("pipe: ") + std::strerror(errno);
        return false;
    }
    if (pipe2(outPipe, O_CLOEXEC) != 0 || pipe2(errPipe, O_CLOEXEC) != 0) {
        why = std::string("pipe: ") + std::strerror(errno);
        close(inPipe[0]);
        close(inPipe[1]);
        return false;
    }
    const pid_t pid = fork();
    if (pid < 0) {
        why = std::string("fork: ") + std::strerror(errno);
        for (int fd : {inPipe[0], inPipe[1], outPipe[0], outPipe[1], errPipe[0], errPipe[1]}) close(fd);
        return false;
    }
    if (pid == 0) {
        // Its own process group, so that stop() ends the shell and whatever the shell started.
        setpgid(0, 0);
        dup2(inPipe[0], 0);
        dup2(outPipe[1], 1);
        dup2(errPipe[1], 2);
        execl("/bin/sh", "sh", "-c", command_.c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    setpgid(pid, pid);  // also here: whichever of the two runs first
    noteLive(pid);
    close(inPipe[0]);
    close(outPipe[1]);
    close(errPipe[1]);
    pid_ = pid;
    in_ = inPipe[1];
    out_ = outPipe[0];
    err_ = errPipe[0];
    setNonBlocking(in_);
    setNonBlocking(out_);
    setNonBlocking(err_);
    pending_.clear();
    errorTail_.clear();
    ++starts_;
    return true;
}

void ResolverProcess::stop() noexcept {
    if (pid_ > 0) {
        kill(-pid_, SIGKILL);
        kill(pid_, SIGKILL);
        int status = 0;
        waitpid(pid_, &status, 0);
        noteGone(pid_);
    }
    pid_ = -1;
    closeFd(in_);
    closeFd(out_);
    closeFd(err_);
    pending_.clear();
}

std::string ResolverProcess::exitDescription() {
    int status = 0;
    std::string what = "closed its output";
    for (int waited = 0; pid_ > 0 && waited <= kExitGraceMs; waited += 5) {
        if (waitpid(pid_, &status, WNOHANG) == pid_) {
            what = describeStatus(status);
            noteGone(pid_);
            pid_ = -1;
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    // Whatever it still wrote to standard error explains the exit best.
    char buffer[4096];
    for (ssize_t n; err_ >= 0 && (n = read(err_, buffer, sizeof buffer)) > 0;)
        errorTail_.append(buffer, static_cast<std::size_t>(n));
    if (errorTail_.size() > kErrorTailBytes) errorTail_.erase(0, errorTail_.size() - kErrorTailBytes);
    return what;
}

std::size_t ResolverProcess::exchangeFrom(const std::vector<std::string>& lines, std::size_t from,
                                          std::vector<ResolverReply>& replies) {
    std::string text;
    for (std::size_t k = from; k < lines.size(); ++k) (text += lines[k]) += '\n';
    std::size_t written = 0;
    std::size_t next = from;
    // The timeout is a silence: it starts again with every answer, so that a batch of any size
    // gets the time it needs while a resolver that stops answering is caught.
    const auto silence = std::chrono::duration_cast<std::chrono::steady_clock::duration>(
        std::chrono::duration<double>(timeoutSeconds_));
    auto deadline = std::chrono::steady_clock::now() + silence;
    char buffer[65536];
    while (next < lines.size()) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
            deadline - std::chrono::steady_clock::now());
        pollfd fds[3];
        nfds_t count = 0;
        const int writing = in_ >= 0 && written < text.size() ? static_cast<int>(count++) : -1;
        if (writing >= 0) fds[writing] = {in_, POLLOUT, 0};
        const int reading = static_cast<int>(count++);
        fds[reading] = {out_, POLLIN, 0};
        const int errors = err_ >= 0 ? static_cast<int>(count++) : -1;
        if (errors >= 0) fds[errors] = {err_, POLLIN, 0};
        const int ready = left.count() > 0 ? poll(fds, count, static_cast<int>(left.count())) : 0;
        if (ready < 0 && errno == EINTR) continue;
        if (ready <= 0) {
            failAfterHang(replies, next,
                          "no answer within " + secondsText(timeoutSeconds_) +
                              " s (--resolver-timeout): the resolver hangs on this scene, after answering " +
                              std::to_string(next - from) + " of the " + std::to_string(lines.size() - from) +
                              " scenes sent" + errorTail());
            return lines.size();
        }
        if (writing >= 0 && fds[writing].revents != 0) {
            const std::size_t chunk = std::min<std::size_t>(text.size() - written, 65536);
            const ssize_t n = write(in_, text.data() + written, chunk);
            if (n > 0)
                written += static_cast<std::size_t>(n);
            else if (n < 0 && errno != EAGAIN && errno != EINTR)
                closeFd(in_);  // it stopped reading; what it already answered still counts
        }
        if (errors >= 0 && fds[errors].revents != 0) {
            const ssize_t n = read(err_, buffer, sizeof buffer);
            if (n > 0) {
                errorTail_.append(buffer, static_cast<std::size_t>(n));
                if (errorTail_.size() > kErrorTailBytes)
                    errorTail_.erase(0, errorTail_.size() - kErrorTailBytes);
            } else if (n == 0) {
                closeFd(err_);
            }
        }
        if (fds[reading].revents != 0) {
            const ssize_t n = read(out_, buffer, sizeof buffer);
            if (n < 0 && (errno == EAGAIN || errno == EINTR)) continue;
            if (n <= 0) {
                replies[next].failure = "the resolver " + exitDescription() + " after answering " +
                                        std::to_string(next - from) + " of the " +
                                        std::to_string(lines.size() - from) + " scenes sent" + errorTail();
                return next;
            }
            pending_.append(buffer, static_cast<std::size_t>(n));
            std::size_t end;
            while (next < lines.size() && (end = pending_.find('\n')) != std::string::npos) {
                replies[next].line = pending_.substr(0, end);
                if (!replies[next].line.empty() && replies[next].line.back() == '\r')
                    replies[next].line.pop_back();
                pending_.erase(0, end + 1);
                ++next;
                deadline = std::chrono::steady_clock::now() + silence;
            }
        }
    }
    // Every scene has its line. More output now means the lines are not one per scene.
    if (pending_.empty()) {
        pollfd p{out_, POLLIN, 0};
        if (poll(&p, 1, 0) > 0 && (p.revents & POLLIN)) {
            const ssize_t n = read(out_, buffer, sizeof buffer);
            if (n > 0) pending_.append(buffer, static_cast<std::size_t>(n));
        }
    }
    if (!pending_.empty()) {
        replies.back().failure = "the resolver printed more lines than it was sent scenes (extra: '" +
                                 pending_.substr(0, 80) + "')";
        return lines.size() - 1;
    }
    return lines.size();
}

void ResolverProcess::failAfterHang(std::vector<ResolverReply>& replies, std::size_t from,
                                    const std::string& why) {
    replies[from].failure = why;
    for (std::size_t k = from + 1; k < replies.size(); ++k)
        replies[k].failure = "not answered: the resolver hung on scene " + std::to_string(from + 1) +
                             " of its batch (" + why + ")";
    hung_ = true;
    report(why);
}

void ResolverProcess::report(const std::string& why) const {
    if (observer_) observer_(why);
}

std::string ResolverProcess::errorTail() const {
    std::string tail = errorTail_;
    while (!tail.empty() && (tail.back() == '\n' || tail.back() == '\r')) tail.pop_back();
    if (tail.empty()) return {};
    return (fileMode_ ? "; its output ends: " : "; its standard error ends: ") + tail;
}

std::vector<ResolverReply> ResolverProcess::exchange(const std::vector<std::string>& lines) {
    return send(lines);
}

std::vector<ResolverReply> ResolverProcess::send(const std::vector<std::string>& lines) {
    if (lines.empty()) return {};
    scenesSent_ += lines.size();
    ++batchesSent_;
    if (fileMode_ || barrier_.empty()) return sendPlain(lines);
    // The batch between two barriers: in step, the two barrier answers are the same line.
    std::vector<std::string> framed;
    framed.reserve(lines.size() + 2);
    framed.push_back(barrier_);
    framed.insert(framed.end(), lines.begin(), lines.end());
    framed.push_back(barrier_);
    std::vector<ResolverReply> replies = sendPlain(framed);
    const ResolverReply first = replies.front();
    const ResolverReply last = replies.back();
    replies.pop_back();
    replies.erase(replies.begin());
    if (!first.failure.empty() || !last.failure.empty() || first.line == last.line) {
        // In step; or a crash or hang, already in the replies (a crash at the last barrier is
        // the extra output that a line printed past the batch's end shows as).
        if (!last.failure.empty() && first.failure.empty() &&
            last.failure.find("more lines") != std::string::npos)
            return attributeStrayLines(lines, first.line);
        return replies;
    }
    return attributeStrayLines(lines, first.line);
}

std::vector<ResolverReply> ResolverProcess::attributeStrayLines(const std::vector<std::string>& lines,
                                                                const std::string& barrierAnswer) {
    // Some scene printed more than one line. Each scene again, followed by the barrier, to a
    // fresh process: the scene whose barrier answer is not the barrier's printed the extra line.
    stop();
    std::vector<ResolverReply> replies(lines.size());
    for (std::size_t k = 0; k < lines.size(); ++k) {
        const std::vector<ResolverReply> pair = sendPlain({lines[k], barrier_});
        if (!pair[0].failure.empty()) {
            replies[k] = pair[0];
        } else if (pair[1].failure.empty() && pair[1].line == barrierAnswer) {
            replies[k] = pair[0];
        } else {
            replies[k].failure = "the resolver printed more than one line for this scene (its first: '" +
                                 pair[0].line.substr(0, 80) + "'; then: '" +
                                 (pair[1].failure.empty() ? pair[1].line.substr(0, 80) : pair[1].failure) +
                                 "')";
            report(replies[k].failure);
            stop();  // out of step: the next scene gets a fresh process
        }
    }
    return replies;
}

std::vector<ResolverReply> ResolverProcess::sendPlain(const std::vector<std::string>& lines) {
    std::vector<ResolverReply> replies(lines.size());
    if (fileMode_) {
        for (std::size_t from = 0; from < lines.size();) {
            const std::size_t failed = runFileBatch(lines, from, replies);
            if (hung_) {  // the rest of the batch is failed
                hung_ = false;
                break;
            }
            if (failed >= lines.size()) break;
            report(replies[failed].failure);
            from = failed + 1;  // the scene it failed on is answered by its failure; go on after it
        }
        return replies;
    }
    // Output that came after the last batch was judged means the process is out of step (it
    // printed more than one line for some scene): start afresh rather than misread it.
    if (pid_ > 0) {
        pollfd p{out_, POLLIN, 0};
        if (poll(&p, 1, 0) > 0) stop();
    }
    std::size_t from = 0;
    while (from < lines.size()) {
        if (pid_ > 0 && !pending_.empty()) stop();  // out of step since the last batch: start afresh
        if (pid_ <= 0) {
            std::string why;
            if (!start(why)) {
                for (std::size_t k = from; k < lines.size(); ++k)
                    replies[k].failure = "cannot start the resolver: " + why;
                report(replies[from].failure);
                return replies;
            }
        }
        const std::size_t failed = exchangeFrom(lines, from, replies);
        if (hung_) {  // the rest of the batch is failed; the next batch gets a fresh process
            hung_ = false;
            stop();
            break;
        }
        if (failed >= lines.size()) break;
        report(replies[failed].failure);
        stop();  // crashed or out of step: the next scene gets a fresh process
        from = failed + 1;
    }
    return replies;
}

std::size_t ResolverProcess::runFileBatch(const std::vector<std::string>& lines, std::size_t from,
                                          std::vector<ResolverReply>& replies) {
    auto failFrom = [&](const std::string& why) {
        for (std::size_t k = from; k < lines.size(); ++k) replies[k].failure = why;
        return lines.size();
    };
    if (directory_.empty()) return failFrom("cannot create a temporary directory for the batch files");
    const std::string inPath = directory_ + "/scenes.jsonl";
    const std::string outPath = directory_ + "/answers.jsonl";
    {
        std::ofstream in(inPath, std::ios::binary | std::ios::trunc);
        for (std::size_t k = from; k < lines.size(); ++k) in << lines[k] << '\n';
        if (!in.flush()) return failFrom("cannot write the batch file " + inPath);
    }
    std::error_code ignored;
    std::filesystem::remove(outPath, ignored);
    const std::string command = replaceAll(replaceAll(command_, kInPlaceholder, shellQuote(inPath)),
                                           kOutPlaceholder, shellQuote(outPath));

    // Its standard output and error go to one pipe, whose tail explains a failure.
    int output[2];
    if (pipe2(output, O_CLOEXEC) != 0) return failFrom(std::string("pipe: ") + std::strerror(errno));
    const pid_t pid = fork();
    if (pid < 0) {
        close(output[0]);
        close(output[1]);
        return failFrom(std::string("fork: ") + std::strerror(errno));
    }
    if (pid == 0) {
        setpgid(0, 0);
        const int null = open("/dev/null", O_RDONLY);
        if (null >= 0) dup2(null, 0);
        dup2(output[1], 1);
        dup2(output[1], 2);
        execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    setpgid(pid, pid);
    noteLive(pid);
    close(output[1]);
    ++starts_;
    errorTail_.clear();
    // As in pipe mode, the timeout is a silence: it starts again whenever the answer file grows.
    const auto silence = std::chrono::duration_cast<std::chrono::steady_clock::duration>(
        std::chrono::duration<double>(timeoutSeconds_));
    auto deadline = std::chrono::steady_clock::now() + silence;
    std::uintmax_t answered = 0;
    bool hung = false;
    int status = 0;
    bool exited = false;
    char buffer[4096];
    // Non-blocking: a process the command left behind may hold the pipe open after it exits.
    int fd = output[0];
    setNonBlocking(fd);
    while (!exited) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
            deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) {
            std::error_code noFile;
            const std::uintmax_t size = std::filesystem::file_size(outPath, noFile);
            if (!noFile && size > answered) {  // still answering
                answered = size;
                deadline = std::chrono::steady_clock::now() + silence;
                continue;
            }
            hung = true;
            break;
        }
        if (fd >= 0) {
            pollfd p{fd, POLLIN, 0};
            const int ready = poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), 50)));
            if (ready > 0) {
                const ssize_t n = read(fd, buffer, sizeof buffer);
                if (n > 0) {
                    keepTail(errorTail_, buffer, static_cast<std::size_t>(n));
                } else if (n == 0 || (errno != EAGAIN && errno != EINTR)) {
                    close(fd);
                    fd = -1;
                }
            }
        } else {
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
        }
        exited = waitpid(pid, &status, WNOHANG) == pid;
        if (exited) noteGone(pid);
        if (exited && fd >= 0) {  // what it wrote last explains the exit best
            for (ssize_t n; (n = read(fd, buffer, sizeof buffer)) > 0;)
                keepTail(errorTail_, buffer, static_cast<std::size_t>(n));
            close(fd);
            fd = -1;
        }
        if (exited) break;
        if (fd < 0 && hung) break;
    }
    if (!exited) {
        kill(-pid, SIGKILL);
        kill(pid, SIGKILL);
        waitpid(pid, &status, 0);
        noteGone(pid);
    }
    if (fd >= 0) close(fd);

    // The answers written so far: whole lines, and a last line without its newline when the
    // resolver finished by itself.
    std::vector<std::string> answers;
    {
        std::ifstream out(outPath, std::ios::binary);
        std::stringstream text;
        text << out.rdbuf();
        const std::string all = text.str();
        std::size_t begin = 0;
        for (std::size_t end; (end = all.find('\n', begin)) != std::string::npos; begin = end + 1) {
            std::string line = all.substr(begin, end - begin);
            if (!line.empty() && line.back() == '\r') line.pop_back();
            answers.push_back(std::move(line));
        }
        if (begin < all.size() && exited && !hung) answers.push_back(all.substr(begin));
    }
    const std::size_t sent = lines.size() - from;
    for (std::size_t k = 0; k < answers.size() && k < sent; ++k) replies[from + k].line = answers[k];
    if (answers.size() > sent) {
        replies.back().failure = "the resolver wrote more lines than it was sent scenes (extra: '" +
                                 answers[sent].substr(0, 80) + "')";
        return lines.size() - 1;
    }
    if (answers.size() == sent) return lines.size();
    const std::size_t failed = from + answers.size();
    if (hung) {
        failAfterHang(replies, failed,
                      "no answer within " + secondsText(timeoutSeconds_) +
                          " s (--resolver-timeout): the resolver hangs on this scene, after answering " +
                          std::to_string(answers.size()) + " of the " + std::to_string(sent) +
                          " scenes of its batch" + errorTail());
        return lines.size();
    } else {
        replies[failed].failure = "the resolver " + describeStatus(status) + " after answering " +
                                  std::to_string(answers.size()) + " of the " + std::to_string(sent) +
                                  " scenes of its batch file" + errorTail();
    }
    return failed;
}

}  // namespace tilesweep::resolvers

// SPDX-License-Identifier: MIT
#pragma once

// Progress of a long command on standard error: on a terminal one line rewritten in place
// (carriage return); anywhere else (a CI log, a file) one plain line every few seconds, so that
// a log holds a readable trace rather than a single line of carriage returns.
//
//     ProgressLine progress("tilesweep audit");
//     progress.update(done, total);  // as often as you like
//     progress.finish(total);        // always prints the last line

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>
#include <unistd.h>

namespace tilesweep::cli {

class ProgressLine {
public:
    /// @param label the command's name, first on each line
    /// @param unit what is counted ("cases", "scenes")
    /// @param everySeconds how often a line is written when standard error is not a terminal
    explicit ProgressLine(std::string label, std::string unit = "cases", double everySeconds = 5)
        : label_(std::move(label)),
          unit_(std::move(unit)),
          every_(everySeconds),
          terminal_(isatty(STDERR_FILENO) != 0),
          started_(std::chrono::steady_clock::now()) {}

    /// Shows `done` of `total`, with the time spent and an estimate of the time left.
    void update(std::uint64_t done, std::uint64_t total) {
        const double elapsed = secondsSince(started_);
        if (!terminal_ && elapsed - lastPrinted_ < every_ && done < total) return;
        lastPrinted_ = elapsed;
        const double share = total == 0 ? 1.0 : static_cast<double>(done) / static_cast<double>(total);
        const double left = share > 0 ? elapsed / share - elapsed : 0.0;
        std::fprintf(stderr, "%s%s: %llu/%llu %s (%3.0f%%), %.0f s, about %.0f s left%s",
                     terminal_ ? "\r" : "", label_.c_str(), static_cast<unsigned long long>(done),
                     static_cast<unsigned long long>(total), unit_.c_str(), 100.0 * share, elapsed, left,
                     terminal_ ? "   " : "\n");
        std::fflush(stderr);
    }

    /// The last line, always printed, and the end of the line on a terminal.
    void finish(std::uint64_t total) {
        lastPrinted_ = -every_;
        update(total, total);
        if (terminal_) std::fprintf(stderr, "\n");
    }

private:
    static double secondsSince(std::chrono::steady_clock::time_point t) {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
    }

    std::string label_;
    std::string unit_;
    double every_;
    bool terminal_;
    std::chrono::steady_clock::time_point started_;
    double lastPrinted_ = -1e9;
};

}  // namespace tilesweep::cli

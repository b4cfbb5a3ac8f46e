// SPDX-License-Identifier: MIT
#pragma once

// `--shard K/N`: this run's deterministic slice of the work, so that N machines (a CI matrix, a
// Slurm job array, a Kubernetes Indexed Job) cover what one would, and `tilesweep merge` adds
// their reports up. K counts from 0.

#include <cstdlib>
#include <string>

namespace tilesweep::cli {

/// A slice: index K of N.
struct Shard {
    int index = 0;
    int count = 1;
};

/// Parses "K/N" with 0 <= K < N; on error returns false and says why in `error`.
inline bool parseShard(const std::string& text, Shard& shard, std::string& error) {
    const std::size_t slash = text.find('/');
    char* end = nullptr;
    const long k = slash == std::string::npos ? -1 : std::strtol(text.c_str(), &end, 10);
    const bool kOk = slash != std::string::npos && end == text.c_str() + slash && slash > 0;
    const long n = kOk ? std::strtol(text.c_str() + slash + 1, &end, 10) : 0;
    const bool nOk = kOk && *end == '\0' && end != text.c_str() + slash + 1;
    if (!nOk || n < 1 || n > 1000000 || k < 0 || k >= n) {
        error = "--shard: expected K/N with 0 <= K < N (as 0/4 .. 3/4), got '" + text + "'";
        return false;
    }
    shard = {static_cast<int>(k), static_cast<int>(n)};
    return true;
}

}  // namespace tilesweep::cli

// SPDX-License-Identifier: MIT
#pragma once

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

// How a fuzz target reports a broken rule: a message on stderr, then abort(), which libFuzzer
// records as a crash (and saves the input), and which fails the replay test.

namespace tilesweep::fuzz {

/// Prints "<target>: <what>" and the input's own description, then aborts.
[[noreturn]] inline void failCheck(const char* target, const std::string& what, const std::string& input) {
    std::fprintf(stderr, "%s: %s\n  input: %s\n", target, what.c_str(), input.c_str());
    std::fflush(stderr);
    std::abort();
}

/// The bits of a scalar, so that -0 and 0 (and NaN payloads) compare as different.
template <class T>
[[nodiscard]] bool sameBits(T a, T b) noexcept {
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}

}  // namespace tilesweep::fuzz

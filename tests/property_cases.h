// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <cstdlib>

// The budget of the unit tests' random-scene loops (mover_test.cpp, batch_test.cpp), set as the
// property suite's is (TILESWEEP_PROPERTY_CASES).

namespace tilesweep::test {

/// Cases per property: TILESWEEP_PROPERTY_CASES when set, else `fallback`.
inline std::uint64_t propertyCases(std::uint64_t fallback) {
    if (const char* env = std::getenv("TILESWEEP_PROPERTY_CASES")) {
        const long long n = std::atoll(env);
        if (n > 0) return static_cast<std::uint64_t>(n);
    }
    return fallback;
}

}  // namespace tilesweep::test

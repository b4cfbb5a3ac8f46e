// SPDX-License-Identifier: MIT
#include "grid_line.h"

// Boost's headers are not written for the project's warning set, and GCC reports some of their
// warnings where their code is inlined, so the whole file is compiled with those warnings off
// (tilesweep/boost_warnings_off.h, cmake/include/).
#include "tilesweep/boost_warnings_off.h"

#include <boost/multiprecision/cpp_int.hpp>

namespace tilesweep::checks::detail {
namespace {

using BigInt = boost::multiprecision::cpp_int;

BigInt scaled(Split s, int lowest) {
    if (s.mantissa == 0) return 0;
    BigInt v = s.mantissa;
    return v << (s.exponent - lowest);
}

}  // namespace

bool gridLineInExact(const Split* low, int lowCount, const Split* high, int highCount, Split origin,
                     Split tile) {
    // Every value is an integer multiple of 2^lowest.
    int lowest = tile.exponent;
    const auto note = [&lowest](Split s) {
        if (s.mantissa != 0) lowest = std::min(lowest, s.exponent);
    };
    for (int k = 0; k < lowCount; ++k) note(low[k]);
    for (int k = 0; k < highCount; ++k) note(high[k]);
    note(origin);
    BigInt lo = 0;
    BigInt hi = 0;
    for (int k = 0; k < lowCount; ++k) lo += scaled(low[k], lowest);
    for (int k = 0; k < highCount; ++k) hi += scaled(high[k], lowest);
    if (!(lo < hi)) return false;
    const BigInt o = scaled(origin, lowest);
    const BigInt t = scaled(tile, lowest);
    // The first line at or above lo: k = ceil((lo - o) / t). Integer division truncates toward
    // zero, which is the ceiling for a negative quotient and the floor for a positive one.
    const BigInt offset = lo - o;
    BigInt k = offset / t;
    if (k * t < offset) ++k;
    return o + k * t < hi;
}

}  // namespace tilesweep::checks::detail

#include "tilesweep/boost_warnings_on.h"

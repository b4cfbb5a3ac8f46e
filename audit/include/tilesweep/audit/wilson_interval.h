// SPDX-License-Identifier: MIT
#pragma once

// The Wilson score interval of a proportion: the range of true rates that `failures` out of
// `trials` is consistent with, at a confidence set by `z` (1.96 for 95%). Unlike the plain
// p +- z*sqrt(p(1-p)/n), it stays inside [0, 1] and says something when nothing failed:
// 0 failures in 3,000 trials gives [0, 0.13%], the "rule of three" a reader would expect.

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace tilesweep::audit {

/// A two-sided interval of rates, each in [0, 1].
struct RateInterval {
    double low = 0;
    double high = 1;
};

/// The z of a two-sided 95% interval.
constexpr double kZ95 = 1.959963984540054;

/// The Wilson score interval of `failures` out of `trials`; [0, 1] when there were no trials.
[[nodiscard]] inline RateInterval wilsonInterval(std::uint64_t failures, std::uint64_t trials,
                                                 double z = kZ95) noexcept {
    if (trials == 0) return {0, 1};
    const double n = static_cast<double>(trials);
    const double p = static_cast<double>(std::min(failures, trials)) / n;
    const double z2 = z * z;
    const double centre = (p + z2 / (2 * n)) / (1 + z2 / n);
    const double half = z / (1 + z2 / n) * std::sqrt(p * (1 - p) / n + z2 / (4 * n * n));
    // The bounds are exact at the ends: no failure gives 0, all failures give 1.
    return {failures == 0 ? 0.0 : std::max(0.0, centre - half),
            failures >= trials ? 1.0 : std::min(1.0, centre + half)};
}

}  // namespace tilesweep::audit

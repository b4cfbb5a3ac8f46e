// SPDX-License-Identifier: MIT
#include "coverage_judgement.h"

#include <algorithm>
#include <cmath>

namespace tilesweep::properties {

ShareInterval wilsonInterval(long long hits, long long cases, double z) {
    if (cases <= 0) return {};
    const double n = static_cast<double>(cases);
    const double k = static_cast<double>(std::clamp(hits, 0LL, cases));
    const double z2 = z * z;
    const double centre = (k + z2 / 2) / (n + z2);
    const double half = z / (n + z2) * std::sqrt(k * (n - k) / n + z2 / 4);
    return {std::max(0.0, centre - half), std::min(1.0, centre + half)};
}

FloorVerdict judgeFloor(long long hits, long long cases, double fraction) {
    const ShareInterval share = wilsonInterval(hits, cases);
    if (share.high < fraction) return FloorVerdict::Short;
    if (share.low >= kCoverageTolerance * fraction) return FloorVerdict::Met;
    return FloorVerdict::Undecided;
}

}  // namespace tilesweep::properties

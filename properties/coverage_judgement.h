// SPDX-License-Identifier: MIT
#pragma once

// Coverage floors judged statistically, as QuickCheck's checkCoverage judges them (Claessen,
// "QuickCheck: checkCoverage", Data.Test.QuickCheck.Features): a floor says that at least a share
// f of a family's cases must carry a tag. A run of n cases of which k carry it does not show the
// true share, only an interval for it; a floor is settled when the interval lies wholly on one
// side of it, at an error rate so small that a sound generator never fails by chance:
//   met       the Wilson lower bound is at least kCoverageTolerance * f;
//   short     the Wilson upper bound is below f (insufficient coverage);
//   undecided neither: draw more cases (property_suite.cpp), up to a cap.
// An undecided floor at the cap is not a shortfall (nothing shows the share below the floor).

namespace tilesweep::properties {

/// The error rate of each floor's verdict, one-sided: a floor whose true share is at least f is
/// judged short with probability below this, and one whose true share is below 0.9 f is judged
/// met with probability below it (per look; a run looks a few times at each floor).
inline constexpr double kCoverageErrorRate = 1e-9;

/// The standard normal quantile of 1 - kCoverageErrorRate: the Wilson interval's z.
inline constexpr double kCoverageZ = 5.997807015;

/// A floor counts as met once the share is certainly above this fraction of it (QuickCheck's
/// tolerance: a generator whose share sits exactly at the floor still settles, and quickly).
inline constexpr double kCoverageTolerance = 0.9;

/// The Wilson score interval of a share from `hits` of `cases` at z (Wilson 1927).
struct ShareInterval {
    double low = 0;
    double high = 1;
};

/// The interval; [0, 1] when there are no cases.
[[nodiscard]] ShareInterval wilsonInterval(long long hits, long long cases, double z = kCoverageZ);

/// What the cases seen so far say of one floor.
enum class FloorVerdict {
    Met,        ///< the share is certainly at least kCoverageTolerance times the floor
    Short,      ///< the share is certainly below the floor: insufficient coverage
    Undecided,  ///< the interval straddles the floor: more cases are needed
};

/// The verdict on a floor `fraction` from `hits` tagged cases of `cases`.
[[nodiscard]] FloorVerdict judgeFloor(long long hits, long long cases, double fraction);

}  // namespace tilesweep::properties

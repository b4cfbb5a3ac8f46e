// SPDX-License-Identifier: MIT
// The cached GMP allocation (gmp_allocation.h) changes where the limbs live, never a value: numbers
// that grow through every cached size class and past it, shrink again, move between threads and
// outlive the thread that made them keep their values. Each test calls useCachedGmpAllocation
// before it makes a number, as main does; ctest runs each test in a process of its own.
#include "tilesweep/oracle/exact/gmp_allocation.h"

#include "tilesweep/oracle/exact/rational.h"

#include <gtest/gtest.h>

#include <string>
#include <thread>
#include <vector>

namespace {

using tilesweep::oracle::Integer;
using tilesweep::oracle::Rational;

/// n! by repeated products: its limbs grow one at a time, through every size class and beyond.
Integer factorial(unsigned n) {
    Integer f = 1;
    for (unsigned k = 2; k <= n; ++k) f *= k;
    return f;
}

/// Whether f is n!: dividing by n, n - 1, ..., 2 leaves 1 with no remainder on the way.
bool isFactorial(Integer f, unsigned n) {
    for (unsigned k = n; k >= 2; --k) {
        if (f % k != 0) return false;
        f /= k;
    }
    return f == 1;
}

TEST(GmpAllocation, numbersGrowingPastEveryClassKeepTheirValues) {
    tilesweep::oracle::useCachedGmpAllocation();
    tilesweep::oracle::useCachedGmpAllocation();  // a second call changes nothing
    for (unsigned n : {1u, 20u, 21u, 100u, 400u, 1000u}) {
        const Integer f = factorial(n);
        EXPECT_TRUE(isFactorial(f, n)) << n;
    }
    // 1000! has 2,568 digits: 8,530 bits, far past the largest cached class (512 bytes).
    EXPECT_EQ(factorial(1000).str().size(), 2568u);
    // A number that grows past the classes and shrinks back reuses what it freed.
    for (int round = 0; round < 3; ++round) {
        Integer big = factorial(600);
        big /= factorial(599);
        EXPECT_EQ(big, 600);
    }
}

TEST(GmpAllocation, rationalsKeepTheirValuesInLowestTerms) {
    tilesweep::oracle::useCachedGmpAllocation();
    // 1/1 + 1/2 + ... + 1/n: each sum reduces by a gcd, so every temporary is made and dropped.
    Rational sum = 0;
    for (int k = 1; k <= 60; ++k) sum += Rational(1, k);
    Rational check = sum;
    for (int k = 60; k >= 1; --k) check -= Rational(1, k);
    EXPECT_EQ(check, 0);
    EXPECT_EQ(numerator(sum) % 2, 1);  // H_n's numerator is odd for n > 1
    EXPECT_EQ(tilesweep::oracle::toString(Rational(3, 6)), "1/2");
}

TEST(GmpAllocation, numbersMadeOnOneThreadAreFreedOnAnother) {
    tilesweep::oracle::useCachedGmpAllocation();
    constexpr unsigned kThreads = 4;
    constexpr unsigned kPerThread = 200;
    std::vector<std::vector<Integer>> made(kThreads);
    {
        std::vector<std::thread> makers;
        for (unsigned t = 0; t < kThreads; ++t)
            makers.emplace_back([t, &made] {
                for (unsigned k = 0; k < kPerThread; ++k) made[t].push_back(factorial(10 + (k + t) % 200));
            });
        for (std::thread& m : makers) m.join();  // each maker's cache is gone with its thread
    }
    // Checked and freed on other threads than their makers', whose caches then take the blocks.
    std::vector<std::thread> checkers;
    std::vector<unsigned> wrong(kThreads, 0);
    for (unsigned t = 0; t < kThreads; ++t)
        checkers.emplace_back([t, &made, &wrong] {
            std::vector<Integer>& mine = made[(t + 1) % kThreads];
            for (unsigned k = 0; k < kPerThread; ++k)
                if (!isFactorial(mine[k], 10 + (k + (t + 1) % kThreads) % 200)) ++wrong[t];
            mine.clear();
        });
    for (std::thread& c : checkers) c.join();
    for (unsigned t = 0; t < kThreads; ++t) EXPECT_EQ(wrong[t], 0u) << "checker " << t;
}

}  // namespace

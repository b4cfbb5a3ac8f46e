// SPDX-License-Identifier: MIT
#pragma once

#include "tilesweep/oracle/exact/exact_resolve.h"
#include "tilesweep/scene/scene.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

// The expectations the hand-worked tests of the exact reference state: a frame's contacts, in
// order, with their exact times and steps, and its exact final position.

namespace tilesweep::oracle::test {

inline Rational ratio(std::int64_t a, std::int64_t b) { return Rational(a) / Rational(b); }

struct Expected {
    Cell tile;
    Normal normal;
    Rational time;
    std::int32_t step;
};

inline void expectContacts(const ExactFrame& frame, const std::vector<Expected>& expected) {
    ASSERT_EQ(frame.contacts.size(), expected.size());
    for (std::size_t k = 0; k < expected.size(); ++k) {
        const ExactContact& c = frame.contacts[k];
        EXPECT_EQ(c.tile, expected[k].tile) << "contact " << k;
        EXPECT_EQ(c.normal, expected[k].normal) << "contact " << k;
        EXPECT_EQ(c.time, expected[k].time) << "contact " << k << ": " << toString(c.time);
        EXPECT_EQ(c.step, expected[k].step) << "contact " << k;
    }
}

inline void expectPosition(const ExactFrame& frame, const Rational& x, const Rational& y) {
    EXPECT_EQ(frame.position.x, x) << toString(frame.position.x);
    EXPECT_EQ(frame.position.y, y) << toString(frame.position.y);
}

/// The exact frame of a one-frame scene.
inline ExactFrame onlyFrame(const Scene<float>& scene) {
    const std::vector<ExactFrame> frames = resolveSceneExact(scene);
    EXPECT_EQ(frames.size(), 1U);
    return frames.front();
}

}  // namespace tilesweep::oracle::test

// SPDX-License-Identifier: MIT
#pragma once

// The tiny-scale family: a scene scaled down near the bottom of T's normal range.

#include "tilesweep/scenarios/scene_pieces.h"

#include <rapidcheck.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

namespace tilesweep::scenarios::detail {

/// Every length of a scene times 2^-shift (origin, tile size, box, moves): exact, so long as every
/// nonzero value stays normal (the caller's shift keeps it so).
template <class T>
Scene<T> scaledDown(const Scene<T>& scene, int shift) {
    Scene<T> s = scene;
    const auto scale = [shift](Vec2<T>& v) { v = {std::ldexp(v.x, -shift), std::ldexp(v.y, -shift)}; };
    scale(s.map.origin);
    scale(s.map.tileSize);
    scale(s.box.pos);
    scale(s.box.size);
    for (Vec2<T>& m : s.moves) scale(m);
    return s;
}

/// The tiny end of the range: a scene of `base` with every length scaled by 2^-shift, the shift
/// drawn near the bottom of T's normal range (double: 2^-600 to the least normal, float: 2^-60
/// to it) and capped so that the scene's smallest nonzero value stays normal, so the scaled
/// scene is exact and, by the contract, decides exactly as the original did. A range test that
/// forgets its lower bound lets products and TwoProduct error terms underflow here.
template <class T>
rc::Gen<GeneratedScene<T>> genTinyScaleScene(rc::Gen<GeneratedScene<T>> base) {
    return rc::gen::exec([base] {
        GeneratedScene<T> g = *base;
        const bool isFloat = std::is_same<T, float>::value;
        int lowest = std::numeric_limits<int>::max();  // the least frexp exponent of a nonzero value
        const auto note = [&lowest](T v) {
            if (v == 0) return;
            int e = 0;
            (void)std::frexp(v, &e);
            lowest = std::min(lowest, e);
        };
        const Scene<T>& s = g.scene;
        forEachSceneValue(s, note);
        // v * 2^-shift stays normal while frexp's exponent e - shift >= min_exponent.
        const int most = lowest - std::numeric_limits<T>::min_exponent;
        const int wanted = isFloat ? *rc::gen::element(100, 110, 120, 1000, 60)
                                   : *rc::gen::element(600, 700, 900, 1000, 5000);
        g.scene = scaledDown(s, std::max(0, std::min(wanted, most)));
        g.family = Family::TinyScale;
        return g;
    });
}

}  // namespace tilesweep::scenarios::detail

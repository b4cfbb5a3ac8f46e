// SPDX-License-Identifier: MIT
#pragma once

// Whether a frame's six box inputs lie in a window of magnitudes [least, limit): the test behind
// the short forms of the range tests (range_admission.h), and so the one that a game's frames pay
// for. Every nonzero component of the position and the displacement has its magnitude in the
// window; each size is in it itself (so positive); zeros of the position and the displacement
// pass. A NaN, an infinity (limit is at most infinity), a negative or zero size, a subnormal
// (least is normal) fail.
//
// With SSE2 (the x86-64 baseline) the six values are compared as floating-point vectors: a few
// instructions and no branch. Elsewhere, and in the portable build (TILESWEEP_PORTABLE_INTEGERS,
// which CI tests under the sanitizers, so that this path is exercised too), one scalar comparison
// per value. Both compute the same predicate. In tests/exact_primitives_test.cpp,
// FloatFrameRange holds the float short form to the full test, and DoubleFrameRange checks every
// admitted double frame, the short form's included, for what the fast path needs of it (exact
// far-edge distances).

#include "tilesweep/math.h"

#include <cmath>
#include <cstring>

#if defined(__SSE2__) && !defined(TILESWEEP_PORTABLE_INTEGERS)
#include <emmintrin.h>
#define TILESWEEP_INPUT_WINDOW_SSE2 1
#endif

namespace tilesweep::detail {

static_assert(sizeof(Box<float>) == 4 * sizeof(float) && sizeof(Vec2<float>) == 2 * sizeof(float),
              "a box is four packed floats, a vector two");
static_assert(sizeof(Box<double>) == 4 * sizeof(double) && sizeof(Vec2<double>) == 2 * sizeof(double),
              "a box is four packed doubles, a vector two");

/// Whether a magnitude `m` (or a size) lies in [least, limit), or is zero where `zeroPasses`.
template <class T>
[[nodiscard, gnu::always_inline]] inline bool inWindow(T m, T least, T limit, bool zeroPasses) noexcept {
    return (m < limit) & ((m >= least) | (zeroPasses & (m == 0)));
}

/// The six inputs, one comparison each (the way without SSE2).
template <class T>
[[nodiscard, gnu::always_inline]] inline bool eachInWindow(const Box<T>& box, const Vec2<T>& move, T least,
                                                           T limit) noexcept {
    const bool x = inWindow(std::fabs(box.pos.x), least, limit, true);
    const bool y = inWindow(std::fabs(box.pos.y), least, limit, true);
    const bool w = inWindow(box.size.x, least, limit, false);
    const bool h = inWindow(box.size.y, least, limit, false);
    const bool dx = inWindow(std::fabs(move.x), least, limit, true);
    const bool dy = inWindow(std::fabs(move.y), least, limit, true);
    return x & y & w & h & dx & dy;  // no branch per value
}

/// The six inputs of a float frame: position, size, displacement.
[[nodiscard, gnu::always_inline]] inline bool boxInputsInWindow(const Box<float>& box,
                                                                const Vec2<float>& move, float least,
                                                                float limit) noexcept {
#if defined(TILESWEEP_INPUT_WINDOW_SSE2)
    __m128 xywh;  // lanes 0 to 3: x, y, w, h
    std::memcpy(&xywh, &box, sizeof xywh);
    double moveBits = 0;
    std::memcpy(&moveBits, &move, sizeof moveBits);
    const __m128 d = _mm_castpd_ps(_mm_set_sd(moveBits));  // dx, dy, 0, 0
    // Magnitudes of x, y, dx and dy; the sizes keep their sign, so that a negative one fails.
    const __m128 magnitude = _mm_castsi128_ps(_mm_set_epi32(-1, -1, 0x7fffffff, 0x7fffffff));
    const __m128 zeroPasses = _mm_castsi128_ps(_mm_set_epi32(0, 0, -1, -1));
    const __m128 lo = _mm_set1_ps(least);
    const __m128 hi = _mm_set1_ps(limit);
    const __m128 zero = _mm_setzero_ps();
    const __m128 a = _mm_and_ps(xywh, magnitude);
    const __m128 b = _mm_and_ps(d, _mm_castsi128_ps(_mm_set1_epi32(0x7fffffff)));
    const __m128 okA = _mm_and_ps(
        _mm_cmplt_ps(a, hi), _mm_or_ps(_mm_cmpge_ps(a, lo), _mm_and_ps(_mm_cmpeq_ps(a, zero), zeroPasses)));
    const __m128 okB = _mm_and_ps(_mm_cmplt_ps(b, hi), _mm_or_ps(_mm_cmpge_ps(b, lo), _mm_cmpeq_ps(b, zero)));
    return _mm_movemask_ps(_mm_and_ps(okA, okB)) == 0xf;
#else
    return eachInWindow(box, move, least, limit);
#endif
}

/// The six inputs of a double frame.
[[nodiscard, gnu::always_inline]] inline bool boxInputsInWindow(const Box<double>& box,
                                                                const Vec2<double>& move, double least,
                                                                double limit) noexcept {
#if defined(TILESWEEP_INPUT_WINDOW_SSE2)
    __m128d xy;
    __m128d wh;
    __m128d d;
    std::memcpy(&xy, &box.pos, sizeof xy);
    std::memcpy(&wh, &box.size, sizeof wh);
    std::memcpy(&d, &move, sizeof d);
    const __m128d magnitude = _mm_castsi128_pd(_mm_set1_epi64x(0x7fffffffffffffff));
    const __m128d lo = _mm_set1_pd(least);
    const __m128d hi = _mm_set1_pd(limit);
    const __m128d zero = _mm_setzero_pd();
    const __m128d p = _mm_and_pd(xy, magnitude);
    const __m128d m = _mm_and_pd(d, magnitude);
    const __m128d okP =
        _mm_and_pd(_mm_cmplt_pd(p, hi), _mm_or_pd(_mm_cmpge_pd(p, lo), _mm_cmpeq_pd(p, zero)));
    const __m128d okS = _mm_and_pd(_mm_cmplt_pd(wh, hi), _mm_cmpge_pd(wh, lo));
    const __m128d okM =
        _mm_and_pd(_mm_cmplt_pd(m, hi), _mm_or_pd(_mm_cmpge_pd(m, lo), _mm_cmpeq_pd(m, zero)));
    return _mm_movemask_pd(_mm_and_pd(okP, _mm_and_pd(okS, okM))) == 0x3;
#else
    return eachInWindow(box, move, least, limit);
#endif
}

}  // namespace tilesweep::detail

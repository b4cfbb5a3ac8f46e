// SPDX-License-Identifier: MIT
// The coverage tags of a scene (all_claims.h, classifyScene): what its exact resolution and the
// resolver's decision path say it reaches, for RC_CLASSIFY and the coverage floors.
#include "all_claims.h"

#include "tilesweep/mover.h"
#include "tilesweep/oracle/exact/exact_geometry.h"
#include "tilesweep/oracle/exact/exact_resolve.h"
#include "tilesweep/oracle/exact/exact_sweep.h"
#include "tilesweep/oracle/exact/rational_convert.h"
#include "tilesweep/resolve.h"
#include "tilesweep/scenarios/scene_pieces.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace tilesweep::properties {

using oracle::Rational;

namespace {

/// Whether the contract's rounding rule rounded some axis down, where rounding toward the start
/// would have carried the far edge over a grid line: the two roundings differ.
template <class T>
bool roundedDown(const oracle::ExactFrame& f) {
    const FrameResult<T> rounded = oracle::roundFrame<T>(f);
    const T startX = oracle::fromRational<T>(f.start.x, oracle::Rounding::NearestEven);
    const T startY = oracle::fromRational<T>(f.start.y, oracle::Rounding::NearestEven);
    return rounded.position.x != oracle::roundToward<T>(f.position.x, startX) ||
           rounded.position.y != oracle::roundToward<T>(f.position.y, startY);
}

/// Whether an exact time lies exactly halfway between two neighbouring T values (the
/// ties-to-even case of the frame times' rounding).
template <class T>
bool halfwayBetweenValues(const Rational& t) {
    const T below = oracle::fromRational<T>(t, oracle::Rounding::TowardNegative);
    const T above = oracle::fromRational<T>(t, oracle::Rounding::TowardPositive);
    return below != above && (oracle::toRational(below) + oracle::toRational(above)) / 2 == t;
}

/// The cells [first, last] of a map's axis that a closed interval [low, high] of coordinates
/// meets or touches, clamped to the map: a cell whose edge equals an end of the interval counts.
/// Exact: floor of exact quotients.
std::pair<std::int64_t, std::int64_t> cellsMeeting(const oracle::Rational& low, const oracle::Rational& high,
                                                   const oracle::Rational& origin,
                                                   const oracle::Rational& tile, std::int32_t count) {
    const auto floorOf = [](const oracle::Rational& q) {
        const oracle::Integer n = boost::multiprecision::numerator(q);
        const oracle::Integer d = boost::multiprecision::denominator(q);
        oracle::Integer f = n / d;  // truncates toward zero; d > 0
        if (n < 0 && f * d != n) f -= 1;
        return f;
    };
    const auto clamp = [count](const oracle::Integer& k) {
        if (k < 0) return std::int64_t{0};
        if (k >= count) return static_cast<std::int64_t>(count) - 1;
        return static_cast<std::int64_t>(k);
    };
    // The cell left of the one holding `low` ends exactly at `low` when `low` is on a grid line.
    const oracle::Integer first = floorOf((low - origin) / tile) - 1;
    const oracle::Integer last = floorOf((high - origin) / tile);
    if (last < 0 || first >= count) return {0, -1};
    return {clamp(first), clamp(last)};
}

/// Whether, in the first step of some frame with both axes moving, a solid tile is first
/// reached at exactly t = 1 (which the contract does not count as a hit). Such a tile touches the
/// step's closed swept bounds, so only the cells those bounds meet are swept.
template <class T>
bool reachesATileAtTheEnd(const Scene<T>& scene, const std::vector<oracle::ExactFrame>& frames) {
    const oracle::ExactTileMap map = oracle::toExact(scene.map);
    for (std::size_t f = 0; f < frames.size(); ++f) {
        const oracle::ExactVec2 d = oracle::toExact(scene.moves[f]);
        if (d.x == 0 || d.y == 0) continue;
        const oracle::ExactVec2& p = frames[f].start;
        const oracle::ExactVec2& size = frames[f].size;
        const oracle::ExactVec2 end{p.x + d.x, p.y + d.y};
        const auto [i0, i1] =
            cellsMeeting(d.x < 0 ? end.x : p.x, oracle::Rational((d.x < 0 ? p.x : end.x) + size.x),
                         map.origin.x, map.tileSize.x, map.columns);
        const auto [j0, j1] =
            cellsMeeting(d.y < 0 ? end.y : p.y, oracle::Rational((d.y < 0 ? p.y : end.y) + size.y),
                         map.origin.y, map.tileSize.y, map.rows);
        for (std::int64_t j = j0; j <= j1; ++j)
            for (std::int64_t i = i0; i <= i1; ++i) {
                if (!map.isSolid(i, j)) continue;
                const oracle::ExactSweepOutput sweep =
                    oracle::sweepTileExact({{frames[f].start, frames[f].size}, d, map.tileRect(i, j)});
                if (!sweep.overlap.empty && sweep.overlap.low.isFinite() && sweep.overlap.low.value == 1)
                    return true;
            }
    }
    return false;
}

/// The bits between the finest set bit and the largest magnitude among a scene's inputs: what
/// sets the width of the resolver's integers (above about 60 it needs more than 128 bits for
/// products; above about 92, more than 192).
template <class T>
int latticeSpan(const Scene<T>& scene) {
    int lowest = std::numeric_limits<int>::max();
    int highest = std::numeric_limits<int>::min();
    const auto note = [&](T v) {
        if (v == 0) return;
        int e = 0;
        const T fraction = std::frexp(v, &e);
        auto m = static_cast<std::int64_t>(std::ldexp(fraction, std::numeric_limits<T>::digits));
        int low = e - std::numeric_limits<T>::digits;
        while (m % 2 == 0) {
            m /= 2;
            ++low;
        }
        lowest = std::min(lowest, low);
        highest = std::max(highest, e);
    };
    scenarios::forEachSceneValue(scene, note);
    return highest >= lowest ? highest - lowest : 0;
}

/// The least frexp exponent of a scene's nonzero inputs (a large number when all are zero).
template <class T>
int smallestInputExponent(const Scene<T>& scene) {
    int lowest = std::numeric_limits<int>::max();
    const auto note = [&lowest](T v) {
        if (v == 0 || !std::isfinite(v)) return;
        int e = 0;
        (void)std::frexp(v, &e);
        lowest = std::min(lowest, e);
    };
    scenarios::forEachSceneValue(scene, note);
    return lowest;
}

/// The most significant bits any input of the scene needs (its significand without trailing zeros).
template <class T>
int widestSignificand(const Scene<T>& scene) {
    int widest = 0;
    const auto note = [&widest](T v) {
        if (v == 0 || !std::isfinite(v)) return;
        int e = 0;
        auto m = static_cast<std::int64_t>(
            std::ldexp(std::frexp(std::fabs(v), &e), std::numeric_limits<T>::digits));
        int bits = std::numeric_limits<T>::digits;
        while (m % 2 == 0) {
            m /= 2;
            --bits;
        }
        widest = std::max(widest, bits);
    };
    scenarios::forEachSceneValue(scene, note);
    return widest;
}

/// The span C + 1 - G that the float range test (admitFloatFrame, src/range_admission.h) takes for
/// the scene's first frame, from frexp exponents (|v| < 2^e, ulp 2^(e - 24) for a normal float):
/// B the largest of the box's inputs, E = max over both axes of max(e(origin), e(tile) +
/// bitLength(cells + 2)) + 1, C = max(B + 2, E), G the lowest ulp. Admitted at 53 and below.
int floatRangeSpan(const Scene<float>& scene) {
    const auto exponent = [](float v) {
        int e = 0;
        (void)std::frexp(v, &e);
        return v == 0 ? -100000 : e;
    };
    const Vec2<float> move = scene.moves.empty() ? Vec2<float>{0, 0} : scene.moves.front();
    const float box[6] = {scene.box.pos.x,  scene.box.pos.y, scene.box.size.x,
                          scene.box.size.y, move.x,          move.y};
    const float grid[4] = {scene.map.origin.x, scene.map.origin.y, scene.map.tileSize.x,
                           scene.map.tileSize.y};
    int top = -100000;
    int lowest = 100000;
    for (const float v : box) {
        top = std::max(top, exponent(v));
        if (v != 0) lowest = std::min(lowest, exponent(v) - 24);
    }
    int edges = -100000;
    const std::int32_t cells[2] = {scene.map.columns, scene.map.rows};
    for (int a = 0; a < 2; ++a) {
        int cellBits = 0;
        for (auto n = static_cast<std::uint32_t>(cells[a]) + 2; n != 0; n >>= 1) ++cellBits;
        edges = std::max(edges, std::max(exponent(grid[a]), exponent(grid[2 + a]) + cellBits) + 1);
        for (const float v : {grid[a], grid[2 + a]})
            if (v != 0) lowest = std::min(lowest, exponent(v) - 24);
    }
    return std::max(top + 2, edges) + 1 - lowest;
}

/// How deep into the double filter's band (kPairProductErrorBound, src/proof_constants.h) the
/// first frame's entry comparisons reach: for each solid tile that both axes approach, the
/// resolver's D = fl(fl(ex.hi * vy) - fl(ey.hi * vx)) (ex.hi, ey.hi the entry distances rounded to
/// nearest: the high parts of its exact pairs) against the exact ex * vy - ey * vx, the error as a
/// fraction of the bound (2 + 16u)u (|p| + |q|); the largest, or 0. Only entries that are not
/// doubles count (pairs with a low part: the filter's path).
double deepestFilterError(const Scene<double>& scene) {
    if (scene.moves.empty()) return 0;
    const Vec2<double> move = scene.moves.front();
    if (move.x == 0 || move.y == 0) return 0;
    const oracle::ExactTileMap map = oracle::toExact(scene.map);
    const Rational x0 = oracle::toRational(scene.box.pos.x);
    const Rational y0 = oracle::toRational(scene.box.pos.y);
    const Rational x1 = x0 + oracle::toRational(scene.box.size.x);
    const Rational y1 = y0 + oracle::toRational(scene.box.size.y);
    const double bound = (2.0 + 16.0 * 0x1p-53) * 0x1p-53;
    double deepest = 0;
    for (std::int32_t j = 0; j < map.rows; ++j)
        for (std::int32_t i = 0; i < map.columns; ++i) {
            if (!map.isSolid(i, j)) continue;
            const oracle::ExactRect r = map.tileRect(i, j);
            const Rational ex = move.x > 0 ? r.min.x - x1 : x0 - r.max.x;
            const Rational ey = move.y > 0 ? r.min.y - y1 : y0 - r.max.y;
            if (ex < 0 || ey < 0) continue;
            const double exHi = oracle::fromRational<double>(ex, oracle::Rounding::NearestEven);
            const double eyHi = oracle::fromRational<double>(ey, oracle::Rounding::NearestEven);
            if (oracle::toRational(exHi) == ex && oracle::toRational(eyHi) == ey) continue;
            const double vx = std::fabs(move.x);
            const double vy = std::fabs(move.y);
            const double p = exHi * vy;
            const double q = eyHi * vx;
            if (!std::isfinite(p - q) || !std::isfinite(std::fabs(p) + std::fabs(q))) continue;  // huge moves
            const Rational exact = ex * oracle::toRational(vy) - ey * oracle::toRational(vx);
            const double error = oracle::fromRational<double>(abs(exact - oracle::toRational(p - q)),
                                                              oracle::Rounding::NearestEven);
            deepest = std::max(deepest, error / (bound * (std::fabs(p) + std::fabs(q))));
        }
    return deepest;
}

/// Whether the box at `pos` with `size` overlaps the rectangle `t` (open interiors), exactly.
inline bool overlapsExactly(const oracle::ExactVec2& pos, const oracle::ExactVec2& size,
                            const oracle::ExactRect& t) {
    return pos.x < t.max.x && t.min.x < pos.x + size.x && pos.y < t.max.y && t.min.y < pos.y + size.y;
}

/// The one-way tags (all_claims.h), from the exact frames and the scene's map:
///   one-way-hit     a hit on a one-way tile;  one-way-tie: such a hit on an exact corner tie;
///   one-way-fast    a one-way hit in a frame moving four tiles or more down;
///   one-way-seam    two one-way tiles hit at once (a landing across a platform's seam);
///   on-platform     a frame that starts standing on a one-way tile's top and moves down;
///   in-one-way      the box overlaps a one-way tile at a frame's start or exact end (jumping
///                   through it, or entered through a side); starts-in-one-way: at a start.
template <class T>
void addOneWayTags(const Scene<T>& scene, const std::vector<oracle::ExactFrame>& frames,
                   std::vector<std::string>& tags) {
    std::vector<Cell> platforms;
    for (std::int32_t j = 0; j < scene.map.rows; ++j)
        for (std::int32_t i = 0; i < scene.map.columns; ++i)
            if (scene.map.kind(i, j) == CellKind::OneWay) platforms.push_back({i, j});
    if (platforms.empty()) return;
    tags.push_back("one-way-map");
    const oracle::ExactTileMap map = oracle::toExact(scene.map);
    bool hit = false, tie = false, fast = false, seam = false, onPlatform = false, inside = false,
         startsInside = false;
    for (std::size_t f = 0; f < frames.size(); ++f) {
        const oracle::ExactFrame& frame = frames[f];
        const Vec2<T> move = scene.moves[f];
        int oneWayHits[3] = {0, 0, 0};  // by step
        for (const oracle::ExactContact& c : frame.contacts) {
            if (scene.map.kind(c.tile.i, c.tile.j) != CellKind::OneWay) continue;
            hit = true;
            tie = tie || c.tie;
            fast = fast || move.y >= 4 * scene.map.tileSize.y;
            ++oneWayHits[std::min<std::int32_t>(2, std::max<std::int32_t>(0, c.step))];
        }
        seam = seam || oneWayHits[1] > 1 || oneWayHits[2] > 1;
        for (const Cell c : platforms) {
            const oracle::ExactRect t = map.tileRect(c.i, c.j);
            const bool atStart = overlapsExactly(frame.start, frame.size, t);
            startsInside = startsInside || atStart;
            inside = inside || atStart || overlapsExactly(frame.position, frame.size, t);
            onPlatform = onPlatform || (move.y > 0 && t.min.y == frame.start.y + frame.size.y &&
                                        t.min.x < frame.start.x + frame.size.x && frame.start.x < t.max.x);
        }
    }
    if (hit) tags.push_back("one-way-hit");
    if (tie) tags.push_back("one-way-tie");
    if (fast) tags.push_back("one-way-fast");
    if (seam) tags.push_back("one-way-seam");
    if (onPlatform) tags.push_back("on-platform");
    if (inside) tags.push_back("in-one-way");
    if (startsInside) tags.push_back("starts-in-one-way");
}

/// The path that decided the scene's frames (tilesweep/frame_stats.h): "exact" when any frame fell
/// back to the lattice, else "filtered" when any predicate needed the exact refinement, else "fast".
template <class T>
const char* decisionPathOf(const Scene<T>& scene) {
    DecisionPath worst = DecisionPath::Fast;
    Vec2<T> start = scene.box.pos;
    std::vector<Contact<T>> contacts(64);
    std::vector<Cell> overlaps(64);
    for (const Vec2<T>& move : scene.moves) {
        FrameStats stats;
        const ResolveResult<T> r = resolveMove<T>({scene.map.view(), {start, scene.box.size}, move},
                                                  {contacts.data(), 64, overlaps.data(), 64, &stats});
        const DecisionPath path = stats.path;
        if (static_cast<int>(path) > static_cast<int>(worst)) worst = path;
        start = r.position;
    }
    return worst == DecisionPath::Fast ? "fast" : (worst == DecisionPath::Filtered ? "filtered" : "exact");
}

}  // namespace

template <class T>
std::vector<std::string> classifyScene(const Scene<T>& scene) {
    std::vector<std::string> tags;
    const auto frames = oracle::resolveSceneExact(scene);
    bool hit = false;
    bool tie = false;
    bool touch0 = false;
    bool twoStep = false;
    bool seam = false;
    bool startOverlap = false;
    bool down = false;
    bool timeTie = false;
    bool slide = false;         // a contact the box slides on from (Contact::position's own number)
    bool lateSlide = false;     // the same at a time after 0
    bool roundedSlide = false;  // the same at a coordinate T cannot hold
    for (const auto& f : frames) {
        hit = hit || !f.contacts.empty();
        startOverlap = startOverlap || !f.startOverlaps.empty();
        down = down || roundedDown<T>(f);
        for (std::size_t k = 0; k < f.contacts.size(); ++k) {
            const auto& c = f.contacts[k];
            tie = tie || c.tie;
            touch0 = touch0 || c.time == 0;
            twoStep = twoStep || c.step == 2;
            timeTie = timeTie || halfwayBetweenValues<T>(c.time);
            if (c.movesOnX || c.movesOnY) {
                slide = true;
                lateSlide = lateSlide || c.time != 0;
                const Rational& free = c.movesOnX ? c.position.x : c.position.y;
                roundedSlide = roundedSlide || oracle::toRational(oracle::fromRational<T>(
                                                   free, oracle::Rounding::NearestEven)) != free;
            }
            if (k > 0 && f.contacts[k - 1].step == c.step && f.contacts[k - 1].normal == c.normal)
                seam = true;
        }
    }
    tags.push_back(hit ? "hit" : "miss");
    if (down) tags.push_back("rounded-down");
    if (tie) tags.push_back("tie");
    if (timeTie) tags.push_back("time-tie");
    if (reachesATileAtTheEnd(scene, frames)) tags.push_back("reaches-at-end");
    if (touch0) tags.push_back("touch-at-0");
    if (twoStep) tags.push_back("two-step");
    if (slide) tags.push_back("hit-then-slide");
    if (lateSlide) tags.push_back("late-hit-then-slide");
    if (roundedSlide) tags.push_back("hit-then-slide-rounded");
    if (seam) tags.push_back("seam");
    if (startOverlap) tags.push_back("start-overlap");
    if (std::find(scene.map.solid.begin(), scene.map.solid.end(), std::uint8_t{1}) == scene.map.solid.end())
        tags.push_back("empty-map");
    addOneWayTags(scene, frames, tags);
    const T huge = std::ldexp(T(1), 40);
    if (std::any_of(scene.moves.begin(), scene.moves.end(),
                    [huge](Vec2<T> m) { return std::fabs(m.x) >= huge || std::fabs(m.y) >= huge; }))
        tags.push_back("huge-move");
    const int span = latticeSpan(scene);
    if (span > 60) tags.push_back("lattice-wide");
    if (span > 92) tags.push_back("lattice-192");
    if (std::fabs(scene.map.origin.x) >= T(1048576) || std::fabs(scene.map.origin.y) >= T(1048576))
        tags.push_back("far-origin");
    const std::string path = decisionPathOf(scene);
    tags.push_back("path:" + path);
    if (path != "fast") tags.push_back("fallback");
    // A near tie its refinement settled: no exact tie, yet the filter could not decide alone.
    if (path == "filtered" && !tie && hit) tags.push_back("near-tie-refined");
    // Code only double frames reach: a refinement on inputs of more than 27 significant bits,
    // where TwoProduct's split leaves both low halves nonzero (productError's aLow * bLow term)
    // and contact times are exact pairs rounded by roundTimeToDouble's remainder test.
    if (std::is_same<T, double>::value && path == "filtered" && widestSignificand(scene) > 27)
        tags.push_back("full-precision-refined");
    // The tiny end of the range: some nonzero input below 2^-500 (double) or 2^-100 (float),
    // where a product of two inputs would underflow a double (or come near it).
    if (smallestInputExponent(scene) < (std::is_same<T, float>::value ? -100 : -500)) tags.push_back("tiny");
    // The upper half of the double filter's band (between half its bound and the bound), by tenths.
    if constexpr (std::is_same<T, double>::value) {
        const double deepest = deepestFilterError(scene);
        if (deepest > 0.5) {
            tags.push_back("filter-upper-half");
            tags.push_back("filter-band-tenth:" +
                           std::to_string(std::min(9, static_cast<int>(deepest * 10))));
        }
    }
    // The edge of the float range test: spans 53 (the last admitted) to 57 (four binades past).
    if constexpr (std::is_same<T, float>::value) {
        const int rangeSpan = floatRangeSpan(scene);
        if (rangeSpan >= 53 && rangeSpan <= 57) tags.push_back("range-boundary");
    }
    // Capacity boundaries (mover.h): the contact bound at the inline limit, or past it (the wide
    // path), and frames with many contacts (an exact count the buffers are sized to).
    const std::int32_t bound = maxContacts(scene.box.size, scene.map.tileSize);
    if (bound == kInlineContacts) tags.push_back("bound-inline-limit");
    if (bound > kInlineContacts && bound <= kInlineContacts + 2) tags.push_back("bound-wide");
    std::size_t most = 0;
    for (const auto& f : frames) most = std::max(most, f.contacts.size());
    if (most >= 16) tags.push_back("many-contacts");
    // The C error claim's unrepresentable-edge causes need tile * 2^(digits + 2) finite.
    constexpr int digits = std::numeric_limits<T>::digits;
    if (std::isfinite(std::ldexp(scene.map.tileSize.x, digits + 2)) &&
        std::isfinite(std::ldexp(scene.map.tileSize.y, digits + 2)))
        tags.push_back("edge-causes-built");
    return tags;
}

template std::vector<std::string> classifyScene<float>(const Scene<float>&);
template std::vector<std::string> classifyScene<double>(const Scene<double>&);

}  // namespace tilesweep::properties

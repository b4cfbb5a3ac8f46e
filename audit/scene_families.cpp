// SPDX-License-Identifier: MIT
// The audit's columns (scene_families.h) over the scenario library.
#include "tilesweep/audit/scene_families.h"

#include <string>

namespace tilesweep::audit {
namespace {

// A stable 64-bit mix (SplitMix64's finaliser), so that a case's scene depends only on the seed,
// the family and the case index, never on the run's order or its number of jobs.
std::uint64_t mix(std::uint64_t x) {
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

// FNV-1a: a stable hash of a family's name.
std::uint64_t hashName(const std::string& name) {
    std::uint64_t h = 0xCBF29CE484222325ull;
    for (const char c : name) {
        h ^= static_cast<unsigned char>(c);
        h *= 0x100000001B3ull;
    }
    return h;
}

}  // namespace

std::vector<Family> auditFamilies() {
    std::vector<Family> f = {
        {"uniform", FamilyKind::Uniform, 0, true},
        {"near-corner", FamilyKind::NearCorner, 0, true},
        {"tie", FamilyKind::Tie, 0, true},
        {"seam", FamilyKind::Seam, 0, true},
        {"tiny", FamilyKind::Tiny, 0, true},
        {"high-speed", FamilyKind::HighSpeed, 0, true},
        {"far-1", FamilyKind::Far, 1, true},
        {"far-1e3", FamilyKind::Far, 1e3, true},
        {"far-1e5", FamilyKind::Far, 1e5, true},
        {"far-1e6", FamilyKind::Far, 1e6, true},
        {"far-2^23", FamilyKind::Far, 8388608.0, true},
        {"far-1e9", FamilyKind::Far, 1e9, false},
        {"far-1e12", FamilyKind::Far, 1e12, false},
        {"far-2^52", FamilyKind::Far, 4503599627370496.0, false},
    };
    // Every family of the property suite but `extreme`, whose moves of up to the largest finite
    // value would send the grid and substep baselines through billions of cells, and
    // `high-speed`, which is the high-speed column above.
    for (const scenarios::Family suite : scenarios::allFamilies()) {
        if (suite == scenarios::Family::Extreme || suite == scenarios::Family::HighSpeed) continue;
        f.push_back(
            {std::string("suite:") + scenarios::familyName(suite), FamilyKind::Suite, 0, true, suite});
    }
    return f;
}

template <class T>
Scene<T> generateScene(const Family& family, std::uint64_t seed, std::uint64_t caseIndex) {
    using scenarios::DrawnFamily;
    // The far families share one stream per case: case c of every magnitude is the same local
    // scene, translated, so that the error-against-magnitude curve compares like with like.
    const std::uint64_t stream = family.kind == FamilyKind::Far ? hashName("far") : hashName(family.name);
    const std::uint64_t sceneSeed = mix(mix(seed ^ stream) + caseIndex);
    const double m = family.magnitude;
    Scene<T> s;
    switch (family.kind) {
        case FamilyKind::Uniform:
            s = scenarios::drawScene<T>(DrawnFamily::Uniform, sceneSeed, m);
            break;
        case FamilyKind::NearCorner:
            s = scenarios::drawScene<T>(DrawnFamily::NearCorner, sceneSeed, m);
            break;
        case FamilyKind::Tie:
            s = scenarios::drawScene<T>(DrawnFamily::Tie, sceneSeed, m);
            break;
        case FamilyKind::Seam:
            s = scenarios::drawScene<T>(DrawnFamily::Seam, sceneSeed, m);
            break;
        case FamilyKind::Tiny:
            s = scenarios::drawScene<T>(DrawnFamily::Tiny, sceneSeed, m);
            break;
        case FamilyKind::HighSpeed:  // the property family's builder: one high-speed scene model
            s = scenarios::buildScene<T>(scenarios::Family::HighSpeed, sceneSeed).scene;
            break;
        case FamilyKind::Far: {
            static constexpr DrawnFamily kFar[] = {DrawnFamily::Uniform, DrawnFamily::NearCorner,
                                                   DrawnFamily::Tie, DrawnFamily::Seam};
            s = scenarios::drawScene<T>(kFar[caseIndex % 4], sceneSeed, m);
            break;
        }
        case FamilyKind::Suite:
            s = scenarios::buildScene<T>(family.suite, sceneSeed).scene;
            break;
    }
    s.name = "audit/" + family.name + "/" + std::to_string(caseIndex);
    return s;
}

template Scene<float> generateScene<float>(const Family&, std::uint64_t, std::uint64_t);
template Scene<double> generateScene<double>(const Family&, std::uint64_t, std::uint64_t);

}  // namespace tilesweep::audit

// SPDX-License-Identifier: MIT
// The audit's columns (scene_families.h) over the scenario library.
#include "tilesweep/audit/scene_families.h"

#include <iterator>
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

Family suiteFamily(scenarios::Family suite) {
    return {scenarios::familyName(suite), FamilyKind::Suite, 0, true, suite};
}

std::vector<Family> auditFamilies() {
    // Every family of the property suite but `extreme`, whose moves of up to the largest finite
    // value would send the grid and substep baselines through billions of cells.
    std::vector<Family> f;
    for (const scenarios::Family suite : scenarios::allFamilies())
        if (suite != scenarios::Family::Extreme) f.push_back(suiteFamily(suite));
    const std::vector<Family> far = {
        {"far-1", FamilyKind::Far, 1, true},
        {"far-1e3", FamilyKind::Far, 1e3, true},
        {"far-1e5", FamilyKind::Far, 1e5, true},
        {"far-1e6", FamilyKind::Far, 1e6, true},
        {"far-2^23", FamilyKind::Far, 8388608.0, true},
        {"far-1e9", FamilyKind::Far, 1e9, false},
        {"far-1e12", FamilyKind::Far, 1e12, false},
        {"far-2^52", FamilyKind::Far, 4503599627370496.0, false},
    };
    f.insert(f.end(), far.begin(), far.end());
    return f;
}

template <class T>
Scene<T> generateScene(const Family& family, std::uint64_t seed, std::uint64_t caseIndex) {
    // The far families share one stream per case: case c of every magnitude is the same local
    // scene, built at each magnitude, so that the error-against-magnitude curve compares like
    // with like.
    const std::uint64_t stream = family.kind == FamilyKind::Far ? hashName("far") : hashName(family.name);
    const std::uint64_t sceneSeed = mix(mix(seed ^ stream) + caseIndex);
    Scene<T> s = family.kind == FamilyKind::Far
                     ? scenarios::buildSceneAt<T>(kFarFamilies[caseIndex % std::size(kFarFamilies)],
                                                  sceneSeed, family.magnitude)
                           .scene
                     : scenarios::buildScene<T>(family.suite, sceneSeed).scene;
    s.name = "audit/" + family.name + "/" + std::to_string(caseIndex);
    return s;
}

template Scene<float> generateScene<float>(const Family&, std::uint64_t, std::uint64_t);
template Scene<double> generateScene<double>(const Family&, std::uint64_t, std::uint64_t);

}  // namespace tilesweep::audit

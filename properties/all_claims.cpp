// SPDX-License-Identifier: MIT
// The claims, gathered (all_claims.h): each is declared with its kind, beside its definition, in
// exact_reference_claims.cpp, safety_claims.cpp, metamorphic_claims.cpp, game_feel_claims.cpp or
// boundary_claims.cpp (claim.h); the coverage tags are in scene_classification.cpp.
#include "all_claims.h"

#include "boundary_claims.h"
#include "claims.h"

#include <exception>
#include <string>
#include <utility>
#include <vector>

namespace tilesweep::properties {

template <class T>
const std::vector<Claim<T>>& allClaims() {
    static const std::vector<Claim<T>> claims = [] {
        std::vector<Claim<T>> all;
        for (std::vector<Claim<T>> (*group)() :
             {&exactReferenceClaims<T>, &safetyClaims<T>, &metamorphicClaims<T>, &gameFeelClaims<T>,
              &boundaryClaims<T>})
            for (Claim<T>& c : group()) all.push_back(std::move(c));
        return all;
    }();
    return claims;
}

template <class T>
std::string checkClaim(const Claim<T>& claim, const Scene<T>& scene, SceneResolver& resolver) {
    try {
        return claim.check(scene, resolver);
    } catch (const ResolverFailure& failure) {
        return std::string("resolver failed: ") + failure.what();
    } catch (const std::exception& error) {
        return std::string("the check threw: ") + error.what();
    }
}

template <class T>
const Claim<T>* findClaim(const std::string& name) {
    for (const Claim<T>& c : allClaims<T>())
        if (name == c.name) return &c;
    return nullptr;
}

template const std::vector<Claim<float>>& allClaims<float>();
template const std::vector<Claim<double>>& allClaims<double>();
template const Claim<float>* findClaim<float>(const std::string&);
template const Claim<double>* findClaim<double>(const std::string&);
template std::string checkClaim<float>(const Claim<float>&, const Scene<float>&, SceneResolver&);
template std::string checkClaim<double>(const Claim<double>&, const Scene<double>&, SceneResolver&);

}  // namespace tilesweep::properties

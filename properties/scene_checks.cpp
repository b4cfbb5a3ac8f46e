// SPDX-License-Identifier: MIT
// The claims, listed (scene_checks.h): each is defined with its kind in safety_claims.cpp,
// exact_reference_claims.cpp, metamorphic_claims.cpp, game_feel_claims.cpp or
// boundary_checks.cpp; the coverage tags are in scene_classification.cpp.
#include "scene_checks.h"

#include "boundary_checks.h"
#include "claims.h"
#include "scene_runner.h"

#include <exception>
#include <string>
#include <vector>

namespace tilesweep::properties {

template <class T>
const std::vector<Claim<T>>& allClaims() {
    // Scope: what an outside resolver is held to (scene_checks.h, ClaimScope).
    using S = ClaimScope;
    static const std::vector<Claim<T>> claims = {
        {"matchesExactReferenceBitForBit", &matchesExactReferenceBitForBit<T>, S::BitForBit},
        {"neverEndsInsideATileItDidNotStartIn", &neverEndsInsideATileItDidNotStartIn<T>, S::Safety},
        {"neverGetsIntoAWall", &neverGetsIntoAWall<T>, S::Safety},
        {"stopsJustTouching", &stopsJustTouching<T>, S::Safety},
        {"obeysTheSafetyRules", &obeysTheSafetyRules<T>, S::Safety},
        {"substepOracleFindsNoMissedContact", &substepOracleFindsNoMissedContact<T>, S::Safety},
        {"exactReferenceAgreesWithSubsteps", &exactReferenceAgreesWithSubsteps<T>, S::Internal},
        {"placesContactsLikeTheExactReference", &placesContactsLikeTheExactReference<T>, S::Internal},
        {"zeroMoveChangesNothing", &zeroMoveChangesNothing<T>, S::Safety},
        {"scalingByPowerOfTwoScalesTheResult", &scalingByPowerOfTwoScalesTheResult<T>, S::Safety},
        {"mirroringXMirrorsTheResult", &mirroringMirrorsTheResult<T, Axis::X>, S::Safety},
        {"mirroringYMirrorsTheResult", &mirroringMirrorsTheResult<T, Axis::Y>, S::Safety},
        {"translatingByWholeTilesKeepsDecisions", &translatingByWholeTilesKeepsDecisions<T>, S::Safety},
        {"restingContactIsStable", &restingContactIsStable<T>, S::Safety},
        {"slidingAlongFloorNeverSnags", &slidingAlongFloorNeverSnags<T>, S::Safety},
        {"neverFallsThroughAPlatformItStoodOn", &neverFallsThroughAPlatformItStoodOn<T>, S::Safety},
        {"neverBlockedByAPlatformFromBelow", &neverBlockedByAPlatformFromBelow<T>, S::Safety},
        {"badInputIsRejected", &badInputIsRejected<T>, S::Internal},
        {"sweepBoxMatchesTheReference", &sweepBoxMatchesTheReference<T>, S::Internal},
        {"storesContactsAtExactCapacity", &storesContactsAtExactCapacity<T>, S::Internal},
        {"reportsEachCErrorByItsCause", &reportsEachCErrorByItsCause<T>, S::Internal},
    };
    return claims;
}

template <class T>
std::string checkClaim(const Claim<T>& claim, const Scene<T>& scene) {
    try {
        return claim.check(scene);
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
template std::string checkClaim<float>(const Claim<float>&, const Scene<float>&);
template std::string checkClaim<double>(const Claim<double>&, const Scene<double>&);

}  // namespace tilesweep::properties

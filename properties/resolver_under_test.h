// SPDX-License-Identifier: MIT
#pragma once

// The resolver a claim is held against, as the claims see it. Every claim about results takes it
// as a parameter (claims.h), so the same claim holds against tilesweep's own resolver, an oracle,
// a user's library or an engine in another process (tilesweep/resolvers/scene_resolver.h):
//
//     std::string why = obeysTheSafetyRules(scene, resolver);   // "" when the claim holds
//
// Inside a claim, framesFrom asks the resolver and throws ResolverFailure when it gives no
// answer; checkClaim (all_claims.h) turns that into the claim's failure on that scene, so a
// crash or a hang of the resolver is a counterexample like any other.

#include "tilesweep/resolvers/scene_resolver.h"
#include "tilesweep/scene/scene.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace tilesweep::properties {

using resolvers::SceneResolver;

/// The resolver under test gave no answer for a scene: crash, hang, garbage, refusal.
struct ResolverFailure : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// The frames of each scene from `resolver`, asked in one batch; throws ResolverFailure naming
/// the first scene it could not answer.
template <class T>
[[nodiscard]] std::vector<std::vector<FrameResult<T>>> framesFrom(SceneResolver& resolver,
                                                                  const resolvers::SceneBatch<T>& scenes) {
    std::vector<resolvers::Answer<T>> answers = resolver.resolve(scenes);
    std::vector<std::vector<FrameResult<T>>> frames;
    frames.reserve(answers.size());
    for (std::size_t k = 0; k < answers.size(); ++k) {
        if (!answers[k].answered())
            throw ResolverFailure(answers[k].failure +
                                  (answers.size() == 1
                                       ? std::string()
                                       : " (scene " + std::to_string(k + 1) + " of the batch)"));
        frames.push_back(std::move(answers[k].frames));
    }
    return frames;
}

/// One scene's frames.
template <class T>
[[nodiscard]] std::vector<FrameResult<T>> framesFrom(SceneResolver& resolver, const Scene<T>& scene) {
    return std::move(framesFrom(resolver, resolvers::SceneBatch<T>{&scene}).front());
}

/// Two scenes' frames, in one batch: a metamorphic claim's pair.
template <class T>
[[nodiscard]] std::vector<std::vector<FrameResult<T>>> framesFrom(SceneResolver& resolver, const Scene<T>& a,
                                                                  const Scene<T>& b) {
    return framesFrom(resolver, resolvers::SceneBatch<T>{&a, &b});
}

}  // namespace tilesweep::properties

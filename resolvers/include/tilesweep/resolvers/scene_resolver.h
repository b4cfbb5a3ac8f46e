// SPDX-License-Identifier: MIT
#pragma once

// The one seam every resolver sits behind: a batch of scenes in, one answer per scene out, in
// float and in double. The claims (properties/), the audit's rates (audit/) and every command of
// the tool (cli/) ask their resolver through it and nothing else, so a claim written once holds
// against tilesweep's own resolver, an oracle, a game-style baseline, a user's shared library or
// an engine in another process alike (resolver_registry.h names them all).
//
//     std::string error;
//     std::unique_ptr<SceneResolver> r = makeResolver("cmd:adapters/godot/run.sh", error);
//     std::vector<Answer<float>> answers = r->resolve(SceneBatch<float>{&scene1, &scene2});
//     if (!answers[0].answered()) report(answers[0].failure);   // crash, hang, garbage, refusal
//
// Nothing crosses the seam as an exception: a resolver that cannot answer a scene says why in
// that scene's answer, and the other scenes of the batch keep theirs.

#include "tilesweep/scene/scene.h"

#include <string>
#include <utility>
#include <vector>

namespace tilesweep::resolvers {

/// One scene's answer: its frames, or why there are none.
template <class T>
struct Answer {
    std::vector<FrameResult<T>> frames;
    std::string failure;  ///< non-empty: no usable answer (crash, hang, garbage, an error line)
    /// What the resolver printed, as it printed it (an outside process's result line), for a
    /// report to quote; empty for a resolver in this process, whose frames say it all.
    std::string text;

    [[nodiscard]] bool answered() const noexcept { return failure.empty(); }
};

/// The scenes of one request, in order (not owned).
template <class T>
using SceneBatch = std::vector<const Scene<T>*>;

/// Something that answers scenes. Not thread-safe: each thread (or worker process) makes its own.
class SceneResolver {
public:
    virtual ~SceneResolver() = default;
    /// One answer per scene, in order. Never throws for the resolver's misbehaviour.
    [[nodiscard]] virtual std::vector<Answer<float>> resolve(const SceneBatch<float>& scenes) = 0;
    [[nodiscard]] virtual std::vector<Answer<double>> resolve(const SceneBatch<double>& scenes) = 0;
    /// Names the resolver in reports: its registry name, or an outside process's command line.
    [[nodiscard]] virtual std::string name() const = 0;
    /// True for a resolver in another process (a request costs a round trip; a crash costs one
    /// scene): the claims then keep to what an outside resolver is held to.
    [[nodiscard]] virtual bool outside() const noexcept { return false; }
};

/// Every scene of `scenes` in one batch.
template <class T>
[[nodiscard]] std::vector<Answer<T>> resolveAll(SceneResolver& resolver,
                                                const std::vector<Scene<T>>& scenes) {
    SceneBatch<T> batch;
    batch.reserve(scenes.size());
    for (const Scene<T>& s : scenes) batch.push_back(&s);
    return resolver.resolve(batch);
}

/// One scene, a batch of one.
template <class T>
[[nodiscard]] Answer<T> resolveOne(SceneResolver& resolver, const Scene<T>& scene) {
    return std::move(resolver.resolve(SceneBatch<T>{&scene}).front());
}

}  // namespace tilesweep::resolvers

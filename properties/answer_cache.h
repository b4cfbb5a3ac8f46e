// SPDX-License-Identifier: MIT
#pragma once

// A round's answers, asked for in one batch before the round is judged. A property round draws
// its cases first, gives the cache every scene their claims ask for (Claim::asks), and then
// judges each case against the cache: an outside resolver sees one request per round, not one
// per case. A scene the cache does not hold (a shrinking candidate's) is passed on to the
// resolver as it comes, in the batch it was asked in.
//
//     AnswerCache cache(outside);
//     cache.fill(scenesOfTheRound);              // one batch
//     std::string why = checkClaim(claim, scene, cache);

#include "tilesweep/resolvers/scene_resolver.h"

#include <string>
#include <unordered_map>
#include <vector>

namespace tilesweep::properties {

class AnswerCache final : public resolvers::SceneResolver {
public:
    explicit AnswerCache(resolvers::SceneResolver& resolver) : resolver_(resolver) {}

    /// Asks the resolver, in one batch, for every scene not already held, and keeps the answers.
    template <class T>
    void fill(const std::vector<Scene<T>>& scenes);
    /// Forgets every answer held.
    void clear() noexcept;

    [[nodiscard]] std::vector<resolvers::Answer<float>> resolve(
        const resolvers::SceneBatch<float>& scenes) override;
    [[nodiscard]] std::vector<resolvers::Answer<double>> resolve(
        const resolvers::SceneBatch<double>& scenes) override;
    [[nodiscard]] std::string name() const override { return resolver_.name(); }
    [[nodiscard]] bool outside() const noexcept override { return resolver_.outside(); }

private:
    template <class T>
    std::unordered_map<std::string, resolvers::Answer<T>>& held() noexcept;
    template <class T>
    std::vector<resolvers::Answer<T>> answer(const resolvers::SceneBatch<T>& scenes);

    resolvers::SceneResolver& resolver_;
    std::unordered_map<std::string, resolvers::Answer<float>> float_;  ///< by formatScene's line
    std::unordered_map<std::string, resolvers::Answer<double>> double_;
};

extern template void AnswerCache::fill<float>(const std::vector<Scene<float>>&);
extern template void AnswerCache::fill<double>(const std::vector<Scene<double>>&);

}  // namespace tilesweep::properties

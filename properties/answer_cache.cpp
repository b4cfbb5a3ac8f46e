// SPDX-License-Identifier: MIT
#include "answer_cache.h"

#include <utility>

namespace tilesweep::properties {

template <>
std::unordered_map<std::string, resolvers::Answer<float>>& AnswerCache::held<float>() noexcept {
    return float_;
}
template <>
std::unordered_map<std::string, resolvers::Answer<double>>& AnswerCache::held<double>() noexcept {
    return double_;
}

template <class T>
void AnswerCache::fill(const std::vector<Scene<T>>& scenes) {
    auto& held = this->held<T>();
    resolvers::SceneBatch<T> batch;
    std::vector<std::string> lines;
    for (const Scene<T>& s : scenes) {
        std::string line = formatScene(s);
        if (held.count(line) != 0) continue;
        held.emplace(line, resolvers::Answer<T>{});  // a placeholder: duplicates are asked once
        lines.push_back(std::move(line));
        batch.push_back(&s);
    }
    if (batch.empty()) return;
    std::vector<resolvers::Answer<T>> answers = resolver_.resolve(batch);
    for (std::size_t k = 0; k < answers.size(); ++k) held[lines[k]] = std::move(answers[k]);
}

void AnswerCache::clear() noexcept {
    float_.clear();
    double_.clear();
}

template <class T>
std::vector<resolvers::Answer<T>> AnswerCache::answer(const resolvers::SceneBatch<T>& scenes) {
    const auto& held = this->held<T>();
    if (held.empty()) return resolver_.resolve(scenes);
    std::vector<resolvers::Answer<T>> answers(scenes.size());
    resolvers::SceneBatch<T> missing;
    std::vector<std::size_t> where;
    for (std::size_t k = 0; k < scenes.size(); ++k) {
        const auto found = held.find(formatScene(*scenes[k]));
        if (found != held.end()) {
            answers[k] = found->second;
        } else {
            missing.push_back(scenes[k]);
            where.push_back(k);
        }
    }
    if (!missing.empty()) {
        std::vector<resolvers::Answer<T>> asked = resolver_.resolve(missing);
        for (std::size_t k = 0; k < asked.size(); ++k) answers[where[k]] = std::move(asked[k]);
    }
    return answers;
}

std::vector<resolvers::Answer<float>> AnswerCache::resolve(const resolvers::SceneBatch<float>& scenes) {
    return answer(scenes);
}

std::vector<resolvers::Answer<double>> AnswerCache::resolve(const resolvers::SceneBatch<double>& scenes) {
    return answer(scenes);
}

template void AnswerCache::fill<float>(const std::vector<Scene<float>>&);
template void AnswerCache::fill<double>(const std::vector<Scene<double>>&);

}  // namespace tilesweep::properties

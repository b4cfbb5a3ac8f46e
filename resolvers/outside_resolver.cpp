// SPDX-License-Identifier: MIT
#include "tilesweep/resolvers/outside_resolver.h"

#include "tilesweep/resolvers/resolver_probe.h"
#include "tilesweep/resolvers/result_reader.h"

#include <utility>

namespace tilesweep::resolvers {

OutsideResolver::OutsideResolver(std::string command, double timeoutSeconds)
    : process_(std::move(command), timeoutSeconds) {
    process_.setBarrier(knownSceneLine());
}

std::vector<Answer<float>> OutsideResolver::resolve(const SceneBatch<float>& scenes) {
    return answer(scenes);
}

std::vector<Answer<double>> OutsideResolver::resolve(const SceneBatch<double>& scenes) {
    return answer(scenes);
}

template <class T>
std::vector<Answer<T>> OutsideResolver::answer(const SceneBatch<T>& scenes) {
    std::vector<std::string> lines;
    lines.reserve(scenes.size());
    for (const Scene<T>* s : scenes) lines.push_back(formatScene(*s));
    std::vector<ResolverReply> replies = process_.exchange(lines);
    std::vector<Answer<T>> answers(scenes.size());
    for (std::size_t k = 0; k < scenes.size(); ++k) {
        Answer<T>& a = answers[k];
        if (!replies[k].failure.empty()) {
            a.failure = std::move(replies[k].failure);
            continue;
        }
        a.text = std::move(replies[k].line);
        ResultParse<T> parsed = parseResultLine<T>(a.text, scenes[k]->moves.size());
        if (parsed.frames)
            a.frames = std::move(*parsed.frames);
        else
            a.failure = "unreadable answer: " + parsed.error + " in '" + a.text.substr(0, 200) + "'";
    }
    return answers;
}

}  // namespace tilesweep::resolvers

// SPDX-License-Identifier: MIT
#include "tilesweep/resolvers/in_process_resolver.h"

#include <exception>

namespace tilesweep::resolvers {
namespace {

template <class T>
std::vector<Answer<T>> answerEach(const FramesOf<T>& frames, const SceneBatch<T>& scenes,
                                  const char* scalar) {
    std::vector<Answer<T>> answers(scenes.size());
    for (std::size_t k = 0; k < scenes.size(); ++k) {
        if (!frames) {
            answers[k].failure = std::string("this resolver does not answer ") + scalar + " scenes";
            continue;
        }
        try {
            answers[k].frames = frames(*scenes[k]);
        } catch (const std::exception& error) {
            answers[k].failure = error.what();
        }
    }
    return answers;
}

}  // namespace

std::vector<Answer<float>> InProcessResolver::resolve(const SceneBatch<float>& scenes) {
    return answerEach(float_, scenes, "float");
}

std::vector<Answer<double>> InProcessResolver::resolve(const SceneBatch<double>& scenes) {
    return answerEach(double_, scenes, "double");
}

}  // namespace tilesweep::resolvers

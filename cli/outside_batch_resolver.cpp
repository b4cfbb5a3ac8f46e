// SPDX-License-Identifier: MIT
#include "outside_batch_resolver.h"

#include "resolver_probe.h"
#include "resolver_process.h"
#include "result_reader.h"

#include <utility>
#include <vector>

namespace tilesweep::cli {
namespace {

class OutsideBatchResolver final : public audit::BatchResolver {
public:
    OutsideBatchResolver(const std::string& command, double timeoutSeconds)
        : process_(command, timeoutSeconds) {
        process_.setBarrier(properties::knownSceneLine());
    }

    std::vector<audit::EngineAnswer> resolve(const std::vector<Scene<float>>& scenes) override {
        return answer(scenes);
    }
    std::vector<audit::EngineAnswerOf<double>> resolveDouble(
        const std::vector<Scene<double>>& scenes) override {
        return answer(scenes);
    }

private:
    template <class T>
    std::vector<audit::EngineAnswerOf<T>> answer(const std::vector<Scene<T>>& scenes) {
        std::vector<std::string> lines;
        lines.reserve(scenes.size());
        for (const Scene<T>& s : scenes) lines.push_back(formatScene(s));
        const std::vector<properties::ResolverReply> replies = process_.exchange(lines);
        std::vector<audit::EngineAnswerOf<T>> answers(scenes.size());
        for (std::size_t k = 0; k < scenes.size(); ++k) {
            if (!replies[k].failure.empty()) {
                answers[k].failure = replies[k].failure;
                continue;
            }
            properties::ResultParse<T> parsed =
                properties::parseResultLine<T>(replies[k].line, scenes[k].moves.size());
            if (parsed.frames)
                answers[k].frames = std::move(*parsed.frames);
            else
                answers[k].failure =
                    "unreadable answer: " + parsed.error + " in '" + replies[k].line.substr(0, 160) + "'";
        }
        return answers;
    }

    properties::ResolverProcess process_;
};

}  // namespace

std::unique_ptr<audit::BatchResolver> makeOutsideBatchResolver(const std::string& command,
                                                               double timeoutSeconds) {
    return std::make_unique<OutsideBatchResolver>(command, timeoutSeconds);
}

}  // namespace tilesweep::cli

// SPDX-License-Identifier: MIT
#include "scene_runner.h"

#include "result_reader.h"

#include <utility>

namespace tilesweep::properties {
namespace {

// One slot per scalar type and thread: check's workers are processes, the GoogleTest runs one
// thread; a slot per thread keeps a future threaded runner from crossing resolvers.
template <class T>
SceneRunner<T>*& slot() noexcept {
    thread_local SceneRunner<T>* runner = nullptr;
    return runner;
}

}  // namespace

template <class T>
SceneRunner<T>* currentSceneRunner() noexcept {
    return slot<T>();
}

template <class T>
ScopedSceneRunner<T>::ScopedSceneRunner(SceneRunner<T>& runner) : previous_(slot<T>()) {
    slot<T>() = &runner;
}

template <class T>
ScopedSceneRunner<T>::~ScopedSceneRunner() {
    slot<T>() = previous_;
}

template <class T>
std::vector<FrameResult<T>> resolveUnderTest(const Scene<T>& scene) {
    if (SceneRunner<T>* runner = slot<T>()) return std::move(runner->runAll({&scene}).front());
    return runScene(scene);
}

template <class T>
std::vector<std::vector<FrameResult<T>>> resolveUnderTest(const Scene<T>& a, const Scene<T>& b) {
    if (SceneRunner<T>* runner = slot<T>()) return runner->runAll({&a, &b});
    return {runScene(a), runScene(b)};
}

template <class T>
std::vector<std::vector<FrameResult<T>>> OutsideSceneRunner<T>::runAll(
    const std::vector<const Scene<T>*>& scenes) {
    std::vector<std::string> lines;
    lines.reserve(scenes.size());
    for (const Scene<T>* s : scenes) lines.push_back(formatScene(*s));
    const std::vector<ResolverReply> replies = process_->exchange(lines);
    std::vector<std::vector<FrameResult<T>>> out;
    out.reserve(scenes.size());
    for (std::size_t k = 0; k < scenes.size(); ++k) {
        const std::string which =
            scenes.size() == 1 ? std::string() : " (scene " + std::to_string(k + 1) + " of the batch)";
        if (!replies[k].failure.empty()) throw ResolverFailure(replies[k].failure + which);
        ResultParse<T> parsed = parseResultLine<T>(replies[k].line, scenes[k]->moves.size());
        if (!parsed.frames)
            throw ResolverFailure("unreadable answer" + which + ": " + parsed.error + " in '" +
                                  replies[k].line.substr(0, 200) + "'");
        out.push_back(std::move(*parsed.frames));
    }
    return out;
}

template <class T>
std::string OutsideSceneRunner<T>::answerText(const Scene<T>& scene) {
    const std::vector<ResolverReply> replies = process_->exchange({formatScene(scene)});
    if (!replies.front().failure.empty()) return "(no answer: " + replies.front().failure + ")";
    return replies.front().line;
}

template <class T>
std::vector<std::vector<FrameResult<T>>> RecordingSceneRunner<T>::runAll(
    const std::vector<const Scene<T>*>& scenes) {
    for (const Scene<T>* s : scenes) lines_.push_back(formatScene(*s));
    throw RehearsalDone{};
}

template <class T>
std::string RecordingSceneRunner<T>::answerText(const Scene<T>& scene) {
    return formatFrames(runScene(scene));
}

template SceneRunner<float>* currentSceneRunner<float>() noexcept;
template SceneRunner<double>* currentSceneRunner<double>() noexcept;
template class ScopedSceneRunner<float>;
template class ScopedSceneRunner<double>;
template std::vector<FrameResult<float>> resolveUnderTest<float>(const Scene<float>&);
template std::vector<FrameResult<double>> resolveUnderTest<double>(const Scene<double>&);
template std::vector<std::vector<FrameResult<float>>> resolveUnderTest<float>(const Scene<float>&,
                                                                              const Scene<float>&);
template std::vector<std::vector<FrameResult<double>>> resolveUnderTest<double>(const Scene<double>&,
                                                                                const Scene<double>&);
template class OutsideSceneRunner<float>;
template class OutsideSceneRunner<double>;
template class RecordingSceneRunner<float>;
template class RecordingSceneRunner<double>;

}  // namespace tilesweep::properties

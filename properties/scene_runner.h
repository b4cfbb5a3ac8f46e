// SPDX-License-Identifier: MIT
#pragma once

// The resolver under test. The claims about results (scene_checks.h) never call runScene
// directly: they call resolveUnderTest, which runs the scene through the runner installed for
// the current thread, or through tilesweep's own resolver when none is. So every claim is
// written once and holds against either:
//
//     auto process = std::make_shared<ResolverProcess>("./my_engine_adapter", 10.0);
//     OutsideSceneRunner<float> outside(process);
//     ScopedSceneRunner<float> use(outside);             // until the end of the scope
//     std::string why = claim.check(scene);               // the claim, against the outside resolver
//
// A runner that cannot produce frames for a scene (the process crashed, hung, printed a line
// that is not a valid answer, refused the scene) throws ResolverFailure; the property runner
// turns that into a failure of the claim with that scene as its counterexample.

#include "resolver_process.h"

#include "tilesweep/scene/scene.h"

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace tilesweep::properties {

/// An outside resolver could not answer a scene: crash, hang, malformed or missing line.
struct ResolverFailure : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// Runs scenes through some resolver.
template <class T>
class SceneRunner {
public:
    virtual ~SceneRunner() = default;
    /// The frames of each scene, in order; throws ResolverFailure naming the first scene that
    /// could not be answered.
    [[nodiscard]] virtual std::vector<std::vector<FrameResult<T>>> runAll(
        const std::vector<const Scene<T>*>& scenes) = 0;
    /// What the resolver answered for one scene, as text for a report: its result line, or why
    /// there is none. Never throws.
    [[nodiscard]] virtual std::string answerText(const Scene<T>& scene) = 0;
    /// Names the resolver in reports (the command line of an outside one).
    [[nodiscard]] virtual std::string name() const = 0;
};

/// The runner installed for this thread, or nullptr: tilesweep's own resolver (runScene).
template <class T>
[[nodiscard]] SceneRunner<T>* currentSceneRunner() noexcept;

/// Installs a runner for this thread for its lifetime, then puts the previous one back.
template <class T>
class ScopedSceneRunner {
public:
    explicit ScopedSceneRunner(SceneRunner<T>& runner);
    ~ScopedSceneRunner();
    ScopedSceneRunner(const ScopedSceneRunner&) = delete;
    ScopedSceneRunner& operator=(const ScopedSceneRunner&) = delete;

private:
    SceneRunner<T>* previous_;
};

/// The frames of a scene from the resolver under test (see the header comment).
template <class T>
[[nodiscard]] std::vector<FrameResult<T>> resolveUnderTest(const Scene<T>& scene);

/// Two scenes at once (one batch for an outside resolver): the metamorphic claims' pair.
template <class T>
[[nodiscard]] std::vector<std::vector<FrameResult<T>>> resolveUnderTest(const Scene<T>& a, const Scene<T>& b);

/// An outside process speaking the `tilesweep resolve` protocol. Scene lines are written with
/// every number a hexfloat (formatScene), so the process reads exactly the scene the claim
/// built; each answer is read back with parseResultLine. Several runners (float and double)
/// may share one process.
template <class T>
class OutsideSceneRunner final : public SceneRunner<T> {
public:
    explicit OutsideSceneRunner(std::shared_ptr<ResolverProcess> process) : process_(std::move(process)) {}
    [[nodiscard]] std::vector<std::vector<FrameResult<T>>> runAll(
        const std::vector<const Scene<T>*>& scenes) override;
    [[nodiscard]] std::string answerText(const Scene<T>& scene) override;
    [[nodiscard]] std::string name() const override { return process_->command(); }

private:
    std::shared_ptr<ResolverProcess> process_;
};

/// Thrown by RecordingSceneRunner once it has noted a case's scenes: the case is rehearsed, not
/// judged. Not a std::exception, so that no claim's error handling takes it for a failure; the
/// property runner (property_suite.cpp) ends the case as a pass when it sees it.
struct RehearsalDone {};

/// Notes the line of every scene it is asked for (formatScene, as an outside runner would send
/// it), then ends the case with RehearsalDone. `tilesweep check` rehearses a property round
/// through it, prefetches the noted lines from the outside resolver in one batch
/// (ResolverProcess::prefetch), and runs the same round again through an OutsideSceneRunner: the
/// same seed makes the same cases (the generator and the coverage tags never depend on the
/// resolver under test, and each claim asks for its scenes in one call), so the second run asks
/// only for answers already kept; shrinking, which asks for new scenes, goes to the resolver one
/// request at a time as before.
template <class T>
class RecordingSceneRunner final : public SceneRunner<T> {
public:
    explicit RecordingSceneRunner(std::vector<std::string>& lines) : lines_(lines) {}
    [[nodiscard]] std::vector<std::vector<FrameResult<T>>> runAll(
        const std::vector<const Scene<T>*>& scenes) override;
    [[nodiscard]] std::string answerText(const Scene<T>& scene) override;
    [[nodiscard]] std::string name() const override { return "tilesweep (recording)"; }

private:
    std::vector<std::string>& lines_;
};

extern template SceneRunner<float>* currentSceneRunner<float>() noexcept;
extern template SceneRunner<double>* currentSceneRunner<double>() noexcept;
extern template class ScopedSceneRunner<float>;
extern template class ScopedSceneRunner<double>;
extern template std::vector<FrameResult<float>> resolveUnderTest<float>(const Scene<float>&);
extern template std::vector<FrameResult<double>> resolveUnderTest<double>(const Scene<double>&);
extern template std::vector<std::vector<FrameResult<float>>> resolveUnderTest<float>(const Scene<float>&,
                                                                                     const Scene<float>&);
extern template std::vector<std::vector<FrameResult<double>>> resolveUnderTest<double>(const Scene<double>&,
                                                                                       const Scene<double>&);
extern template class OutsideSceneRunner<float>;
extern template class OutsideSceneRunner<double>;
extern template class RecordingSceneRunner<float>;
extern template class RecordingSceneRunner<double>;

}  // namespace tilesweep::properties

// SPDX-License-Identifier: MIT
#pragma once

// An outside process speaking `tilesweep resolve`'s protocol (docs/contract.md) behind the seam
// (scene_resolver.h). A batch is one exchange with the process (resolver_process.h): every scene
// as a line of hexfloats (formatScene), so the process reads exactly the scene that was built,
// and every answer read back exactly (result_reader.h). A crash, a hang, garbage or an error line
// is that scene's failure; a fresh process takes the rest. The known scene of resolver_probe.h is
// sent around every batch, so a scene that prints a stray line fails, every time.
//
//     OutsideResolver engine("adapters/godot/run.sh", 10.0);
//     engine.process().onFailure([](const std::string& why) { log(why); });

#include "tilesweep/resolvers/resolver_process.h"
#include "tilesweep/resolvers/scene_resolver.h"

#include <string>
#include <vector>

namespace tilesweep::resolvers {

class OutsideResolver final : public SceneResolver {
public:
    /// @param command a shell command line (resolver_process.h: pipe or file mode)
    /// @param timeoutSeconds how long the process may go without answering before it counts as hung
    OutsideResolver(std::string command, double timeoutSeconds);

    [[nodiscard]] std::vector<Answer<float>> resolve(const SceneBatch<float>& scenes) override;
    [[nodiscard]] std::vector<Answer<double>> resolve(const SceneBatch<double>& scenes) override;
    [[nodiscard]] std::string name() const override { return process_.command(); }
    [[nodiscard]] bool outside() const noexcept override { return true; }

    /// The process behind it: its failures as they happen, its counters, stopping it.
    [[nodiscard]] ResolverProcess& process() noexcept { return process_; }

private:
    template <class T>
    std::vector<Answer<T>> answer(const SceneBatch<T>& scenes);

    ResolverProcess process_;
};

}  // namespace tilesweep::resolvers

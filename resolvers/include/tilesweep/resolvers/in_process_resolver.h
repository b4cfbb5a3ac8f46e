// SPDX-License-Identifier: MIT
#pragma once

// A resolver in this process behind the seam (scene_resolver.h): a function from a scene to its
// frames, per scalar type. What it throws (an invalid scene, a library refusing it) becomes
// that scene's failure; a scalar type with no function fails every scene of it, saying so.
//
//     InProcessResolver core("core", &runScene<float>, &runScene<double>);

#include "tilesweep/resolvers/scene_resolver.h"

#include <functional>
#include <string>
#include <vector>

namespace tilesweep::resolvers {

/// A scene's frames, computed in this process.
template <class T>
using FramesOf = std::function<std::vector<FrameResult<T>>(const Scene<T>&)>;

class InProcessResolver final : public SceneResolver {
public:
    InProcessResolver(std::string name, FramesOf<float> inFloat, FramesOf<double> inDouble)
        : name_(std::move(name)), float_(std::move(inFloat)), double_(std::move(inDouble)) {}

    [[nodiscard]] std::vector<Answer<float>> resolve(const SceneBatch<float>& scenes) override;
    [[nodiscard]] std::vector<Answer<double>> resolve(const SceneBatch<double>& scenes) override;
    [[nodiscard]] std::string name() const override { return name_; }

private:
    std::string name_;
    FramesOf<float> float_;
    FramesOf<double> double_;
};

}  // namespace tilesweep::resolvers

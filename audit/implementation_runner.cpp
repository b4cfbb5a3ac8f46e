// SPDX-License-Identifier: MIT
// The audit's rows (audit.h): each implementation, and a scene's frames through it.
#include "tilesweep/audit/audit.h"
#include "tilesweep/baselines/grid_resolve.h"
#include "tilesweep/baselines/run_frames.h"
#include "tilesweep/baselines/twin_resolve.h"
#include "tilesweep/oracle/seed/seed_resolve.h"
#include "tilesweep/oracle/substep/substep_float.h"
#include "tilesweep/scene/scene.h"

#include <vector>

namespace tilesweep::audit {

std::vector<Implementation> auditImplementations() {
    return {
        {"core-float", ImplementationKind::Core, false, 0},
        {"core-double", ImplementationKind::Core, true, 0},
        {"seed-float", ImplementationKind::Seed, false, 0},
        {"seed-double", ImplementationKind::Seed, true, 0},
        {"substep4-float", ImplementationKind::SubstepFloat, false, 4},
        {"substep16-float", ImplementationKind::SubstepFloat, false, 16},
        {"substep256-float", ImplementationKind::SubstepFloat, false, 256},
        {"twin-float", ImplementationKind::Twin, false, 0},
        {"twin-double", ImplementationKind::Twin, true, 0},
        {"grid-float", ImplementationKind::Grid, false, 0},
        {"grid-double", ImplementationKind::Grid, true, 0},
    };
}

using baselines::runFrames;

template <class T>
std::vector<FrameResult<T>> runImplementation(const Implementation& impl, const Scene<T>& scene) {
    switch (impl.kind) {
        case ImplementationKind::Twin:
            return runFrames(scene, [](const ResolveInput<T>& in, const ResolveOutput<T>& out) {
                return baselines::resolveMoveTwin(in, out);
            });
        case ImplementationKind::Grid:
            return runFrames(scene, [](const ResolveInput<T>& in, const ResolveOutput<T>& out) {
                return baselines::resolveMoveGrid(in, out);
            });
        case ImplementationKind::Core:
            return runScene(scene);
        case ImplementationKind::Seed:
            return oracle::resolveSceneSeed(scene);
        case ImplementationKind::SubstepFloat:
            return oracle::frameResults(oracle::resolveSceneSubstepFloat(scene, impl.substeps));
    }
    return {};
}

template std::vector<FrameResult<float>> runImplementation<float>(const Implementation&, const Scene<float>&);
template std::vector<FrameResult<double>> runImplementation<double>(const Implementation&,
                                                                    const Scene<double>&);

}  // namespace tilesweep::audit

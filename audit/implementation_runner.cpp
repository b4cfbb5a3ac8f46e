// SPDX-License-Identifier: MIT
// The audit's rows (audit.h): each implementation, and the registry name of its resolver.
#include "tilesweep/audit/audit.h"

#include <string>
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

std::string resolverName(const Implementation& impl) {
    switch (impl.kind) {
        case ImplementationKind::Core:
            return "core";
        case ImplementationKind::Seed:
            return "seed";
        case ImplementationKind::SubstepFloat:
            return "substep-float:" + std::to_string(impl.substeps);
        case ImplementationKind::Twin:
            return "twin";
        case ImplementationKind::Grid:
            return "grid";
    }
    return {};
}

}  // namespace tilesweep::audit

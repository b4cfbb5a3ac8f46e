// SPDX-License-Identifier: MIT
#pragma once

// The C API's types by scalar type (include/tilesweep/tilesweep.h): the C names of a float or a
// double map, map description, vector, mover, result and contact, for C++ written once for both.
// The C API itself (c_api.cpp) and the property suite's claims about it (boundary_claims.cpp)
// read them from here. Internal: not installed.

#include "tilesweep/tilesweep.h"

namespace tilesweep::detail {

template <class T>
struct CTypes;

template <>
struct CTypes<float> {
    using Map = ts_map_f;
    using Desc = ts_map_desc_f;
    using Vec = ts_vec2_f;
    using Mover = ts_mover_f;
    using Result = ts_result_f;
    using ContactC = ts_contact_f;
};

template <>
struct CTypes<double> {
    using Map = ts_map_d;
    using Desc = ts_map_desc_d;
    using Vec = ts_vec2_d;
    using Mover = ts_mover_d;
    using Result = ts_result_d;
    using ContactC = ts_contact_d;
};

}  // namespace tilesweep::detail

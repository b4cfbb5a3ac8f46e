// SPDX-License-Identifier: MIT
// Turns off, until boost_warnings_on.h, the warnings of the project's set (cmake/warnings.cmake)
// that Boost's headers are not written for, and one that GCC reports inside them when their code
// is inlined (-Wmaybe-uninitialized, in cpp_int at -O2 and above). Every Boost include of the
// project sits between the two; a comment line before boost_warnings_on.h keeps clang-format's
// include sorting from moving it above the Boost header:
//
//     #include "tilesweep/boost_warnings_off.h"
//
//     #include <boost/multiprecision/cpp_int.hpp>
//     // the project's warnings again
//     #include "tilesweep/boost_warnings_on.h"
//
// No include guard: each use pushes the diagnostic state once, and boost_warnings_on.h pops it.
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wpedantic"
#pragma GCC diagnostic ignored "-Wdouble-promotion"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#if !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#endif

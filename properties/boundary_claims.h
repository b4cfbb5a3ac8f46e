// SPDX-License-Identifier: MIT
#pragma once

// Claims about the boundaries of the game-loop API and the C API: buffers of exactly
// the size needed, the inline contact limit and the wide path at exactly their bounds, and every
// C error code from a cause built to give exactly it. They concern tilesweep's own library
// (ClaimScope::Internal), and all_claims.cpp gathers them with the other claims.

#include "claim.h"

#include "tilesweep/scene/scene.h"

#include <string>
#include <vector>

namespace tilesweep::properties {

/// For every frame: resolveMove into a buffer of exactly the frame's contact count,
/// moveAndSlide into a buffer of exactly that count and of exactly maxContacts, and with no
/// buffer (the inline contacts, up to kInlineContacts; past it ContactBufferTooSmall with the
/// bound), and the same through the C API (ts_move_and_slide_*) at exactly the count and exactly
/// the bound, and at one below the bound on the wide path: the same position, status, flags and
/// contacts as a resolution with room to spare, every contact stored.
template <class T>
[[nodiscard]] std::string storesContactsAtExactCapacity(const Scene<T>& scene);

/// Through the C API, on the scene's map, box and move: each ts_error from a cause built to give
/// exactly it (a NULL argument, a non-finite mover, a non-finite origin, a tile size <= 0,
/// negative dimensions, too many cells, an unrepresentable tile edge on x and on y, a buffer
/// below the bound of a wide box, a cell out of range), and its message naming the field.
/// (TS_ERROR_OUT_OF_MEMORY and TS_ERROR_THREADS have no cause a test can build.)
template <class T>
[[nodiscard]] std::string reportsEachCErrorByItsCause(const Scene<T>& scene);

/// The claims of this file, each with its scope and properties (claim.h).
template <class T>
[[nodiscard]] std::vector<Claim<T>> boundaryClaims();

extern template std::vector<Claim<float>> boundaryClaims<float>();
extern template std::vector<Claim<double>> boundaryClaims<double>();
extern template std::string storesContactsAtExactCapacity<float>(const Scene<float>&);
extern template std::string storesContactsAtExactCapacity<double>(const Scene<double>&);
extern template std::string reportsEachCErrorByItsCause<float>(const Scene<float>&);
extern template std::string reportsEachCErrorByItsCause<double>(const Scene<double>&);

}  // namespace tilesweep::properties

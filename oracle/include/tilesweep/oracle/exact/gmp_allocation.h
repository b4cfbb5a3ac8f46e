// SPDX-License-Identifier: MIT
#pragma once

// How the exact oracles' rationals get their memory. A Rational (GMP's mpq_t) allocates its limbs
// from the heap, and the exact reference makes and drops millions of small ones a second: under
// glibc's malloc and free, that costs about 40% of `tilesweep check`'s CPU time
// (docs/benchmarks.md, "Checking engines"). useCachedGmpAllocation gives GMP allocation functions
// that keep each thread's freed small blocks in lists by size and hand them out again, so a block
// is reused without a call into malloc. Values are unchanged: only where the limbs live changes.

namespace tilesweep::oracle {

/// Makes every later GMP allocation of the process go through per-thread caches of freed blocks.
/// Call it first thing in main, before any GMP number exists (GMP requires that of
/// mp_set_memory_functions): a number made before it would be freed by the wrong functions.
/// Calling it again does nothing. Without it, GMP uses malloc, realloc and free.
void useCachedGmpAllocation() noexcept;

}  // namespace tilesweep::oracle

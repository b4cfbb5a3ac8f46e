// SPDX-License-Identifier: MIT
#pragma once

// Deliberate faults, for proving that the property suite has teeth (scripts/fault-table.sh).
// A build with -DTILESWEEP_FAULT=<NAME> defines TILESWEEP_FAULT_<NAME>, which switches on one
// of these at its place in the code; an ordinary build defines none and compiles none of them.
//
//   TOUCH_OVERLAPS     touching counted as overlapping, wherever the solver asks (overlapsOpen,
//                      axis_sweep.h: start overlaps, the tile test, a one-axis move's held span)
//   NO_CORNER_MISS     the corner-miss test (E < X) dropped        (axis_sweep.h)
//   TIE_REVERSED       the exposed-face tie rule reversed          (axis_sweep.h)
//   DOUBLE_PREDICATE   entry times compared in plain double        (axis_sweep.h)
//   ROUND_NEAREST      positions rounded to nearest, not toward the start (final_rounding.h)
//   BROADPHASE_SHORT   the broadphase's secondary range one cell short   (frame_loop.h)
//   OLD_ROUNDING_RULE  positions always rounded toward the start: the contract before its
//                      amendment, which can leave the far edge inside a missed corner (final_rounding.h)
//   TIME_TIES_AWAY     a frame time exactly halfway between two values rounded away, not to even (lattice.h,
//                      time_rounding.h: one #if in each of the three roundings, float, double, lattice)
//   END_INCLUSIVE      a tile reached at exactly t = 1, both axes moving, counted as a hit (axis_sweep.h)
//   NARROW_TIER        frames that need 128 to 191 bits solved on 128-bit integers (lattice.h)
//   FMA                -ffp-contract=fast instead of off           (cmake/warnings.cmake)
//   ORACLE_SKIPS_TOUCH_AT_0  in the exact reference only: a tile touched at t = 0 never blocks
//                      (oracle/exact/exact_sweep.cpp), for the reference's own cross-check
//   FILTER_BOUND_HALVED  the fast path's certified error bounds halved, below what their
//                      derivations need: the secondary range of its walk
//                      (kSecondaryRangeErrorUlps, fast_frame.h) and the double frames' time
//                      comparison filter (kPairProductErrorBound, exact_double.h)
//   FAST_RANGE_TOO_WIDE  the range test admitting a float frame to the fast path four binades
//                      too generous (spans of 57 bits): the least widening known to show on a
//                      valid map, a far face 2^G past a grid line read as on it (kFastSpanBits,
//                      proof_constants.h: one binade wider cannot change an answer) (range_admission.h)
//   FAST_RANGE_FAR_TOO_WIDE  the same six binades too generous
//   LINES_CLEAR_SIZE_IGNORED  the fast path's proof that no grid line can fall between an end
//                      and the value above it reads the grid's lowest bit alone, not the box
//                      size's, so it skips the amended rule's test where it applies (fast_frame.h)
//   FLOAT_WINDOW_TOO_LOW  the float range test's short form (admitFloatFrameInWindow) with its
//                      window six binades too low at the bottom, past what the span test allows
//                      with the map's top (range_admission.h)
//   WINDOW_MAGNITUDE_SHORT  the cell estimates' magnitude bound for frames in the map's window
//                      (windowMagnitudeOf) takes the box's high edge below the window's limit,
//                      where it can reach twice that (range_admission.h)
//   WINDOW_LINES_CLEAR_BINADE_SHORT  the grid-line shortcut for frames in the map's window
//                      (setWindowLinesClear) bounds the ends by the window's limit, where they
//                      reach twice it (range_admission.h)
//   WALK_ENTRY_TIE_BY_HIGH_PART  the walks of double frames read a cell's entry against the
//                      speed from the pair's high part alone, so a tie of the high part with the
//                      speed counts as entered at t >= 1 whatever the low part (fast_axis.h)
//   FINAL_STEP_SIGN_IGNORED  the final rounding of both ends at once (float and double frames)
//                      steps a negative value's bits as a positive one's, so it rounds away from
//                      the start there (final_rounding.h)
//   FREE_MOVE_FIRST_ROW_SKIPPED  the free-move test (sweptBoundsHoldNoSolidCell) reads the
//                      swept bounds from their second row, so a frame whose only solid cells lie
//                      in the first row is taken as free (free_move.h)
//   SOLID_BLOCK_LAST_COLUMN_MASKED  the block read of the free-move test (blockHoldsNoSolidCell)
//                      masks off its last column, so a solid cell there goes unseen (solid_block.h)
//   POSITION_FROM_FLOAT_TIME  a sliding contact's position on a float frame estimated from the
//                      frame time rounded to float, where its error bound needs the time rounded
//                      to double (as a double frame's is) (fast_frame.h, contact_position.h)
//   SLIDE_SKIP_ONE_SHORT  a short move's slide (step 2) left untested when step 1 hit all but
//                      one of the listed cells, not all of them (frame_loop.h)
//   ONE_WAY_SIDE_BLOCKS  a one-way tile entered through a side blocks on x (frame_loop.h)
//   ONE_WAY_TIE_ON_X   an exact corner landing on a one-way tile blocks on x, not y (frame_loop.h)
//   BATCH_ONE_WAY_IGNORED  the batch solves a frame moving down on a map with one-way cells on
//                      the loop compiled without their test (move_range.cpp)
//   EXACT_DISTANCES_FAR_PAIR  a double frame whose far box edge is an exact pair, not a double,
//                      taken as one whose tile distances are all exact doubles, so its tile
//                      screen drops the pair's low part (fast_frame.h: distancesExact)
// Four classes of inputs that random scenes reach rarely, one fault standing for each:
//   PAIR_REFINEMENT_SWAPPED  double near-ties: the exact refinement of the pair comparison called
//                      with its two sides swapped, so a nonzero sign inside the filter's band
//                      comes out reversed (exact_double.h)
//   RANGE_NO_LOWER_BOUND  the tiny end of the range: the double range test forgets its lower
//                      bound 2^-250, so products and TwoProduct errors underflow (range_admission.h)
//   INLINE_LIMIT_EXCLUSIVE  capacity boundaries: a box whose maxContacts is exactly the inline
//                      limit (64) refused as ContactBufferTooSmall with no buffer (mover.cpp)
//   C_ERROR_CODES_SWAPPED  error codes: the C API maps the unrepresentable-edge errors on x and
//                      y to each other's code (c_api.cpp)

#if defined(TILESWEEP_FAULT_TOUCH_OVERLAPS) || defined(TILESWEEP_FAULT_NO_CORNER_MISS) ||                 \
    defined(TILESWEEP_FAULT_TIE_REVERSED) || defined(TILESWEEP_FAULT_DOUBLE_PREDICATE) ||                 \
    defined(TILESWEEP_FAULT_ROUND_NEAREST) || defined(TILESWEEP_FAULT_BROADPHASE_SHORT) ||                \
    defined(TILESWEEP_FAULT_FMA) || defined(TILESWEEP_FAULT_OLD_ROUNDING_RULE) ||                         \
    defined(TILESWEEP_FAULT_TIME_TIES_AWAY) || defined(TILESWEEP_FAULT_END_INCLUSIVE) ||                  \
    defined(TILESWEEP_FAULT_NARROW_TIER) || defined(TILESWEEP_FAULT_FILTER_BOUND_HALVED) ||               \
    defined(TILESWEEP_FAULT_FAST_RANGE_TOO_WIDE) || defined(TILESWEEP_FAULT_FAST_RANGE_FAR_TOO_WIDE) ||   \
    defined(TILESWEEP_FAULT_PAIR_REFINEMENT_SWAPPED) || defined(TILESWEEP_FAULT_RANGE_NO_LOWER_BOUND) ||  \
    defined(TILESWEEP_FAULT_INLINE_LIMIT_EXCLUSIVE) || defined(TILESWEEP_FAULT_C_ERROR_CODES_SWAPPED) ||  \
    defined(TILESWEEP_FAULT_LINES_CLEAR_SIZE_IGNORED) || defined(TILESWEEP_FAULT_FLOAT_WINDOW_TOO_LOW) || \
    defined(TILESWEEP_FAULT_WINDOW_MAGNITUDE_SHORT) ||                                                    \
    defined(TILESWEEP_FAULT_WINDOW_LINES_CLEAR_BINADE_SHORT) ||                                           \
    defined(TILESWEEP_FAULT_WALK_ENTRY_TIE_BY_HIGH_PART) ||                                               \
    defined(TILESWEEP_FAULT_FINAL_STEP_SIGN_IGNORED) ||                                                   \
    defined(TILESWEEP_FAULT_FREE_MOVE_FIRST_ROW_SKIPPED) ||                                               \
    defined(TILESWEEP_FAULT_SOLID_BLOCK_LAST_COLUMN_MASKED) ||                                            \
    defined(TILESWEEP_FAULT_POSITION_FROM_FLOAT_TIME) || defined(TILESWEEP_FAULT_SLIDE_SKIP_ONE_SHORT) || \
    defined(TILESWEEP_FAULT_ONE_WAY_SIDE_BLOCKS) || defined(TILESWEEP_FAULT_ONE_WAY_TIE_ON_X) ||          \
    defined(TILESWEEP_FAULT_BATCH_ONE_WAY_IGNORED) || defined(TILESWEEP_FAULT_EXACT_DISTANCES_FAR_PAIR)
#define TILESWEEP_FAULT_INJECTED 1
#endif

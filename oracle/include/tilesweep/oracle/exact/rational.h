// SPDX-License-Identifier: MIT
#pragma once

// The exact number type of the oracles: an arbitrary-precision rational (GMP's mpq_t behind
// Boost.Multiprecision). Every value the contract talks about (an input float, a sum, a product,
// a quotient) is one of these, with no rounding anywhere.
//
// Boost is included between pragmas: the project builds with -Wconversion, -Wshadow and friends
// as errors, and Boost's headers are not written for that set. This is the oracles' one Boost
// include. The exact safety checks include Boost's cpp_int under the same pragmas
// (checks/grid_line.cpp), in a library that must not depend on the oracles or on GMP.

#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wpedantic"
#pragma GCC diagnostic ignored "-Wdouble-promotion"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#endif
#include <boost/multiprecision/gmp.hpp>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

#include <string>

namespace tilesweep::oracle {

/// An exact rational number; always in lowest terms, denominator > 0.
using Rational = boost::multiprecision::mpq_rational;

/// An exact integer (numerators and denominators of a Rational).
using Integer = boost::multiprecision::mpz_int;

/// A rational as "p/q" (or "p" when q is 1): the form the command-line tool may print.
[[nodiscard]] inline std::string toString(const Rational& q) { return q.str(); }

}  // namespace tilesweep::oracle

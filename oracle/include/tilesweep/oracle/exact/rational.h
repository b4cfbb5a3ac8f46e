// SPDX-License-Identifier: MIT
#pragma once

// The exact number type of the oracles: an arbitrary-precision rational (GMP's mpq_t behind
// Boost.Multiprecision). Every value the contract talks about (an input float, a sum, a product,
// a quotient) is one of these, with no rounding anywhere.
//
// Boost is included with the warnings of the project's set that its headers are not written for
// turned off (tilesweep/boost_warnings_off.h, in cmake/include/). This is the oracles' one Boost
// include.

#include "tilesweep/boost_warnings_off.h"

#include <boost/multiprecision/gmp.hpp>
// The project's warnings again, for the oracles' own code.
#include "tilesweep/boost_warnings_on.h"

#include <string>

namespace tilesweep::oracle {

/// An exact rational number; always in lowest terms, denominator > 0.
using Rational = boost::multiprecision::mpq_rational;

/// An exact integer (numerators and denominators of a Rational).
using Integer = boost::multiprecision::mpz_int;

/// A rational as "p/q" (or "p" when q is 1): the form the command-line tool may print.
[[nodiscard]] inline std::string toString(const Rational& q) { return q.str(); }

}  // namespace tilesweep::oracle

// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <string_view>

// Numbers as scene files write them, used inside tilesweep_scene and by the tools built on it
// (the property suite reads result lines and names scalar types with them), and shares as the
// tools' reports write them, in percent (the audit's tables, the property suite's coverage).
//
// Reading: a JSON number lexeme, or a C99 hexadecimal float as printf("%a") writes it, is
// rounded once, straight to T, to nearest (ties to even). Going through double first would
// round twice, and the float nearest a double is not always the float nearest the decimal.
// Writing: a hexfloat that reads back to the same bits, or the shortest decimal that does.
// Both directions use <charconv>, so neither depends on the C locale's decimal point.

namespace tilesweep::detail {

/// How reading a scalar ended.
enum class ScalarTextStatus {
    Ok,
    Malformed,  ///< not a JSON number lexeme / not a hexfloat of the form [-]0x<hex>[.<hex>]p<exp>
    NonFinite,  ///< spells a NaN or an infinity ("nan", "-inf", "Infinity", ...)
    Overflow,   ///< finite, but rounds to an infinity in T
};

/// A scalar read from text: `value` is meaningful only when `status` is Ok.
template <class T>
struct ScalarText {
    T value = 0;
    ScalarTextStatus status = ScalarTextStatus::Malformed;
};

/// Rounds a JSON number lexeme (as the JSON grammar allows: -?int(.frac)?(e[+-]?exp)?) to T.
/// Values too small for T round to a signed zero or a subnormal, as to nearest demands.
template <class T>
[[nodiscard]] ScalarText<T> readDecimalScalar(std::string_view lexeme);

/// Rounds a hexfloat string ("0x1.8p+3", "-0x1p-3", "0x0.0000000000001p-1022"; the 'x' and
/// 'p' may be upper case) to T. Anything else, including "nan" and "inf", is refused.
template <class T>
[[nodiscard]] ScalarText<T> readHexfloatScalar(std::string_view text);

/// Appends `value` as printf("%a") writes it in the C locale ("0x1.8p+3", "-0x0p+0"); exact,
/// because a float promotes to double without rounding.
void appendHexfloat(std::string& out, double value);

/// Appends the shortest decimal that reads back to the same T (std::to_chars without a
/// format). A finite value always gives valid JSON ("-0", "1e+21", "0.1").
template <class T>
void appendShortest(std::string& out, T value);

/// The name of T in messages: "float" or "double".
template <class T>
[[nodiscard]] const char* scalarName() noexcept;

/// A share of a whole (0 to 1) in percent, as reports write it: two significant digits, trailing
/// zeros dropped, never in exponent form ("45%", "5.2%", "5%", "0.16%", "0.0034%"). Only zero
/// reads "0%" and only one reads "100%": a share just short of one keeps the digits that tell
/// it apart ("99.97%", and ">99.999999%" within 5e-9 of one), and a nonzero share below 5e-9
/// reads "<0.000001%". NaN and shares below zero read "0%", shares above one "100%".
[[nodiscard]] std::string percentText(double share);

}  // namespace tilesweep::detail

// SPDX-License-Identifier: MIT
#include "tilesweep/scene/scalar_text.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <system_error>

namespace tilesweep::detail {
namespace {

[[nodiscard]] bool isDecimalDigit(char c) noexcept { return c >= '0' && c <= '9'; }

[[nodiscard]] bool isHexDigit(char c) noexcept {
    return isDecimalDigit(c) || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F');
}

[[nodiscard]] char toLower(char c) noexcept {
    return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
}

[[nodiscard]] bool equalsIgnoringCase(std::string_view a, std::string_view b) noexcept {
    if (a.size() != b.size()) return false;
    for (std::size_t k = 0; k < a.size(); ++k)
        if (toLower(a[k]) != toLower(b[k])) return false;
    return true;
}

// "nan", "inf", "infinity", "nan(...)", with an optional sign, in any case: the spellings that
// strtod would turn into a non-finite value. They are named as such in errors rather than as
// merely malformed, because a NaN that leaked out of a game is the likely story behind them.
[[nodiscard]] bool spellsNonFinite(std::string_view text) noexcept {
    if (!text.empty() && (text.front() == '-' || text.front() == '+')) text.remove_prefix(1);
    if (equalsIgnoringCase(text, "nan") || equalsIgnoringCase(text, "inf") ||
        equalsIgnoringCase(text, "infinity"))
        return true;
    return text.size() >= 5 && equalsIgnoringCase(text.substr(0, 4), "nan(") && text.back() == ')';
}

// std::from_chars reports result_out_of_range both when the value rounds to an infinity
// (an error here) and when it rounds to zero (a valid result: zero is the nearest value).
// The two cases lie at opposite ends of the range, beyond 2^128 and below 2^-149 for float,
// so it is enough to know whether the value is at least 1: that is, whether its leading nonzero
// digit, scaled by the exponent, sits at or above the units place. `text` is unsigned.
[[nodiscard]] bool isAtLeastOne(std::string_view text, bool hex) noexcept {
    const std::size_t expAt = text.find_first_of(hex ? "pP" : "eE");
    const std::string_view mantissa = text.substr(0, expAt);
    const std::size_t pointAt = mantissa.find('.');
    const auto intDigits =
        static_cast<long long>(pointAt == std::string_view::npos ? mantissa.size() : pointAt);

    long long lead = 0;  // the place value of the leading nonzero digit, as a power of the base
    bool nonzero = false;
    for (std::size_t k = 0; k < mantissa.size(); ++k) {
        if (mantissa[k] == '.' || mantissa[k] == '0') continue;
        const auto at = static_cast<long long>(k);
        lead = at < intDigits ? intDigits - 1 - at : intDigits - at;  // skips the point
        nonzero = true;
        break;
    }
    if (!nonzero) return false;

    long long exponent = 0;
    if (expAt != std::string_view::npos) {
        std::string_view digits = text.substr(expAt + 1);
        bool negative = false;
        if (!digits.empty() && (digits.front() == '+' || digits.front() == '-')) {
            negative = digits.front() == '-';
            digits.remove_prefix(1);
        }
        // Saturate: an exponent beyond a billion is out of range either way.
        for (char c : digits)
            if (exponent < 1000000000) exponent = exponent * 10 + (c - '0');
        if (negative) exponent = -exponent;
    }
    // A hex digit is 4 bits and the 'p' exponent is binary.
    return (hex ? 4 * lead : lead) + exponent >= 0;
}

// Runs from_chars on an unsigned number text and applies the sign afterwards: negation is
// exact, so the result is still rounded once.
template <class T>
[[nodiscard]] ScalarText<T> readUnsigned(std::string_view text, bool negative, std::chars_format format) {
    ScalarText<T> result;
    T magnitude = 0;
    const char* const end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, magnitude, format);
    if (ptr != end || text.empty()) return result;  // Malformed
    if (ec == std::errc::result_out_of_range) {
        if (isAtLeastOne(text, format == std::chars_format::hex)) {
            result.status = ScalarTextStatus::Overflow;
            return result;
        }
        magnitude = 0;  // underflow: zero is the nearest value
    } else if (ec != std::errc()) {
        return result;
    }
    result.value = negative ? -magnitude : magnitude;
    result.status = ScalarTextStatus::Ok;
    return result;
}

[[nodiscard]] bool isHexfloatSyntax(std::string_view body) noexcept {
    // body follows the "0x": <hex>*[.<hex>*] with at least one hex digit, then p[+-]<dec>+.
    std::size_t k = 0;
    std::size_t mantissaDigits = 0;
    while (k < body.size() && isHexDigit(body[k])) ++k, ++mantissaDigits;
    if (k < body.size() && body[k] == '.') {
        ++k;
        while (k < body.size() && isHexDigit(body[k])) ++k, ++mantissaDigits;
    }
    if (mantissaDigits == 0 || k == body.size() || (body[k] != 'p' && body[k] != 'P')) return false;
    ++k;
    if (k < body.size() && (body[k] == '+' || body[k] == '-')) ++k;
    if (k == body.size()) return false;
    for (; k < body.size(); ++k)
        if (!isDecimalDigit(body[k])) return false;
    return true;
}

}  // namespace

template <class T>
ScalarText<T> readDecimalScalar(std::string_view lexeme) {
    const bool negative = !lexeme.empty() && lexeme.front() == '-';
    if (negative) lexeme.remove_prefix(1);
    // from_chars would also take "inf", "nan" and hex digits; a JSON lexeme starts with a digit.
    if (lexeme.empty() || !isDecimalDigit(lexeme.front())) return {};
    return readUnsigned<T>(lexeme, negative, std::chars_format::general);
}

template <class T>
ScalarText<T> readHexfloatScalar(std::string_view text) {
    if (spellsNonFinite(text)) return {T(0), ScalarTextStatus::NonFinite};
    const bool negative = !text.empty() && text.front() == '-';
    if (negative) text.remove_prefix(1);
    if (text.size() < 2 || text[0] != '0' || (text[1] != 'x' && text[1] != 'X')) return {};
    text.remove_prefix(2);
    if (!isHexfloatSyntax(text)) return {};
    return readUnsigned<T>(text, negative, std::chars_format::hex);
}

void appendHexfloat(std::string& out, double value) {
    if (!std::isfinite(value)) throw std::invalid_argument("cannot write a non-finite value");
    // to_chars writes what glibc's "%a" writes after the "0x" ("1.8p+3", "0p+0",
    // "0.0000000000001p-1022"), without reading the locale's decimal point.
    if (std::signbit(value)) {
        out += '-';
        value = -value;
    }
    out += "0x";
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::hex);
    out.append(buffer, result.ptr);
}

template <class T>
void appendShortest(std::string& out, T value) {
    if (!std::isfinite(value)) throw std::invalid_argument("cannot write a non-finite value");
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.append(buffer, result.ptr);
}

template <>
const char* scalarName<float>() noexcept {
    return "float";
}
template <>
const char* scalarName<double>() noexcept {
    return "double";
}

std::string percentText(double share) {
    if (!(share > 0)) return "0%";
    if (share >= 1) return "100%";
    constexpr int kMostDecimals = 6;
    const double percent = 100 * share;
    // Two significant digits: one decimal more than the place of the leading digit's.
    int decimals = std::clamp(1 - static_cast<int>(std::floor(std::log10(percent))), 0, kMostDecimals);
    char buffer[32];
    std::string text;
    for (;; ++decimals) {
        const auto result =
            std::to_chars(buffer, buffer + sizeof buffer, percent, std::chars_format::fixed, decimals);
        text.assign(buffer, result.ptr);
        // Below one, rounding can only reach 100 from beneath: more digits, up to the most.
        if (text.compare(0, 3, "100") != 0 || decimals == kMostDecimals) break;
    }
    if (text.compare(0, 3, "100") == 0) return ">99.999999%";
    if (text.find_first_not_of("0.") == std::string::npos) return "<0.000001%";
    if (text.find('.') != std::string::npos) {
        text.erase(text.find_last_not_of('0') + 1);
        if (text.back() == '.') text.pop_back();
    }
    return text + '%';
}

template ScalarText<float> readDecimalScalar<float>(std::string_view);
template ScalarText<double> readDecimalScalar<double>(std::string_view);
template ScalarText<float> readHexfloatScalar<float>(std::string_view);
template ScalarText<double> readHexfloatScalar<double>(std::string_view);
template void appendShortest<float>(std::string&, float);
template void appendShortest<double>(std::string&, double);

}  // namespace tilesweep::detail

// SPDX-License-Identifier: MIT
// Writing SVG (svg_writer.h).
#include "svg_writer.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>

namespace tilesweep::detail {

// ---- text ----------------------------------------------------------------------------------

/// Appends a pixel coordinate with two decimals (a hundredth of a pixel is invisible), trailing
/// zeros dropped. Non-finite or absurd values cannot come from a finite scene; they are clamped
/// so that the document stays valid whatever a foreign resolver returned.
void appendPx(std::string& out, Real value) {
    double v = static_cast<double>(value);
    if (!std::isfinite(v)) v = 0;
    v = std::clamp(v, -static_cast<double>(kMaxPx), static_cast<double>(kMaxPx));
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::fixed, 2);
    std::string_view text(buffer, static_cast<std::size_t>(result.ptr - buffer));
    if (text.find('.') != std::string_view::npos) {
        while (text.back() == '0') text.remove_suffix(1);
        if (text.back() == '.') text.remove_suffix(1);
    }
    if (text == "-0") text = "0";
    out += text;
}

[[nodiscard]] std::string px(Real value) {
    std::string out;
    appendPx(out, value);
    return out;
}

/// Appends text as XML character data or attribute content. Markup characters are escaped;
/// bytes that are not well-formed UTF-8 become U+FFFD and control characters a space, because
/// XML 1.0 forbids them and a scene name may carry either (JSON allows "\u0001").
void appendXmlText(std::string& out, std::string_view text, std::size_t maxCodePoints) {
    std::size_t codePoints = 0;
    std::size_t k = 0;
    while (k < text.size()) {
        if (codePoints == maxCodePoints) {
            out += "\u2026";
            return;
        }
        ++codePoints;
        const auto lead = static_cast<unsigned char>(text[k]);
        if (lead < 0x80) {
            switch (lead) {
                case '&':
                    out += "&amp;";
                    break;
                case '<':
                    out += "&lt;";
                    break;
                case '>':
                    out += "&gt;";
                    break;
                case '"':
                    out += "&quot;";
                    break;
                case '\'':
                    out += "&apos;";
                    break;
                default:
                    out += (lead < 0x20 || lead == 0x7f) ? ' ' : static_cast<char>(lead);
            }
            ++k;
            continue;
        }
        // The length and the smallest code point a lead byte allows (overlong forms are refused).
        std::size_t length = 0;
        std::uint32_t codePoint = 0;
        std::uint32_t minimum = 0;
        if (lead >= 0xc2 && lead <= 0xdf) {
            length = 2;
            codePoint = lead & 0x1fu;
            minimum = 0x80;
        } else if (lead >= 0xe0 && lead <= 0xef) {
            length = 3;
            codePoint = lead & 0x0fu;
            minimum = 0x800;
        } else if (lead >= 0xf0 && lead <= 0xf4) {
            length = 4;
            codePoint = lead & 0x07u;
            minimum = 0x10000;
        }
        bool wellFormed = length != 0 && k + length <= text.size();
        for (std::size_t m = 1; wellFormed && m < length; ++m) {
            const auto next = static_cast<unsigned char>(text[k + m]);
            wellFormed = (next & 0xc0u) == 0x80u;
            codePoint = (codePoint << 6) | (next & 0x3fu);
        }
        // Surrogates, U+FFFE, U+FFFF and C1 controls are not XML characters either.
        const bool allowed = wellFormed && codePoint >= minimum && codePoint <= 0x10ffff &&
                             !(codePoint >= 0xd800 && codePoint <= 0xdfff) && codePoint != 0xfffe &&
                             codePoint != 0xffff && !(codePoint >= 0x80 && codePoint <= 0x9f);
        if (allowed) out.append(text.substr(k, length));
        if (!allowed) out += "\uFFFD";
        // A well-formed sequence is one character even when it is not allowed; a broken one is
        // replaced byte by byte, so that the bytes after it are read afresh.
        k += wellFormed ? length : 1;
    }
}

[[nodiscard]] std::size_t countCodePoints(std::string_view text) {
    std::size_t count = 0;
    for (const char c : text)
        if ((static_cast<unsigned char>(c) & 0xc0u) != 0x80u) ++count;
    return count;
}

// ---- SVG elements --------------------------------------------------------------------------

void appendRect(std::string& out, Real x, Real y, Real width, Real height, std::string_view attributes) {
    out += "<rect x=\"" + px(x) + "\" y=\"" + px(y) + "\" width=\"" + px(std::max(width, Real(0))) +
           "\" height=\"" + px(std::max(height, Real(0))) + "\" ";
    out += attributes;
    out += "/>\n";
}

void appendLine(std::string& out, Real x0, Real y0, Real x1, Real y1, std::string_view attributes) {
    out += "<line x1=\"" + px(x0) + "\" y1=\"" + px(y0) + "\" x2=\"" + px(x1) + "\" y2=\"" + px(y1) + "\" ";
    out += attributes;
    out += "/>\n";
}

void appendCircle(std::string& out, Real cx, Real cy, Real r, std::string_view attributes) {
    out += "<circle cx=\"" + px(cx) + "\" cy=\"" + px(cy) + "\" r=\"" + px(r) + "\" ";
    out += attributes;
    out += "/>\n";
}

/// A text element; `anchor` is start, middle or end, `style` the remaining attributes.
void appendText(std::string& out, Real x, Real y, std::string_view text, std::string_view anchor,
                std::string_view style) {
    out += "<text x=\"" + px(x) + "\" y=\"" + px(y) + "\" text-anchor=\"";
    out += anchor;
    out += "\" ";
    out += style;
    out += ">";
    appendXmlText(out, text);
    out += "</text>\n";
}

/// An arrow from (x, y) along the unit direction (dx, dy), `length` pixels long, head included.
void appendArrowShape(std::string& out, Real x, Real y, Real dx, Real dy, Real length,
                      std::string_view colour) {
    constexpr Real kHead = 9;
    const Real tipX = x + dx * length;
    const Real tipY = y + dy * length;
    const Real baseX = tipX - dx * kHead;
    const Real baseY = tipY - dy * kHead;
    const std::string stroke =
        "stroke=\"" + std::string(colour) + "\" stroke-width=\"2.5\" stroke-linecap=\"round\"";
    appendLine(out, x, y, baseX, baseY, stroke);
    // The head: the tip and two corners on either side of the shaft, half a head wide.
    out += "<polygon points=\"" + px(tipX) + "," + px(tipY) + " " + px(baseX - dy * kHead * 0.5L) + "," +
           px(baseY + dx * kHead * 0.5L) + " " + px(baseX + dy * kHead * 0.5L) + "," +
           px(baseY - dx * kHead * 0.5L) + "\" fill=\"" + std::string(colour) + "\"/>\n";
}

}  // namespace tilesweep::detail

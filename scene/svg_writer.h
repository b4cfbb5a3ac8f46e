// SPDX-License-Identifier: MIT
#pragma once
// Writing SVG: numbers as pixel coordinates, XML-safe text, and the few elements the scene
// renderer draws with (rect, line, circle, text, arrow). Knows nothing about scenes.

#include <cstddef>
#include <limits>
#include <string>
#include <string_view>

namespace tilesweep::detail {

// Coordinates are long double: see render_layout.h.
using Real = long double;

inline constexpr Real kMaxPx = 1e7L;  // printed coordinates are clamped to this, see appendPx

// ---- text ----------------------------------------------------------------------------------

/// Appends a pixel coordinate with two decimals (a hundredth of a pixel is invisible), trailing
/// zeros dropped. Non-finite or absurd values cannot come from a finite scene; they are clamped
/// so that the document stays valid whatever a foreign resolver returned.
void appendPx(std::string& out, Real value);

[[nodiscard]] std::string px(Real value);

/// Appends text as XML character data or attribute content. Markup characters are escaped;
/// bytes that are not well-formed UTF-8 become U+FFFD and control characters a space, because
/// XML 1.0 forbids them and a scene name may carry either (JSON allows "\u0001").
void appendXmlText(std::string& out, std::string_view text,
                   std::size_t maxCodePoints = std::numeric_limits<std::size_t>::max());

[[nodiscard]] std::size_t countCodePoints(std::string_view text);

// ---- SVG elements --------------------------------------------------------------------------

void appendRect(std::string& out, Real x, Real y, Real width, Real height, std::string_view attributes);

void appendLine(std::string& out, Real x0, Real y0, Real x1, Real y1, std::string_view attributes);

void appendCircle(std::string& out, Real cx, Real cy, Real r, std::string_view attributes);

/// A text element; `anchor` is start, middle or end, `style` the remaining attributes.
void appendText(std::string& out, Real x, Real y, std::string_view text, std::string_view anchor,
                std::string_view style);

/// An arrow from (x, y) along the unit direction (dx, dy), `length` pixels long, head included.
void appendArrowShape(std::string& out, Real x, Real y, Real dx, Real dy, Real length,
                      std::string_view colour);

}  // namespace tilesweep::detail

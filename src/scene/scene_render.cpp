// SPDX-License-Identifier: MIT
// Drawing a scene and its resolved frames as a self-contained SVG document (render.h).
#include "tilesweep/render.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <vector>

namespace tilesweep {
namespace {

// Every world coordinate is taken relative to the map origin in long double before it is
// scaled: at an origin of 2^40 a float or double box is still exact there (64-bit significand),
// whereas scaling absolute coordinates would lose the box's size to cancellation.
using Real = long double;

// ---- layout, in SVG pixels -----------------------------------------------------------------

constexpr Real kDrawWidth = 880;  // the map and the motion are scaled to fit this box
constexpr Real kDrawHeight = 520;
constexpr Real kPad = 40;              // around the drawing: room for indices and arrows
constexpr Real kHeaderHeight = 60;     // title and caption
constexpr Real kMinCanvasWidth = 700;  // so that the legend and the listing fit
constexpr Real kMaxPx = 1e7L;          // printed coordinates are clamped to this, see appendPx
constexpr Real kMinGridSpacing = 4;    // below this a grid is grey noise, so it is left out
constexpr Real kLegendColumnWidth = 240;
constexpr Real kLegendRowHeight = 20;
constexpr Real kListingLineHeight = 15;
// Rough glyph advances, to size the canvas around text (there is no font metrics in SVG).
constexpr Real kTitleCharWidth = 10;     // 17px bold sans-serif
constexpr Real kCaptionCharWidth = 6.9L; // 12px sans-serif
constexpr Real kListingCharWidth = 6.7L; // 11px monospace

// Past this many frames the picture switches to its compact form: frame ends in between become
// dots, and the per-frame extras (requested motion, box at contact) are left out.
constexpr std::size_t kMaxFramesDrawnInFull = 8;
// The listing shows every frame up to this many, else the first and the last few.
constexpr std::size_t kMaxListedFrames = 12;
constexpr std::size_t kMaxListedContacts = 3;  // per frame
constexpr std::size_t kMaxTitleCodePoints = 120;

// Colours: boxes blue, contacts red, started-overlapping amber, path near-black.
constexpr const char* kInk = "#1b1f24";
constexpr const char* kMuted = "#6e7781";
constexpr const char* kBoxBlue = "#1f6feb";
constexpr const char* kBoxDark = "#0a3069";
constexpr const char* kContactRed = "#cf222e";
constexpr const char* kTileFill = "#8c959f";
constexpr const char* kTileStroke = "#57606a";
constexpr const char* kMapFill = "#f6f8fa";
constexpr const char* kGrid = "#d0d7de";
constexpr const char* kOverlapStroke = "#bf8700";
constexpr const char* kFont = "font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\"";
constexpr const char* kMonoFont = "font-family=\"DejaVu Sans Mono, Menlo, Consolas, monospace\"";
// A white outline under label text keeps it readable over tiles and lines.
constexpr const char* kHalo =
    "stroke=\"#ffffff\" stroke-width=\"3\" stroke-linejoin=\"round\" paint-order=\"stroke\"";

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

/// A scene number for people: six significant digits, but every integer digit and two decimals
/// for large values, so that positions near a far origin (1000003.25) stay distinguishable.
template <class T>
[[nodiscard]] std::string formatNumber(T value) {
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    const double v = static_cast<double>(value);
    int precision = 6;
    const double magnitude = std::fabs(v);
    if (magnitude >= 1e5) {
        const int integerDigits = static_cast<int>(std::floor(std::log10(magnitude))) + 1;
        precision = std::min(integerDigits + 2, std::numeric_limits<T>::max_digits10);
    }
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*g", precision, v);
    return buffer;
}

template <class T>
[[nodiscard]] std::string formatPair(T a, T b) {
    return "(" + formatNumber(a) + ", " + formatNumber(b) + ")";
}

[[nodiscard]] std::string formatCell(Cell cell) {
    return "[" + std::to_string(cell.i) + "," + std::to_string(cell.j) + "]";
}

/// Appends text as XML character data or attribute content. Markup characters are escaped;
/// bytes that are not well-formed UTF-8 become U+FFFD and control characters a space, because
/// XML 1.0 forbids them and a scene name may carry either (JSON allows "\u0001").
void appendXmlText(std::string& out, std::string_view text,
                   std::size_t maxCodePoints = std::numeric_limits<std::size_t>::max()) {
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

// ---- geometry ------------------------------------------------------------------------------

/// A rectangle in map-relative world units.
struct Rect {
    Real x0, y0, x1, y1;
};

struct Bounds {
    Real minX = std::numeric_limits<Real>::infinity();
    Real minY = std::numeric_limits<Real>::infinity();
    Real maxX = -std::numeric_limits<Real>::infinity();
    Real maxY = -std::numeric_limits<Real>::infinity();

    void add(const Rect& r) {
        if (!std::isfinite(r.x0) || !std::isfinite(r.y0) || !std::isfinite(r.x1) || !std::isfinite(r.y1))
            return;
        minX = std::min(minX, r.x0);
        minY = std::min(minY, r.y0);
        maxX = std::max(maxX, r.x1);
        maxY = std::max(maxY, r.y1);
    }
};

/// World (map-relative) to SVG pixels: a uniform scale and a translation; y down in both.
struct View {
    Real minX = 0;
    Real minY = 0;
    Real scale = 1;
    Real left = 0;   ///< pixel x of minX
    Real top = 0;    ///< pixel y of minY
    Real width = 0;  ///< pixel size of the world bounds
    Real height = 0;

    [[nodiscard]] Real x(Real worldX) const { return left + (worldX - minX) * scale; }
    [[nodiscard]] Real y(Real worldY) const { return top + (worldY - minY) * scale; }
};

/// Where the box stood when a group of contacts (all at one frame time) happened.
struct Stop {
    Real x, y;          ///< box top-left, map-relative
    std::size_t first;  ///< index of the group's first contact in the frame's list
    std::size_t count;
};

/// One frame, map-relative, ready to draw.
struct FramePlan {
    Real startX, startY;
    Real moveX, moveY;
    Real endX, endY;
    bool endFinite;
    std::vector<Stop> stops;
};

[[nodiscard]] bool isFinitePoint(Real x, Real y) { return std::isfinite(x) && std::isfinite(y); }

/// The box positions at a frame's contacts. Contacts are listed step by step, so consecutive
/// contacts with equal frame times form one group. At a group's time t the box is, on each axis
/// still moving, at start + t*move (the resolver's motion is linear in frame time on a free
/// axis, in both steps); on an axis zeroed by an earlier group it stays where that group left
/// it; on the group's own contact axes it touches the face that was hit, which is computed
/// exactly from the tile instead of from t. The free-axis value is approximate only by the
/// rounding of t (half an ulp of a number below 1), far below a pixel. A step-2 contact at the
/// same frame time as step 1 joins step 1's group, which is harmless: the box has not moved in
/// between, so both groups stand at the same position.
template <class T>
[[nodiscard]] std::vector<Stop> planStops(const TileMap<T>& map, Real w, Real h, Real startX, Real startY,
                                          Real moveX, Real moveY, const std::vector<Contact<T>>& contacts) {
    std::vector<Stop> stops;
    const auto tw = static_cast<Real>(map.tileSize.x);
    const auto th = static_cast<Real>(map.tileSize.y);
    bool heldX = false;
    bool heldY = false;
    Real x = startX;
    Real y = startY;
    std::size_t k = 0;
    while (k < contacts.size()) {
        const T time = contacts[k].time;
        std::size_t end = k + 1;
        while (end < contacts.size() && contacts[end].time == time) ++end;
        if (!std::isfinite(time)) {
            k = end;
            continue;
        }
        const auto t = static_cast<Real>(time);
        if (!heldX) x = startX + t * moveX;
        if (!heldY) y = startY + t * moveY;
        for (std::size_t m = k; m < end; ++m) {
            const Contact<T>& c = contacts[m];
            const auto i = static_cast<Real>(c.tile.i);
            const auto j = static_cast<Real>(c.tile.j);
            if (c.normal.x != 0) {
                x = c.normal.x < 0 ? i * tw - w : (i + 1) * tw;
                heldX = true;
            }
            if (c.normal.y != 0) {
                y = c.normal.y < 0 ? j * th - h : (j + 1) * th;
                heldY = true;
            }
        }
        stops.push_back({x, y, k, end - k});
        k = end;
    }
    return stops;
}

/// Clips the segment from (x0, y0), which lies in the rectangle, toward (x1, y1) to the
/// rectangle (Liang-Barsky); returns the fraction of the segment kept, in [0, 1].
[[nodiscard]] Real clipFraction(Real x0, Real y0, Real x1, Real y1, const Rect& r) {
    Real keep = 1;
    const Real dx = x1 - x0;
    const Real dy = y1 - y0;
    if (dx > 0) keep = std::min(keep, (r.x1 - x0) / dx);
    if (dx < 0) keep = std::min(keep, (r.x0 - x0) / dx);
    if (dy > 0) keep = std::min(keep, (r.y1 - y0) / dy);
    if (dy < 0) keep = std::min(keep, (r.y0 - y0) / dy);
    return std::clamp(keep, Real(0), Real(1));
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

/// Index labels every `step` cells, step one of 1, 2, 5, 10, 20, 50, ..., the smallest that
/// leaves `needed` pixels per label at `spacing` pixels per cell.
[[nodiscard]] std::int64_t labelStep(Real spacing, Real needed) {
    std::int64_t step = 1;
    for (int k = 0; spacing * static_cast<Real>(step) < needed && k < 60; ++k)
        step = (k % 3 == 1) ? step / 2 * 5 : step * 2;
    return step;
}

// ---- the document --------------------------------------------------------------------------

template <class T>
class Renderer {
public:
    Renderer(const Scene<T>& scene, const std::vector<FrameResult<T>>& frames)
        : scene_(scene), frames_(frames) {}

    std::string render() {
        plan();
        layout();
        out_.reserve(8192 + frames_.size() * 512 + scene_.map.solid.size() * 96);
        out_ += "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" + px(canvasWidth_) +
                "\" height=\"" + px(canvasHeight_) + "\" viewBox=\"0 0 " + px(canvasWidth_) + " " +
                px(canvasHeight_) + "\">\n";
        out_ += "<title>";
        appendXmlText(out_, title(), kMaxTitleCodePoints);
        out_ += "</title>\n";
        out_ +=
            "<desc>tilesweep scene: tiles, box at start and at each frame end, path, contacts "
            "and their normals; y grows downward</desc>\n";
        appendDefs();
        appendRect(out_, 0, 0, canvasWidth_, canvasHeight_, "fill=\"#ffffff\"");
        appendHeader();
        appendMap();
        appendTileMarks();
        appendMotion();
        appendContacts();
        appendBoxLabels();
        appendLegend();
        appendListing();
        out_ += "</svg>\n";
        return std::move(out_);
    }

private:
    // ---- planning: map-relative geometry and the view ----

    void plan() {
        const TileMap<T>& map = scene_.map;
        if (map.columns < 0 || map.rows < 0 ||
            map.solid.size() != static_cast<std::size_t>(map.columns) * static_cast<std::size_t>(map.rows))
            throw std::invalid_argument("renderSceneSvg: the map's cells do not match its size");
        if (frames_.size() != scene_.moves.size())
            throw std::invalid_argument("renderSceneSvg: " + std::to_string(frames_.size()) + " frames for " +
                                        std::to_string(scene_.moves.size()) + " moves");
        tw_ = static_cast<Real>(map.tileSize.x);
        th_ = static_cast<Real>(map.tileSize.y);
        w_ = static_cast<Real>(scene_.box.size.x);
        h_ = static_cast<Real>(scene_.box.size.y);

        Real x = relX(scene_.box.pos.x);
        Real y = relY(scene_.box.pos.y);
        startX_ = x;
        startY_ = y;
        for (std::size_t k = 0; k < frames_.size(); ++k) {
            FramePlan frame;
            frame.startX = x;
            frame.startY = y;
            frame.moveX = static_cast<Real>(scene_.moves[k].x);
            frame.moveY = static_cast<Real>(scene_.moves[k].y);
            frame.endX = relX(frames_[k].position.x);
            frame.endY = relY(frames_[k].position.y);
            frame.endFinite = isFinitePoint(frame.endX, frame.endY);
            if (isFinitePoint(x, y))
                frame.stops = planStops(map, w_, h_, x, y, frame.moveX, frame.moveY, frames_[k].contacts);
            plans_.push_back(std::move(frame));
            x = plans_.back().endX;
            y = plans_.back().endY;
        }
    }

    void layout() {
        Bounds bounds;
        if (hasMap())
            bounds.add({0, 0, static_cast<Real>(scene_.map.columns) * tw_,
                        static_cast<Real>(scene_.map.rows) * th_});
        bounds.add(boxRect(startX_, startY_));
        for (std::size_t k = 0; k < plans_.size(); ++k) {
            const FramePlan& frame = plans_[k];
            if (frame.endFinite) bounds.add(boxRect(frame.endX, frame.endY));
            for (const Stop& stop : frame.stops) bounds.add(boxRect(stop.x, stop.y));
            // A foreign resolver may name cells outside the map; they must still be in view.
            for (const Contact<T>& c : frames_[k].contacts) bounds.add(cellRect(c.tile));
            for (const Cell& cell : frames_[k].startOverlaps) bounds.add(cellRect(cell));
        }
        if (!(bounds.maxX >= bounds.minX)) bounds = Bounds{0, 0, 1, 1};  // nothing finite at all
        Real extentX = bounds.maxX - bounds.minX;
        Real extentY = bounds.maxY - bounds.minY;
        // A box a few units wide next to a coordinate of 1e300 has no extent in long double;
        // give the view some size rather than divide by zero.
        if (!(extentX > 0)) extentX = extentY > 0 ? extentY : 1;
        if (!(extentY > 0)) extentY = extentX;
        view_.minX = bounds.minX;
        view_.minY = bounds.minY;
        view_.scale = std::min(kDrawWidth / extentX, kDrawHeight / extentY);
        view_.width = extentX * view_.scale;
        view_.height = extentY * view_.scale;

        // Canvas width: the drawing, or the text if that is wider.
        Real width = std::max(view_.width + 2 * kPad, kMinCanvasWidth);
        width = std::max(width, kTitleCharWidth * static_cast<Real>(std::min(countCodePoints(title()),
                                                                             kMaxTitleCodePoints + 1)) +
                                    32);
        width = std::max(width, kCaptionCharWidth * static_cast<Real>(countCodePoints(caption())) + 32);
        listing_ = listingLines();
        for (const std::string& line : listing_)
            width = std::max(width, kListingCharWidth * static_cast<Real>(countCodePoints(line)) + 32);
        canvasWidth_ = std::ceil(width);
        // Left-aligned like the legend and the listing, so that a longer text (a far origin
        // prints more digits) widens the canvas without moving the drawing.
        view_.left = kPad;
        view_.top = kHeaderHeight + kPad;

        legendTop_ = view_.top + view_.height + kPad + 8;
        const auto columns =
            std::max<std::size_t>(1, static_cast<std::size_t>((canvasWidth_ - 32) / kLegendColumnWidth));
        legendColumns_ = columns;
        const std::size_t legendRows = (kLegendItems + columns - 1) / columns;
        listingTop_ = legendTop_ + static_cast<Real>(legendRows) * kLegendRowHeight + 18;
        canvasHeight_ = std::ceil(listingTop_ + static_cast<Real>(listing_.size()) * kListingLineHeight + 8);
    }

    // ---- the parts of the picture ----

    void appendDefs() {
        // The hatch of started-overlapping cells; a pattern is internal, so the file stays
        // self-contained.
        out_ +=
            "<defs>\n<pattern id=\"tilesweep-hatch\" patternUnits=\"userSpaceOnUse\" width=\"7\" "
            "height=\"7\" patternTransform=\"rotate(45)\">\n"
            "<rect width=\"7\" height=\"7\" fill=\"#ffd33d\" fill-opacity=\"0.55\"/>\n"
            "<line x1=\"0\" y1=\"0\" x2=\"0\" y2=\"7\" stroke=\"";
        out_ += kOverlapStroke;
        out_ += "\" stroke-width=\"3\"/>\n</pattern>\n</defs>\n";
    }

    void appendHeader() {
        out_ += "<text x=\"16\" y=\"27\" font-size=\"17\" font-weight=\"bold\" ";
        out_ += kFont;
        out_ += " fill=\"";
        out_ += kInk;
        out_ += "\" class=\"title\">";
        appendXmlText(out_, title(), kMaxTitleCodePoints);
        out_ += "</text>\n";
        appendText(out_, 16, 47, caption(), "start",
                   std::string("font-size=\"12\" ") + kFont + " fill=\"" + kMuted + "\" class=\"caption\"");
    }

    void appendMap() {
        if (!hasMap()) {
            // Nothing to draw but the origin: mark it, so the view still says where the map is.
            const Real x = view_.x(0);
            const Real y = view_.y(0);
            if (x >= view_.left && x <= view_.left + view_.width && y >= view_.top &&
                y <= view_.top + view_.height) {
                const std::string stroke = std::string("stroke=\"") + kMuted + "\" stroke-width=\"1\"";
                appendLine(out_, x - 5, y, x + 5, y, stroke);
                appendLine(out_, x, y - 5, x, y + 5, stroke);
            }
            return;
        }
        const TileMap<T>& map = scene_.map;
        const Real cellW = tw_ * view_.scale;
        const Real cellH = th_ * view_.scale;
        const Real left = view_.x(0);
        const Real top = view_.y(0);
        const Real right = view_.x(static_cast<Real>(map.columns) * tw_);
        const Real bottom = view_.y(static_cast<Real>(map.rows) * th_);

        out_ += "<g class=\"map\">\n";
        appendRect(out_, left, top, right - left, bottom - top,
                   std::string("fill=\"") + kMapFill + "\" class=\"map-area\"");
        const std::string grid = std::string("stroke=\"") + kGrid + "\" stroke-width=\"1\"";
        if (cellW >= kMinGridSpacing)
            for (std::int32_t i = 1; i < map.columns; ++i)
                appendLine(out_, view_.x(static_cast<Real>(i) * tw_), top,
                           view_.x(static_cast<Real>(i) * tw_), bottom, grid);
        if (cellH >= kMinGridSpacing)
            for (std::int32_t j = 1; j < map.rows; ++j)
                appendLine(out_, left, view_.y(static_cast<Real>(j) * th_), right,
                           view_.y(static_cast<Real>(j) * th_), grid);

        const std::string tileStyle = std::string("fill=\"") + kTileFill + "\" stroke=\"" + kTileStroke +
                                      "\" stroke-width=\"1\" class=\"tile-solid\"";
        for (std::int32_t j = 0; j < map.rows; ++j) {
            for (std::int32_t i = 0; i < map.columns; ++i) {
                if (!map.solid[static_cast<std::size_t>(j) * static_cast<std::size_t>(map.columns) +
                               static_cast<std::size_t>(i)])
                    continue;
                appendRect(out_, view_.x(static_cast<Real>(i) * tw_), view_.y(static_cast<Real>(j) * th_),
                           cellW, cellH,
                           tileStyle + " data-cell=\"" + std::to_string(i) + "," + std::to_string(j) + "\"");
            }
        }
        appendRect(out_, left, top, right - left, bottom - top,
                   std::string("fill=\"none\" stroke=\"") + kTileStroke + "\" stroke-width=\"1.2\"");

        // Indices along the top and the left edge, so that a contact's [i, j] can be found.
        const std::string indexStyle = std::string("font-size=\"10\" ") + kFont + " fill=\"" + kMuted + "\"";
        const auto digits = static_cast<Real>(std::to_string(map.columns - 1).size());
        const std::int64_t stepI = labelStep(cellW, 6.5L * digits + 6);
        for (std::int64_t i = 0; i < map.columns; i += stepI)
            appendText(out_, view_.x((static_cast<Real>(i) + 0.5L) * tw_), top - 5, std::to_string(i),
                       "middle", indexStyle);
        const std::int64_t stepJ = labelStep(cellH, 13);
        for (std::int64_t j = 0; j < map.rows; j += stepJ)
            appendText(out_, left - 5, view_.y((static_cast<Real>(j) + 0.5L) * th_) + 3.5L, std::to_string(j),
                       "end", indexStyle);
        out_ += "</g>\n";
    }

    /// Started-overlapping hatches and hit-tile outlines, each cell once.
    void appendTileMarks() {
        std::set<std::pair<std::int32_t, std::int32_t>> overlapped;
        std::set<std::pair<std::int32_t, std::int32_t>> hit;
        for (const FrameResult<T>& frame : frames_) {
            for (const Cell& cell : frame.startOverlaps) overlapped.insert({cell.i, cell.j});
            for (const Contact<T>& c : frame.contacts) hit.insert({c.tile.i, c.tile.j});
        }
        for (const auto& [i, j] : overlapped) {
            const Rect r = cellRect({i, j});
            appendRect(out_, view_.x(r.x0), view_.y(r.y0), (r.x1 - r.x0) * view_.scale,
                       (r.y1 - r.y0) * view_.scale,
                       std::string("fill=\"url(#tilesweep-hatch)\" stroke=\"") + kOverlapStroke +
                           "\" stroke-width=\"2\" class=\"overlap-tile\" data-cell=\"" + std::to_string(i) +
                           "," + std::to_string(j) + "\"");
        }
        const Real cellW = tw_ * view_.scale;
        const Real cellH = th_ * view_.scale;
        for (const auto& [i, j] : hit) {
            const Rect r = cellRect({i, j});
            appendRect(out_, view_.x(r.x0) + 1.5L, view_.y(r.y0) + 1.5L, cellW - 3, cellH - 3,
                       std::string("fill=\"none\" stroke=\"") + kContactRed +
                           "\" stroke-width=\"3\" class=\"hit-tile\" data-cell=\"" + std::to_string(i) + "," +
                           std::to_string(j) + "\"");
            if (cellW >= 30 && cellH >= 16)
                appendText(
                    out_, view_.x(r.x0) + cellW / 2, view_.y(r.y0) + cellH - 5,
                    std::to_string(i) + "," + std::to_string(j), "middle",
                    std::string("font-size=\"10\" font-weight=\"bold\" ") + kFont + " fill=\"#ffffff\"");
        }
    }

    /// Requested motion, frame ends, boxes at contacts, the start box and the paths.
    void appendMotion() {
        const bool full = plans_.size() <= kMaxFramesDrawnInFull;
        const Rect viewRect{view_.left - kPad + 2, view_.top - kPad + 2, view_.left + view_.width + kPad - 2,
                            view_.top + view_.height + kPad - 2};

        // The motion each frame asked for, from the start centre to start + move, clipped to
        // the view: a blocked move into a distant wall must not shrink the picture.
        if (full) {
            for (const FramePlan& frame : plans_) {
                if (!isFinitePoint(frame.startX, frame.startY)) continue;
                const Real x0 = view_.x(frame.startX + w_ / 2);
                const Real y0 = view_.y(frame.startY + h_ / 2);
                const Real x1 = view_.x(frame.startX + frame.moveX + w_ / 2);
                const Real y1 = view_.y(frame.startY + frame.moveY + h_ / 2);
                if (std::hypot(x1 - x0, y1 - y0) < 1) continue;
                const Real keep = clipFraction(x0, y0, x1, y1, viewRect);
                const Real ex = x0 + (x1 - x0) * keep;
                const Real ey = y0 + (y1 - y0) * keep;
                appendLine(out_, x0, y0, ex, ey,
                           std::string("stroke=\"") + kMuted +
                               "\" stroke-width=\"1.2\" stroke-dasharray=\"2 3\" class=\"request\"");
                if (keep >= 1)
                    appendCircle(
                        out_, ex, ey, 3.5L,
                        std::string("fill=\"#ffffff\" stroke=\"") + kMuted + "\" stroke-width=\"1.2\"");
            }
        }

        // Frame ends, all but the last: boxes when few, else dots with the first one a box.
        const std::string boxStroke = std::string("stroke=\"") + kBoxBlue + "\"";
        for (std::size_t k = 0; k + 1 < plans_.size(); ++k) {
            const FramePlan& frame = plans_[k];
            if (!frame.endFinite) continue;
            const std::string data = " data-frame=\"" + std::to_string(k + 1) + "\"";
            if (full || k == 0) {
                appendBox(frame.endX, frame.endY,
                          "fill=\"" + std::string(kBoxBlue) + "\" fill-opacity=\"0.13\" " + boxStroke +
                              " stroke-opacity=\"0.6\" stroke-width=\"1\" class=\"frame-end box\"" + data);
            } else {
                appendCircle(out_, view_.x(frame.endX + w_ / 2), view_.y(frame.endY + h_ / 2), 2.2L,
                             "fill=\"" + std::string(kBoxBlue) + "\" class=\"frame-end dot\"" + data);
            }
        }

        // Where the box touched, when there are few frames to look at. A touch where the frame
        // starts or ends (a box already resting on a floor, a head-on stop) is drawn there already.
        if (full)
            for (const FramePlan& frame : plans_)
                for (const Stop& stop : frame.stops)
                    if (!(stop.x == frame.startX && stop.y == frame.startY) &&
                        !(stop.x == frame.endX && stop.y == frame.endY))
                        appendBox(
                            stop.x, stop.y,
                            "fill=\"none\" " + boxStroke +
                                " stroke-width=\"1.2\" stroke-dasharray=\"5 3\" class=\"box-at-contact\"");

        if (isFinitePoint(startX_, startY_))
            appendBox(startX_, startY_,
                      "fill=\"none\" " + boxStroke + " stroke-width=\"2\" class=\"box-start\"");

        if (!plans_.empty() && plans_.back().endFinite)
            appendBox(plans_.back().endX, plans_.back().endY,
                      "fill=\"" + std::string(kBoxBlue) + "\" fill-opacity=\"0.38\" stroke=\"" + kBoxDark +
                          "\" stroke-width=\"2.5\" class=\"frame-end box last\" data-frame=\"" +
                          std::to_string(plans_.size()) + "\"");

        // The path of the box centre: start, each contact position, end; one polyline a frame.
        for (std::size_t k = 0; k < plans_.size(); ++k) {
            const FramePlan& frame = plans_[k];
            if (!isFinitePoint(frame.startX, frame.startY) || !frame.endFinite) continue;
            std::string points;
            const auto addPoint = [&](Real x, Real y) {
                if (!points.empty()) points += ' ';
                points += px(view_.x(x + w_ / 2)) + "," + px(view_.y(y + h_ / 2));
            };
            addPoint(frame.startX, frame.startY);
            for (const Stop& stop : frame.stops) addPoint(stop.x, stop.y);
            addPoint(frame.endX, frame.endY);
            out_ += "<polyline points=\"" + points + "\" fill=\"none\" stroke=\"" + kInk +
                    "\" stroke-width=\"1.6\" stroke-linejoin=\"round\" class=\"path\" data-frame=\"" +
                    std::to_string(k + 1) + "\"/>\n";
            for (const Stop& stop : frame.stops)
                appendCircle(out_, view_.x(stop.x + w_ / 2), view_.y(stop.y + h_ / 2), 3,
                             std::string("fill=\"") + kContactRed + "\" class=\"contact-point\"");
        }
    }

    /// One arrow per distinct (tile, normal), from the middle of the touching part of the face.
    void appendContacts() {
        std::set<std::tuple<std::int32_t, std::int32_t, int, int>> drawn;
        const Real cellPx = std::min(tw_, th_) * view_.scale;
        const Real length = std::clamp(cellPx * 0.55L, Real(18), Real(34));
        for (std::size_t k = 0; k < plans_.size(); ++k) {
            for (const Stop& stop : plans_[k].stops) {
                for (std::size_t m = stop.first; m < stop.first + stop.count; ++m) {
                    const Contact<T>& c = frames_[k].contacts[m];
                    const int nx = c.normal.x;
                    const int ny = c.normal.y;
                    if ((nx == 0) == (ny == 0)) continue;  // not a unit axis normal: nothing to point
                    if (!drawn.insert({c.tile.i, c.tile.j, nx, ny}).second) continue;
                    const Rect tile = cellRect(c.tile);
                    Real ax = 0;
                    Real ay = 0;
                    if (nx != 0) {
                        ax = nx < 0 ? tile.x0 : tile.x1;
                        ay = middleOfOverlap(stop.y, stop.y + h_, tile.y0, tile.y1);
                    } else {
                        ay = ny < 0 ? tile.y0 : tile.y1;
                        ax = middleOfOverlap(stop.x, stop.x + w_, tile.x0, tile.x1);
                    }
                    out_ += "<g class=\"normal-arrow\" data-tile=\"" + std::to_string(c.tile.i) + "," +
                            std::to_string(c.tile.j) + "\" data-normal=\"" + std::to_string(nx) + "," +
                            std::to_string(ny) + "\">\n";
                    appendArrowShape(out_, view_.x(ax), view_.y(ay), static_cast<Real>(nx),
                                     static_cast<Real>(ny), length, kContactRed);
                    out_ += "</g>\n";
                }
            }
        }
    }

    /// "start" above the start box; "end k" below the frame ends that are drawn as boxes,
    /// consecutive equal positions sharing one label ("end 1-3").
    void appendBoxLabels() {
        const std::string style = std::string("font-size=\"11\" ") + kFont + " " + kHalo;
        if (isFinitePoint(startX_, startY_))
            appendText(out_, view_.x(startX_), view_.y(startY_) - 5, "start", "start",
                       style + " fill=\"" + kBoxBlue + "\" class=\"label\"");
        const bool full = plans_.size() <= kMaxFramesDrawnInFull;
        std::size_t k = 0;
        while (k < plans_.size()) {
            std::size_t end = k + 1;
            while (end < plans_.size() && plans_[end].endX == plans_[k].endX &&
                   plans_[end].endY == plans_[k].endY)
                ++end;
            const bool labelled = full || k == 0 || end == plans_.size();
            if (labelled && plans_[k].endFinite) {
                const std::string text = end - k == 1
                                             ? "end " + std::to_string(k + 1)
                                             : "end " + std::to_string(k + 1) + "-" + std::to_string(end);
                appendText(out_, view_.x(plans_[k].endX + w_), view_.y(plans_[k].endY + h_) + 13, text, "end",
                           style + " fill=\"" + kBoxDark + "\" class=\"label\"");
            }
            k = end;
        }
    }

    static constexpr std::size_t kLegendItems = 11;

    void appendLegend() {
        out_ += "<g class=\"legend\">\n";
        const std::string textStyle = std::string("font-size=\"12\" ") + kFont + " fill=\"" + kInk + "\"";
        for (std::size_t item = 0; item < kLegendItems; ++item) {
            const Real x = 16 + static_cast<Real>(item % legendColumns_) * kLegendColumnWidth;
            const Real y = legendTop_ + static_cast<Real>(item / legendColumns_) * kLegendRowHeight;
            appendLegendSwatch(item, x, y);
            appendText(out_, x + 34, y + 11, legendText(item), "start", textStyle);
        }
        out_ += "</g>\n";
    }

    /// The sample drawn for legend item `item`, in a 26 x 14 box at (x, y).
    void appendLegendSwatch(std::size_t item, Real x, Real y) {
        const std::string blue = kBoxBlue;
        switch (item) {
            case 0:
                appendRect(out_, x, y, 26, 14,
                           std::string("fill=\"") + kTileFill + "\" stroke=\"" + kTileStroke + "\"");
                break;
            case 1:
                appendRect(out_, x, y, 26, 14,
                           std::string("fill=\"") + kMapFill + "\" stroke=\"" + kGrid + "\"");
                appendLine(out_, x + 13, y, x + 13, y + 14, std::string("stroke=\"") + kGrid + "\"");
                break;
            case 2:
                appendRect(out_, x + 1, y + 1, 24, 12,
                           "fill=\"none\" stroke=\"" + blue + "\" stroke-width=\"2\"");
                break;
            case 3:
                appendRect(out_, x + 1, y + 1, 24, 12,
                           "fill=\"" + blue + "\" fill-opacity=\"0.13\" stroke=\"" + blue +
                               "\" stroke-opacity=\"0.6\"");
                appendCircle(out_, x + 13, y + 7, 2.2L, "fill=\"" + blue + "\"");
                break;
            case 4:
                appendRect(out_, x + 1, y + 1, 24, 12,
                           "fill=\"" + blue + "\" fill-opacity=\"0.38\" stroke=\"" + kBoxDark +
                               "\" stroke-width=\"2.5\"");
                break;
            case 5:
                appendRect(
                    out_, x + 1, y + 1, 24, 12,
                    "fill=\"none\" stroke=\"" + blue + "\" stroke-width=\"1.2\" stroke-dasharray=\"5 3\"");
                break;
            case 6:
                appendLine(out_, x, y + 7, x + 26, y + 7,
                           std::string("stroke=\"") + kInk + "\" stroke-width=\"1.6\"");
                appendCircle(out_, x + 13, y + 7, 3, std::string("fill=\"") + kContactRed + "\"");
                break;
            case 7:
                appendLine(
                    out_, x, y + 7, x + 22, y + 7,
                    std::string("stroke=\"") + kMuted + "\" stroke-width=\"1.2\" stroke-dasharray=\"2 3\"");
                appendCircle(out_, x + 22, y + 7, 3.5L,
                             std::string("fill=\"#ffffff\" stroke=\"") + kMuted + "\" stroke-width=\"1.2\"");
                break;
            case 8:
                appendRect(out_, x + 1.5L, y + 1.5L, 23, 11,
                           std::string("fill=\"") + kTileFill + "\" stroke=\"" + kContactRed +
                               "\" stroke-width=\"3\"");
                break;
            case 9:
                appendArrowShape(out_, x + 2, y + 7, 1, 0, 24, kContactRed);
                break;
            default:
                appendRect(out_, x, y, 26, 14,
                           std::string("fill=\"url(#tilesweep-hatch)\" stroke=\"") + kOverlapStroke +
                               "\" stroke-width=\"2\"");
                break;
        }
    }

    [[nodiscard]] std::string legendText(std::size_t item) const {
        switch (item) {
            case 0:
                return "solid tile";
            case 1:
                return "empty cell (grid)";
            case 2:
                return "box at the start";
            case 3:
                return "box at a frame end";
            case 4:
                return "box at the last frame end";
            case 5:
                return "box where it touched";
            case 6:
                return "path of the box centre, \u25CF contact";
            case 7:
                return "requested move (start + move)";
            case 8:
                return "tile hit";
            case 9:
                return "contact normal, from the face hit";
            default:
                return "started overlapping";
        }
    }

    void appendListing() {
        const std::string style = std::string("font-size=\"11\" ") + kMonoFont + " fill=\"" + kInk + "\"";
        out_ += "<g class=\"listing\">\n";
        Real y = listingTop_;
        for (const std::string& line : listing_) {
            appendText(out_, 16, y, line, "start", style);
            y += kListingLineHeight;
        }
        out_ += "</g>\n";
    }

    // ---- text content ----

    [[nodiscard]] std::string title() const {
        return scene_.name.empty() ? std::string("(unnamed scene)") : scene_.name;
    }

    [[nodiscard]] std::string caption() const {
        const TileMap<T>& map = scene_.map;
        std::size_t solid = 0;
        for (const std::uint8_t cell : map.solid) solid += cell != 0;
        std::string text = std::is_same_v<T, float> ? "float" : "double";
        text += " \u00B7 tile " + formatNumber(map.tileSize.x) + " \u00D7 " + formatNumber(map.tileSize.y) +
                ", origin " + formatPair(map.origin.x, map.origin.y) + " \u00B7 ";
        if (hasMap())
            text += "map " + std::to_string(map.columns) + " \u00D7 " + std::to_string(map.rows) +
                    " cells, " + std::to_string(solid) + " solid";
        else
            text += "empty map (no cells)";
        text += " \u00B7 box " + formatNumber(scene_.box.size.x) + " \u00D7 " +
                formatNumber(scene_.box.size.y) + " \u00B7 " + std::to_string(frames_.size()) +
                (frames_.size() == 1 ? " frame" : " frames") + " \u00B7 y grows downward";
        return text;
    }

    [[nodiscard]] std::vector<std::string> listingLines() const {
        std::vector<std::string> lines;
        lines.push_back("frame: start + move -> end; contacts: tile normal t (frame time)");
        const std::size_t count = frames_.size();
        const std::size_t head = count <= kMaxListedFrames ? count : kMaxListedFrames / 2;
        const std::size_t tail = count <= kMaxListedFrames ? 0 : kMaxListedFrames / 2 - 1;
        Vec2<T> start = scene_.box.pos;
        for (std::size_t k = 0; k < count; ++k) {
            if (k < head || k >= count - tail) lines.push_back(frameLine(k, start));
            if (k == head && tail != 0)
                lines.push_back("  ... " + std::to_string(count - head - tail) + " more frames ...");
            start = frames_[k].position;
        }
        return lines;
    }

    [[nodiscard]] std::string frameLine(std::size_t k, Vec2<T> start) const {
        const FrameResult<T>& frame = frames_[k];
        std::string line = std::to_string(k + 1) + ": " + formatPair(start.x, start.y) + " + " +
                           formatPair(scene_.moves[k].x, scene_.moves[k].y) + " -> " +
                           formatPair(frame.position.x, frame.position.y);
        if (frame.contacts.empty()) line += "; no contact";
        for (std::size_t m = 0; m < frame.contacts.size() && m < kMaxListedContacts; ++m) {
            const Contact<T>& c = frame.contacts[m];
            line += m == 0 ? "; hit " : ", ";
            line += formatCell(c.tile) + " n(" + std::to_string(c.normal.x) + "," +
                    std::to_string(c.normal.y) + ") t=" + formatNumber(c.time);
        }
        if (frame.contacts.size() > kMaxListedContacts)
            line += " +" + std::to_string(frame.contacts.size() - kMaxListedContacts) + " more";
        if (!frame.startOverlaps.empty()) {
            line += "; started overlapping";
            for (std::size_t m = 0; m < frame.startOverlaps.size() && m < kMaxListedContacts; ++m)
                line += " " + formatCell(frame.startOverlaps[m]);
            if (frame.startOverlaps.size() > kMaxListedContacts)
                line += " +" + std::to_string(frame.startOverlaps.size() - kMaxListedContacts) + " more";
        }
        return line;
    }

    // ---- small helpers ----

    [[nodiscard]] bool hasMap() const { return scene_.map.columns > 0 && scene_.map.rows > 0; }
    [[nodiscard]] Real relX(T x) const {
        return static_cast<Real>(x) - static_cast<Real>(scene_.map.origin.x);
    }
    [[nodiscard]] Real relY(T y) const {
        return static_cast<Real>(y) - static_cast<Real>(scene_.map.origin.y);
    }
    [[nodiscard]] Rect boxRect(Real x, Real y) const { return {x, y, x + w_, y + h_}; }
    [[nodiscard]] Rect cellRect(Cell cell) const {
        const auto i = static_cast<Real>(cell.i);
        const auto j = static_cast<Real>(cell.j);
        return {i * tw_, j * th_, (i + 1) * tw_, (j + 1) * th_};
    }

    /// The box drawn at (x, y), sized from w*scale so that cancellation near a far coordinate
    /// cannot collapse it.
    void appendBox(Real x, Real y, const std::string& attributes) {
        appendRect(out_, view_.x(x), view_.y(y), w_ * view_.scale, h_ * view_.scale, attributes);
    }

    /// The middle of [a0, a1] and [b0, b1]'s common part; at an exact corner touch that part is
    /// a point, and without one (a foreign resolver's contact) the tile face's middle.
    [[nodiscard]] static Real middleOfOverlap(Real a0, Real a1, Real b0, Real b1) {
        const Real lo = std::max(a0, b0);
        const Real hi = std::min(a1, b1);
        return lo <= hi ? (lo + hi) / 2 : (b0 + b1) / 2;
    }

    const Scene<T>& scene_;
    const std::vector<FrameResult<T>>& frames_;
    std::vector<FramePlan> plans_;
    std::vector<std::string> listing_;
    Real tw_ = 1, th_ = 1, w_ = 1, h_ = 1;
    Real startX_ = 0, startY_ = 0;
    View view_;
    Real canvasWidth_ = 0, canvasHeight_ = 0;
    Real legendTop_ = 0, listingTop_ = 0;
    std::size_t legendColumns_ = 1;
    std::string out_;
};

}  // namespace

template <class T>
std::string renderSceneSvg(const Scene<T>& scene, const std::vector<FrameResult<T>>& frames) {
    return Renderer<T>(scene, frames).render();
}

template std::string renderSceneSvg<float>(const Scene<float>&, const std::vector<FrameResult<float>>&);
template std::string renderSceneSvg<double>(const Scene<double>&, const std::vector<FrameResult<double>>&);

}  // namespace tilesweep

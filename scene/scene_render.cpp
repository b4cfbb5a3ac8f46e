// SPDX-License-Identifier: MIT
// What a scene picture shows (render.h): the map, the boxes, the path, the contacts, the legend
// and the listing, drawn on the layout of render_layout.h with the elements of svg_writer.h.
#include "render_layout.h"
#include "svg_writer.h"

#include "tilesweep/scene/render.h"

#include <algorithm>
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

using namespace detail;

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
// One-way tiles green: a slab at the cell's top (its only face) and a dashed outline of the cell.
constexpr const char* kOneWayFill = "#2da44e";
constexpr const char* kOneWayStroke = "#116329";
/// The slab's height, as a fraction of the cell's.
constexpr Real kOneWaySlab = 0.25L;
constexpr const char* kFont = "font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\"";
constexpr const char* kMonoFont = "font-family=\"DejaVu Sans Mono, Menlo, Consolas, monospace\"";
// A white outline under label text keeps it readable over tiles and lines.
constexpr const char* kHalo =
    "stroke=\"#ffffff\" stroke-width=\"3\" stroke-linejoin=\"round\" paint-order=\"stroke\"";

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

// ---- the document --------------------------------------------------------------------------

template <class T>
class Renderer {
public:
    Renderer(const Scene<T>& scene, const std::vector<FrameResult<T>>& frames)
        : scene_(scene), frames_(frames), layout_(scene, frames) {}

    std::string render() {
        listing_ = listingLines();
        layout_.fit(countCodePoints(title()), countCodePoints(caption()), listing_, legendItems());
        out_.reserve(8192 + frames_.size() * 512 + scene_.map.solid.size() * 96);
        out_ += "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" +
                px(layout_.canvasWidth) + "\" height=\"" + px(layout_.canvasHeight) + "\" viewBox=\"0 0 " +
                px(layout_.canvasWidth) + " " + px(layout_.canvasHeight) + "\">\n";
        out_ += "<title>";
        appendXmlText(out_, title(), kMaxTitleCodePoints);
        out_ += "</title>\n";
        out_ +=
            "<desc>tilesweep scene: tiles, box at start and at each frame end, path, contacts "
            "and their normals; y grows downward</desc>\n";
        appendDefs();
        appendRect(out_, 0, 0, layout_.canvasWidth, layout_.canvasHeight, "fill=\"#ffffff\"");
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
        if (!layout_.hasMap()) {
            // Nothing to draw but the origin: mark it, so the view still says where the map is.
            const Real x = layout_.view.x(0);
            const Real y = layout_.view.y(0);
            if (x >= layout_.view.left && x <= layout_.view.left + layout_.view.width &&
                y >= layout_.view.top && y <= layout_.view.top + layout_.view.height) {
                const std::string stroke = std::string("stroke=\"") + kMuted + "\" stroke-width=\"1\"";
                appendLine(out_, x - 5, y, x + 5, y, stroke);
                appendLine(out_, x, y - 5, x, y + 5, stroke);
            }
            return;
        }
        const TileMap<T>& map = scene_.map;
        const Real cellW = layout_.tw * layout_.view.scale;
        const Real cellH = layout_.th * layout_.view.scale;
        const Real left = layout_.view.x(0);
        const Real top = layout_.view.y(0);
        const Real right = layout_.view.x(static_cast<Real>(map.columns) * layout_.tw);
        const Real bottom = layout_.view.y(static_cast<Real>(map.rows) * layout_.th);

        out_ += "<g class=\"map\">\n";
        appendRect(out_, left, top, right - left, bottom - top,
                   std::string("fill=\"") + kMapFill + "\" class=\"map-area\"");
        const std::string grid = std::string("stroke=\"") + kGrid + "\" stroke-width=\"1\"";
        if (cellW >= kMinGridSpacing)
            for (std::int32_t i = 1; i < map.columns; ++i)
                appendLine(out_, layout_.view.x(static_cast<Real>(i) * layout_.tw), top,
                           layout_.view.x(static_cast<Real>(i) * layout_.tw), bottom, grid);
        if (cellH >= kMinGridSpacing)
            for (std::int32_t j = 1; j < map.rows; ++j)
                appendLine(out_, left, layout_.view.y(static_cast<Real>(j) * layout_.th), right,
                           layout_.view.y(static_cast<Real>(j) * layout_.th), grid);

        const std::string tileStyle = std::string("fill=\"") + kTileFill + "\" stroke=\"" + kTileStroke +
                                      "\" stroke-width=\"1\" class=\"tile-solid\"";
        for (std::int32_t j = 0; j < map.rows; ++j) {
            for (std::int32_t i = 0; i < map.columns; ++i) {
                if (!map.solid[static_cast<std::size_t>(j) * static_cast<std::size_t>(map.columns) +
                               static_cast<std::size_t>(i)])
                    continue;
                appendRect(out_, layout_.view.x(static_cast<Real>(i) * layout_.tw),
                           layout_.view.y(static_cast<Real>(j) * layout_.th), cellW, cellH,
                           tileStyle + " data-cell=\"" + std::to_string(i) + "," + std::to_string(j) + "\"");
            }
        }
        appendOneWayTiles(cellW, cellH);
        appendRect(out_, left, top, right - left, bottom - top,
                   std::string("fill=\"none\" stroke=\"") + kTileStroke + "\" stroke-width=\"1.2\"");

        // Indices along the top and the left edge, so that a contact's [i, j] can be found.
        const std::string indexStyle = std::string("font-size=\"10\" ") + kFont + " fill=\"" + kMuted + "\"";
        const auto digits = static_cast<Real>(std::to_string(map.columns - 1).size());
        const std::int64_t stepI = labelStep(cellW, 6.5L * digits + 6);
        for (std::int64_t i = 0; i < map.columns; i += stepI)
            appendText(out_, layout_.view.x((static_cast<Real>(i) + 0.5L) * layout_.tw), top - 5,
                       std::to_string(i), "middle", indexStyle);
        const std::int64_t stepJ = labelStep(cellH, 13);
        for (std::int64_t j = 0; j < map.rows; j += stepJ)
            appendText(out_, left - 5, layout_.view.y((static_cast<Real>(j) + 0.5L) * layout_.th) + 3.5L,
                       std::to_string(j), "end", indexStyle);
        out_ += "</g>\n";
    }

    /// One-way tiles, in their own style: a slab along the top face (`class="tile-one-way"`, one
    /// per cell) over a dashed outline of the rest of the cell (`class="one-way-outline"`).
    void appendOneWayTiles(Real cellW, Real cellH) {
        const TileMap<T>& map = scene_.map;
        if (!hasOneWay()) return;
        const std::string outlineStyle =
            std::string("fill=\"none\" stroke=\"") + kOneWayStroke +
            "\" stroke-width=\"1\" stroke-dasharray=\"3 2\" class=\"one-way-outline\"";
        const std::string slabStyle = std::string("fill=\"") + kOneWayFill + "\" stroke=\"" + kOneWayStroke +
                                      "\" stroke-width=\"1\" class=\"tile-one-way\"";
        const Real slab = std::min(std::max(cellH * kOneWaySlab, Real{1}), cellH);
        const TileMapView<T> view = map.view();
        for (std::int32_t j = 0; j < map.rows; ++j) {
            for (std::int32_t i = 0; i < map.columns; ++i) {
                if (view.kind(i, j) != CellKind::OneWay) continue;
                const std::string cell = " data-cell=\"" + std::to_string(i) + "," + std::to_string(j) + "\"";
                const Real x = layout_.view.x(static_cast<Real>(i) * layout_.tw);
                const Real y = layout_.view.y(static_cast<Real>(j) * layout_.th);
                appendRect(out_, x, y, cellW, cellH, outlineStyle + cell);
                appendRect(out_, x, y, cellW, slab, slabStyle + cell);
            }
        }
    }

    /// True when the map holds a one-way cell: only then does the legend show one.
    [[nodiscard]] bool hasOneWay() const {
        const TileMap<T>& map = scene_.map;
        for (std::size_t k = 0; k < map.oneWay.size(); ++k)
            if (map.oneWay[k] != 0 && map.solid[k] == 0) return true;
        return false;
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
            const Rect r = layout_.cellRect({i, j});
            appendRect(out_, layout_.view.x(r.x0), layout_.view.y(r.y0), (r.x1 - r.x0) * layout_.view.scale,
                       (r.y1 - r.y0) * layout_.view.scale,
                       std::string("fill=\"url(#tilesweep-hatch)\" stroke=\"") + kOverlapStroke +
                           "\" stroke-width=\"2\" class=\"overlap-tile\" data-cell=\"" + std::to_string(i) +
                           "," + std::to_string(j) + "\"");
        }
        const Real cellW = layout_.tw * layout_.view.scale;
        const Real cellH = layout_.th * layout_.view.scale;
        for (const auto& [i, j] : hit) {
            const Rect r = layout_.cellRect({i, j});
            appendRect(out_, layout_.view.x(r.x0) + 1.5L, layout_.view.y(r.y0) + 1.5L, cellW - 3, cellH - 3,
                       std::string("fill=\"none\" stroke=\"") + kContactRed +
                           "\" stroke-width=\"3\" class=\"hit-tile\" data-cell=\"" + std::to_string(i) + "," +
                           std::to_string(j) + "\"");
            if (cellW >= 30 && cellH >= 16)
                appendText(
                    out_, layout_.view.x(r.x0) + cellW / 2, layout_.view.y(r.y0) + cellH - 5,
                    std::to_string(i) + "," + std::to_string(j), "middle",
                    std::string("font-size=\"10\" font-weight=\"bold\" ") + kFont + " fill=\"#ffffff\"");
        }
    }

    /// Requested motion, frame ends, boxes at contacts, the start box and the paths.
    void appendMotion() {
        const bool full = layout_.plans.size() <= kMaxFramesDrawnInFull;
        const Rect viewRect{layout_.view.left - kPad + 2, layout_.view.top - kPad + 2,
                            layout_.view.left + layout_.view.width + kPad - 2,
                            layout_.view.top + layout_.view.height + kPad - 2};

        // The motion each frame asked for, from the start centre to start + move, clipped to
        // the view: a blocked move into a distant wall must not shrink the picture.
        if (full) {
            for (const FramePlan& frame : layout_.plans) {
                if (!isFinitePoint(frame.startX, frame.startY)) continue;
                const Real x0 = layout_.view.x(frame.startX + layout_.w / 2);
                const Real y0 = layout_.view.y(frame.startY + layout_.h / 2);
                const Real x1 = layout_.view.x(frame.startX + frame.moveX + layout_.w / 2);
                const Real y1 = layout_.view.y(frame.startY + frame.moveY + layout_.h / 2);
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
        for (std::size_t k = 0; k + 1 < layout_.plans.size(); ++k) {
            const FramePlan& frame = layout_.plans[k];
            if (!frame.endFinite) continue;
            const std::string data = " data-frame=\"" + std::to_string(k + 1) + "\"";
            if (full || k == 0) {
                appendBox(frame.endX, frame.endY,
                          "fill=\"" + std::string(kBoxBlue) + "\" fill-opacity=\"0.13\" " + boxStroke +
                              " stroke-opacity=\"0.6\" stroke-width=\"1\" class=\"frame-end box\"" + data);
            } else {
                appendCircle(out_, layout_.view.x(frame.endX + layout_.w / 2),
                             layout_.view.y(frame.endY + layout_.h / 2), 2.2L,
                             "fill=\"" + std::string(kBoxBlue) + "\" class=\"frame-end dot\"" + data);
            }
        }

        // Where the box touched, when there are few frames to look at. A touch where the frame
        // starts or ends (a box already resting on a floor, a head-on stop) is drawn there already.
        if (full)
            for (const FramePlan& frame : layout_.plans)
                for (const Stop& stop : frame.stops)
                    if (!(stop.x == frame.startX && stop.y == frame.startY) &&
                        !(stop.x == frame.endX && stop.y == frame.endY))
                        appendBox(
                            stop.x, stop.y,
                            "fill=\"none\" " + boxStroke +
                                " stroke-width=\"1.2\" stroke-dasharray=\"5 3\" class=\"box-at-contact\"");

        if (isFinitePoint(layout_.startX, layout_.startY))
            appendBox(layout_.startX, layout_.startY,
                      "fill=\"none\" " + boxStroke + " stroke-width=\"2\" class=\"box-start\"");

        if (!layout_.plans.empty() && layout_.plans.back().endFinite)
            appendBox(layout_.plans.back().endX, layout_.plans.back().endY,
                      "fill=\"" + std::string(kBoxBlue) + "\" fill-opacity=\"0.38\" stroke=\"" + kBoxDark +
                          "\" stroke-width=\"2.5\" class=\"frame-end box last\" data-frame=\"" +
                          std::to_string(layout_.plans.size()) + "\"");

        // The path of the box centre: start, each contact position, end; one polyline a frame.
        for (std::size_t k = 0; k < layout_.plans.size(); ++k) {
            const FramePlan& frame = layout_.plans[k];
            if (!isFinitePoint(frame.startX, frame.startY) || !frame.endFinite) continue;
            std::string points;
            const auto addPoint = [&](Real x, Real y) {
                if (!points.empty()) points += ' ';
                points += px(layout_.view.x(x + layout_.w / 2)) + "," + px(layout_.view.y(y + layout_.h / 2));
            };
            addPoint(frame.startX, frame.startY);
            for (const Stop& stop : frame.stops) addPoint(stop.x, stop.y);
            addPoint(frame.endX, frame.endY);
            out_ += "<polyline points=\"" + points + "\" fill=\"none\" stroke=\"" + kInk +
                    "\" stroke-width=\"1.6\" stroke-linejoin=\"round\" class=\"path\" data-frame=\"" +
                    std::to_string(k + 1) + "\"/>\n";
            for (const Stop& stop : frame.stops)
                appendCircle(out_, layout_.view.x(stop.x + layout_.w / 2),
                             layout_.view.y(stop.y + layout_.h / 2), 3,
                             std::string("fill=\"") + kContactRed + "\" class=\"contact-point\"");
        }
    }

    /// One arrow per distinct (tile, normal), from the middle of the touching part of the face.
    void appendContacts() {
        std::set<std::tuple<std::int32_t, std::int32_t, int, int>> drawn;
        const Real cellPx = std::min(layout_.tw, layout_.th) * layout_.view.scale;
        const Real length = std::clamp(cellPx * 0.55L, Real(18), Real(34));
        for (std::size_t k = 0; k < layout_.plans.size(); ++k) {
            for (const Stop& stop : layout_.plans[k].stops) {
                for (std::size_t m = stop.first; m < stop.first + stop.count; ++m) {
                    const Contact<T>& c = frames_[k].contacts[m];
                    const int nx = c.normal.x;
                    const int ny = c.normal.y;
                    if ((nx == 0) == (ny == 0)) continue;  // not a unit axis normal: nothing to point
                    if (!drawn.insert({c.tile.i, c.tile.j, nx, ny}).second) continue;
                    const Rect tile = layout_.cellRect(c.tile);
                    Real ax = 0;
                    Real ay = 0;
                    if (nx != 0) {
                        ax = nx < 0 ? tile.x0 : tile.x1;
                        ay = middleOfOverlap(stop.y, stop.y + layout_.h, tile.y0, tile.y1);
                    } else {
                        ay = ny < 0 ? tile.y0 : tile.y1;
                        ax = middleOfOverlap(stop.x, stop.x + layout_.w, tile.x0, tile.x1);
                    }
                    out_ += "<g class=\"normal-arrow\" data-tile=\"" + std::to_string(c.tile.i) + "," +
                            std::to_string(c.tile.j) + "\" data-normal=\"" + std::to_string(nx) + "," +
                            std::to_string(ny) + "\">\n";
                    appendArrowShape(out_, layout_.view.x(ax), layout_.view.y(ay), static_cast<Real>(nx),
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
        if (isFinitePoint(layout_.startX, layout_.startY))
            appendText(out_, layout_.view.x(layout_.startX), layout_.view.y(layout_.startY) - 5, "start",
                       "start", style + " fill=\"" + kBoxBlue + "\" class=\"label\"");
        const bool full = layout_.plans.size() <= kMaxFramesDrawnInFull;
        std::size_t k = 0;
        while (k < layout_.plans.size()) {
            std::size_t end = k + 1;
            while (end < layout_.plans.size() && layout_.plans[end].endX == layout_.plans[k].endX &&
                   layout_.plans[end].endY == layout_.plans[k].endY)
                ++end;
            const bool labelled = full || k == 0 || end == layout_.plans.size();
            if (labelled && layout_.plans[k].endFinite) {
                const std::string text = end - k == 1
                                             ? "end " + std::to_string(k + 1)
                                             : "end " + std::to_string(k + 1) + "-" + std::to_string(end);
                appendText(out_, layout_.view.x(layout_.plans[k].endX + layout_.w),
                           layout_.view.y(layout_.plans[k].endY + layout_.h) + 13, text, "end",
                           style + " fill=\"" + kBoxDark + "\" class=\"label\"");
            }
            k = end;
        }
    }

    /// The legend's items 0 to 10; kOneWayItem follows the solid tile when the map has one-way cells.
    static constexpr std::size_t kFixedLegendItems = 11;
    static constexpr std::size_t kOneWayItem = kFixedLegendItems;

    [[nodiscard]] std::size_t legendItems() const { return kFixedLegendItems + (hasOneWay() ? 1 : 0); }

    /// The item shown at legend slot `slot`.
    [[nodiscard]] std::size_t legendItemAt(std::size_t slot) const {
        if (!hasOneWay() || slot == 0) return slot;
        return slot == 1 ? kOneWayItem : slot - 1;
    }

    void appendLegend() {
        out_ += "<g class=\"legend\">\n";
        const std::string textStyle = std::string("font-size=\"12\" ") + kFont + " fill=\"" + kInk + "\"";
        const std::size_t items = legendItems();
        for (std::size_t slot = 0; slot < items; ++slot) {
            const Real x = 16 + static_cast<Real>(slot % layout_.legendColumns) * kLegendColumnWidth;
            const Real y =
                layout_.legendTop + static_cast<Real>(slot / layout_.legendColumns) * kLegendRowHeight;
            const std::size_t item = legendItemAt(slot);
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
            case kOneWayItem:
                appendRect(
                    out_, x, y, 26, 14,
                    std::string("fill=\"none\" stroke=\"") + kOneWayStroke + "\" stroke-dasharray=\"3 2\"");
                appendRect(out_, x, y, 26, 14 * kOneWaySlab,
                           std::string("fill=\"") + kOneWayFill + "\" stroke=\"" + kOneWayStroke + "\"");
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
            case kOneWayItem:
                return "one-way tile (blocks from above)";
            default:
                return "started overlapping";
        }
    }

    void appendListing() {
        const std::string style = std::string("font-size=\"11\" ") + kMonoFont + " fill=\"" + kInk + "\"";
        out_ += "<g class=\"listing\">\n";
        Real y = layout_.listingTop;
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
        if (layout_.hasMap())
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

    /// The box drawn at (x, y), sized from w*scale so that cancellation near a far coordinate
    /// cannot collapse it.
    void appendBox(Real x, Real y, const std::string& attributes) {
        appendRect(out_, layout_.view.x(x), layout_.view.y(y), layout_.w * layout_.view.scale,
                   layout_.h * layout_.view.scale, attributes);
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
    SceneLayout<T> layout_;
    std::vector<std::string> listing_;
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

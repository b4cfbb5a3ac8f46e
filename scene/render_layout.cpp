// SPDX-License-Identifier: MIT
// Layout of a scene picture (render_layout.h).
#include "render_layout.h"

#include <algorithm>
#include <stdexcept>

namespace tilesweep::detail {

template <class T>
SceneLayout<T>::SceneLayout(const Scene<T>& scene_, const std::vector<FrameResult<T>>& frames_)
    : scene(scene_), frames(frames_) {
    const TileMap<T>& map = scene.map;
    if (map.columns < 0 || map.rows < 0 ||
        map.solid.size() != static_cast<std::size_t>(map.columns) * static_cast<std::size_t>(map.rows) ||
        (!map.oneWay.empty() && map.oneWay.size() != map.solid.size()))
        throw std::invalid_argument("renderSceneSvg: the map's cells do not match its size");
    if (frames.size() != scene.moves.size())
        throw std::invalid_argument("renderSceneSvg: " + std::to_string(frames.size()) + " frames for " +
                                    std::to_string(scene.moves.size()) + " moves");
    tw = static_cast<Real>(map.tileSize.x);
    th = static_cast<Real>(map.tileSize.y);
    w = static_cast<Real>(scene.box.size.x);
    h = static_cast<Real>(scene.box.size.y);

    Real x = relX(scene.box.pos.x);
    Real y = relY(scene.box.pos.y);
    startX = x;
    startY = y;
    for (std::size_t k = 0; k < frames.size(); ++k) {
        FramePlan frame;
        frame.startX = x;
        frame.startY = y;
        frame.moveX = static_cast<Real>(scene.moves[k].x);
        frame.moveY = static_cast<Real>(scene.moves[k].y);
        frame.endX = relX(frames[k].position.x);
        frame.endY = relY(frames[k].position.y);
        frame.endFinite = isFinitePoint(frame.endX, frame.endY);
        if (isFinitePoint(x, y))
            frame.stops = planStops(map, w, h, x, y, frame.moveX, frame.moveY, frames[k].contacts);
        plans.push_back(std::move(frame));
        x = plans.back().endX;
        y = plans.back().endY;
    }
}

template <class T>
void SceneLayout<T>::fit(std::size_t titleCodePoints, std::size_t captionCodePoints,
                         const std::vector<std::string>& listing, std::size_t legendItems) {
    Bounds bounds;
    if (hasMap())
        bounds.add({0, 0, static_cast<Real>(scene.map.columns) * tw, static_cast<Real>(scene.map.rows) * th});
    bounds.add(boxRect(startX, startY));
    for (std::size_t k = 0; k < plans.size(); ++k) {
        const FramePlan& frame = plans[k];
        if (frame.endFinite) bounds.add(boxRect(frame.endX, frame.endY));
        for (const Stop& stop : frame.stops) bounds.add(boxRect(stop.x, stop.y));
        // A foreign resolver may name cells outside the map; they must still be in view.
        for (const Contact<T>& c : frames[k].contacts) bounds.add(cellRect(c.tile));
        for (const Cell& cell : frames[k].startOverlaps) bounds.add(cellRect(cell));
    }
    if (!(bounds.maxX >= bounds.minX)) bounds = Bounds{0, 0, 1, 1};  // nothing finite at all
    Real extentX = bounds.maxX - bounds.minX;
    Real extentY = bounds.maxY - bounds.minY;
    // A box a few units wide next to a coordinate of 1e300 has no extent in long double;
    // give the view some size rather than divide by zero.
    if (!(extentX > 0)) extentX = extentY > 0 ? extentY : 1;
    if (!(extentY > 0)) extentY = extentX;
    view.minX = bounds.minX;
    view.minY = bounds.minY;
    view.scale = std::min(kDrawWidth / extentX, kDrawHeight / extentY);
    view.width = extentX * view.scale;
    view.height = extentY * view.scale;

    // Canvas width: the drawing, or the text if that is wider.
    Real width = std::max(view.width + 2 * kPad, kMinCanvasWidth);
    width = std::max(
        width, kTitleCharWidth * static_cast<Real>(std::min(titleCodePoints, kMaxTitleCodePoints + 1)) + 32);
    width = std::max(width, kCaptionCharWidth * static_cast<Real>(captionCodePoints) + 32);
    for (const std::string& line : listing)
        width = std::max(width, kListingCharWidth * static_cast<Real>(countCodePoints(line)) + 32);
    canvasWidth = std::ceil(width);
    // Left-aligned like the legend and the listing, so that a longer text (a far origin
    // prints more digits) widens the canvas without moving the drawing.
    view.left = kPad;
    view.top = kHeaderHeight + kPad;

    legendTop = view.top + view.height + kPad + 8;
    const auto columns =
        std::max<std::size_t>(1, static_cast<std::size_t>((canvasWidth - 32) / kLegendColumnWidth));
    legendColumns = columns;
    const std::size_t legendRows = (legendItems + columns - 1) / columns;
    listingTop = legendTop + static_cast<Real>(legendRows) * kLegendRowHeight + 18;
    canvasHeight = std::ceil(listingTop + static_cast<Real>(listing.size()) * kListingLineHeight + 8);
}

/// Index labels every `step` cells, step one of 1, 2, 5, 10, 20, 50, ..., the smallest that
/// leaves `needed` pixels per label at `spacing` pixels per cell.
[[nodiscard]] std::int64_t labelStep(Real spacing, Real needed) {
    std::int64_t step = 1;
    for (int k = 0; spacing * static_cast<Real>(step) < needed && k < 60; ++k)
        step = (k % 3 == 1) ? step / 2 * 5 : step * 2;
    return step;
}

template struct SceneLayout<float>;
template struct SceneLayout<double>;

}  // namespace tilesweep::detail

// SPDX-License-Identifier: MIT
#pragma once
// Layout of a scene picture: where everything goes, in SVG pixels. The frames are planned in
// map-relative long double (the box at each contact included), then a view scales the map and the
// whole motion to fit the drawing, and the canvas grows around the text. What is drawn there is
// scene_render.cpp's job, and how SVG is written svg_writer's.

#include "svg_writer.h"

#include "tilesweep/scene/scene.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace tilesweep::detail {

// Every world coordinate is taken relative to the map origin in long double before it is
// scaled: at an origin of 2^40 a float or double box is still exact there (64-bit significand),
// whereas scaling absolute coordinates would lose the box's size to cancellation.

// ---- layout, in SVG pixels -----------------------------------------------------------------

inline constexpr Real kDrawWidth = 880;  // the map and the motion are scaled to fit this box
inline constexpr Real kDrawHeight = 520;
inline constexpr Real kPad = 40;              // around the drawing: room for indices and arrows
inline constexpr Real kHeaderHeight = 60;     // title and caption
inline constexpr Real kMinCanvasWidth = 700;  // so that the legend and the listing fit
inline constexpr Real kMinGridSpacing = 4;    // below this a grid is grey noise, so it is left out
inline constexpr Real kLegendColumnWidth = 240;
inline constexpr Real kLegendRowHeight = 20;
inline constexpr Real kListingLineHeight = 15;
// Rough glyph advances, to size the canvas around text (there is no font metrics in SVG).
inline constexpr Real kTitleCharWidth = 10;      // 17px bold sans-serif
inline constexpr Real kCaptionCharWidth = 6.9L;  // 12px sans-serif
inline constexpr Real kListingCharWidth = 6.7L;  // 11px monospace

// Past this many frames the picture switches to its compact form: frame ends in between become
// dots, and the per-frame extras (requested motion, box at contact) are left out.
inline constexpr std::size_t kMaxFramesDrawnInFull = 8;
// The listing shows every frame up to this many, else the first and the last few.
inline constexpr std::size_t kMaxListedFrames = 12;
inline constexpr std::size_t kMaxListedContacts = 3;  // per frame
inline constexpr std::size_t kMaxTitleCodePoints = 120;

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

[[nodiscard]] inline bool isFinitePoint(Real x, Real y) { return std::isfinite(x) && std::isfinite(y); }

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
[[nodiscard]] inline Real clipFraction(Real x0, Real y0, Real x1, Real y1, const Rect& r) {
    Real keep = 1;
    const Real dx = x1 - x0;
    const Real dy = y1 - y0;
    if (dx > 0) keep = std::min(keep, (r.x1 - x0) / dx);
    if (dx < 0) keep = std::min(keep, (r.x0 - x0) / dx);
    if (dy > 0) keep = std::min(keep, (r.y1 - y0) / dy);
    if (dy < 0) keep = std::min(keep, (r.y0 - y0) / dy);
    return std::clamp(keep, Real(0), Real(1));
}

/// The frames of `scene` planned map-relative, and the view and canvas they are drawn on.
template <class T>
struct SceneLayout {
    /// Plans every frame (throws std::invalid_argument when `frames` does not hold one frame per
    /// move or the map's cells do not match its size).
    SceneLayout(const Scene<T>& scene, const std::vector<FrameResult<T>>& frames);

    /// Fits the view to the map and the motion, and the canvas around it and around the text:
    /// the title and caption (in code points), the listing lines, the legend's item count.
    void fit(std::size_t titleCodePoints, std::size_t captionCodePoints,
             const std::vector<std::string>& listing, std::size_t legendItems);

    [[nodiscard]] bool hasMap() const { return scene.map.columns > 0 && scene.map.rows > 0; }
    [[nodiscard]] Real relX(T x) const {
        return static_cast<Real>(x) - static_cast<Real>(scene.map.origin.x);
    }
    [[nodiscard]] Real relY(T y) const {
        return static_cast<Real>(y) - static_cast<Real>(scene.map.origin.y);
    }
    [[nodiscard]] Rect boxRect(Real x, Real y) const { return {x, y, x + w, y + h}; }
    [[nodiscard]] Rect cellRect(Cell cell) const {
        const auto i = static_cast<Real>(cell.i);
        const auto j = static_cast<Real>(cell.j);
        return {i * tw, j * th, (i + 1) * tw, (j + 1) * th};
    }

    const Scene<T>& scene;
    const std::vector<FrameResult<T>>& frames;
    std::vector<FramePlan> plans;
    Real tw = 1, th = 1, w = 1, h = 1;
    Real startX = 0, startY = 0;
    View view;
    Real canvasWidth = 0, canvasHeight = 0;
    Real legendTop = 0, listingTop = 0;
    std::size_t legendColumns = 1;
};

/// Index labels every `step` cells, step one of 1, 2, 5, 10, 20, 50, ..., the smallest that
/// leaves `needed` pixels per label at `spacing` pixels per cell.
[[nodiscard]] std::int64_t labelStep(Real spacing, Real needed);

}  // namespace tilesweep::detail

// SPDX-License-Identifier: MIT
#include "tilesweep/oracle/substep/substep_oracle.h"

#include "tilesweep/oracle/exact/rational_convert.h"
#include "tilesweep/oracle/substep/normal_guess.h"

#include <stdexcept>
#include <vector>

namespace tilesweep::oracle {
namespace {

struct Candidate {
    Cell cell;
    CellKind kind = CellKind::Solid;
    ExactRect rect;
};

int signOf(const Rational& q) { return q > 0 ? 1 : (q < 0 ? -1 : 0); }

Rational minOf(const Rational& a, const Rational& b) { return a < b ? a : b; }
Rational maxOf(const Rational& a, const Rational& b) { return a < b ? b : a; }

// The box at substep k of n: pos + (k/n)*d, exactly.
ExactRect rectAt(const ExactBox& box, const ExactVec2& d, std::int64_t k, std::int64_t n) {
    const Rational t = Rational(k) / Rational(n);
    return rectOf({{box.pos.x + t * d.x, box.pos.y + t * d.y}, box.size});
}

// Whether the box at substep k stops on a candidate: a solid tile by overlapping it; a one-way
// tile by overlapping it having been, at substep k - 1, over it on x (strictly) with its bottom
// at or above the top. A box that was beside the platform at k - 1 and is in it at k may have
// come in through the side, so it passes.
bool stopsOn(const Candidate& c, const ExactRect& before, const ExactRect& at) {
    if (!overlaps(at, c.rect)) {
        return false;
    }
    if (c.kind == CellKind::Solid) {
        return true;
    }
    const bool overOnX = before.min.x < c.rect.max.x && before.max.x > c.rect.min.x;
    return overOnX && before.max.y <= c.rect.min.y;
}

// The substep search; `candidates` receives the tiles worth testing, for the caller's normals.
SubstepOverlap search(const ExactTileMap& map, const ExactBox& box, const ExactVec2& d, std::int64_t n,
                      std::vector<Candidate>& candidates) {
    if (n < 1) {
        throw std::invalid_argument("substep oracle: the number of substeps must be >= 1");
    }
    SubstepOverlap result;
    result.substeps = n;

    // Every position the box takes lies inside the swept bounds, so a tile that does not overlap
    // them can never overlap the box: leaving it out is a bound, not a use of entry times.
    const ExactRect start = rectOf(box);
    const ExactRect end = rectOf({{box.pos.x + d.x, box.pos.y + d.y}, box.size});
    const ExactRect swept{{minOf(start.min.x, end.min.x), minOf(start.min.y, end.min.y)},
                          {maxOf(start.max.x, end.max.x), maxOf(start.max.y, end.max.y)}};
    candidates.clear();
    const bool movesDown = d.y > 0;
    for (std::int32_t j = 0; j < map.rows; ++j) {
        for (std::int32_t i = 0; i < map.columns; ++i) {
            const CellKind kind = map.kind(i, j);
            if (kind == CellKind::Empty) {
                continue;
            }
            const ExactRect tile = map.tileRect(i, j);
            if (kind == CellKind::Solid && overlaps(start, tile)) {
                result.startOverlaps.push_back({i, j});
            } else if (kind == CellKind::OneWay && !(movesDown && start.max.y <= tile.min.y)) {
                // A platform stops only a box moving down whose bottom starts at or above its
                // top; any other never stops on it, and is not listed as a start overlap.
                continue;
            } else if (overlaps(swept, tile)) {
                candidates.push_back({{i, j}, kind, tile});
            }
        }
    }

    ExactRect before = start;
    for (std::int64_t k = 1; k <= n && !candidates.empty(); ++k) {
        const ExactRect at = rectAt(box, d, k, n);
        for (const Candidate& c : candidates) {
            if (stopsOn(c, before, at)) {
                result.tiles.push_back(c.cell);
            }
        }
        if (!result.tiles.empty()) {
            result.firstOverlap = k;
            break;
        }
        before = at;
    }
    return result;
}

}  // namespace

SubstepOverlap findFirstOverlapExact(const ExactTileMap& map, const ExactBox& box,
                                     const ExactVec2& displacement, std::int64_t substeps) {
    std::vector<Candidate> candidates;
    return search(map, box, displacement, substeps, candidates);
}

template <class T>
std::vector<SubstepFrame<T>> resolveSceneSubstep(const Scene<T>& scene, std::int64_t substeps) {
    const ExactTileMap map = toExact(scene.map);
    const ExactVec2 size = toExact(scene.box.size);
    std::vector<SubstepFrame<T>> frames;
    std::vector<Candidate> candidates;
    Vec2<T> start = scene.box.pos;
    for (const Vec2<T>& move : scene.moves) {
        const ExactBox box{toExact(start), size};
        const ExactVec2 d = toExact(move);
        const SubstepOverlap overlap = search(map, box, d, substeps, candidates);

        SubstepFrame<T> out;
        out.substeps = substeps;
        out.firstOverlap = overlap.firstOverlap;
        out.frame.startOverlaps = overlap.startOverlaps;
        const std::int64_t stopAt = overlap.found() ? overlap.firstOverlap - 1 : substeps;
        const ExactRect stopped = rectAt(box, d, stopAt, substeps);
        if (overlap.found()) {
            const T time = fromRational<T>(overlap.bracketHigh(), Rounding::NearestEven);
            const bool xDominant = abs(d.x) > abs(d.y);
            for (const Cell& cell : overlap.tiles) {
                const ExactRect tile = map.tileRect(cell.i, cell.j);
                const bool separatedX = !(stopped.min.x < tile.max.x && stopped.max.x > tile.min.x);
                const bool separatedY = !(stopped.min.y < tile.max.y && stopped.max.y > tile.min.y);
                out.frame.contacts.push_back(  // no position: the substeps judge decisions only
                    {cell,
                     guessNormal(separatedX, separatedY, signOf(d.x), signOf(d.y), xDominant),
                     time,
                     {}});
            }
        }
        out.frame.position = {
            roundFinalCoordinate<T>(stopped.min.x, start.x, size.x, map.origin.x, map.tileSize.x),
            roundFinalCoordinate<T>(stopped.min.y, start.y, size.y, map.origin.y, map.tileSize.y)};
        start = out.frame.position;
        frames.push_back(std::move(out));
    }
    return frames;
}

template std::vector<SubstepFrame<float>> resolveSceneSubstep<float>(const Scene<float>&, std::int64_t);
template std::vector<SubstepFrame<double>> resolveSceneSubstep<double>(const Scene<double>&, std::int64_t);

}  // namespace tilesweep::oracle

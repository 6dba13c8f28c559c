#include "facade/openings.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace veduta {

namespace {

constexpr double kSamePoint = 1e-12;  // metres: repeated outline points
constexpr const char *kEdgeNames[] = {"bottom", "right", "top", "left"};
constexpr const char *kCornerNames[] = {"f_bl", "f_br", "f_tr", "f_tl"};

Vec2d bilinear(const WallQuad &w, double v, double h) { return lerp(lerp(w.bl, w.br, v), lerp(w.tl, w.tr, v), h); }

void checkUnit(double value, const char *edge, const char *what) {
    if (!(value >= 0 && value <= 1)) {
        throw std::invalid_argument(fmt::format("{} edge: {} = {} is outside [0,1]", edge, what, value));
    }
}

void checkRefinement(const EdgeRefinement &e, const char *edge) {
    checkUnit(e.distL, edge, "dist_l");
    checkUnit(e.distR, edge, "dist_r");
    checkUnit(e.distB, edge, "dist_b");
    checkUnit(e.size, edge, "size");
    if (e.distL + e.distR >= 1) throw std::invalid_argument(fmt::format("{} edge: dist_l + dist_r ≥ 1", edge));
    for (Vec2d p : e.profile) {
        if (!(p.x >= 0 && p.x <= 1 && p.y >= 0 && p.y <= 1)) {
            throw std::invalid_argument(
                fmt::format("{} edge: profile point ({}, {}) is outside [0,1]²", edge, p.x, p.y));
        }
    }
}

// Edge k's inward vector across the opening: the next edge's direction f_{k+2} − f_{k+1}, except
// for the left edge, which moves along the top edge like the right one (L1322 with its sign
// fixed, digest §10): f_tr − f_tl.
Vec2d inwardOf(const CoarseOpening &c, int k) {
    if (k == kLeft) return c.tr - c.tl;
    return c.corner(k + 2) - c.corner(k + 1);
}

bool isFinite(Vec2d p) { return std::isfinite(p.x) && std::isfinite(p.y); }

// The refinement formulas move edges along the opening's sides, which only stay inside it when
// the quad is convex; a degenerate or clockwise one would give a folded outline.
void checkCoarse(const CoarseOpening &c) {
    for (int k = 0; k < 4; ++k) {
        if (!isFinite(c.corner(k))) {
            throw std::invalid_argument(fmt::format("coarse opening: corner {} is not finite", kCornerNames[k]));
        }
    }
    for (int k = 0; k < 4; ++k) {
        Vec2d in = c.corner(k + 1) - c.corner(k), out = c.corner(k + 2) - c.corner(k + 1);
        double turn = cross(in, out);  // infinite where the corners are too far apart to measure
        if (!(turn > 0 && std::isfinite(turn))) {
            throw std::invalid_argument("coarse opening: corners are not a convex counter-clockwise quad");
        }
    }
}

double offsetOf(const EdgeRefinement &e) { return e.distB + e.size; }

}  // namespace

CoarseOpening coarseOpening(const WallQuad &wall, double vStart, double vEnd, double hStart, double hEnd) {
    if (!(isFinite(wall.bl) && isFinite(wall.br) && isFinite(wall.tr) && isFinite(wall.tl))) {
        throw std::invalid_argument("wall quad: a corner is not finite");
    }
    if (!(0 <= vStart && vStart < vEnd && vEnd <= 1 && 0 <= hStart && hStart < hEnd && hEnd <= 1)) {
        throw std::invalid_argument(
            fmt::format("opening needs 0 ≤ v_s < v_e ≤ 1 and 0 ≤ h_s < h_e ≤ 1, got v [{}, {}], h [{}, {}]", vStart,
                        vEnd, hStart, hEnd));
    }
    return {bilinear(wall, vStart, hStart), bilinear(wall, vEnd, hStart), bilinear(wall, vEnd, hEnd),
            bilinear(wall, vStart, hEnd)};
}

CoarseOpening placeOpening(const WallQuad &wall, const AbsolutePlacement &p) {
    double wallWidth = length(wall.br - wall.bl), wallHeight = length(wall.tl - wall.bl);
    for (double value : {p.width, p.height, p.distLeft, p.distRight, p.sillHeight}) {
        if (!std::isfinite(value)) throw std::invalid_argument("opening placement: a value is not finite");
    }
    if (!(p.width > 0 && p.height > 0 && p.distLeft >= 0 && p.distRight >= 0 && p.sillHeight >= 0) ||
        p.distLeft + p.distRight <= 0) {
        throw std::invalid_argument("opening width and height must be positive, distances and sill not negative");
    }
    if (p.width > wallWidth || p.sillHeight + p.height > wallHeight) {
        throw std::invalid_argument(fmt::format("opening {} × {} m at sill {} m does not fit the {} × {} m wall",
                                                p.width, p.height, p.sillHeight, wallWidth, wallHeight));
    }
    double left = (wallWidth - p.width) * p.distLeft / (p.distLeft + p.distRight);
    return coarseOpening(wall, left / wallWidth, (left + p.width) / wallWidth, p.sillHeight / wallHeight,
                         (p.sillHeight + p.height) / wallHeight);
}

std::vector<Vec2d> RefinedEdge::polyline(double depth, double lift) const {
    std::vector<Vec2d> points{l + outward * lift};
    for (Vec2d p : profile) points.push_back(lerp(l, r, p.x) + outward * (lift + p.y * depth));
    points.push_back(r + outward * lift);
    return points;
}

std::vector<Vec2d> RefinedOpening::outline() const {
    std::vector<Vec2d> points;
    for (const RefinedEdge &edge : edges) {
        for (Vec2d p : edge.polyline()) {
            if (points.empty() || length(p - points.back()) > kSamePoint) points.push_back(p);
        }
    }
    while (points.size() > 1 && length(points.back() - points.front()) <= kSamePoint) points.pop_back();
    return points;
}

RefinedOpening refineOpening(const CoarseOpening &coarse, const std::array<EdgeRefinement, 4> &given,
                             Dominance dominance, OpeningKind kind) {
    std::array<EdgeRefinement, 4> edges = given;
    if (kind == OpeningKind::Door) edges[kBottom] = {};
    checkCoarse(coarse);
    for (int k = 0; k < 4; ++k) checkRefinement(edges[size_t(k)], kEdgeNames[k]);
    int firstDominant = dominance == Dominance::BottomAndTop ? kBottom : kRight;
    for (int k = 0; k < 4; ++k) {
        if ((k - firstDominant) % 2 == 0) continue;
        // A band on a non-dominant edge would be crossed by its full-width neighbours, and the
        // outline would fold back along their refined lines.
        if (edges[size_t(k)].size > 0) {
            throw std::invalid_argument(fmt::format("{} edge: a size band needs a dominant edge", kEdgeNames[k]));
        }
    }
    for (int k = 0; k < 2; ++k) {
        if (offsetOf(edges[size_t(k)]) + offsetOf(edges[size_t(k + 2)]) >= 1) {
            throw std::invalid_argument(fmt::format("{} and {} edges meet: their dist_b + size add up to 1 or more",
                                                    kEdgeNames[k], kEdgeNames[k + 2]));
        }
    }
    RefinedOpening opening;
    opening.coarse = coarse;
    opening.kind = kind;
    for (int k = 0; k < 4; ++k) opening.inward[size_t(k)] = inwardOf(coarse, k);
    for (int k = 0; k < 4; ++k) {
        const EdgeRefinement &e = edges[size_t(k)];
        Vec2d fl = coarse.corner(k), fr = coarse.corner(k + 1), in = opening.inward[size_t(k)];
        RefinedEdge &edge = opening.edges[size_t(k)];
        edge.dominant = (k - firstDominant) % 2 == 0;
        edge.l = fl + (fr - fl) * e.distL + in * offsetOf(e);
        edge.r = fr + (fl - fr) * e.distR + in * offsetOf(e);
        if (!edge.dominant) {
            // End on the dominant neighbours' refined lines (L1322: rr = … + size(f_bl − f_tl)).
            size_t before = size_t((k + 3) % 4), after = size_t((k + 1) % 4);
            edge.l = edge.l + opening.inward[before] * offsetOf(edges[before]);
            edge.r = edge.r + opening.inward[after] * offsetOf(edges[after]);
        }
        edge.outward = in * -e.size;
        edge.distB = e.distB;
        edge.size = e.size;
        edge.profile = e.profile;
    }
    return opening;
}

}  // namespace veduta

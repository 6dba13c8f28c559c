#include "slg/corridors.h"

#include <algorithm>
#include <array>

#include "slg/exact_region.h"

namespace veduta {

namespace {

// Points this close to a line lie on it: faces' corners are intersections of lines, a rounding
// off the edges they stand on.
constexpr double kOnLine = 1e-6;

// The part of segment a → b, as parameters in [0, 1], that segment c → d runs along.
std::optional<std::pair<double, double>> overlap(Vec2d a, Vec2d b, Vec2d c, Vec2d d) {
    Vec2d v = b - a;
    double len = length(v);
    if (std::abs(cross(v, c - a)) / len > kOnLine || std::abs(cross(v, d - a)) / len > kOnLine) return std::nullopt;
    double s = dot(c - a, v) / (len * len), t = dot(d - a, v) / (len * len);
    double lo = std::max(std::min(s, t), 0.0), hi = std::min(std::max(s, t), 1.0);
    if ((hi - lo) * len <= kOnLine) return std::nullopt;
    return std::pair{lo, hi};
}

double coveredFraction(std::vector<std::pair<double, double>> parts) {
    std::ranges::sort(parts);
    double covered = 0, reached = 0;
    for (auto [lo, hi] : parts) {
        lo = std::max(lo, reached);
        if (hi > lo) covered += hi - lo;
        reached = std::max(reached, hi);
    }
    return covered;
}

enum SideName { kTop, kLeft, kRight };

std::vector<size_t> &side(FaceSides &sides, int name) {
    return name == kTop ? sides.top : name == kLeft ? sides.left : sides.right;
}

class CorridorMaker {
  public:
    CorridorMaker(const Subdivision &subdivision, const CorridorParameters &parameters) :
        outline_(subdivision.outline), parameters_(parameters) {
        for (const PlanFace *face : subdivision.borderFaces()) {
            plan_.faces.push_back(faceShape(subdivision, *face));
            plan_.sides.push_back(fourSides(plan_.faces.back().points, frontEdges(*face)));
            borders_.push_back(face);
        }
        moved_.assign(plan_.faces.size(), {false, false, false});
    }

    CorridorPlan make(SlgNodeId entrance) {
        std::vector<bool> done(plan_.faces.size(), false);
        for (size_t f = 0; f < borders_.size(); ++f) {
            if (borders_[f]->right == entrance) done[f] = move(f, kRight, parameters_.width / 2);
            if (borders_[f]->left == entrance) done[f] = move(f, kLeft, parameters_.width / 2);
        }
        if (parameters_.kind == CorridorKind::Apartment) {
            for (size_t f = 0; f < done.size(); ++f)
                if (!done[f] && !plan_.sides[f].top.empty()) move(f, kTop, parameters_.width);
        } else {
            reachEveryFace(done);
        }
        return std::move(plan_);
    }

  private:
    // A face moves a side that already touches the corridor, so the strip it gives up joins it;
    // faces that touch it nowhere wait for their neighbours' strips, and only when no face can
    // move so does one of them move its top (or its shorter side).
    void reachEveryFace(std::vector<bool> &done) {
        bool blind = false;
        for (size_t pass = 0; pass < 4 * plan_.faces.size() + 4; ++pass) {
            bool changed = false;
            for (size_t f = 0; f < plan_.faces.size(); ++f) {
                if (done[f]) continue;
                std::vector<double> free = freeLengths(plan_.faces, f, outline_);
                if (*std::ranges::max_element(free) >= parameters_.entranceWidth) {
                    done[f] = true;
                    continue;
                }
                int chosen = sideToMove(f, free, blind);
                if (chosen < 0) continue;
                move(f, chosen, parameters_.width);
                changed = true;
                if (blind) break;
            }
            if (!changed && blind) break;
            blind = !changed;
        }
        for (size_t f = 0; f < plan_.faces.size(); ++f) {
            std::vector<double> free = freeLengths(plan_.faces, f, outline_);
            if (*std::ranges::max_element(free) < parameters_.entranceWidth) ++plan_.unreached;
        }
    }

    // The side of top, left and right with the most free length (the shortest on a tie), of
    // those not moved yet; with `blind`, also one with none. −1 when there is none to move.
    int sideToMove(size_t f, const std::vector<double> &free, bool blind) {
        int best = -1;
        double bestFree = 0, bestLength = 0;
        for (int name : {kTop, kLeft, kRight}) {
            const std::vector<size_t> &edges = side(plan_.sides[f], name);
            if (edges.empty() || moved_[f][name]) continue;
            double sideFree = 0;
            for (size_t e : edges) sideFree += free[e];
            double sideLong = sideLength(plan_.faces[f], edges);
            if (sideFree <= 0 && !blind) continue;
            if (best < 0 || sideFree > bestFree || (sideFree == bestFree && sideLong < bestLength)) {
                best = name;
                bestFree = sideFree;
                bestLength = sideLong;
            }
        }
        return best;
    }

    bool move(size_t f, int name, double distance) {
        moved_[f][name] = true;
        FaceSides single;
        side(single, name) = side(plan_.sides[f], name);
        std::vector<double> distances(plan_.faces[f].size(), 0);
        for (size_t e : side(single, name)) distances[e] = distance;
        EdgeLocation gap =
            parameters_.kind == CorridorKind::House ? EdgeLocation::HouseCorridor : EdgeLocation::ApartmentCorridor;
        auto movedShape = moveEdges(plan_.faces[f], distances, gap);
        if (!movedShape) {
            ++plan_.tooSmall;
            return false;
        }
        plan_.sides[f] = sidesAfterMove(plan_.sides[f], movedShape->source);
        plan_.faces[f] = std::move(movedShape->shape);
        return true;
    }

    const Polygon2d &outline_;
    const CorridorParameters &parameters_;
    CorridorPlan plan_;
    std::vector<const PlanFace *> borders_;
    std::vector<std::array<bool, 3>> moved_;
};

}  // namespace

// Corners computed in double stand a rounding off the outline, so the exact difference leaves
// slivers along it; pieces of no appreciable area are dropped.
std::vector<std::vector<Polygon2d>> corridorPieces(const Polygon2d &outline, const std::vector<PlanShape> &faces) {
    ExactRegion region(exactPolygon(outline));
    for (const PlanShape &face : faces) region.difference(exactPolygon(face.points));
    std::vector<CGAL::Polygon_with_holes_2<ExactKernel>> parts;
    region.polygons_with_holes(std::back_inserter(parts));
    double negligible = 1e-9 * signedArea(outline);
    std::vector<std::vector<Polygon2d>> pieces;
    for (const auto &part : parts) {
        std::vector<Polygon2d> piece{inexactPolygon(part.outer_boundary())};
        if (signedArea(piece.front()) <= negligible) continue;
        for (const auto &hole : part.holes())
            if (-signedArea(inexactPolygon(hole)) > negligible) piece.push_back(inexactPolygon(hole));
        pieces.push_back(std::move(piece));
    }
    return pieces;
}

std::vector<double> freeLengths(const std::vector<PlanShape> &faces, size_t f, const Polygon2d &outline) {
    const PlanShape &face = faces[f];
    std::vector<double> free;
    for (size_t e = 0; e < face.size(); ++e) {
        Vec2d a = face.start(e), b = face.end(e);
        std::vector<std::pair<double, double>> parts;
        auto cover = [&](Vec2d c, Vec2d d) {
            if (auto part = overlap(a, b, c, d)) parts.push_back(*part);
        };
        for (size_t i = 0; i < outline.size(); ++i) cover(outline[i], outline[(i + 1) % outline.size()]);
        for (size_t g = 0; g < faces.size(); ++g)
            if (g != f)
                for (size_t i = 0; i < faces[g].size(); ++i) cover(faces[g].start(i), faces[g].end(i));
        free.push_back(face.edgeLength(e) * (1 - coveredFraction(std::move(parts))));
    }
    return free;
}

CorridorPlan makeCorridor(const Subdivision &subdivision, SlgNodeId entrance, const CorridorParameters &parameters) {
    return CorridorMaker(subdivision, parameters).make(entrance);
}

}  // namespace veduta

#include "city/roof_gables.h"

#include <CGAL/intersections.h>

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace veduta {

namespace {

using Point = RoofKernel::Point_3;
using Line = RoofKernel::Line_3;
using Plane = RoofKernel::Plane_3;

std::optional<Line> meetingLine(const Plane &p, const Plane &q) {
    auto hit = CGAL::intersection(p, q);
    if (const Line *line = hit ? boost::get<Line>(&*hit) : nullptr) return *line;
    return std::nullopt;
}

std::optional<Point> meetingPoint(const Line &line, const Plane &plane) {
    auto hit = CGAL::intersection(line, plane);
    if (const Point *point = hit ? boost::get<Point>(&*hit) : nullptr) return *point;
    return std::nullopt;
}

// The vertical plane over an edge, facing away from the building.
Plane wallPlane(const SkeletonRoof &roof, size_t edge) {
    Vec2f a = roof.edges[edge].start, b = roof.edges[edge].end;
    return {Point(a.x, a.y, roof.eavesZ), RoofKernel::Vector_3(double(b.y) - a.y, double(a.x) - b.x, 0)};
}

bool liesIn(const SkeletonRoof &roof, const RoofFace &face) {
    return std::all_of(face.corners.begin(), face.corners.end(), [&](uint32_t c) {
        return CGAL::squared_distance(roof.corners[c], face.plane) <= kMaxPlaneDistance * kMaxPlaneDistance;
    });
}

bool isCornerOfAnotherFace(const SkeletonRoof &roof, uint32_t corner, std::initializer_list<size_t> except) {
    for (size_t f = 0; f < roof.faces.size(); ++f) {
        const std::vector<uint32_t> &corners = roof.faces[f].corners;
        if (std::find(except.begin(), except.end(), f) == except.end() &&
            std::find(corners.begin(), corners.end(), corner) != corners.end()) {
            return true;
        }
    }
    return false;
}

}  // namespace

bool endsARidge(const SkeletonRoof &roof, size_t edge) {
    const std::vector<uint32_t> &corners = roof.faces[edge].corners;
    return corners.size() == 3 && corners[2] < roof.skeletonCorners;
}

std::vector<size_t> ridgeEnds(const SkeletonRoof &roof) {
    std::vector<size_t> ends;
    for (size_t e = 0; e < roof.edges.size(); ++e) {
        if (endsARidge(roof, e)) ends.push_back(e);
    }
    auto span = [&](size_t e) { return length(lift(roof.edges[e].end, 0) - lift(roof.edges[e].start, 0)); };
    std::stable_sort(ends.begin(), ends.end(), [&](size_t x, size_t y) { return span(x) < span(y); });
    return ends;
}

std::optional<std::string> addGableEnd(SkeletonRoof &roof, size_t edge, std::optional<float> halfHipFraction) {
    const RoofEdge &sides = roof.edges[edge];
    const std::vector<uint32_t> &hip = roof.faces[edge].corners;
    uint32_t apex = hip[2];
    RoofFace before = roof.faces[sides.previous], after = roof.faces[sides.next];
    if (before.corners[2] != apex || after.corners.back() != apex)
        return "the slopes beside it do not meet at its apex";
    // The ridge between the neighbouring slopes, carried on to the edge's line.
    std::optional<Line> ridge = meetingLine(before.plane, after.plane);
    std::optional<Point> top = ridge ? meetingPoint(*ridge, wallPlane(roof, edge)) : std::nullopt;
    if (!top) return "the slopes beside it run parallel to it";
    Point a = roof.corners[hip[0]], b = roof.corners[hip[1]];
    double span = std::sqrt(CGAL::squared_distance(a, b)), along = (*top - a) * (b - a) / span;
    if (along < kMinGableSize || along > span - kMinGableSize) {
        return fmt::format("its ridge meets the edge's line {:.3f} m along an edge {:.3f} m long", along, span);
    }
    double height = top->z() - roof.eavesZ;
    if (height < kMinGableSize) return fmt::format("its gable would stand {:.4f} m high", height);

    size_t cornersBefore = roof.corners.size();
    auto addCorner = [&](const Point &p) {
        roof.corners.push_back(p);
        return uint32_t(roof.corners.size() - 1);
    };
    RoofFace wall{{hip[0], hip[1]}, wallPlane(roof, edge), edge, RoofGableWall};
    std::vector<RoofFace> added;
    if (halfHipFraction) {
        // The wall stops at the fraction of the gable's height; from its top a small hip rises
        // at the roof's pitch until it meets the ridge, between the gable's apex and the hip's.
        double fraction = *halfHipFraction;
        Plane smallHip = slopePlane(roof, edge, fraction * height);
        std::optional<Point> hipTop = meetingPoint(*ridge, smallHip);
        if (!hipTop) return "its small hip would not meet the ridge";
        uint32_t wallLeft = addCorner(a + (*top - a) * fraction), wallRight = addCorner(b + (*top - b) * fraction);
        uint32_t ridgeEnd = addCorner(*hipTop);
        before.corners.insert(before.corners.begin() + 2, {wallLeft, ridgeEnd});
        after.corners.insert(after.corners.end(), {ridgeEnd, wallRight});
        wall.corners.insert(wall.corners.end(), {wallRight, wallLeft});
        added.push_back({{wallLeft, wallRight, ridgeEnd}, smallHip, edge, RoofCovering});
    } else {
        uint32_t ridgeEnd = addCorner(*top);
        before.corners.insert(before.corners.begin() + 2, ridgeEnd);
        after.corners.push_back(ridgeEnd);
        wall.corners.push_back(ridgeEnd);
    }
    // Where only the two stretched slopes still meet at the old apex, it lies on the straight
    // ridge between them.
    if (!isCornerOfAnotherFace(roof, apex, {edge, sides.previous, sides.next})) {
        std::erase(before.corners, apex);
        std::erase(after.corners, apex);
    }
    bool valid = isSimpleFromAbove(roof, before) && isSimpleFromAbove(roof, after) && liesIn(roof, before) &&
        liesIn(roof, after) && liesIn(roof, wall) &&
        std::all_of(added.begin(), added.end(), [&](const RoofFace &f) { return liesIn(roof, f); });
    if (!valid) {
        roof.corners.resize(cornersBefore);
        return "the slopes beside it would cross themselves or leave their planes";
    }
    roof.faces[sides.previous] = std::move(before);
    roof.faces[sides.next] = std::move(after);
    roof.faces[edge] = std::move(wall);
    roof.faces.insert(roof.faces.end(), added.begin(), added.end());
    return std::nullopt;
}

}  // namespace veduta

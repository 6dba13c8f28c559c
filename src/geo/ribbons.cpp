#include "geo/ribbons.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "core/error.h"
#include "geo/mesh_normals.h"

namespace veduta {

namespace {

constexpr double kShortest = 1e-3;  // metres: closer points merge, so every direction is well defined

// How far the ribbon's edge on the inside of a bend of `turn` radians moves back along the
// line from the corner: the miter's share along the line, half width · tan(turn / 2) while
// the miter limit does not clamp it.
double miterShift(double turn, double halfWidth, double miterLimit) {
    double half = std::abs(turn) / 2;
    return halfWidth * std::min(1 / std::cos(half), miterLimit) * std::sin(half);
}

double turnAt(const std::vector<Vec2d> &line, size_t i) {
    Vec2d a = line[i] - line[i - 1], b = line[i + 1] - line[i];
    return std::atan2(cross(a, b), dot(a, b));
}

// Drops the points that lie on a straight stretch (cuts at grid lines, mostly) nearer to a
// corner than the corner's miter shift: the piece between them would be shorter than the
// inner edge's step back, and its edge would fold back over its neighbour's, two triangles
// over one spot at different heights. Without the point the pieces only span a cell line,
// which the raising below still keeps clear of the ground.
std::vector<Vec2d> withoutPointsInCorners(const std::vector<Vec2d> &line, double halfWidth, double miterLimit) {
    if (line.size() < 3) return line;
    std::vector<double> shift(line.size(), 0);
    for (size_t i = 1; i + 1 < line.size(); ++i) shift[i] = miterShift(turnAt(line, i), halfWidth, miterLimit);
    std::vector<Vec2d> kept{line.front()};
    for (size_t i = 1; i + 1 < line.size(); ++i) {
        bool straight = shift[i] < 1e-9;
        bool crowded = length(line[i] - kept.back()) < shift[i - 1] || length(line[i + 1] - line[i]) < shift[i + 1];
        if (!(straight && crowded)) kept.push_back(line[i]);
    }
    kept.push_back(line.back());
    return kept;
}

std::vector<Vec2d> centreLine(const MapLine &centre, const TerrainSurface &surface, const LocalFrame &frame) {
    std::vector<Vec2d> line;
    for (const MapPoint &p : centre) {
        if (!std::isfinite(p.easting) || !std::isfinite(p.northing)) {
            throw InputError(FileLoc{}, "a ribbon's centre line has a point that is not a finite number");
        }
        line.push_back(toLocalDouble(p, frame));
    }
    std::vector<Vec2d> cut = splitAtGridLines(line, surface.cellLines(), false);
    std::vector<Vec2d> kept;
    for (size_t i = 0; i < cut.size(); ++i) {
        if (kept.empty() || std::hypot(cut[i].x - kept.back().x, cut[i].y - kept.back().y) >= kShortest) {
            kept.push_back(cut[i]);
        } else if (i + 1 == cut.size() && kept.size() > 1) {
            kept.back() = cut[i];  // keep the true end, unless that brings it too close to the point before
            size_t n = kept.size();
            if (std::hypot(kept[n - 1].x - kept[n - 2].x, kept[n - 1].y - kept[n - 2].y) < kShortest) kept.pop_back();
        }
    }
    return kept;
}

Vec2d leftOf(Vec2d a, Vec2d b) {  // up × d, normalised: the left side going from a to b
    double dx = b.x - a.x, dy = b.y - a.y, length = std::hypot(dx, dy);
    return {-dy / length, dx / length};
}

// The offset from centre point i to the ribbon's left edge: the perpendicular at the ends,
// the averaged perpendicular at corners, long enough to keep the width along both pieces
// but at most miterLimit half widths.
std::vector<Vec2d> leftOffsets(const std::vector<Vec2d> &line, double halfWidth, double miterLimit) {
    std::vector<Vec2d> offsets(line.size());
    for (size_t i = 0; i < line.size(); ++i) {
        Vec2d before = leftOf(line[i == 0 ? 0 : i - 1], line[i == 0 ? 1 : i]);
        Vec2d after = i + 1 < line.size() ? leftOf(line[i], line[i + 1]) : before;
        Vec2d sum{before.x + after.x, before.y + after.y};
        double length = std::hypot(sum.x, sum.y);
        if (length < 1e-9) {  // turning back on itself
            offsets[i] = {after.x * halfWidth * miterLimit, after.y * halfWidth * miterLimit};
            continue;
        }
        Vec2d miter{sum.x / length, sum.y / length};
        double scale = std::min(1.0 / (miter.x * after.x + miter.y * after.y), miterLimit);
        offsets[i] = {miter.x * halfWidth * scale, miter.y * halfWidth * scale};
    }
    return offsets;
}

// The plane through three points; nullopt when they are collinear in plan.
std::optional<HeightPlane> planeThrough(Vec2d p0, double z0, Vec2d p1, double z1, Vec2d p2, double z2) {
    double ax = p1.x - p0.x, ay = p1.y - p0.y, az = z1 - z0, bx = p2.x - p0.x, by = p2.y - p0.y, bz = z2 - z0;
    double nz = ax * by - ay * bx;
    if (nz == 0) return std::nullopt;
    double b = -(ay * bz - az * by) / nz, c = -(az * bx - ax * bz) / nz;
    return HeightPlane{z0 - b * p0.x - c * p0.y, b, c};
}

}  // namespace

double ribbonLift(LandClass landClass) {
    switch (landClass) {
    case LandClass::Rail: return 0.09;
    case LandClass::Road: return 0.07;
    default: return 0.05;
    }
}

Mesh drapeRibbon(const MapLine &centre, double width, const TerrainSurface &surface, const LocalFrame &frame,
                 const RibbonOptions &options) {
    if (!(width > 0) || !std::isfinite(width)) {
        throw InputError(FileLoc{}, fmt::format("a ribbon's width must be a positive number, not {}", width));
    }
    if (!(options.tileLength > 0) || !(options.lift >= 0) || !(options.miterLimit >= 1)) {
        throw InputError(FileLoc{},
                         fmt::format("ribbon options: tile length {} must be positive, lift {} not negative, "
                                     "miter limit {} at least 1",
                                     options.tileLength, options.lift, options.miterLimit));
    }
    Mesh mesh;
    std::vector<Vec2d> line =
        withoutPointsInCorners(centreLine(centre, surface, frame), 0.5 * width, options.miterLimit);
    if (line.size() < 2) return mesh;
    std::vector<Vec2d> offsets = leftOffsets(line, 0.5 * width, options.miterLimit);
    std::vector<Vec2d> left, right;
    for (size_t i = 0; i < line.size(); ++i) {
        left.push_back({line[i].x + offsets[i].x, line[i].y + offsets[i].y});
        right.push_back({line[i].x - offsets[i].x, line[i].y - offsets[i].y});
    }

    // Level across: one height per centre point, first the highest ground on its cross-section
    // plus the lift. Between cross-sections the ground may still rise above a piece (a node
    // inside it); such a piece is raised with both its ends until neither of its triangles is
    // below surface + lift. Raising a later piece only lifts the ones before it further, so one
    // pass leaves every piece clear.
    constexpr double kUnset = -std::numeric_limits<double>::infinity();
    std::vector<double> heights(line.size(), kUnset);
    for (size_t i = 0; i < line.size(); ++i) {
        std::array<Vec2d, 2> across{left[i], right[i]};
        if (std::optional<double> top = surface.maxOver(across)) heights[i] = *top + options.lift;
    }
    bool onTerrain = false;
    for (size_t i = 0; i + 1 < line.size(); ++i) {
        std::array<Vec2d, 4> quad{right[i], right[i + 1], left[i + 1], left[i]};
        if (heights[i] == kUnset || heights[i + 1] == kUnset) {  // an end off the terrain: start from the piece's top
            std::optional<double> top = surface.maxOver(quad);
            if (!top) continue;
            if (heights[i] == kUnset) heights[i] = *top + options.lift;
            if (heights[i + 1] == kUnset) heights[i + 1] = *top + options.lift;
        }
        onTerrain = true;
        double rise = -std::numeric_limits<double>::infinity();
        for (std::array<int, 3> triangle : {std::array<int, 3>{0, 1, 2}, std::array<int, 3>{0, 2, 3}}) {
            auto z = [&](int k) { return k == 0 || k == 3 ? heights[i] : heights[i + 1]; };
            std::array<Vec2d, 3> corners{quad[size_t(triangle[0])], quad[size_t(triangle[1])],
                                         quad[size_t(triangle[2])]};
            std::optional<HeightPlane> plane =
                planeThrough(corners[0], z(triangle[0]), corners[1], z(triangle[1]), corners[2], z(triangle[2]));
            // A triangle flat in plan covers nothing; its edges belong to the other one or the
            // neighbours.
            if (!plane) continue;
            if (std::optional<double> above = surface.maxAbove(corners, *plane))
                rise = std::max(rise, *above + options.lift);
        }
        if (rise > 0) heights[i] += rise, heights[i + 1] += rise;
    }
    if (!onTerrain) return mesh;
    for (size_t i = 1; i < line.size(); ++i) {  // ends off the terrain take their neighbour's height
        if (heights[i] == kUnset) heights[i] = heights[i - 1];
    }
    for (size_t i = line.size(); i-- > 1;) {
        if (heights[i - 1] == kUnset) heights[i - 1] = heights[i];
    }

    double along = 0;
    for (size_t i = 0; i < line.size(); ++i) {
        if (i > 0) along += std::hypot(line[i].x - line[i - 1].x, line[i].y - line[i - 1].y);
        float v = float(along / options.tileLength);
        mesh.positions.push_back({float(left[i].x), float(left[i].y), float(heights[i])});
        mesh.positions.push_back({float(right[i].x), float(right[i].y), float(heights[i])});
        float u = float(0.5 * width / options.tileLength);
        mesh.uvs.push_back({-u, v});
        mesh.uvs.push_back({u, v});
    }
    for (uint32_t i = 0; i + 1 < line.size(); ++i) {
        uint32_t l0 = 2 * i, r0 = 2 * i + 1, l1 = 2 * i + 2, r1 = 2 * i + 3;
        mesh.indices.insert(mesh.indices.end(), {r0, r1, l1, r0, l1, l0});
    }
    mesh.normals = areaWeightedNormals(mesh);
    mesh.triangleMaterials.assign(mesh.triangleCount(), 0);
    return mesh;
}

}  // namespace veduta

#include "facade/roof_merge.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "core/check.h"

namespace veduta {

namespace {

// The shared part of two connected edges, in the direction of the first.
struct Seam {
    Vec2d from, to;
};

struct RidgeEnds {
    Vec3d touching, other;
};

// a + b·p ≥ 0 over the plan.
struct Constraint {
    double a = 0;
    Vec2d b;
    double at(Vec2d p) const { return a + dot(b, p); }
};

// a + b·t ≥ 0 along a ray.
struct RayConstraint {
    double a = 0, b = 0;
};

Vec2d plan(const Vec3d &p) { return {p.x, p.y}; }

bool samePoint(const Vec3d &p, const Vec3d &q, double tolerance) {
    return std::abs(p.x - q.x) <= tolerance && std::abs(p.y - q.y) <= tolerance && std::abs(p.z - q.z) <= tolerance;
}

double distanceToSegment(Vec2d p, Vec2d a, Vec2d b) {
    Vec2d ab = b - a;
    double t = std::clamp(dot(p - a, ab) / dot(ab, ab), 0.0, 1.0);
    return length(p - (a + ab * t));
}

Vec2d edgeStart(const ModuleRoof &roof, size_t edge) { return roof.outline[edge]; }
Vec2d edgeEnd(const ModuleRoof &roof, size_t edge) { return roof.outline[(edge + 1) % roof.outline.size()]; }

Seam seamOf(const ModuleRoof &first, size_t firstEdge, const ModuleRoof &second, size_t secondEdge, double tolerance) {
    VEDUTA_CHECK(firstEdge < first.outline.size() && secondEdge < second.outline.size(), "no such edge");
    Vec2d a = edgeStart(first, firstEdge), dir = edgeEnd(first, firstEdge) - a;
    Vec2d b0 = edgeStart(second, secondEdge), b1 = edgeEnd(second, secondEdge);
    double len = length(dir);
    VEDUTA_CHECK(std::abs(cross(dir, b0 - a)) <= tolerance * len && std::abs(cross(dir, b1 - a)) <= tolerance * len,
                 "connected edges off one line");
    VEDUTA_CHECK(dot(b1 - b0, dir) < 0, "connected edges run the same way");
    double t0 = dot(b1 - a, dir) / (len * len), t1 = dot(b0 - a, dir) / (len * len);
    double from = std::max(0.0, t0), to = std::min(1.0, t1);
    VEDUTA_CHECK((to - from) * len > tolerance, "connected edges do not overlap");
    return {a + dir * from, a + dir * to};
}

// The ridge with its end over the seam first, if an end is there (L980: r ∈ k).
std::optional<RidgeEnds> touchingRidge(const ModuleRoof &roof, const Seam &seam, double tolerance) {
    if (!roof.ridge) return std::nullopt;
    auto touches = [&](const Vec3d &r) { return distanceToSegment(plan(r), seam.from, seam.to) <= tolerance; };
    if (touches(roof.ridge->a)) return RidgeEnds{roof.ridge->a, roof.ridge->b};
    if (touches(roof.ridge->b)) return RidgeEnds{roof.ridge->b, roof.ridge->a};
    return std::nullopt;
}

bool hasCorner(const ModuleRoofFace &face, const Vec3d &p, double tolerance) {
    return std::any_of(face.corners.begin(), face.corners.end(),
                       [&](const Vec3d &c) { return samePoint(c, p, tolerance); });
}

size_t cornerIndex(const ModuleRoofFace &face, const Vec3d &p, double tolerance) {
    for (size_t k = 0; k < face.corners.size(); ++k) {
        if (samePoint(face.corners[k], p, tolerance)) return k;
    }
    VEDUTA_UNREACHABLE("a face without the corner it was chosen for");
}

// The faces round the ridge end of a gable: the interface on the seam edge, then the two slopes
// that share the ridge; nothing else meets there.
std::optional<std::array<size_t, 3>> gableEnd(const ModuleRoof &roof, size_t edge, const RidgeEnds &ends,
                                              double tolerance) {
    if (length(plan(ends.touching) - plan(ends.other)) <= tolerance) return std::nullopt;
    std::vector<size_t> around;
    for (size_t f = 0; f < roof.faces.size(); ++f) {
        if (hasCorner(roof.faces[f], ends.touching, tolerance)) around.push_back(f);
    }
    if (around.size() != 3) return std::nullopt;
    std::stable_partition(around.begin(), around.end(), [&](size_t f) {
        return roof.faces[f].kind == RoofFaceKind::Interface && roof.faces[f].edge == edge;
    });
    const ModuleRoofFace &gable = roof.faces[around[0]];
    if (gable.kind != RoofFaceKind::Interface || gable.edge != edge || gable.corners.size() != 3) return std::nullopt;
    for (size_t k : {1, 2}) {
        const ModuleRoofFace &slope = roof.faces[around[k]];
        if (slope.kind != RoofFaceKind::Slope || !hasCorner(slope, ends.other, tolerance)) return std::nullopt;
    }
    return std::array<size_t, 3>{around[0], around[1], around[2]};
}

double surfaceHeight(const std::vector<RoofPlane> &planes, Vec2d p) {
    double height = std::numeric_limits<double>::infinity();
    for (const RoofPlane &plane : planes) height = std::min(height, plane.heightAt(p));
    return height;
}

// The first distance along the ray from `origin` (on the neighbour's edge) in `direction` at
// which the neighbour's surface reaches `height` while the ray is still over the neighbour: the
// surface is the minimum of planes, so that is where the last of the linear conditions holds.
std::optional<double> rayHit(const ModuleRoof &neighbour, const std::vector<RoofPlane> &planes, Vec2d origin,
                             Vec2d direction, double height, double tolerance) {
    std::vector<RayConstraint> along;
    for (size_t i = 0; i < neighbour.outline.size(); ++i) {
        Vec2d a = edgeStart(neighbour, i), side = edgeEnd(neighbour, i) - a;
        double scale = 1 / length(side);
        along.push_back({cross(side, origin - a) * scale, cross(side, direction) * scale});
    }
    for (const RoofPlane &plane : planes) {
        along.push_back({plane.heightAt(origin) - height, plane.gx * direction.x + plane.gy * direction.y});
    }
    double lowest = 0, highest = std::numeric_limits<double>::infinity();
    for (const RayConstraint &c : along) {
        if (std::abs(c.b) <= 1e-15) {
            if (c.a < -tolerance) return std::nullopt;
        } else if (c.b > 0) {
            lowest = std::max(lowest, -c.a / c.b);
        } else {
            highest = std::min(highest, -c.a / c.b);
        }
    }
    if (lowest <= tolerance || lowest > highest + tolerance) return std::nullopt;
    return lowest;
}

// Sutherland–Hodgman: the part of a convex polygon where the constraint holds, up to the
// tolerance, so that a region squeezed onto a line (a valley that is the chord) keeps its ends.
std::vector<Vec2d> clip(const std::vector<Vec2d> &polygon, const Constraint &keep, double tolerance) {
    std::vector<Vec2d> kept;
    for (size_t k = 0, n = polygon.size(); k < n; ++k) {
        Vec2d p = polygon[k], q = polygon[(k + 1) % n];
        double vp = keep.at(p), vq = keep.at(q);
        bool pIn = vp >= -tolerance, qIn = vq >= -tolerance;
        if (pIn) kept.push_back(p);
        if (pIn != qIn) kept.push_back(p + (q - p) * std::clamp(vp / (vp - vq), 0.0, 1.0));
    }
    return kept;
}

size_t nearest(const std::vector<Vec2d> &points, Vec2d p) {
    size_t best = 0;
    for (size_t k = 1; k < points.size(); ++k) {
        if (length(points[k] - p) < length(points[best] - p)) best = k;
    }
    return best;
}

// The valley of a slope over the neighbour, from the seam corner s to the new ridge end p,
// without its ends. Triangle (s, ridge foot, p) holds it: the region where the neighbour lies
// above the slope is convex (the neighbour's surface is concave) and holds s, p and the ridge
// beyond p, so the slope stands above the neighbour only between the valley and the ridge foot.
// That region clipped out of the triangle leaves the valley as the boundary from s to p that
// is not the chord, or the chord itself.
std::vector<Vec2d> valleyBetween(Vec2d s, Vec2d foot, Vec2d p, const RoofPlane &slope,
                                 const std::vector<RoofPlane> &neighbour, double tolerance) {
    std::vector<Vec2d> region{s, foot, p};
    if (cross(foot - s, p - s) < 0) std::swap(region[1], region[2]);
    for (const RoofPlane &plane : neighbour) {
        region = clip(region, {plane.z0 - slope.z0, {plane.gx - slope.gx, plane.gy - slope.gy}}, tolerance);
    }
    std::vector<Vec2d> corners;
    for (Vec2d c : region) {
        if (corners.empty() || length(c - corners.back()) > tolerance) corners.push_back(c);
    }
    while (corners.size() > 1 && length(corners.front() - corners.back()) <= tolerance) corners.pop_back();
    VEDUTA_CHECK(!corners.empty(), "a valley region without corners");
    size_t n = corners.size(), from = nearest(corners, s), to = nearest(corners, p);
    VEDUTA_CHECK(length(corners[from] - s) <= 1e3 * tolerance && length(corners[to] - p) <= 1e3 * tolerance,
                 "a valley that misses its ends");
    auto onValley = [&](Vec2d c) { return std::abs(slope.heightAt(c) - surfaceHeight(neighbour, c)) <= tolerance; };
    std::vector<Vec2d> best;
    for (size_t step : {size_t{1}, n - 1}) {
        std::vector<Vec2d> inner;
        for (size_t k = (from + step) % n; k != to && k != from; k = (k + step) % n) inner.push_back(corners[k]);
        if (std::all_of(inner.begin(), inner.end(), onValley) && inner.size() > best.size()) best = inner;
    }
    return best;
}

Vec3d onPlane(Vec2d p, const RoofPlane &plane) { return {p.x, p.y, plane.heightAt(p)}; }

// The slope with its corner at the old ridge end replaced by the valley up to the new one.
void extendSlope(ModuleRoofFace &slope, const RidgeEnds &ends, const Vec3d &newEnd,
                 const std::vector<RoofPlane> &neighbour, double tolerance) {
    size_t n = slope.corners.size(), at = cornerIndex(slope, ends.touching, tolerance);
    const Vec3d &before = slope.corners[(at + n - 1) % n], &after = slope.corners[(at + 1) % n];
    bool seamBefore = !samePoint(before, ends.other, tolerance);
    Vec3d seamCorner = seamBefore ? before : after;
    RoofPlane plane = facePlane(slope);
    std::vector<Vec3d> valley;
    for (Vec2d v : valleyBetween(plan(seamCorner), plan(ends.touching), plan(newEnd), plane, neighbour, tolerance)) {
        valley.push_back(onPlane(v, plane));
    }
    // Walking the face, the seam corner comes before the old end or after it.
    if (seamBefore) {
        valley.push_back(newEnd);
    } else {
        std::reverse(valley.begin(), valley.end());
        valley.insert(valley.begin(), newEnd);
    }
    slope.corners.erase(slope.corners.begin() + static_cast<std::ptrdiff_t>(at));
    slope.corners.insert(slope.corners.begin() + static_cast<std::ptrdiff_t>(at), valley.begin(), valley.end());
}

RoofMergeOutcome extendRidge(ModuleRoof &roof, size_t edge, const RidgeEnds &ends, const ModuleRoof &neighbour,
                             const Seam &seam, double tolerance) {
    std::optional<std::array<size_t, 3>> faces = gableEnd(roof, edge, ends, tolerance);
    if (!faces) return RoofMergeOutcome::NotAGableEnd;
    if (std::abs(roof.eavesZ - neighbour.eavesZ) > tolerance) return RoofMergeOutcome::EavesDiffer;
    std::vector<RoofPlane> planes = slopePlanes(neighbour);
    for (const Vec3d &corner : roof.faces[(*faces)[0]].corners) {
        if (samePoint(corner, ends.touching, tolerance)) continue;
        if (distanceToSegment(plan(corner), seam.from, seam.to) > tolerance)
            return RoofMergeOutcome::GableWiderThanSeam;
        if (std::abs(surfaceHeight(planes, plan(corner)) - neighbour.eavesZ) > tolerance) {
            return RoofMergeOutcome::NeighbourRisesAtSeam;
        }
    }
    Vec2d origin = plan(ends.touching), direction = origin - plan(ends.other);
    direction = direction * (1 / length(direction));
    std::optional<double> hit = rayHit(neighbour, planes, origin, direction, ends.touching.z, tolerance);
    if (!hit) return RoofMergeOutcome::RidgeMissesNeighbour;
    Vec2d end = origin + direction * *hit;
    Vec3d newEnd{end.x, end.y, ends.touching.z};
    for (size_t k : {1, 2}) extendSlope(roof.faces[(*faces)[k]], ends, newEnd, planes, tolerance);
    roof.faces.erase(roof.faces.begin() + static_cast<std::ptrdiff_t>((*faces)[0]));
    (samePoint(roof.ridge->a, ends.touching, tolerance) ? roof.ridge->a : roof.ridge->b) = newEnd;
    return RoofMergeOutcome::Extended;
}

}  // namespace

RoofMergeOutcome mergeRoofs(ModuleRoof &first, size_t firstEdge, ModuleRoof &second, size_t secondEdge) {
    double tolerance = std::max(roofTolerance(first), roofTolerance(second));
    Seam seam = seamOf(first, firstEdge, second, secondEdge, tolerance);
    std::optional<RidgeEnds> firstTouches = touchingRidge(first, seam, tolerance);
    std::optional<RidgeEnds> secondTouches = touchingRidge(second, seam, tolerance);
    if (firstTouches && secondTouches) return RoofMergeOutcome::BothRidgesTouch;
    if (firstTouches) return extendRidge(first, firstEdge, *firstTouches, second, seam, tolerance);
    if (secondTouches) return extendRidge(second, secondEdge, *secondTouches, first, seam, tolerance);
    return RoofMergeOutcome::NeitherRidgeTouches;
}

}  // namespace veduta

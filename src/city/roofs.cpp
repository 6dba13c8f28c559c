#include "city/roofs.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <stdexcept>

namespace veduta {

namespace {

// Top edges shorter than this along their footprint edge count as vanished: a roof facet
// narrower than a centimetre is float noise, not a roof.
constexpr float kMinTopEdgeLength = 0.01f;

// Texture coordinates in metres on a plane: distances from `origin` along two unit axes.
struct UvPlane {
    Vec3f origin, u, v;
    Vec2f at(const Vec3f &p) const { return {dot(p - origin, u), dot(p - origin, v)}; }
};

// The unit normal of a planar polygon, counter-clockwise seen from its front: Newell's sum,
// taken relative to the first corner so that buildings far from the origin keep their precision.
Vec3f faceNormal(std::initializer_list<Vec3f> corners) {
    Vec3f sum{0.0f};
    const Vec3f *c = corners.begin();
    for (size_t i = 1; i + 1 < corners.size(); ++i) sum += cross(c[i] - c[0], c[i + 1] - c[0]);
    return normalize(sum);
}

// A roof covering's texture runs one tile per metre along its eaves (its first edge) and one
// per metre up the slant, not per metre of height, so that tiles keep their size on any pitch.
UvPlane slopeUvPlane(std::initializer_list<Vec3f> corners) {
    const Vec3f *c = corners.begin();
    Vec3f along = normalize(c[1] - c[0]);
    return {c[0], along, cross(faceNormal(corners), along)};
}

// A convex face, counter-clockwise seen from outside, with its own vertices, so that its normal
// is the face's.
void addFace(Mesh &m, std::initializer_list<Vec3f> corners, const UvPlane &uv, RoofSurface surface) {
    auto base = uint32_t(m.positions.size());
    Vec3f normal = faceNormal(corners);
    for (const Vec3f &p : corners) {
        m.positions.push_back(p);
        m.normals.push_back(normal);
        m.uvs.push_back(uv.at(p));
    }
    for (uint32_t k = 1; k + 1 < corners.size(); ++k) {
        m.indices.insert(m.indices.end(), {base, base + k, base + k + 1});
        m.triangleMaterials.push_back(surface);
    }
}

void addSlope(Mesh &m, std::initializer_list<Vec3f> corners) {
    addFace(m, corners, slopeUvPlane(corners), RoofCovering);
}

// A horizontal polygon facing up, u = x and v = y in metres.
void addFlatTop(Mesh &m, const std::vector<Vec2f> &outline, float z) {
    auto base = uint32_t(m.positions.size());
    for (Vec2f p : outline) {
        m.positions.push_back(lift(p, z));
        m.normals.push_back({0, 0, 1});
        m.uvs.push_back(p);
    }
    for (uint32_t index : triangulatePolygon(outline)) m.indices.push_back(base + index);
    m.triangleMaterials.resize(m.triangleCount(), RoofCovering);
}

bool isRightAngled(const Footprint &footprint) {
    float tolerance = std::sin(radians(kRightAngleToleranceDegrees));
    for (size_t e = 0; e < footprint.edgeCount(); ++e) {
        float cosine = dot(footprint.edgeDirection(e), footprint.edgeDirection((e + 1) % footprint.edgeCount()));
        if (std::abs(cosine) > tolerance) return false;
    }
    return true;
}

size_t firstStreetEdge(const Footprint &footprint) {
    auto street = std::find(footprint.streetEdges.begin(), footprint.streetEdges.end(), true);
    return street == footprint.streetEdges.end() ? 0 : size_t(street - footprint.streetEdges.begin());
}

// Each edge moved `inset` inwards and neighbouring lines intersected: corner i moves by
// inset · (a + b) / (1 + a·b), a and b the inward normals of the edges meeting there, which lies
// on both moved lines (and is inset · a where the edges run straight on).
std::vector<Vec2f> insetOutline(const Footprint &footprint, float inset) {
    std::vector<Vec2f> outline;
    size_t n = footprint.edgeCount();
    for (size_t i = 0; i < n; ++i) {
        Vec3f a = -footprint.outwardNormal((i + n - 1) % n), b = -footprint.outwardNormal(i);
        Vec3f corner = lift(footprint.points[i], 0) + (a + b) * (inset / (1 + dot(a, b)));
        outline.push_back({corner.x, corner.y});
    }
    return outline;
}

// An inset outline is a roof top when every edge still runs the way its footprint edge does,
// at least kMinTopEdgeLength long, and the outline is simple, counter-clockwise and inside.
bool isValidTop(const Footprint &footprint, const std::vector<Vec2f> &top) {
    for (size_t e = 0; e < top.size(); ++e) {
        Vec3f edge = lift(top[(e + 1) % top.size()], 0) - lift(top[e], 0);
        if (dot(edge, footprint.edgeDirection(e)) < kMinTopEdgeLength) return false;
    }
    return isSimplePolygon(top) && isCounterClockwise(top) && liesInside(top, footprint.points);
}

MansardRoof slopedMansard(const Footprint &footprint, std::vector<Vec2f> top, float inset, float eavesZ, float topZ) {
    MansardRoof roof{{}, inset, std::move(top)};
    size_t n = footprint.edgeCount();
    for (size_t e = 0; e < n; ++e) {
        Vec3f lowerLeft = lift(footprint.edgeStart(e), eavesZ), lowerRight = lift(footprint.edgeEnd(e), eavesZ);
        Vec3f upperRight = lift(roof.top[(e + 1) % n], topZ), upperLeft = lift(roof.top[e], topZ);
        addSlope(roof.mesh, {lowerLeft, lowerRight, upperRight, upperLeft});
    }
    addFlatTop(roof.mesh, roof.top, topZ);
    return roof;
}

}  // namespace

RoofKind chooseRoofKind(const Footprint &footprint) {
    bool gable = footprint.edgeCount() == 4 &&
                 std::count(footprint.streetEdges.begin(), footprint.streetEdges.end(), true) == 1 &&
                 isRightAngled(footprint);
    return gable ? RoofKind::Gable : RoofKind::Mansard;
}

Mesh gableRoof(const Footprint &footprint, float eavesHeight, float roofHeight) {
    if (footprint.edgeCount() != 4) throw std::invalid_argument("a gable roof needs a footprint of four points");
    if (!(roofHeight > 0)) throw std::invalid_argument("a gable roof needs a positive roof height");
    // P1 → P2 is the street edge; the thesis' corners, in its order.
    size_t street = firstStreetEdge(footprint);
    float eavesZ = footprint.base + eavesHeight;
    Vec3f p[4];
    for (size_t k = 0; k < 4; ++k) p[k] = lift(footprint.points[(street + k) % 4], eavesZ);
    Vec3f rise{0, 0, roofHeight};
    Vec3f ridge1 = (p[3] + p[0]) * 0.5f + rise, ridge2 = (p[1] + p[2]) * 0.5f + rise;

    Mesh m;
    addSlope(m, {p[0], p[1], ridge2, ridge1});
    addSlope(m, {p[2], p[3], ridge1, ridge2});
    // The gable ends carry on their facades' walls: metres along the perimeter and up, as the
    // walls' texture runs (building_generator.h).
    for (size_t k : {size_t(1), size_t(3)}) {
        size_t edge = (street + k) % 4;
        Vec3f along = footprint.edgeDirection(edge);
        UvPlane wall{lift(footprint.edgeStart(edge), footprint.base) - along * footprint.perimeterBefore(edge), along,
                     {0, 0, 1}};
        addFace(m, {p[k], p[(k + 1) % 4], k == 1 ? ridge2 : ridge1}, wall, RoofGableWall);
    }
    return m;
}

MansardRoof mansardRoof(const Footprint &footprint, float eavesHeight, float roofHeight, float inset) {
    float eavesZ = footprint.base + eavesHeight;
    for (int halvings = 0; inset > 0 && halvings <= kMansardInsetHalvings; ++halvings, inset /= 2) {
        std::vector<Vec2f> top = insetOutline(footprint, inset);
        if (isValidTop(footprint, top)) return slopedMansard(footprint, std::move(top), inset, eavesZ, eavesZ + roofHeight);
    }
    MansardRoof flat{{}, 0, footprint.points};
    addFlatTop(flat.mesh, flat.top, eavesZ);
    return flat;
}

}  // namespace veduta

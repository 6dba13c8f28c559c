#include "city/roofs.h"

#include "city/roof_faces.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace veduta {

namespace {

// Top edges shorter than this along their footprint edge count as vanished: a roof facet
// narrower than a centimetre is float noise, not a roof.
constexpr float kMinTopEdgeLength = 0.01f;

void addSlope(Mesh &m, const std::vector<Vec3f> &corners) {
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

size_t firstStreetEdge(const Footprint &footprint) {
    auto street = std::find(footprint.streetEdges.begin(), footprint.streetEdges.end(), true);
    return street == footprint.streetEdges.end() ? 0 : size_t(street - footprint.streetEdges.begin());
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

bool isRightAngled(const Footprint &footprint) {
    float tolerance = std::sin(radians(kRightAngleToleranceDegrees));
    for (size_t e = 0; e < footprint.edgeCount(); ++e) {
        float cosine = dot(footprint.edgeDirection(e), footprint.edgeDirection((e + 1) % footprint.edgeCount()));
        if (std::abs(cosine) > tolerance) return false;
    }
    return true;
}

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
        UvPlane wall = wallUvPlane(footprint.edgeStart(edge), footprint.edgeDirection(edge),
                                   footprint.perimeterBefore(edge), footprint.base);
        addFace(m, {p[k], p[(k + 1) % 4], k == 1 ? ridge2 : ridge1}, wall, RoofGableWall);
    }
    return m;
}

MansardRoof mansardRoof(const Footprint &footprint, float eavesHeight, float roofHeight, float inset) {
    float eavesZ = footprint.base + eavesHeight;
    for (int halvings = 0; inset > 0 && halvings <= kMansardInsetHalvings; ++halvings, inset /= 2) {
        std::vector<Vec2f> top = offsetPolygon(footprint.points, -inset);
        if (isValidTop(footprint, top)) return slopedMansard(footprint, std::move(top), inset, eavesZ, eavesZ + roofHeight);
    }
    MansardRoof flat{{}, 0, footprint.points};
    addFlatTop(flat.mesh, flat.top, eavesZ);
    return flat;
}

}  // namespace veduta

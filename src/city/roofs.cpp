#include "city/roofs.h"

#include "city/roof_faces.h"

#include <cmath>

namespace veduta {

namespace {

// Top edges shorter than this along their footprint edge count as vanished: a roof facet
// narrower than a centimetre is float noise, not a roof.
constexpr float kMinTopEdgeLength = 0.01f;

void addSlope(Mesh &m, const std::vector<Vec3f> &corners) { addFace(m, corners, slopeUvPlane(corners), RoofCovering); }

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

MansardRoof mansardRoof(const Footprint &footprint, float eavesHeight, float roofHeight, float inset) {
    float eavesZ = footprint.base + eavesHeight;
    for (int halvings = 0; inset > 0 && halvings <= kMansardInsetHalvings; ++halvings, inset /= 2) {
        std::vector<Vec2f> top = offsetPolygon(footprint.points, -inset);
        if (isValidTop(footprint, top))
            return slopedMansard(footprint, std::move(top), inset, eavesZ, eavesZ + roofHeight);
    }
    MansardRoof flat{{}, 0, footprint.points};
    addFlatTop(flat.mesh, flat.top, eavesZ);
    return flat;
}

}  // namespace veduta

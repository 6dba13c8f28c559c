#include "city/roof_faces.h"

namespace veduta {

namespace {

void addCorners(Mesh &m, const std::vector<Vec3f> &corners, const Vec3f &normal, const UvPlane &uv) {
    for (const Vec3f &p : corners) {
        m.positions.push_back(p);
        m.normals.push_back(normal);
        m.uvs.push_back(uv.at(p));
    }
}

}  // namespace

Vec3f faceNormal(const std::vector<Vec3f> &corners) {
    Vec3f sum{0.0f};
    for (size_t i = 1; i + 1 < corners.size(); ++i) sum += cross(corners[i] - corners[0], corners[i + 1] - corners[0]);
    return normalize(sum);
}

UvPlane slopeUvPlane(const std::vector<Vec3f> &corners) {
    Vec3f along = normalize(corners[1] - corners[0]);
    return {corners[0], along, cross(faceNormal(corners), along)};
}

UvPlane wallUvPlane(Vec2f start, const Vec3f &along, float perimeterBefore, float base) {
    return {lift(start, base) - along * perimeterBefore, along, {0, 0, 1}};
}

void addFace(Mesh &m, const std::vector<Vec3f> &corners, const UvPlane &uv, RoofSurface surface) {
    auto base = uint32_t(m.positions.size());
    addCorners(m, corners, faceNormal(corners), uv);
    for (uint32_t k = 1; k + 1 < corners.size(); ++k) {
        m.indices.insert(m.indices.end(), {base, base + k, base + k + 1});
        m.triangleMaterials.push_back(surface);
    }
}

void addProjectedFace(Mesh &m, const std::vector<std::vector<Vec3f>> &rings, const Vec3f &normal, const UvPlane &uv,
                      RoofSurface surface) {
    auto base = uint32_t(m.positions.size());
    std::vector<std::vector<Vec2f>> ground;
    for (const std::vector<Vec3f> &ring : rings) {
        addCorners(m, ring, normal, uv);
        ground.emplace_back();
        for (const Vec3f &p : ring) ground.back().push_back({p.x, p.y});
    }
    for (uint32_t index : triangulatePolygonWithHoles(ground)) m.indices.push_back(base + index);
    m.triangleMaterials.resize(m.triangleCount(), surface);
}

}  // namespace veduta

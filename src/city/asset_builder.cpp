#include "city/asset_builder.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "core/check.h"

namespace veduta {

namespace {

float cross2(Vec2f u, Vec2f v) { return u.x * v.y - u.y * v.x; }

float signedArea(std::span<const Vec2f> outline) {
    float area = 0;
    for (size_t i = 0; i < outline.size(); ++i) area += cross2(outline[i], outline[(i + 1) % outline.size()]);
    return area / 2;
}

bool insideTriangle(Vec2f p, Vec2f a, Vec2f b, Vec2f c) {
    return cross2(b - a, p - a) >= 0 && cross2(c - b, p - b) >= 0 && cross2(a - c, p - c) >= 0;
}

// Ear clipping: the outlines here have a few dozen points, so the quadratic search for ears
// costs nothing. Takes a counter-clockwise outline; gives triangles counter-clockwise.
std::vector<uint32_t> triangulate(std::span<const Vec2f> outline) {
    std::vector<uint32_t> left(outline.size());
    std::iota(left.begin(), left.end(), 0u);
    std::vector<uint32_t> triangles;
    auto isEar = [&](size_t i) {
        size_t n = left.size();
        uint32_t a = left[(i + n - 1) % n], b = left[i], c = left[(i + 1) % n];
        if (cross2(outline[b] - outline[a], outline[c] - outline[b]) <= 0) return false;
        return std::none_of(left.begin(), left.end(), [&](uint32_t p) {
            return p != a && p != b && p != c && insideTriangle(outline[p], outline[a], outline[b], outline[c]);
        });
    };
    while (left.size() > 3) {
        size_t i = 0;
        while (i < left.size() && !isEar(i)) ++i;
        // Built-in outlines are simple polygons; one without an ear is a bug in its model.
        VEDUTA_CHECK(i != left.size(), "asset outline is not a simple polygon");
        size_t n = left.size();
        triangles.insert(triangles.end(), {left[(i + n - 1) % n], left[i], left[(i + 1) % n]});
        left.erase(left.begin() + std::ptrdiff_t(i));
    }
    triangles.insert(triangles.end(), left.begin(), left.end());
    return triangles;
}

// Outline edges closer than this to a straight continuation share their vertex normal:
// arcs of up to 12 segments per quarter turn are smooth, the corners of a profile sharp.
const float kSmoothCosine = std::cos(radians(30));

// A prism in its own frame: the outline in (x, y), counter-clockwise, extruded along z.
Mesh extrude(std::span<const Vec2f> outline, float from, float to) {
    Mesh m;
    size_t n = outline.size();
    std::vector<Vec3f> edgeNormals(n);
    for (size_t i = 0; i < n; ++i) {
        Vec2f d = outline[(i + 1) % n] - outline[i];
        edgeNormals[i] = normalize(Vec3f{d.y, -d.x, 0});
    }
    auto cornerNormal = [&](const Vec3f &own, const Vec3f &neighbour) {
        return dot(own, neighbour) > kSmoothCosine ? normalize(own + neighbour) : own;
    };
    float u = 0;
    for (size_t i = 0; i < n; ++i) {
        Vec2f p = outline[i], q = outline[(i + 1) % n];
        float width = std::hypot(q.x - p.x, q.y - p.y);
        auto base = uint32_t(m.positions.size());
        m.positions.insert(m.positions.end(), {{p.x, p.y, from}, {q.x, q.y, from}, {q.x, q.y, to}, {p.x, p.y, to}});
        Vec3f start = cornerNormal(edgeNormals[i], edgeNormals[(i + n - 1) % n]);
        Vec3f end = cornerNormal(edgeNormals[i], edgeNormals[(i + 1) % n]);
        m.normals.insert(m.normals.end(), {start, end, end, start});
        m.uvs.insert(m.uvs.end(), {{u, from}, {u + width, from}, {u + width, to}, {u, to}});
        m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
        u += width;
    }
    std::vector<uint32_t> capTriangles = triangulate(outline);
    for (bool front : {true, false}) {
        auto base = uint32_t(m.positions.size());
        for (Vec2f p : outline) {
            m.positions.push_back({p.x, p.y, front ? to : from});
            m.normals.push_back({0, 0, front ? 1.0f : -1.0f});
            // Mirrored on the back so that the texture reads the right way round from there too.
            m.uvs.push_back({front ? p.x : -p.x, p.y});
        }
        for (size_t t = 0; t < capTriangles.size(); t += 3) {
            uint32_t a = base + capTriangles[t], b = base + capTriangles[t + 1], c = base + capTriangles[t + 2];
            if (front) {
                m.indices.insert(m.indices.end(), {a, b, c});
            } else {
                m.indices.insert(m.indices.end(), {a, c, b});
            }
        }
    }
    return m;
}

// Maps a prism's own frame (outline in x, y; extrusion along z) onto the model axes. Each is
// a cyclic permutation, so no triangle turns inside out.
Transform prismPlacement(PrismAxis axis) {
    switch (axis) {
    case PrismAxis::X: return {{0, 0, 1, 0, 1, 0, 0, 0, 0, 1, 0, 0}};
    case PrismAxis::Y: return {{0, 1, 0, 0, 0, 0, 1, 0, 1, 0, 0, 0}};
    case PrismAxis::Z: return {};
    }
    return {};
}

}  // namespace

void AssetBuilder::prism(std::span<const Vec2f> outline, PrismAxis axis, float from, float to,
                         MaterialCategory surface) {
    if (signedArea(outline) >= 0) {
        add(extrude(outline, from, to), prismPlacement(axis), surface);
        return;
    }
    std::vector<Vec2f> counterClockwise(outline.rbegin(), outline.rend());
    add(extrude(counterClockwise, from, to), prismPlacement(axis), surface);
}

void AssetBuilder::box(const Vec3f &min, const Vec3f &max, MaterialCategory surface) {
    const Vec2f outline[] = {{min.x, min.y}, {max.x, min.y}, {max.x, max.y}, {min.x, max.y}};
    prism(outline, PrismAxis::Z, min.z, max.z, surface);
}

void AssetBuilder::rectangle(const Vec3f &corner, const Vec3f &u, const Vec3f &v, MaterialCategory surface) {
    Mesh m;
    m.positions = {corner, corner + u, corner + u + v, corner + v};
    m.normals.assign(4, normalize(cross(u, v)));
    float width = length(u), height = length(v);
    m.uvs = {{0, 0}, {width, 0}, {width, height}, {0, height}};
    m.indices = {0, 1, 2, 0, 2, 3};
    add(std::move(m), {}, surface);
}

void AssetBuilder::add(Mesh part, const Transform &placement, MaterialCategory surface) {
    auto it = std::find(surfaces_.begin(), surfaces_.end(), surface);
    auto index = uint32_t(it - surfaces_.begin());
    if (it == surfaces_.end()) surfaces_.push_back(surface);
    part.setMaterial(index);
    mesh_.append(part, placement);
}

Asset AssetBuilder::finish(std::string name, ModelType type) && {
    Asset asset{std::move(name), type, std::move(mesh_), std::move(surfaces_), Vec3f{0.0f}, Vec3f{0.0f}};
    if (!asset.mesh.positions.empty()) {
        asset.boundsMin = asset.boundsMax = asset.mesh.positions.front();
        for (const Vec3f &p : asset.mesh.positions) {
            for (int axis = 0; axis < 3; ++axis) {
                asset.boundsMin[axis] = std::min(asset.boundsMin[axis], p[axis]);
                asset.boundsMax[axis] = std::max(asset.boundsMax[axis], p[axis]);
            }
        }
    }
    return asset;
}

void appendArc(std::vector<Vec2f> &points, Vec2f centre, float radius, float fromDegrees, float toDegrees,
               int segments) {
    for (int i = 0; i <= segments; ++i) {
        float angle = radians(fromDegrees + (toDegrees - fromDegrees) * float(i) / float(segments));
        points.push_back({centre.x + radius * std::cos(angle), centre.y + radius * std::sin(angle)});
    }
}

std::vector<Vec2f> mouldingOutline(std::span<const Vec2f> profile, float bottom) {
    std::vector<Vec2f> outline;
    for (Vec2f p : profile) outline.push_back({bottom + p.x, p.y});
    return outline;
}

}  // namespace veduta

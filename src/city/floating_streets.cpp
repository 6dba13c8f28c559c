#include "city/floating_streets.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <cmath>
#include <map>

namespace veduta {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vertex = CGAL::Triangulation_vertex_base_with_info_2<uint32_t, Kernel>;
using Delaunay = CGAL::Delaunay_triangulation_2<Kernel, CGAL::Triangulation_data_structure_2<Vertex>>;

uint32_t addVertex(Mesh &mesh, const Vec3f &p, const Vec3f &normal, Vec2f uv) {
    mesh.positions.push_back(p);
    mesh.normals.push_back(normal);
    mesh.uvs.push_back(uv);
    return uint32_t(mesh.positions.size() - 1);
}

void addTriangle(Mesh &mesh, uint32_t a, uint32_t b, uint32_t c) {
    mesh.indices.insert(mesh.indices.end(), {a, b, c});
    mesh.triangleMaterials.push_back(0);
}

// The side wall under the top's boundary edge from p to q (counter-clockwise seen from above,
// so the outside lies to the right).
void addSide(Mesh &mesh, Vec2f p, Vec2f q, float top, float bottom) {
    Vec2f d = q - p;
    float length = std::hypot(d.x, d.y);
    if (length == 0) return;
    Vec3f out{d.y / length, -d.x / length, 0};
    float depth = top - bottom;
    uint32_t pb = addVertex(mesh, {p.x, p.y, bottom}, out, {0, 0});
    uint32_t qb = addVertex(mesh, {q.x, q.y, bottom}, out, {length, 0});
    uint32_t qt = addVertex(mesh, {q.x, q.y, top}, out, {length, depth});
    uint32_t pt = addVertex(mesh, {p.x, p.y, top}, out, {0, depth});
    addTriangle(mesh, pb, qb, qt);
    addTriangle(mesh, pb, qt, pt);
}

}  // namespace

namespace {

// Contour points closer than this are one: neighbouring arms whose corners meet would otherwise
// leave slivers a rounding error wide.
constexpr float kSamePoint = 1e-3f;

void addContourPoint(Vec2f p, std::vector<Vec2f> &plan) {
    for (Vec2f q : plan)
        if (std::hypot(p.x - q.x, p.y - q.y) < kSamePoint) return;
    plan.push_back(p);
}

}  // namespace

Mesh crossingSolid(const Vec3f &centre, std::span<const CrossingArm> arms, float mouth, float thickness) {
    std::vector<std::pair<Kernel::Point_2, uint32_t>> points;
    std::vector<Vec2f> plan{{centre.x, centre.y}};
    for (const CrossingArm &arm : arms) {
        Vec2f across{-arm.direction.y, arm.direction.x};
        Vec2f mouthCentre = Vec2f{centre.x, centre.y} + arm.direction * mouth;
        addContourPoint(mouthCentre + across * (arm.width / 2), plan);
        addContourPoint(mouthCentre - across * (arm.width / 2), plan);
    }
    for (uint32_t i = 0; i < plan.size(); ++i) points.push_back({{plan[i].x, plan[i].y}, i});
    Delaunay triangulation(points.begin(), points.end());

    Mesh mesh;
    float top = centre.z, bottom = centre.z - thickness;
    std::vector<uint32_t> topIds(plan.size()), bottomIds(plan.size());
    for (uint32_t i = 0; i < plan.size(); ++i) {
        topIds[i] = addVertex(mesh, {plan[i].x, plan[i].y, top}, {0, 0, 1}, plan[i]);
        bottomIds[i] = addVertex(mesh, {plan[i].x, plan[i].y, bottom}, {0, 0, -1}, plan[i]);
    }
    for (auto face = triangulation.finite_faces_begin(); face != triangulation.finite_faces_end(); ++face) {
        uint32_t v[3] = {face->vertex(0)->info(), face->vertex(1)->info(), face->vertex(2)->info()};
        addTriangle(mesh, topIds[v[0]], topIds[v[1]], topIds[v[2]]);
        addTriangle(mesh, bottomIds[v[0]], bottomIds[v[2]], bottomIds[v[1]]);
        for (int i = 0; i < 3; ++i)
            if (triangulation.is_infinite(face->neighbor(i)))
                addSide(mesh, plan[v[(i + 1) % 3]], plan[v[(i + 2) % 3]], top, bottom);
    }
    return mesh;
}

Mesh solidBox(const Vec3f &corner, const Vec3f &e1, const Vec3f &e2, const Vec3f &e3) {
    // With a left-handed frame the faces below would face in: swap two edges.
    bool rightHanded = dot(cross(e1, e2), e3) > 0;
    const Vec3f &a = rightHanded ? e1 : e2, &b = rightHanded ? e2 : e1;
    // The corners once, so that faces meeting at one share its float position exactly: bit i of
    // the index adds edge a, b or e3.
    Vec3f corners[8];
    for (int i = 0; i < 8; ++i)
        corners[i] = corner + a * float(i & 1) + b * float((i >> 1) & 1) + e3 * float((i >> 2) & 1);
    Mesh mesh;
    // Each face: four corners counter-clockwise seen from outside, and its two edge lengths.
    auto face = [&](int p0, int p1, int p2, int p3) {
        Vec3f u = corners[p1] - corners[p0], v = corners[p3] - corners[p0];
        Vec3f normal = normalize(cross(u, v));
        float lu = length(u), lv = length(v);
        uint32_t q0 = addVertex(mesh, corners[p0], normal, {0, 0});
        uint32_t q1 = addVertex(mesh, corners[p1], normal, {lu, 0});
        uint32_t q2 = addVertex(mesh, corners[p2], normal, {lu, lv});
        uint32_t q3 = addVertex(mesh, corners[p3], normal, {0, lv});
        addTriangle(mesh, q0, q1, q2);
        addTriangle(mesh, q0, q2, q3);
    };
    face(0, 2, 3, 1);  // below: b then a
    face(4, 5, 7, 6);  // above: a then b
    face(0, 1, 5, 4);  // the a, e3 side at the corner
    face(2, 6, 7, 3);  // the one across, b further
    face(0, 4, 6, 2);  // the b, e3 side at the corner
    face(1, 3, 7, 5);  // the one across, a further
    return mesh;
}

Mesh streetSlab(const Vec3f &a, const Vec3f &b, float width, float thickness) {
    Vec3f along = b - a;
    Vec3f across = normalize(Vec3f{-along.y, along.x, 0}) * width;
    return solidBox(a - across * 0.5f - Vec3f{0, 0, thickness}, along, across, {0, 0, thickness});
}

}  // namespace veduta

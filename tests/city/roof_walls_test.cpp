// Walls and roof meet without gaps (issue 7): the top of every wall, the footprint's outline at
// the eaves, lies on the roof's surface, for every roof type, with and without an overhang.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <span>
#include <vector>

#include "city/roof_shapes.h"
#include "core/hash.h"

namespace veduta {
namespace {

constexpr float kEaves = 10;
constexpr float kOnSurface = 1e-3f;  // metres: float roundoff on coordinates of tens of metres

// Points in double precision: a sliver triangle (a gable a few centimetres high) puts the
// closest-point formula's float roundoff above the tolerance.
struct Point3 {
    double x, y, z;
    Point3(const Vec3f &v) : x(v.x), y(v.y), z(v.z) {}
    Point3(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}
    Point3 operator+(const Point3 &o) const { return {x + o.x, y + o.y, z + o.z}; }
    Point3 operator-(const Point3 &o) const { return {x - o.x, y - o.y, z - o.z}; }
    Point3 operator*(double s) const { return {x * s, y * s, z * s}; }
};
double dot(const Point3 &a, const Point3 &b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// The closest point of triangle abc to p (Ericson, Real-Time Collision Detection, 5.1.5).
Point3 closestOnTriangle(const Point3 &p, const Point3 &a, const Point3 &b, const Point3 &c) {
    Point3 ab = b - a, ac = c - a, ap = p - a;
    double d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return a;
    Point3 bp = p - b;
    double d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return b;
    double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
    Point3 cp = p - c;
    double d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return c;
    double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
    double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    double denominator = 1 / (va + vb + vc);
    return a + ab * (vb * denominator) + ac * (vc * denominator);
}

float distanceToMesh(const Vec3f &p, const Mesh &m) {
    double nearest = std::numeric_limits<double>::max();
    for (size_t t = 0; t < m.triangleCount(); ++t) {
        const uint32_t *i = &m.indices[3 * t];
        Point3 q = closestOnTriangle(p, m.positions[i[0]], m.positions[i[1]], m.positions[i[2]]);
        nearest = std::min(nearest, std::sqrt(dot(q - p, q - p)));
    }
    return float(nearest);
}

// The largest distance from the wall tops (every ring of the footprint at the eaves, sampled
// at its corners and at eight points along each edge) to the roof.
float widestGap(const RoofFootprint &footprint, const Mesh &roof) {
    std::vector<std::vector<Vec2f>> rings{footprint.outer};
    rings.insert(rings.end(), footprint.holes.begin(), footprint.holes.end());
    float widest = 0;
    for (const auto &ring : rings) {
        for (size_t i = 0; i < ring.size(); ++i) {
            Vec2f a = ring[i], b = ring[(i + 1) % ring.size()];
            for (int s = 0; s < 9; ++s) {
                float f = float(s) / 9;
                Vec3f top = lift(a, footprint.base + kEaves) * (1 - f) + lift(b, footprint.base + kEaves) * f;
                widest = std::max(widest, distanceToMesh(top, roof));
            }
        }
    }
    return widest;
}

std::vector<RoofFootprint> footprints() {
    return {
        {{{0, 0}, {14, -2}, {16, 9}, {2, 11}}, {}, 1},  // convex quad
        {{{0, 0}, {20, 0}, {20, 12}, {0, 12}}, {}, 1},  // rectangle
        {{{0, 0}, {20, 0}, {20, 3}, {0, 3}}, {}, 1},    // too narrow for the mansard's 2 m inset: halved
        {{{0, 0}, {24, 0}, {24, 12}, {12, 12}, {12, 24}, {0, 24}}, {}, 1},                      // L
        {{{0, 0}, {30, 0}, {30, 10}, {20, 10}, {20, 25}, {10, 25}, {10, 10}, {0, 10}}, {}, 1},  // T
        {{{0, 0}, {30, 0}, {30, 20}, {22, 20}, {22, 8}, {8, 8}, {8, 20}, {0, 20}}, {}, 1},      // U
        {{{0, 0}, {30, 0}, {30, 30}, {0, 30}}, {{{10, 10}, {10, 20}, {20, 20}, {20, 10}}}, 1},  // courtyard
    };
}

TEST(RoofShapesMeetWalls, EveryTypeOnEveryFootprint) {
    for (const RoofFootprint &footprint : footprints()) {
        for (RoofType type : kRoofTypes) {
            for (float overhang : {0.0f, 0.5f}) {
                RoofOptions options;
                options.type = type;
                options.overhang = overhang;
                RoofResult roof = buildRoof(footprint, kEaves, options);
                EXPECT_LT(widestGap(footprint, roof.mesh), kOnSurface)
                    << roofTypeName(type) << " (built " << roofTypeName(roof.built) << ") with overhang " << overhang
                    << " on a footprint of " << footprint.outer.size() << " corners";
            }
        }
    }
}

// Star-shaped polygons round the origin, some with a square courtyard near the middle.
RoofFootprint randomFootprint(uint32_t index) {
    auto draw = [&](uint32_t k) { return bitsToUnitFloat(hashValues({index, k})); };
    int corners = 5 + int(draw(0) * 10);
    RoofFootprint footprint;
    for (int c = 0; c < corners; ++c) {
        float angle = 2 * kPi * (float(c) + 0.8f * draw(uint32_t(1 + c))) / float(corners);
        float radius = 8 + 14 * draw(uint32_t(100 + c));
        footprint.outer.push_back({radius * std::cos(angle), radius * std::sin(angle)});
    }
    if (draw(999) < 0.3f) footprint.holes.push_back({{-2, -2}, {-2, 2}, {2, 2}, {2, -2}});
    return footprint;
}

void expectWallsMeetRandomRoofs(std::span<const RoofType> types) {
    for (uint32_t i = 0; i < 150; ++i) {
        RoofFootprint footprint = randomFootprint(i);
        for (RoofType type : types) {
            RoofOptions options;
            options.type = type;
            options.overhang = i % 2 ? 0.4f : 0;
            RoofResult roof = buildRoof(footprint, kEaves, options);
            EXPECT_LT(widestGap(footprint, roof.mesh), kOnSurface)
                << "polygon " << i << ": " << roofTypeName(type) << " built as " << roofTypeName(roof.built);
        }
    }
}

TEST(RoofShapesMeetWalls, RandomFootprints) { expectWallsMeetRandomRoofs(kRoofTypes); }

}  // namespace
}  // namespace veduta

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <thread>

#include "city/assets.h"

namespace veduta {
namespace {

// Every model the Gründerzeit rules of Bilke 2009 name, with its type.
const std::map<std::string, ModelType> kModels = {
    {"Wall0", ModelType::Wall},
    {"Wall+1", ModelType::Wall},
    {"WallHole", ModelType::Wall},
    {"Glass0", ModelType::Glass},
    {"Glass+1", ModelType::Glass},
    {"Window1", ModelType::Window},
    {"WindowBasement", ModelType::Window},
    {"WindowBasementSimple", ModelType::Window},
    {"Entrance1", ModelType::Door},
    {"Entrance2", ModelType::Door},
    {"Cornice1", ModelType::Horizontal},
    {"Cornice2Chamfer", ModelType::Horizontal},
    {"Cornice3Nasengesims", ModelType::Horizontal},
    {"Cornice4FallenderKarnies", ModelType::Horizontal},
    {"Cornice4FallenderKarniesOben", ModelType::Horizontal},
    {"Cornice5Basement", ModelType::Horizontal},
    {"Cornice6Kranzleiste", ModelType::Horizontal},
    {"SmallRoof1", ModelType::SmallRoof},
    {"SmallRoofArc", ModelType::SmallRoof},
    {"SmallRoofTri", ModelType::SmallRoof},
    {"ColumnDoric1", ModelType::Vertical},
    {"Balcony1", ModelType::NoType},
    {"Balcony1Ground", ModelType::NoType},
    {"Balcony1Roof", ModelType::NoType},
    {"Balcony1RoofSolar", ModelType::NoType},
    {"BalconyDoor", ModelType::Door},
    {"BalconyDoor2", ModelType::Door},
    {"gutterElement", ModelType::Horizontal},
    {"gutterEnd", ModelType::Horizontal},
    {"Cylinder", ModelType::Vertical},
};

const Asset &asset(const std::string &name) {
    const AssetLibrary &library = AssetLibrary::builtIn();
    std::optional<uint32_t> index = library.find(name);
    if (!index) throw std::runtime_error("no asset " + name);
    return library[*index];
}

Vec3f corner(const Mesh &m, size_t triangle, int k) { return m.positions[m.indices[3 * triangle + size_t(k)]]; }

Vec3f faceNormal(const Mesh &m, size_t t) {
    return cross(corner(m, t, 1) - corner(m, t, 0), corner(m, t, 2) - corner(m, t, 0));
}

// For a closed mesh whose triangles face out, the sum of signed tetrahedra is its volume.
double signedVolume(const Mesh &m) {
    double volume = 0;
    for (size_t t = 0; t < m.triangleCount(); ++t) {
        volume += double(dot(corner(m, t, 0), cross(corner(m, t, 1), corner(m, t, 2)))) / 6.0;
    }
    return volume;
}

// The distance along a ray to the nearest triangle, if it meets one (Möller–Trumbore).
std::optional<float> nearestHit(const Mesh &m, const Vec3f &origin, const Vec3f &direction) {
    std::optional<float> nearest;
    for (size_t t = 0; t < m.triangleCount(); ++t) {
        Vec3f a = corner(m, t, 0), e1 = corner(m, t, 1) - a, e2 = corner(m, t, 2) - a;
        Vec3f p = cross(direction, e2);
        float det = dot(e1, p);
        if (std::abs(det) < 1e-12f) continue;
        Vec3f s = origin - a;
        float u = dot(s, p) / det;
        Vec3f q = cross(s, e1);
        float v = dot(direction, q) / det;
        float distance = dot(e2, q) / det;
        if (u < 0 || v < 0 || u + v > 1 || distance <= 0) continue;
        if (!nearest || distance < *nearest) nearest = distance;
    }
    return nearest;
}

TEST(Assets, EveryModelIsFoundWithAndWithoutItsExtension) {
    const AssetLibrary &library = AssetLibrary::builtIn();
    EXPECT_EQ(library.size(), kModels.size());
    for (const auto &[name, type] : kModels) {
        std::optional<uint32_t> bare = library.find(name), withExtension = library.find(name + ".wrl");
        ASSERT_TRUE(bare.has_value()) << name;
        EXPECT_EQ(bare, withExtension) << name;
        EXPECT_EQ(library[*bare].name, name);
        EXPECT_TRUE(library.isModelName(name + ".wrl"));
        EXPECT_FALSE(library.isModelName(name)) << "a rule file's terminals end in .wrl";
        EXPECT_EQ(library.findTerminal(name + ".wrl"), bare);
    }
}

TEST(Assets, UnknownNamesAreNotModels) {
    const AssetLibrary &library = AssetLibrary::builtIn();
    for (const char *name :
         {"Window2.wrl", "Window1.obj", "window1", "Window1.wrl.wrl", ".wrl", "", "Window1 ", "FloorTileChoice"}) {
        EXPECT_FALSE(library.find(name).has_value()) << '"' << name << '"';
        EXPECT_FALSE(library.isModelName(name)) << '"' << name << '"';
    }
}

TEST(Assets, TypesAreThoseOfTheRuleSet) {
    for (const auto &[name, type] : kModels) EXPECT_EQ(asset(name).type, type) << name;
}

TEST(Assets, MeshesAreValid) {
    const AssetLibrary &library = AssetLibrary::builtIn();
    for (uint32_t i = 0; i < library.size(); ++i) {
        const Asset &a = library[i];
        const Mesh &m = a.mesh;
        SCOPED_TRACE(a.name);
        ASSERT_GT(m.triangleCount(), 0u);
        ASSERT_EQ(m.indices.size() % 3, 0u);
        ASSERT_EQ(m.normals.size(), m.vertexCount());
        ASSERT_EQ(m.uvs.size(), m.vertexCount());
        ASSERT_EQ(m.triangleMaterials.size(), m.triangleCount());
        for (uint32_t index : m.indices) ASSERT_LT(index, m.vertexCount());
        for (const Vec3f &n : m.normals) ASSERT_NEAR(length(n), 1.0f, 1e-4f);
        for (const Vec2f &uv : m.uvs) ASSERT_TRUE(std::isfinite(uv.x) && std::isfinite(uv.y));
        std::vector<bool> used(a.surfaces.size(), false);
        for (MaterialId surface : m.triangleMaterials) {
            ASSERT_LT(surface, a.surfaces.size());
            used[surface] = true;
        }
        EXPECT_EQ(std::count(used.begin(), used.end(), false), 0) << "a surface no triangle uses";
        for (size_t t = 0; t < m.triangleCount(); ++t) {
            ASSERT_GT(length(faceNormal(m, t)) / 2, 1e-7f) << "degenerate triangle " << t;
        }
    }
}

// Vertex normals and winding agree: each triangle, counter-clockwise seen from outside, faces
// the way its normals do. (Normals are flat or smoothed over at most 30°.)
TEST(Assets, TrianglesWindTheWayTheirNormalsPoint) {
    const AssetLibrary &library = AssetLibrary::builtIn();
    for (uint32_t i = 0; i < library.size(); ++i) {
        const Mesh &m = library[i].mesh;
        for (size_t t = 0; t < m.triangleCount(); ++t) {
            Vec3f face = normalize(faceNormal(m, t));
            for (int k = 0; k < 3; ++k) {
                ASSERT_GT(dot(face, m.normals[m.indices[3 * t + size_t(k)]]), 0.9f)
                    << library[i].name << " triangle " << t;
            }
        }
    }
}

TEST(Assets, ClosedModelsFaceOutwards) {
    // A 16-gon of radius 0.5, 1 m long: (16/2)·sin(2π/16)·0.5² m³.
    EXPECT_NEAR(signedVolume(asset("Cylinder").mesh), 8 * std::sin(2 * M_PI / 16) * 0.25, 1e-5);
    EXPECT_NEAR(signedVolume(asset("Wall+1").mesh), 1.0, 1e-6);
    for (const char *name : {"ColumnDoric1", "Cornice1", "Cornice3Nasengesims", "Cornice6Kranzleiste", "gutterEnd",
                             "gutterElement", "SmallRoofArc", "SmallRoofTri"}) {
        EXPECT_GT(signedVolume(asset(name).mesh), 0.0) << name;
    }
}

TEST(Assets, BoundsAreThoseOfThePositions) {
    const AssetLibrary &library = AssetLibrary::builtIn();
    for (uint32_t i = 0; i < library.size(); ++i) {
        const Asset &a = library[i];
        Vec3f lo = a.mesh.positions.front(), hi = lo;
        for (const Vec3f &p : a.mesh.positions) {
            for (int axis = 0; axis < 3; ++axis) {
                lo[axis] = std::min(lo[axis], p[axis]);
                hi[axis] = std::max(hi[axis], p[axis]);
            }
        }
        EXPECT_EQ(a.boundsMin, lo) << a.name;
        EXPECT_EQ(a.boundsMax, hi) << a.name;
    }
}

// x and y are centred, z starts at the wall plane and goes no deeper than 1 m into it.
TEST(Assets, ModelsSitInTheModelFrame) {
    const AssetLibrary &library = AssetLibrary::builtIn();
    for (uint32_t i = 0; i < library.size(); ++i) {
        const Asset &a = library[i];
        for (int axis : {0, 1}) {
            float extent = a.boundsMax[axis] - a.boundsMin[axis];
            EXPECT_GT(extent, 0) << a.name;
            EXPECT_LE(std::abs(a.boundsMax[axis] + a.boundsMin[axis]), 0.1f * extent) << a.name << " axis " << axis;
        }
        EXPECT_GE(a.boundsMin.z, -1.0f) << a.name;
        EXPECT_GE(a.boundsMax.z, 0.0f) << a.name;
    }
}

TEST(Assets, HorizontalModelsSpanOneMetreAlongTheFacade) {
    for (const auto &[name, type] : kModels) {
        if (type != ModelType::Horizontal) continue;
        EXPECT_EQ(asset(name).boundsMin.x, -0.5f) << name;
        EXPECT_EQ(asset(name).boundsMax.x, 0.5f) << name;
        EXPECT_GE(asset(name).boundsMin.z, 0.0f) << name;
    }
}

TEST(Assets, SurfacesTakeTheirMaterialsByCategory) {
    using enum MaterialCategory;
    EXPECT_EQ(asset("Wall0").surfaces, std::vector{Wall});
    EXPECT_EQ(asset("Glass0").surfaces, std::vector{Window});
    EXPECT_EQ(asset("Window1").surfaces, (std::vector{Material, None}));
    EXPECT_EQ(asset("Cornice6Kranzleiste").surfaces, std::vector{Material});
    EXPECT_EQ(asset("BalconyDoor2").surfaces, (std::vector{Door, Window, None}));
    EXPECT_EQ(asset("Balcony1").surfaces, (std::vector{Material, Reflection}));
    EXPECT_EQ(asset("Balcony1RoofSolar").surfaces, (std::vector{Material, Window}));
    EXPECT_EQ(asset("gutterElement").surfaces, std::vector{Reflection});
}

// Whatever way one looks into a window or doorway, something stops the view: the reveals,
// the dark room behind, or its back wall.
TEST(Assets, OpeningsDoNotLetOneSeeThroughTheBuilding) {
    // Points clear of the glazing bars, and off the lines along which rays would graze edges.
    const std::pair<const char *, Vec3f> openings[] = {{"Window1", {0.21f, 0.23f, 0}},
                                                       {"WindowBasement", {0.21f, 0.03f, 0}},
                                                       {"WindowBasementSimple", {0.21f, 0.03f, 0}},
                                                       {"Entrance1", {0.27f, 0.23f, 0}},
                                                       {"Entrance2", {0.27f, 0.23f, 0}}};
    for (const auto &[name, point] : openings) {
        const Mesh &m = asset(name).mesh;
        for (float dx = -1.5f; dx <= 1.5f; dx += 0.5f) {
            for (float dy = -1.5f; dy <= 1.5f; dy += 0.5f) {
                Vec3f direction = normalize({dx, dy, -1});
                Vec3f origin = point - direction * (0.01f / -direction.z);
                EXPECT_TRUE(nearestHit(m, origin, direction).has_value()) << name << " looking " << dx << " " << dy;
            }
        }
        // Straight in, the view ends on the room's back wall 0.6 m deep.
        std::optional<float> straight = nearestHit(m, point + Vec3f{0, 0, 0.01f}, {0, 0, -1});
        ASSERT_TRUE(straight.has_value()) << name;
        EXPECT_NEAR(*straight, 0.61f, 1e-5f) << name;
    }
}

TEST(Assets, TheLibraryIsBuiltOnce) {
    const AssetLibrary *fromThread = nullptr;
    std::thread other([&] { fromThread = &AssetLibrary::builtIn(); });
    const AssetLibrary *here = &AssetLibrary::builtIn();
    other.join();
    EXPECT_EQ(here, fromThread);
    EXPECT_EQ(here, &AssetLibrary::builtIn());
}

}  // namespace
}  // namespace veduta

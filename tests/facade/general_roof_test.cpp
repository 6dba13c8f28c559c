#include "facade/general_roof.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

namespace veduta {
namespace {

const std::vector<Vec2d> kUnitSquare{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
const std::vector<bool> kFree(4, false);

// digest-001 §8 row 5: e_i = bottom (edge 0), e_j = top (edge 2), c = d = 0.5, h = 1.
ModuleRoof squareRoof(double a, double b) { return generalRoof(kUnitSquare, 0, kFree, {0, 2, 0.5, 0.5, a, b, 1}); }
ModuleRoof squareShed() { return generalRoof(kUnitSquare, 0, kFree, {0, 0, 0, 1, 0, 1, 1}); }

std::vector<const ModuleRoofFace *> facesOfKind(const ModuleRoof &roof, RoofFaceKind kind) {
    std::vector<const ModuleRoofFace *> faces;
    for (const ModuleRoofFace &face : roof.faces) {
        if (face.kind == kind) faces.push_back(&face);
    }
    return faces;
}

double distanceToPlane(const Vec3d &p, const ModuleRoofFace &face) {
    Vec3d n = faceNormal(face);
    const Vec3d &o = face.corners[0];
    return n.x * (p.x - o.x) + n.y * (p.y - o.y) + n.z * (p.z - o.z);
}

void expectPlanar(const ModuleRoof &roof) {
    for (const ModuleRoofFace &face : roof.faces) {
        ASSERT_GE(face.corners.size(), 3u);
        for (const Vec3d &c : face.corners) EXPECT_NEAR(distanceToPlane(c, face), 0, 1e-9);
    }
}

double projectedArea(const ModuleRoofFace &face) {
    double area = 0;
    for (size_t k = 0, n = face.corners.size(); k < n; ++k) {
        const Vec3d &a = face.corners[k], &b = face.corners[(k + 1) % n];
        area += a.x * b.y - b.x * a.y;
    }
    return area / 2;
}

double coveredArea(const ModuleRoof &roof) {
    double area = 0;
    for (const ModuleRoofFace &face : roof.faces) {
        if (face.kind != RoofFaceKind::Interface && std::abs(faceNormal(face).z) > 1e-9) area += projectedArea(face);
    }
    return area;
}

double outlineArea(const std::vector<Vec2d> &outline) {
    double area = 0;
    for (size_t i = 0; i < outline.size(); ++i) area += cross(outline[i], outline[(i + 1) % outline.size()]);
    return area / 2;
}

bool isVertical(const ModuleRoofFace &face) { return std::abs(faceNormal(face).z) <= 1e-9; }

TEST(GeneralRoof, GableHasExactlyTwoVerticalTrianglesOverTheRidgeEdges) {
    ModuleRoof roof = squareRoof(0, 1);
    auto interfaces = facesOfKind(roof, RoofFaceKind::Interface);
    ASSERT_EQ(interfaces.size(), 2u);
    std::set<size_t> edges;
    for (const ModuleRoofFace *face : interfaces) {
        EXPECT_EQ(face->corners.size(), 3u);
        EXPECT_TRUE(isVertical(*face));
        edges.insert(face->edge);
    }
    EXPECT_EQ(edges, (std::set<size_t>{0, 2}));
    auto slopes = facesOfKind(roof, RoofFaceKind::Slope);
    ASSERT_EQ(slopes.size(), 2u);
    for (const ModuleRoofFace *face : slopes) EXPECT_EQ(face->corners.size(), 4u);
}

TEST(GeneralRoof, PyramidRisesToTheSquaresCentreRaisedByTheHeight) {
    ModuleRoof roof = squareRoof(0.5, 0.5);
    ASSERT_TRUE(roof.ridge);
    EXPECT_DOUBLE_EQ(roof.ridge->a.x, 0.5);
    EXPECT_DOUBLE_EQ(roof.ridge->a.y, 0.5);
    EXPECT_DOUBLE_EQ(roof.ridge->a.z, 1);
    EXPECT_TRUE(facesOfKind(roof, RoofFaceKind::Interface).empty());
    ASSERT_EQ(roof.faces.size(), 4u);
    for (const ModuleRoofFace &face : roof.faces) {
        EXPECT_EQ(face.corners.size(), 3u);
        EXPECT_TRUE(std::any_of(face.corners.begin(), face.corners.end(),
                                [](const Vec3d &c) { return c.x == 0.5 && c.y == 0.5 && c.z == 1; }));
    }
}

TEST(GeneralRoof, HipHasNoVerticalFace) {
    ModuleRoof roof = squareRoof(0.2, 0.8);
    EXPECT_TRUE(facesOfKind(roof, RoofFaceKind::Interface).empty());
    ASSERT_EQ(roof.faces.size(), 4u);
    for (const ModuleRoofFace &face : roof.faces) {
        EXPECT_FALSE(isVertical(face));
        EXPECT_EQ(face.corners.size(), face.edge == 0 || face.edge == 2 ? 3u : 4u);
    }
    EXPECT_NEAR(roof.ridge->a.y, 0.2, 1e-15);
    EXPECT_NEAR(roof.ridge->b.y, 0.8, 1e-15);
}

TEST(GeneralRoof, ShedHasExactlyOneVerticalQuadOnItsRidgeEdge) {
    ModuleRoof roof = squareShed();
    size_t quads = 0;
    for (const ModuleRoofFace &face : roof.faces) {
        if (isVertical(face) && face.corners.size() == 4) {
            ++quads;
            EXPECT_EQ(face.kind, RoofFaceKind::Interface);
            EXPECT_EQ(face.edge, 0u);
        }
    }
    EXPECT_EQ(quads, 1u);
    // One slope from the opposite eaves up to the ridge over edge 0.
    auto slopes = facesOfKind(roof, RoofFaceKind::Slope);
    ASSERT_EQ(slopes.size(), 1u);
    EXPECT_EQ(slopes[0]->edge, 2u);
}

TEST(GeneralRoof, EverySpecialCaseIsPlanarAndCoversExactlyTheModule) {
    for (const ModuleRoof &roof : {squareRoof(0, 1), squareRoof(0.5, 0.5), squareRoof(0.2, 0.8), squareShed()}) {
        expectPlanar(roof);
        EXPECT_NEAR(coveredArea(roof), 1, 1e-12);
    }
}

// Fig 4.23's kind of module: a hexagon with the ridge between e2 and e6, off-centre and oblique.
TEST(GeneralRoof, ObliqueRidgeOnAHexagonStaysPlanarAndClosesOnTheOutline) {
    std::vector<Vec2d> hexagon{{0, 0}, {6, -1}, {10, 2}, {11, 7}, {5, 10}, {-1, 6}};
    for (auto [a, b] : {std::pair{0.0, 1.0}, {0.3, 0.6}, {0.4, 0.4}}) {
        ModuleRoof roof = generalRoof(hexagon, 12.5, std::vector<bool>(6, false), {1, 4, 0.3, 0.7, a, b, 4.5});
        expectPlanar(roof);
        EXPECT_NEAR(coveredArea(roof), outlineArea(hexagon), 1e-9);
        std::set<size_t> edges;
        for (const ModuleRoofFace &face : roof.faces) {
            if (face.edge != kNoOutlineEdge) {
                EXPECT_TRUE(edges.insert(face.edge).second);
            }
        }
        EXPECT_EQ(edges.size(), 6u) << "every outline side carries one face";
        EXPECT_EQ(facesOfKind(roof, RoofFaceKind::Interface).size(), a == 0 ? 2u : 0u);
    }
}

TEST(GeneralRoof, NormalsPointOutAndUp) {
    for (const ModuleRoof &roof : {squareRoof(0, 1), squareRoof(0.2, 0.8), squareShed()}) {
        for (const ModuleRoofFace &face : roof.faces) {
            Vec3d n = faceNormal(face);
            if (face.kind == RoofFaceKind::Slope) {
                EXPECT_GT(n.z, 0.1);
            }
            // Away from the square's centre.
            double outwards = 0;
            for (const Vec3d &c : face.corners) outwards += n.x * (c.x - 0.5) + n.y * (c.y - 0.5) + n.z * c.z;
            EXPECT_GT(outwards, 0);
        }
    }
}

TEST(GeneralRoof, HeightOverAPointFollowsTheSlopes) {
    ModuleRoof gable = squareRoof(0, 1);
    EXPECT_NEAR(*roofHeightAt(gable, {0.25, 0.1}), 0.5, 1e-12);
    EXPECT_NEAR(*roofHeightAt(gable, {0.5, 0.9}), 1, 1e-12);
    EXPECT_NEAR(*roofHeightAt(gable, {1, 0.5}), 0, 1e-12);
    EXPECT_FALSE(roofHeightAt(gable, {1.1, 0.5}));
    ModuleRoof hip = squareRoof(0.2, 0.8);
    EXPECT_NEAR(*roofHeightAt(hip, {0.5, 0.1}), 0.5, 1e-12);
}

TEST(FlatRoof, ParapetStandsOnlyOnUnconnectedSeams) {
    ModuleRoof roof = flatRoof(kUnitSquare, 3, {false, true, false, false}, {0.8, 0.1});
    EXPECT_FALSE(roof.ridge);
    std::set<size_t> edges;
    for (const ModuleRoofFace *face : facesOfKind(roof, RoofFaceKind::Parapet)) edges.insert(face->edge);
    EXPECT_EQ(edges, (std::set<size_t>{0, 2, 3}));
    EXPECT_TRUE(facesOfKind(roof, RoofFaceKind::Interface).empty());
    auto decks = facesOfKind(roof, RoofFaceKind::Slope);
    ASSERT_EQ(decks.size(), 1u);
    // Inset by 0.1 on three sides, flush with the seam on the fourth.
    EXPECT_NEAR(projectedArea(*decks[0]), 0.9 * 0.8, 1e-12);
    EXPECT_NEAR(coveredArea(roof), 1, 1e-12);
    expectPlanar(roof);
    for (const ModuleRoofFace *face : facesOfKind(roof, RoofFaceKind::Parapet)) {
        for (const Vec3d &c : face->corners) EXPECT_TRUE(c.z == 3 || c.z == 3.8);
    }
}

TEST(FlatRoof, ParapetsEndFlushWithTheSeam) {
    ModuleRoof roof = flatRoof(kUnitSquare, 0, {false, true, false, false}, {0.8, 0.1});
    // The end caps of the parapets on edges 0 and 2 stand in the seam's plane x = 1 (edge 3's
    // inner side faces +x too).
    size_t caps = 0;
    for (const ModuleRoofFace *face : facesOfKind(roof, RoofFaceKind::Parapet)) {
        if (faceNormal(*face).x > 0.5 && face->edge != 3) {
            ++caps;
            for (const Vec3d &c : face->corners) EXPECT_EQ(c.x, 1);
        }
    }
    EXPECT_EQ(caps, 2u);
    EXPECT_NEAR(*roofHeightAt(roof, {0.05, 0.5}), 0, 1e-12);
}

TEST(RoofMesh, SlopesAndInterfacesTakeTheirOwnMaterials) {
    Mesh mesh = roofMesh(squareRoof(0, 1), {7, 9, 11});
    // Two quads and two triangles.
    ASSERT_EQ(mesh.triangleCount(), 6u);
    EXPECT_EQ(std::count(mesh.triangleMaterials.begin(), mesh.triangleMaterials.end(), 7u), 4);
    EXPECT_EQ(std::count(mesh.triangleMaterials.begin(), mesh.triangleMaterials.end(), 9u), 2);
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        Vec3f a = mesh.positions[mesh.indices[3 * t]], b = mesh.positions[mesh.indices[3 * t + 1]],
              c = mesh.positions[mesh.indices[3 * t + 2]];
        Vec3f winding = cross(b - a, c - a);
        EXPECT_GT(dot(winding, mesh.normals[mesh.indices[3 * t]]), 0) << "triangles wind counter-clockwise outside";
    }
}

TEST(RoofMesh, TextureCoordinatesAreMetresWithURunningAlongTheEaves) {
    ModuleRoof roof = squareRoof(0, 1);
    Mesh mesh = roofMesh(roof, {0, 1, 2});
    double slant = std::sqrt(0.5 * 0.5 + 1.0);
    for (size_t v = 0; v < mesh.vertexCount(); ++v) {
        Vec3f p = mesh.positions[v], n = mesh.normals[v];
        Vec2f uv = mesh.uvs[v];
        if (n.z > 0.1) {
            // Slopes rise across x: u runs along y, v is the slant distance from the eaves.
            EXPECT_NEAR(std::abs(uv.x), p.y, 1e-6);
            EXPECT_NEAR(uv.y, slant * p.z, 1e-6);
        } else {
            EXPECT_NEAR(std::abs(uv.x), p.x, 1e-6);
            EXPECT_NEAR(uv.y, p.z, 1e-6);
        }
    }
}

TEST(GeneralRoof, RejectsWhatDefinition413RulesOut) {
    EXPECT_THROW(generalRoof({{0, 0}, {0, 1}, {1, 1}, {1, 0}}, 0, kFree, {}), std::invalid_argument);
    EXPECT_THROW(generalRoof(kUnitSquare, 0, kFree, {0, 2, 0.5, 0.5, 0.8, 0.2, 1}), std::invalid_argument);
    EXPECT_THROW(generalRoof(kUnitSquare, 0, kFree, {0, 4, 0.5, 0.5, 0, 1, 1}), std::invalid_argument);
    EXPECT_THROW(generalRoof(kUnitSquare, 0, kFree, {0, 2, 1.5, 0.5, 0, 1, 1}), std::invalid_argument);
    EXPECT_THROW(generalRoof(kUnitSquare, 0, kFree, {0, 2, 0.5, 0.5, 0, 1, 0}), std::invalid_argument);
    EXPECT_THROW(generalRoof({{0, 0}, {1, 0}, {2, 0}, {1, 1}}, 0, kFree, {}), std::invalid_argument);
    EXPECT_THROW(flatRoof(kUnitSquare, 0, kFree, {0, 0.3}), std::invalid_argument);
}

// A module too thin for its parapet (a sliver a footprint's partition cut) gets a narrower one:
// 0.9 of the width at which the deck would vanish, 0.5 on the unit square.
TEST(GeneralRoof, AParapetTooWideForItsModuleNarrowsToLeaveADeck) {
    ModuleRoof roof = flatRoof(kUnitSquare, 2, kFree, {1, 0.6});
    const ModuleRoofFace &deck = roof.faces.front();
    ASSERT_EQ(deck.corners.size(), 4u);
    for (const Vec3d &c : deck.corners) {
        EXPECT_NEAR(std::min(c.x, 1 - c.x), 0.45, 1e-9);
        EXPECT_NEAR(std::min(c.y, 1 - c.y), 0.45, 1e-9);
        EXPECT_EQ(c.z, 2);
    }
    // A parapet that fits keeps its width.
    ModuleRoof fits = flatRoof(kUnitSquare, 2, kFree, {1, 0.3});
    for (const Vec3d &c : fits.faces.front().corners) EXPECT_NEAR(std::min(c.x, 1 - c.x), 0.3, 1e-12);
}

}  // namespace
}  // namespace veduta

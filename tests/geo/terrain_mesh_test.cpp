#include "geo/terrain_mesh.h"

#include <cmath>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "geo/height_queries.h"

namespace veduta {
namespace {

HeightGrid makeGrid(int columns, int rows, double spacing, float (*height)(int, int)) {
    HeightGrid grid;
    grid.west = 600000;
    grid.south = 5700000;
    grid.spacing = spacing;
    grid.columns = columns;
    grid.rows = rows;
    grid.heights.resize(size_t(columns) * size_t(rows));
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < columns; ++c) grid.node(c, r) = height(c, r);
    return grid;
}

float hills(int c, int r) {
    return float(200 + 30 * std::sin(c * 0.05) * std::cos(r * 0.07) + 4 * std::sin(c * 0.31 + r * 0.23) +
                 0.3 * std::sin(c * 1.7) * std::cos(r * 2.3));
}

Vec3f faceNormal(const Mesh &mesh, size_t t) {
    Vec3f a = mesh.positions[mesh.indices[3 * t]], b = mesh.positions[mesh.indices[3 * t + 1]],
          c = mesh.positions[mesh.indices[3 * t + 2]];
    return cross(b - a, c - a);
}

TEST(TerrainMesh, LevelPlane) {
    HeightGrid grid = makeGrid(7, 5, 2, [](int, int) { return 312.5f; });
    LocalFrame frame{{600004, 5700002}};
    Mesh mesh = terrainMesh(grid, frame, {});
    ASSERT_EQ(mesh.vertexCount(), 35u);
    ASSERT_EQ(mesh.triangleCount(), 2u * 6 * 4);
    ASSERT_EQ(mesh.triangleMaterials.size(), mesh.triangleCount());
    for (const Vec3f &n : mesh.normals) EXPECT_EQ(n, Vec3f(0, 0, 1));
    for (size_t t = 0; t < mesh.triangleCount(); ++t) EXPECT_GT(faceNormal(mesh, t).z, 0) << t;
    // Vertices row by row from the south: vertex 8 is node (1, 1), 2 m east and 2 m north of the origin's… west.
    EXPECT_EQ(mesh.positions[8], Vec3f(-2, 0, 312.5f));
    EXPECT_EQ(mesh.uvs[8].x, -0.2f);
    EXPECT_EQ(mesh.uvs[8].y, 0.0f);
}

// Every triangle holds its cell's SW and NE nodes, and the mesh is the surface of surfaceHeight.
TEST(TerrainMesh, CellsSplitSouthWestToNorthEast) {
    HeightGrid grid = makeGrid(30, 20, 1.5, hills);
    LocalFrame frame{{600010, 5700010}};
    Mesh mesh = terrainMesh(grid, frame, {});
    ASSERT_EQ(mesh.triangleCount(), 2u * 29 * 19);
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        uint32_t low = std::min({mesh.indices[3 * t], mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]});
        uint32_t high = std::max({mesh.indices[3 * t], mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]});
        ASSERT_EQ(high, low + 30 + 1) << t;
        Vec3f centre = (mesh.positions[mesh.indices[3 * t]] + mesh.positions[mesh.indices[3 * t + 1]] +
                        mesh.positions[mesh.indices[3 * t + 2]]) /
            3;
        auto h = surfaceHeight(grid, frame.toMap({centre.x, centre.y}));
        ASSERT_TRUE(h);
        EXPECT_NEAR(*h, centre.z, 1e-3) << t;
    }
}

TEST(TerrainMesh, HolesLeaveOutTheirCells) {
    HeightGrid grid = makeGrid(6, 6, 1, hills);
    grid.node(2, 3) = NAN;
    grid.node(5, 0) = NAN;
    Mesh mesh = terrainMesh(grid, {{600000, 5700000}}, {});
    EXPECT_EQ(mesh.vertexCount(), 34u);
    EXPECT_EQ(mesh.triangleCount(), 2u * (25 - 4 - 1));
    for (const Vec3f &p : mesh.positions) EXPECT_TRUE(std::isfinite(p.z));
    for (uint32_t i : mesh.indices) EXPECT_LT(i, mesh.vertexCount());
}

// Nodes of the simplified mesh by their grid coordinates, for the checks below.
struct NodeMesh {
    std::vector<int> column, row;
    std::set<std::pair<int, int>> vertices;
};

NodeMesh nodesOf(const Mesh &mesh, const HeightGrid &grid, const LocalFrame &frame) {
    NodeMesh nodes;
    for (const Vec3f &p : mesh.positions) {
        MapPoint m = frame.toMap({p.x, p.y});
        int c = int(std::lround((m.easting - grid.west) / grid.spacing)),
            r = int(std::lround((m.northing - grid.south) / grid.spacing));
        nodes.column.push_back(c);
        nodes.row.push_back(r);
        nodes.vertices.insert({c, r});
    }
    return nodes;
}

// Every node with a height within maxError of the simplified triangle over it, every full cell
// covered, and no vertex in the middle of another triangle's edge (no T-junctions, no cracks).
void checkSimplified(const HeightGrid &grid, double maxError, size_t &triangles) {
    LocalFrame frame{{grid.west + 17, grid.south + 9}};
    TerrainMeshOptions options;
    options.maxError = maxError;
    Mesh mesh = terrainMesh(grid, frame, options);
    triangles = mesh.triangleCount();
    NodeMesh nodes = nodesOf(mesh, grid, frame);
    std::vector<int> covered(grid.heights.size());
    double worst = 0;
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        ASSERT_GT(faceNormal(mesh, t).z, 0);
        int c[3], r[3];
        double h[3];
        for (int k = 0; k < 3; ++k) {
            uint32_t v = mesh.indices[3 * t + size_t(k)];
            c[k] = nodes.column[v], r[k] = nodes.row[v], h[k] = grid.node(c[k], r[k]);
        }
        double area = double(c[1] - c[0]) * (r[2] - r[0]) - double(c[2] - c[0]) * (r[1] - r[0]);
        for (int y = std::min({r[0], r[1], r[2]}); y <= std::max({r[0], r[1], r[2]}); ++y) {
            for (int x = std::min({c[0], c[1], c[2]}); x <= std::max({c[0], c[1], c[2]}); ++x) {
                double w0 = (double(c[1] - x) * (r[2] - y) - double(c[2] - x) * (r[1] - y)) / area;
                double w1 = (double(c[2] - x) * (r[0] - y) - double(c[0] - x) * (r[2] - y)) / area;
                double w2 = 1 - w0 - w1;
                if (w0 < -1e-12 || w1 < -1e-12 || w2 < -1e-12) continue;
                ++covered[size_t(y) * size_t(grid.columns) + size_t(x)];
                ASSERT_FALSE(std::isnan(grid.node(x, y))) << "a triangle over a hole";
                worst = std::max(worst, std::abs(w0 * h[0] + w1 * h[1] + w2 * h[2] - grid.node(x, y)));
            }
        }
        for (int k = 0; k < 3; ++k) {
            int dc = c[(k + 1) % 3] - c[k], dr = r[(k + 1) % 3] - r[k];
            int steps = std::max(std::abs(dc), std::abs(dr));
            for (int s = 1; s < steps; ++s)
                ASSERT_FALSE(nodes.vertices.count({c[k] + dc / steps * s, r[k] + dr / steps * s})) << "a T-junction";
        }
    }
    // Heights are float: allow their rounding (ulp 3e-5 at 200 m), nothing more.
    EXPECT_LE(worst, maxError + 1e-4);
    for (int r = 0; r + 1 < grid.rows; ++r) {
        for (int c = 0; c + 1 < grid.columns; ++c) {
            bool full = !std::isnan(grid.node(c, r)) && !std::isnan(grid.node(c + 1, r)) &&
                !std::isnan(grid.node(c, r + 1)) && !std::isnan(grid.node(c + 1, r + 1));
            if (full) {
                ASSERT_GT(covered[size_t(r) * size_t(grid.columns) + size_t(c)], 0) << c << ", " << r;
            }
        }
    }
}

TEST(TerrainMesh, SimplifiedWithinMaxError) {
    HeightGrid grid = makeGrid(157, 100, 2, hills);
    size_t full = 2u * 156 * 99;
    for (double maxError : {0.05, 0.5, 2.0}) {
        size_t triangles = 0;
        checkSimplified(grid, maxError, triangles);
        EXPECT_LT(triangles, full) << maxError;
    }
}

TEST(TerrainMesh, SimplifiedAroundHoles) {
    HeightGrid grid = makeGrid(65, 70, 1, hills);
    for (int r = 20; r < 26; ++r)
        for (int c = 30; c < 33; ++c) grid.node(c, r) = NAN;
    grid.node(0, 0) = NAN;
    size_t triangles = 0;
    checkSimplified(grid, 0.3, triangles);
}

TEST(TerrainMesh, SimplifiedPlaneIsTwoTriangles) {
    HeightGrid grid = makeGrid(129, 129, 1, [](int c, int r) { return float(100 + 0.25 * c - 0.5 * r); });
    TerrainMeshOptions options;
    options.maxError = 0.01;
    Mesh mesh = terrainMesh(grid, {{600000, 5700000}}, options);
    EXPECT_EQ(mesh.triangleCount(), 2u);
    EXPECT_EQ(mesh.vertexCount(), 4u);
}

}  // namespace
}  // namespace veduta

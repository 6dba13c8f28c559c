#include "geo/geo_test_terrain.h"

#include <cmath>
#include <map>
#include <utility>

#include <fmt/format.h>

#include "core/hash.h"

namespace veduta::test {

double unitRandom(uint32_t seed, uint32_t index) { return double(hashValues({seed, index})) * 0x1p-32; }

HeightGrid flatTerrain(int columns, int rows, double spacing, MapPoint southWest, float height) {
    HeightGrid grid;
    grid.west = southWest.easting, grid.south = southWest.northing, grid.spacing = spacing;
    grid.columns = columns, grid.rows = rows;
    grid.heights.assign(size_t(columns) * size_t(rows), height);
    return grid;
}

namespace {

double smoothNoise(double x, double y, uint32_t seed) {
    auto lattice = [&](int i, int j) { return unitRandom(seed, hashValues({uint32_t(i), uint32_t(j)})); };
    int i = int(std::floor(x)), j = int(std::floor(y));
    double fx = x - i, fy = y - j;
    fx = fx * fx * (3 - 2 * fx), fy = fy * fy * (3 - 2 * fy);
    double a = lattice(i, j) + fx * (lattice(i + 1, j) - lattice(i, j));
    double b = lattice(i, j + 1) + fx * (lattice(i + 1, j + 1) - lattice(i, j + 1));
    return a + fy * (b - a);
}

}  // namespace

HeightGrid roughTerrain(int columns, int rows, double spacing, MapPoint southWest, uint32_t seed) {
    HeightGrid grid = flatTerrain(columns, rows, spacing, southWest, 0);
    double ridge = 0.5 * (rows - 1) * spacing;
    for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < columns; ++c) {
            double x = c * spacing, y = r * spacing;
            double h = 200 + 40 * smoothNoise(x / 50, y / 50, seed) + 0.8 * x +
                30 * std::max(0.0, 1 - std::abs(y - ridge) / 20) +
                3 * (unitRandom(seed + 1, uint32_t(r * columns + c)) - 0.5);
            grid.node(c, r) = float(h);
        }
    }
    return grid;
}

double gridSurface(const HeightGrid &grid, MapPoint p) {
    double u = (p.easting - grid.west) / grid.spacing, v = (p.northing - grid.south) / grid.spacing;
    if (u < 0 || v < 0 || u > grid.columns - 1 || v > grid.rows - 1) return NAN;
    int c = std::min(int(u), grid.columns - 2), r = std::min(int(v), grid.rows - 2);
    double fu = u - c, fv = v - r;
    double h00 = grid.node(c, r), h10 = grid.node(c + 1, r), h01 = grid.node(c, r + 1), h11 = grid.node(c + 1, r + 1);
    // South-east triangle (00, 10, 11) where fu ≥ fv, else north-west (00, 11, 01).
    if (fu >= fv) return h00 + fu * (h10 - h00) + fv * (h11 - h10);
    return h00 + fv * (h01 - h00) + fu * (h11 - h01);
}

double planArea(const Mesh &mesh, size_t t) {
    const Vec3f &a = mesh.positions[mesh.indices[3 * t]], &b = mesh.positions[mesh.indices[3 * t + 1]];
    const Vec3f &c = mesh.positions[mesh.indices[3 * t + 2]];
    return 0.5 * ((double(b.x) - a.x) * (double(c.y) - a.y) - (double(b.y) - a.y) * (double(c.x) - a.x));
}

Vec2d planCentroid(const Mesh &mesh, size_t t) {
    const Vec3f &a = mesh.positions[mesh.indices[3 * t]], &b = mesh.positions[mesh.indices[3 * t + 1]];
    const Vec3f &c = mesh.positions[mesh.indices[3 * t + 2]];
    return {(double(a.x) + b.x + c.x) / 3, (double(a.y) + b.y + c.y) / 3};
}

std::vector<std::string> meshDefects(const Mesh &mesh, double x0, double y0, double x1, double y1) {
    std::vector<std::string> defects;
    std::map<std::pair<uint32_t, uint32_t>, int> directed;
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        if (!(planArea(mesh, t) > 0)) defects.push_back(fmt::format("triangle {} faces down or has no area", t));
        for (size_t k = 0; k < 3; ++k) ++directed[{mesh.indices[3 * t + k], mesh.indices[3 * t + (k + 1) % 3]}];
    }
    auto onBoundary = [&](const Vec3f &a, const Vec3f &b) {
        return (a.x == float(x0) && b.x == float(x0)) || (a.x == float(x1) && b.x == float(x1)) ||
            (a.y == float(y0) && b.y == float(y0)) || (a.y == float(y1) && b.y == float(y1));
    };
    for (auto [edge, count] : directed) {
        auto reverse = directed.find({edge.second, edge.first});
        int back = reverse == directed.end() ? 0 : reverse->second;
        if (count == 1 && back == 1) continue;
        const Vec3f &a = mesh.positions[edge.first], &b = mesh.positions[edge.second];
        if (count == 1 && back == 0 && onBoundary(a, b)) continue;
        defects.push_back(
            fmt::format("edge ({} {})–({} {}) used {} times forwards, {} backwards", a.x, a.y, b.x, b.y, count, back));
        if (defects.size() > 20) break;
    }
    return defects;
}

double ringArea(const std::vector<Vec2d> &ring) {
    double sum = 0;
    for (size_t i = 0; i < ring.size(); ++i) {
        const Vec2d &a = ring[i], &b = ring[(i + 1) % ring.size()];
        sum += a.x * b.y - b.x * a.y;
    }
    return std::abs(0.5 * sum);
}

bool insideRing(const std::vector<Vec2d> &ring, Vec2d p) {
    bool in = false;
    for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
        const Vec2d &a = ring[j], &b = ring[i];
        if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x)) in = !in;
    }
    return in;
}

}  // namespace veduta::test

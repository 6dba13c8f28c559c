#include "compare/height_map.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace veduta {

namespace {

constexpr float kNoSurface = -std::numeric_limits<float>::infinity();

struct Box {
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    void add(const Vec3f &p) {
        x0 = std::min(x0, double(p.x)), y0 = std::min(y0, double(p.y));
        x1 = std::max(x1, double(p.x)), y1 = std::max(y1, double(p.y));
    }
    bool empty() const { return x1 < x0; }
};

// The extent seen from above of every part of a building.
void addBuildings(const RenderScene &scene, Box &box) {
    for (const BakedMesh &m : scene.meshes)
        if (m.buildingId != 0)
            for (const Vec3f &p : m.mesh.positions) box.add(p);
    std::vector<std::array<Vec3f, 2>> bounds(scene.prototypes.size(),
                                             {Vec3f{1e30f, 1e30f, 1e30f}, Vec3f{-1e30f, -1e30f, -1e30f}});
    for (size_t i = 0; i < scene.prototypes.size(); ++i)
        for (const Vec3f &p : scene.prototypes[i].positions) {
            bounds[i][0] = {std::min(bounds[i][0].x, p.x), std::min(bounds[i][0].y, p.y),
                            std::min(bounds[i][0].z, p.z)};
            bounds[i][1] = {std::max(bounds[i][1].x, p.x), std::max(bounds[i][1].y, p.y),
                            std::max(bounds[i][1].z, p.z)};
        }
    for (const Instance &instance : scene.instances) {
        if (instance.buildingId == 0 || scene.prototypes[instance.prototype].positions.empty()) continue;
        const auto &[low, high] = bounds[instance.prototype];
        for (int corner = 0; corner < 8; ++corner)
            box.add(instance.objectToWorld.applyPoint(
                {corner & 1 ? high.x : low.x, corner & 2 ? high.y : low.y, corner & 4 ? high.z : low.z}));
    }
}

// The first and last cell (of `count`) whose centre lies at or after / at or before `at`, in
// cells from the grid's edge; clamped in double first, since a scene's plane may reach far
// beyond the buildings.
int firstCell(double at, int count) { return int(std::clamp(std::ceil(at - 0.5), 0.0, double(count))); }
int lastCell(double at, int count) { return int(std::clamp(std::floor(at - 0.5), -1.0, double(count - 1))); }

// Draws one triangle: each cell centre inside it (edges included) takes its height there when
// that is higher than what the cell has.
void drawTriangle(const Vec3f &a, const Vec3f &b, const Vec3f &c, uint32_t buildingId, HeightMap &map) {
    const GroundGrid &g = map.grid;
    double ax = (a.x - g.x0) / g.cell, ay = (a.y - g.y0) / g.cell;
    double bx = (b.x - g.x0) / g.cell, by = (b.y - g.y0) / g.cell;
    double cx = (c.x - g.x0) / g.cell, cy = (c.y - g.y0) / g.cell;
    double area = (bx - ax) * (cy - ay) - (cx - ax) * (by - ay);
    if (std::abs(area) < 1e-12) return;
    int i0 = firstCell(std::min({ax, bx, cx}), g.width), i1 = lastCell(std::max({ax, bx, cx}), g.width);
    int j0 = firstCell(std::min({ay, by, cy}), g.height), j1 = lastCell(std::max({ay, by, cy}), g.height);
    for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) {
            double px = i + 0.5, py = j + 0.5;
            double wa = ((bx - px) * (cy - py) - (cx - px) * (by - py)) / area;
            double wb = ((cx - px) * (ay - py) - (ax - px) * (cy - py)) / area;
            double wc = 1 - wa - wb;
            if (wa < 0 || wb < 0 || wc < 0) continue;
            auto z = float(wa * a.z + wb * b.z + wc * c.z);
            size_t cell = size_t(j) * size_t(g.width) + size_t(i);
            if (z > map.top[cell]) {
                map.top[cell] = z;
                map.building[cell] = buildingId;
            }
        }
}

void drawMesh(const Mesh &mesh, const Transform *toWorld, uint32_t buildingId, HeightMap &map) {
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        std::array<Vec3f, 3> p;
        for (int k = 0; k < 3; ++k) {
            p[k] = mesh.positions[mesh.indices[3 * t + k]];
            if (toWorld) p[k] = toWorld->applyPoint(p[k]);
        }
        drawTriangle(p[0], p[1], p[2], buildingId, map);
    }
}

// Marks the cells whose centres lie inside the outline (even-odd rule) with the building's id.
void drawPlan(const std::vector<Vec2f> &outline, uint32_t buildingId, HeightMap &map) {
    const GroundGrid &g = map.grid;
    if (outline.size() < 3) return;
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    for (const Vec2f &p : outline)
        x0 = std::min(x0, double(p.x)), y0 = std::min(y0, double(p.y)), x1 = std::max(x1, double(p.x)),
        y1 = std::max(y1, double(p.y));
    int i0 = firstCell((x0 - g.x0) / g.cell, g.width), i1 = lastCell((x1 - g.x0) / g.cell, g.width);
    int j0 = firstCell((y0 - g.y0) / g.cell, g.height), j1 = lastCell((y1 - g.y0) / g.cell, g.height);
    for (int j = j0; j <= j1; ++j) {
        double y = g.y0 + (j + 0.5) * g.cell;
        for (int i = i0; i <= i1; ++i) {
            double x = g.x0 + (i + 0.5) * g.cell;
            bool inside = false;
            for (size_t k = 0, l = outline.size() - 1; k < outline.size(); l = k++) {
                double ax = outline[k].x, ay = outline[k].y, bx = outline[l].x, by = outline[l].y;
                if ((ay > y) != (by > y) && x < ax + (y - ay) * (bx - ax) / (by - ay)) inside = !inside;
            }
            if (inside) map.plan[size_t(j) * size_t(g.width) + size_t(i)] = buildingId;
        }
    }
}

}  // namespace

GroundGrid gridOverBuildings(const RenderScene &a, const RenderScene &b, size_t maxCells) {
    Box box;
    addBuildings(a, box);
    addBuildings(b, box);
    if (box.empty()) return {};
    constexpr double kMargin = 2, kFinest = 0.1;
    double w = box.x1 - box.x0 + 2 * kMargin, h = box.y1 - box.y0 + 2 * kMargin;
    double cell = std::max(kFinest, std::ceil(std::sqrt(w * h / double(maxCells)) * 100) / 100);
    GroundGrid grid{box.x0 - kMargin, box.y0 - kMargin, cell, int(std::ceil(w / cell)), int(std::ceil(h / cell))};
    while (grid.cellCount() > maxCells) {  // the rounding up above may leave a row or column over
        grid.cell += 0.01;
        grid.width = int(std::ceil(w / grid.cell)), grid.height = int(std::ceil(h / grid.cell));
    }
    return grid;
}

HeightMap topDownHeights(const RenderScene &scene, const GroundGrid &grid) {
    HeightMap map{grid, std::vector<float>(grid.cellCount(), kNoSurface), std::vector<uint32_t>(grid.cellCount(), 0),
                  std::vector<uint32_t>(grid.cellCount(), 0)};
    for (const BakedMesh &m : scene.meshes) drawMesh(m.mesh, nullptr, m.buildingId, map);
    for (const Instance &instance : scene.instances)
        drawMesh(scene.prototypes[instance.prototype], &instance.objectToWorld, instance.buildingId, map);
    for (const BuildingRecord &record : scene.buildings)
        for (const std::vector<Vec2f> &outline : record.footprint) drawPlan(outline, record.id, map);
    return map;
}

}  // namespace veduta

#include "compare/views.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

namespace veduta {

namespace {

constexpr float kEyeHeight = 1.7f;
constexpr float kStreetFov = 60;

// Whether a 3 × 3 cell neighbourhood of the point is free of buildings (off the map is: the
// map covers every building).
bool freeStanding(const HeightMap &map, double x, double y) {
    const GroundGrid &g = map.grid;
    int i = int(std::floor((x - g.x0) / g.cell)), j = int(std::floor((y - g.y0) / g.cell));
    for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
            int ii = i + di, jj = j + dj;
            if (ii < 0 || jj < 0 || ii >= g.width || jj >= g.height) continue;
            if (map.building[size_t(jj) * size_t(g.width) + size_t(ii)] != 0) return false;
        }
    return true;
}

}  // namespace

Camera overviewCamera(const GroundGrid &grid, float ground, float top, int width, int height) {
    Camera camera;
    camera.width = width, camera.height = height;
    camera.verticalFovDegrees = 40;
    float w = float(grid.width * grid.cell), h = float(grid.height * grid.cell);
    Vec3f centre{float(grid.x0) + w / 2, float(grid.y0) + h / 2, (ground + top) / 2};
    float radius = 0.5f * std::sqrt(w * w + h * h + (top - ground) * (top - ground));
    float aspect = std::min(1.0f, float(width) / float(height));
    float halfFov = camera.verticalFovDegrees / 2 * std::numbers::pi_v<float> / 180;
    float distance = radius / std::sin(std::atan(std::tan(halfFov) * aspect)) * 1.05f;
    float elevation = 35 * std::numbers::pi_v<float> / 180, azimuth = 200 * std::numbers::pi_v<float> / 180;
    Vec3f towardCamera{std::sin(azimuth) * std::cos(elevation), std::cos(azimuth) * std::cos(elevation),
                       std::sin(elevation)};
    camera.position = centre + towardCamera * distance;
    camera.lookAt = centre;
    camera.up = {0, 0, 1};
    return camera;
}

std::vector<View> streetViews(const BuildingComparison &buildings, const HeightMap &map, size_t count, int width,
                              int height) {
    std::vector<const MeasuredBuilding *> candidates;
    for (const BuildingPair &pair : buildings.pairs)
        if (pair.a && pair.a->footprintArea > 0 && pair.a->record) candidates.push_back(&*pair.a);
    std::vector<View> views;
    if (candidates.empty() || count == 0) return views;
    const GroundGrid &g = map.grid;
    double cx = g.x0 + g.width * g.cell / 2, cy = g.y0 + g.height * g.cell / 2;
    size_t step = std::max<size_t>(1, candidates.size() / count);
    for (size_t k = step / 2; k < candidates.size() && views.size() < count; k += step) {
        const MeasuredBuilding &b = *candidates[k];
        double radius = std::sqrt(b.footprintArea / std::numbers::pi);
        // Facing away from the district's centre first, then round the building.
        double away = std::atan2(b.centreY - cy, b.centreX - cx);
        for (int turn = 0; turn < 16; ++turn) {
            double angle = away + (turn % 2 ? 1 : -1) * ((turn + 1) / 2) * std::numbers::pi / 8;
            double x = b.centreX + std::cos(angle) * (radius + 12), y = b.centreY + std::sin(angle) * (radius + 12);
            if (!freeStanding(map, x, y)) continue;
            Camera camera;
            camera.width = width, camera.height = height;
            camera.verticalFovDegrees = kStreetFov;
            camera.position = {float(x), float(y), b.record->base + kEyeHeight};
            camera.lookAt = {float(b.centreX), float(b.centreY), (b.record->base + b.record->eaves) / 2 + kEyeHeight};
            camera.up = {0, 0, 1};
            views.push_back({fmt::format("building {}", b.id), camera});
            break;
        }
    }
    return views;
}

}  // namespace veduta

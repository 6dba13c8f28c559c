#include "city/citygml_measures.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

namespace veduta {

double groundArea(const std::vector<CrsCoordinate> &ring) {
    double sum = 0;
    for (size_t i = 0; i < ring.size(); ++i) {
        const CrsCoordinate &a = ring[i], &b = ring[(i + 1) % ring.size()];
        sum += (a.x - ring[0].x) * (b.y - ring[0].y) - (b.x - ring[0].x) * (a.y - ring[0].y);
    }
    return sum / 2;
}

SurfaceSums sumSurfaces(const CityGmlBuilding &building, const CrsCoordinate &o) {
    SurfaceSums s;
    for (const CityGmlPolygon &polygon : building.polygons) {
        std::vector<CrsCoordinate> points;
        for (const auto &ring : polygon.rings) points.insert(points.end(), ring.begin(), ring.end());
        for (size_t t = 0; t + 2 < polygon.triangles.size(); t += 3) {
            const CrsCoordinate &a = points[polygon.triangles[t]], &b = points[polygon.triangles[t + 1]],
                                &c = points[polygon.triangles[t + 2]];
            double ax = a.x - o.x, ay = a.y - o.y, az = a.z - o.z;
            double bx = b.x - o.x, by = b.y - o.y, bz = b.z - o.z;
            double cx = c.x - o.x, cy = c.y - o.y, cz = c.z - o.z;
            double ux = bx - ax, uy = by - ay, uz = bz - az, wx = cx - ax, wy = cy - ay, wz = cz - az;
            double nx = uy * wz - uz * wy, ny = uz * wx - ux * wz, nz = ux * wy - uy * wx;
            s.vx += nx / 2, s.vy += ny / 2, s.vz += nz / 2;
            s.area += std::sqrt(nx * nx + ny * ny + nz * nz) / 2;
            s.volume += (ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx)) / 6;
        }
    }
    return s;
}

BuildingMeasures measureBuilding(const CityGmlBuilding &building) {
    BuildingMeasures m;
    constexpr double kNone = std::numeric_limits<double>::infinity();
    double lowest = kNone, lowestGround = kNone, lowestRoof = kNone, highestWall = -kNone, highest = -kNone;
    for (const CityGmlPolygon &polygon : building.polygons)
        for (const CrsCoordinate &p : polygon.rings.front()) {
            lowest = std::min(lowest, p.z);
            highest = std::max(highest, p.z);
            if (polygon.kind == SurfaceKind::Ground) lowestGround = std::min(lowestGround, p.z);
            if (polygon.kind == SurfaceKind::Roof) lowestRoof = std::min(lowestRoof, p.z);
            if (polygon.kind == SurfaceKind::Wall) highestWall = std::max(highestWall, p.z);
        }
    if (building.polygons.empty()) return m;
    m.ground = lowestGround < kNone ? lowestGround : lowest;
    m.ridge = highest;
    m.eaves = lowestRoof < kNone ? lowestRoof : highestWall > -kNone ? highestWall : highest;

    SurfaceSums s = sumSurfaces(building, building.polygons.front().rings.front().front());
    if (s.area > 0 && std::sqrt(s.vx * s.vx + s.vy * s.vy + s.vz * s.vz) < 1e-6 * s.area) m.volume = std::abs(s.volume);

    for (const CityGmlPolygon &polygon : building.polygons) {
        if (polygon.kind != SurfaceKind::Ground) continue;
        std::vector<CrsCoordinate> outline = polygon.rings.front();
        if (groundArea(outline) < 0) std::reverse(outline.begin(), outline.end());  // ground faces down
        m.footprint.push_back(std::move(outline));
    }
    m.roofType = roofTypeOfCode(building.roofType);
    if (!m.roofType) m.roofType = roofTypeFromSlopes(building);
    return m;
}

namespace {

// A roof surface's normal and area, from Newell's vector area of its outline.
struct RoofFace {
    double azimuth = 0;  // radians, of the direction it faces, seen from above
    double tilt = 0;     // radians from horizontal
    double area = 0;
};

std::optional<RoofFace> roofFace(const std::vector<CrsCoordinate> &ring) {
    double nx = 0, ny = 0, nz = 0;
    for (size_t i = 0; i < ring.size(); ++i) {
        const CrsCoordinate &a = ring[i], &b = ring[(i + 1) % ring.size()];
        double ay = a.y - ring[0].y, az = a.z - ring[0].z, ax = a.x - ring[0].x;
        double by = b.y - ring[0].y, bz = b.z - ring[0].z, bx = b.x - ring[0].x;
        nx += ay * bz - az * by, ny += az * bx - ax * bz, nz += ax * by - ay * bx;
    }
    double length = std::sqrt(nx * nx + ny * ny + nz * nz);
    if (length == 0 || nz <= 0) return std::nullopt;  // a roof faces up
    return RoofFace{std::atan2(ny, nx), std::acos(std::min(1.0, nz / length)), length / 2};
}

double angleBetween(double a, double b) {
    double d = std::fmod(std::abs(a - b), 2 * std::numbers::pi);
    return std::min(d, 2 * std::numbers::pi - d);
}

}  // namespace

std::optional<RoofType> roofTypeFromSlopes(const CityGmlBuilding &building) {
    constexpr double kFlat = 5 * std::numbers::pi / 180, kSameSide = 20 * std::numbers::pi / 180;
    std::vector<RoofFace> faces;
    double roofArea = 0;
    for (const CityGmlPolygon &polygon : building.polygons)
        if (polygon.kind == SurfaceKind::Roof)
            if (auto face = roofFace(polygon.rings.front())) {
                roofArea += face->area;
                faces.push_back(*face);
            }
    if (faces.empty()) return std::nullopt;
    // The sides of the roof: sloped faces grouped by the direction they face, largest first.
    std::sort(faces.begin(), faces.end(), [](const RoofFace &a, const RoofFace &b) { return a.area > b.area; });
    struct Side {
        double azimuth, area, minTilt, maxTilt;
    };
    std::vector<Side> sides;
    double sloped = 0;
    for (const RoofFace &face : faces) {
        if (face.tilt < kFlat) continue;
        sloped += face.area;
        auto side = std::find_if(sides.begin(), sides.end(),
                                 [&](const Side &s) { return angleBetween(s.azimuth, face.azimuth) < kSameSide; });
        if (side == sides.end()) {
            sides.push_back({face.azimuth, face.area, face.tilt, face.tilt});
        } else {
            side->area += face.area;
            side->minTilt = std::min(side->minTilt, face.tilt), side->maxTilt = std::max(side->maxTilt, face.tilt);
        }
    }
    if (sloped < 0.1 * roofArea) return RoofType::Flat;
    // Dormers and bits of other roofs are not sides of it.
    std::erase_if(sides, [&](const Side &s) { return s.area < 0.05 * sloped; });
    bool twoPitches =
        std::any_of(sides.begin(), sides.end(), [&](const Side &s) { return s.maxTilt - s.minTilt > 3 * kFlat; });
    if (sides.size() == 1) return RoofType::Shed;
    if (sides.size() == 2 && angleBetween(sides[0].azimuth, sides[1].azimuth) > std::numbers::pi - kSameSide)
        return twoPitches ? RoofType::Mansard : RoofType::Gable;
    if (sides.size() >= 3) return twoPitches ? RoofType::Mansard : RoofType::Hip;
    return std::nullopt;
}

std::optional<RoofType> roofTypeOfCode(std::string_view code) {
    using enum RoofType;
    static constexpr std::array<std::pair<std::string_view, RoofType>, 14> kCodes{{
        // AdV (ALKIS Dachform, the German LoD2 profile)
        {"1000", Flat},
        {"2100", Shed},
        {"3100", Gable},
        {"3200", Hip},
        {"3300", HalfHip},
        {"3400", Mansard},
        {"3500", Pyramid},
        // CityGML 1.0/2.0 (SIG 3D code list); 1000 is flat in both
        {"1010", Shed},
        {"1030", Gable},
        {"1040", Hip},
        {"1050", HalfHip},
        {"1060", Mansard},
        {"1070", Pyramid},
        {"1120", Pyramid},
    }};
    for (const auto &[text, type] : kCodes)
        if (code == text) return type;
    return std::nullopt;
}

}  // namespace veduta

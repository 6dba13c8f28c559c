#include "city/citygml_twin.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_set_2.h>
#include <fmt/format.h>

#include "city/citygml_buildings.h"
#include "city/citygml_measures.h"
#include "city/footprint.h"

namespace veduta {

namespace {

// Exact constructions: the ground surfaces of a building's parts share edges and corners,
// which an inexact union does not survive.
using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Polygon = CGAL::Polygon_2<Kernel>;
using PolygonWithHoles = CGAL::Polygon_with_holes_2<Kernel>;
using PolygonSet = CGAL::Polygon_set_2<Kernel>;

constexpr double kStoreyHeight = 3.3;  // metres, when the file gives no storeys
constexpr double kMinPointGap = 0.05;  // metres: closer points are one
constexpr double kMinBend = 0.02;      // metres off the line through the neighbours

// The ring's points in the scene's local frame, as a simple counter-clockwise CGAL polygon,
// or nothing when the ring has no area seen from above (a wall) or crosses itself.
std::optional<Polygon> localOutline(const std::vector<CrsCoordinate> &ring, const MapProjection &projection) {
    Polygon polygon;
    for (const CrsCoordinate &p : ring) {
        MapPoint local = projection.toLocal({p.x, p.y});
        polygon.push_back({local.easting, local.northing});
    }
    if (polygon.size() < 3 || !polygon.is_simple() || polygon.area() == 0) return std::nullopt;
    if (polygon.is_clockwise_oriented()) polygon.reverse_orientation();
    return polygon;
}

// The outlines a footprint is the union of: the ground surfaces, else the roofs.
std::vector<Polygon> footprintPieces(const CityGmlBuilding &building, const MapProjection &projection) {
    std::vector<Polygon> pieces;
    for (SurfaceKind kind : {SurfaceKind::Ground, SurfaceKind::Roof}) {
        for (const CityGmlPolygon &polygon : building.polygons)
            if (polygon.kind == kind)
                if (auto outline = localOutline(polygon.rings.front(), projection)) pieces.push_back(*outline);
        if (!pieces.empty()) break;
    }
    return pieces;
}

// Drops points that add nothing to the outline: those within kMinPointGap of the one before,
// and those within kMinBend of the line through their neighbours.
std::vector<Vec2f> simplified(std::vector<Vec2f> ring) {
    bool changed = true;
    while (changed && ring.size() > 3) {
        changed = false;
        for (size_t i = 0; i < ring.size() && ring.size() > 3; ++i) {
            Vec2f a = ring[(i + ring.size() - 1) % ring.size()], p = ring[i], b = ring[(i + 1) % ring.size()];
            float ab = std::hypot(b.x - a.x, b.y - a.y);
            float gap = std::hypot(p.x - a.x, p.y - a.y);
            float off = ab > 0 ? std::abs((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x)) / ab : gap;
            if (gap < kMinPointGap || off < kMinBend) {
                ring.erase(ring.begin() + long(i));
                changed = true;
            }
        }
    }
    return ring;
}

std::vector<Vec2f> pointsOf(const Polygon &polygon) {
    std::vector<Vec2f> points;
    for (const auto &p : polygon.vertices())
        points.push_back({float(CGAL::to_double(p.x())), float(CGAL::to_double(p.y()))});
    return points;
}

// The footprint: the largest piece of the union, without its courtyards.
std::optional<std::vector<Vec2f>> footprintOf(const CityGmlBuilding &building, const MapProjection &projection,
                                              std::vector<std::string> &warnings) {
    std::vector<Polygon> pieces = footprintPieces(building, projection);
    if (pieces.empty()) return std::nullopt;
    PolygonSet united;
    united.join(pieces.begin(), pieces.end());
    std::vector<PolygonWithHoles> parts;
    united.polygons_with_holes(std::back_inserter(parts));
    auto largest = std::max_element(parts.begin(), parts.end(), [](const auto &a, const auto &b) {
        return a.outer_boundary().area() < b.outer_boundary().area();
    });
    if (parts.size() > 1)
        warnings.push_back(fmt::format("building {}: its ground is {} separate pieces; the twin stands on the largest",
                                       building.id, parts.size()));
    if (largest->number_of_holes() > 0)
        warnings.push_back(
            fmt::format("building {}: the twin fills its {} courtyard(s)", building.id, largest->number_of_holes()));
    std::vector<Vec2f> outline = pointsOf(largest->outer_boundary());
    std::vector<Vec2f> simple = simplified(outline);
    if (isSimplePolygon(simple)) return simple;
    if (isSimplePolygon(outline)) return outline;  // the float points of a tight outline may touch
    return std::nullopt;
}

unsigned storeysOf(const CityGmlBuilding &building, double wallHeight) {
    if (building.storeysAboveGround && *building.storeysAboveGround > 0) return unsigned(*building.storeysAboveGround);
    return unsigned(std::max(1.0, std::round(wallHeight / kStoreyHeight)));
}

}  // namespace

std::optional<TwinBuilding> deriveTwin(const CityGmlBuilding &building, const MapProjection &projection,
                                       std::vector<std::string> &warnings) {
    std::optional<std::vector<Vec2f>> footprint;
    try {
        footprint = footprintOf(building, projection, warnings);
    } catch (const std::out_of_range &e) {
        warnings.push_back(fmt::format("building {}: no twin: {}", building.id, e.what()));
        return std::nullopt;
    }
    if (!footprint) {
        warnings.push_back(
            fmt::format("building {}: no twin: it has no ground or roof outline seen from above", building.id));
        return std::nullopt;
    }
    BuildingMeasures m = measureBuilding(building);
    TwinBuilding twin;
    twin.gmlId = building.id;
    twin.id = cityGmlBuildingId(building.id);
    twin.footprint = std::move(*footprint);
    twin.base = m.ground;
    twin.wallHeight = m.eaves - m.ground;
    twin.roofHeight = m.ridge - m.eaves;
    twin.roof = m.roofType;
    if (twin.wallHeight < 0.5) {
        warnings.push_back(
            fmt::format("building {}: no twin: its walls are {:.2f} m high", building.id, twin.wallHeight));
        return std::nullopt;
    }
    twin.storeys = storeysOf(building, twin.wallHeight);
    twin.floorHeight = twin.wallHeight / twin.storeys;
    return twin;
}

}  // namespace veduta

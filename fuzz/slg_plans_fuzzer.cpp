// Schrader's plans on any outline (docs/slg.md): the bytes are a polygon's corners (pairs of
// 16-bit decimetres), a seed and a lot area. A simple outline of some size is subdivided into
// lots as a block, each lot planned down to its rooms; nothing may fail a check, and the
// faces must lie in the outline and make up its area. Real outlines (ATKIS blocks, OSM ways) come
// in any shape, so this is the SLG's reader of the world.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>

#include "slg/building_plan.h"
#include "slg/subdivision.h"

namespace {

using namespace veduta;

struct Reader {
    const uint8_t *data;
    size_t size, at = 0;
    template <typename T>
    T next() {
        T value{};
        if (at + sizeof(T) <= size) std::memcpy(&value, data + at, sizeof(T));
        at += sizeof(T);
        return value;
    }
};

void check(bool condition, const char *what) {
    if (!condition) throw std::logic_error(what);
}

// The faces of a subdivision lie in the outline and make up its area.
void checkFaces(const Subdivision &s, const Polygon2d &outline, double size) {
    double area = 0;
    for (const Polygon2d &face : facePolygons(s)) {
        check(signedArea(face) > 0, "a face runs clockwise");
        area += signedArea(face);
        for (Vec2d p : face) check(distanceOutside(outline, p) < 1e-9 * size, "a face leaves the outline");
    }
    check(std::abs(area - signedArea(outline)) <= 1e-6 * signedArea(outline), "the faces do not make the outline");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    Reader in{data, size};
    uint32_t seed = in.next<uint16_t>();
    double lotArea = 60 + in.next<uint8_t>() * 4.0;
    size_t corners = 3 + in.next<uint8_t>() % 14;
    Polygon2d outline;
    for (size_t i = 0; i < corners; ++i) {
        double x = in.next<int16_t>() * 0.1, y = in.next<int16_t>() * 0.1;
        outline.push_back({x, y});
    }
    if (in.at > size || !isSimple(outline)) return 0;
    if (signedArea(outline) < 0) std::reverse(outline.begin(), outline.end());
    double area = signedArea(outline), extent = 0;
    for (Vec2d p : outline) extent = std::max({extent, std::abs(p.x), std::abs(p.y)});
    if (area < 400 || area > 40000) return 0;

    PlanParameters block;
    block.averageArea = lotArea;
    block.jitter = 0.05;
    SearchLimits limits;
    limits.maximumSteps = 20000;
    Subdivision lots = subdivide(outline, std::vector<EdgeLocation>(outline.size(), EdgeLocation::Street), block,
                                 PlanRandom(seed, 1, RandomStream::SlgPlan), limits);
    checkFaces(lots, outline, extent + 1);

    BuildingPlanParameters building;
    building.storey.rule = building.apartment.rule = LandmarkRule::Growth;
    building.storey.averageArea = 30;
    building.storey.scale = 15;
    building.storey.exponent = 2;
    building.storey.reflexLimits = {1, 1, 0};
    building.apartment.averageArea = 10;
    building.apartment.sideRatio = 1.0 / 3;
    building.apartment.exponent = 3;
    building.apartment.minimumCount = 3;
    building.apartment.reflexLimits = {1, 1, 0};
    building.placement.minimumSide = lengthLimits(building.storey).minimum;
    building.limits = limits;
    uint32_t identity = 0;
    for (const PlanFace *face : lots.borderFaces()) {
        PlanShape shape = faceShape(lots, *face);
        building.placement.bauweise = Bauweise(identity % 3);
        auto plan = planBuilding(shape, fourSides(shape.points, frontEdges(*face)), building, seed, identity++);
        if (!plan) continue;
        for (const ApartmentPlan &a : plan->storey.apartments)
            for (Vec2d p : a.outline.points)
                check(distanceOutside(plan->placement.footprint.points, p) < 1e-6 * (extent + 1),
                      "an apartment leaves its building");
    }
    return 0;
}

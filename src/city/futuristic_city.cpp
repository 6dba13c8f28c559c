#include "city/futuristic_city.h"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <limits>

#include "city/floating_streets.h"
#include "city/generate_city.h"
#include "city/material_palette.h"
#include "city/prism_building.h"
#include "core/hash.h"
#include "core/random_streams.h"

namespace veduta {

uint32_t levelSeed(uint32_t seed, unsigned index) {
    return index == 0 ? seed : hashValues({seed, index, streamTag(RandomStream::StreetLevel)});
}

std::vector<UpperLevel> growUpperLevels(const GrowLevel &grow, const CityGrowth &ground, unsigned count,
                                        const SettingsMap &lotSettings, std::vector<std::string> &warnings) {
    std::vector<UpperLevel> levels;
    for (unsigned index = 1; index < count; ++index) {
        CityGrowth growth = ground;
        growth.seed = levelSeed(ground.seed, index);
        growth.environment = nullptr;
        growth.roads.clear();  // the ground's roads stay on the ground
        std::vector<std::string> found;
        UpperLevel level{index, growth.seed, grow(growth, found)};
        level.city.settings = lotSettings;
        cutLots(level.city, {}, level.seed, found);
        for (const std::string &w : found) warnings.push_back(fmt::format("level {}: {}", index, w));
        levels.push_back(std::move(level));
    }
    return levels;
}

std::vector<Vec2f> junctionsOf(const StreetNetwork &network) {
    std::vector<unsigned> degree(network.nodes.size(), 0);
    for (const StreetNetwork::Street &s : network.streets) ++degree[s.from], ++degree[s.to];
    std::vector<Vec2f> junctions;
    for (size_t v = 0; v < network.nodes.size(); ++v)
        if (degree[v] >= 3) junctions.push_back(network.nodes[v]);
    return junctions;
}

namespace {

float planDistance(const Vec3f &a, const Vec3f &b) { return std::hypot(a.x - b.x, a.y - b.y); }

// The index of the point of `among` nearest `p` in plan (the first of equals).
size_t nearest(const Vec3f &p, std::span<const Vec3f> among) {
    size_t best = 0;
    float bestDistance = std::numeric_limits<float>::infinity();
    for (size_t i = 0; i < among.size(); ++i) {
        float d = planDistance(p, among[i]);
        if (d < bestDistance) best = i, bestDistance = d;
    }
    return best;
}

}  // namespace

std::vector<Lift> liftsBetween(std::span<const Vec3f> lower, std::span<const Vec3f> upper, float reach) {
    std::vector<Lift> lifts;
    if (lower.empty()) return lifts;
    for (size_t u = 0; u < upper.size(); ++u) {
        size_t l = nearest(upper[u], lower);
        if (planDistance(upper[u], lower[l]) <= reach && nearest(lower[l], upper) == u)
            lifts.push_back({lower[l], upper[u]});
    }
    return lifts;
}

namespace {

constexpr float kLiftPlatformSide = 4, kLiftPlatformThickness = 0.3f, kLiftRailSide = 0.25f;

struct LevelMaterials {
    MaterialId slab, crossing, platform, rail, roof, floor;
};

LevelMaterials levelMaterials(RenderSceneBuilder &builder) {
    auto material = [&](const char *name, Vec3f colour) {
        return builder.findOrAddMaterial(Material::lambertian(name, colour));
    };
    return {material("street/floating", {0.2f, 0.21f, 0.24f}), material("street/crossing", {0.33f, 0.34f, 0.38f}),
            material("lift/platform", {0.6f, 0.62f, 0.66f}),   material("lift/rail", {0.45f, 0.46f, 0.5f}),
            material("prism/roof", {0.32f, 0.33f, 0.35f}),     material("prism/floor", {0.55f, 0.57f, 0.6f})};
}

void addSolid(Mesh solid, MaterialId material, Mesh &into) {
    solid.setMaterial(material);
    into.append(solid, Transform());
}

// A level's slabs and crossings at `height`: each street runs from crossing mouth to crossing
// mouth (a dead end to its node); a crossing reaches out half its widest street's width times √2
// (kJunctionReach), so that arms at right angles give distinct contour points and it is an
// octagon, chamfered at the corners, rather than a square.
Mesh levelStreets(const StreetNetwork &network, float height, float thickness, const LevelMaterials &materials) {
    std::vector<std::vector<CrossingArm>> arms(network.nodes.size());
    for (const StreetNetwork::Street &s : network.streets) {
        Vec2f d = network.nodes[s.to] - network.nodes[s.from];
        float length = std::hypot(d.x, d.y);
        if (length == 0) continue;
        d = d * (1 / length);
        arms[s.from].push_back({d, s.width});
        arms[s.to].push_back({d * -1.0f, s.width});
    }
    std::vector<float> mouth(network.nodes.size(), 0);
    Mesh mesh;
    for (size_t v = 0; v < network.nodes.size(); ++v) {
        if (arms[v].size() < 2) continue;
        for (const CrossingArm &arm : arms[v]) mouth[v] = std::max(mouth[v], arm.width / 2 * kJunctionReach);
        addSolid(crossingSolid(lift(network.nodes[v], height), arms[v], mouth[v], thickness), materials.crossing, mesh);
    }
    for (const StreetNetwork::Street &s : network.streets) {
        Vec2f a = network.nodes[s.from], b = network.nodes[s.to], d = b - a;
        float length = std::hypot(d.x, d.y);
        if (length <= mouth[s.from] + mouth[s.to]) continue;  // the crossings cover it
        d = d * (1 / length);
        addSolid(streetSlab(lift(a + d * mouth[s.from], height), lift(b - d * mouth[s.to], height), s.width, thickness),
                 materials.slab, mesh);
    }
    return mesh;
}

// The lift's platform stopped somewhere on its way (the thesis animates it; a still shows it
// where the seed and its two ends put it), between two rails from bottom to top.
Mesh liftMesh(const Lift &lift, uint32_t seed, const LevelMaterials &materials) {
    uint32_t identity =
        hashValues({uint32_t(std::lround(lift.bottom.x * 100)), uint32_t(std::lround(lift.bottom.y * 100)),
                    uint32_t(std::lround(lift.top.x * 100)), uint32_t(std::lround(lift.top.y * 100))});
    float t = bitsToUnitFloat(hashValues({seed, identity, streamTag(RandomStream::LiftStop)}));
    Vec3f way = lift.top - lift.bottom;
    Vec3f at = lift.bottom + way * t;
    Vec3f x{kLiftPlatformSide, 0, 0}, y{0, kLiftPlatformSide, 0}, z{0, 0, kLiftPlatformThickness};
    Mesh mesh;
    addSolid(solidBox(at - x * 0.5f - y * 0.5f - z, x, y, z), materials.platform, mesh);
    Vec3f rx{kLiftRailSide, 0, 0}, ry{0, kLiftRailSide, 0};
    for (float side : {-1.0f, 1.0f}) {
        Vec3f offset = x * (0.5f * side) + rx * (side > 0 ? 0.0f : -1.0f) - ry * 0.5f;
        addSolid(solidBox(lift.bottom + offset, rx, ry, way), materials.rail, mesh);
    }
    return mesh;
}

std::vector<Vec3f> liftStops(const StreetNetwork &network, float height) {
    std::vector<Vec3f> stops;
    for (Vec2f p : junctionsOf(network)) stops.push_back(lift(p, height));
    return stops;
}

uint32_t addPrisms(const UpperLevel &level, float height, uint32_t seed, ObjectId objectId,
                   const MaterialPalette &palette, const LevelMaterials &materials, RenderSceneBuilder &builder) {
    uint32_t built = 0;
    for (const CityBlock &block : level.city.blocks)
        for (const CityLot &lot : block.lots) {
            uint32_t id = cityBuildingId(objectId, hashValues({level.index, lot.sourceId}));
            float h = kPrismMinHeight +
                (kPrismMaxHeight - kPrismMinHeight) *
                    bitsToUnitFloat(hashValues({seed, id, streamTag(RandomStream::BuildingHeights)}));
            MaterialId facade = palette.choose(seed, id)[MaterialCategory::Facade];
            Mesh prism = prismBuilding(lot.points, height, h, builder.materials()[facade].textureSize);
            const MaterialId surfaces[] = {facade, materials.roof, materials.floor};
            for (MaterialId &m : prism.triangleMaterials) m = surfaces[m];
            builder.addWorldMesh(std::move(prism), objectId, id);
            builder.recordBuilding({id, height, height + h, height + h, "flat", {lot.points}});
            ++built;
        }
    return built;
}

}  // namespace

uint32_t buildUpperLevels(std::span<const UpperLevel> levels, std::span<const Vec3f> groundJunctions,
                          const StreetLevels &settings, uint32_t seed, ObjectId objectId, RenderSceneBuilder &builder) {
    float datum = 0;
    for (const Vec3f &p : groundJunctions) datum = std::max(datum, p.z);
    LevelMaterials materials = levelMaterials(builder);
    MaterialPalette palette(builder);
    Mesh structure;
    std::vector<Vec3f> below(groundJunctions.begin(), groundJunctions.end());
    uint32_t built = 0;
    for (const UpperLevel &level : levels) {
        float height = datum + float(level.index) * settings.spacing;
        StreetNetwork network = streetNetworkOf(level.city);
        structure.append(levelStreets(network, height, settings.thickness, materials), Transform());
        std::vector<Vec3f> stops = liftStops(network, height);
        for (const Lift &lift : liftsBetween(below, stops, settings.liftReach))
            structure.append(liftMesh(lift, seed, materials), Transform());
        built += addPrisms(level, height, seed, objectId, palette, materials, builder);
        below = std::move(stops);
    }
    if (!structure.indices.empty()) builder.addWorldMesh(std::move(structure), objectId);
    return built;
}

}  // namespace veduta

#include "city/slg_buildings.h"

#include <algorithm>

#include <fmt/format.h>

#include "core/error.h"
#include "core/hash.h"
#include "slg/building_mesh.h"
#include "slg/ear_clipping.h"
#include "slg/lot_building.h"
#include "slg/urban_geography_file.h"

namespace veduta {

namespace {

// Purposes of the generator's own draws under a building's identity.
enum Draw : uint32_t { kRoof = 0x534c5246u, kRoofSize = 0x534c5253u };  // "SLRF", "SLRS"

struct SlgMaterials {
    BuildingMaterials building;
    MaterialId street = 0, block = 0, sidewalk = 0;
};

SlgMaterials materialsOf(RenderSceneBuilder &builder) {
    auto add = [&](const char *name, Vec3f albedo, MaterialCategory category) {
        Material m = Material::lambertian(name, albedo);
        m.category = category;
        return builder.findOrAddMaterial(std::move(m));
    };
    Material glass;
    glass.name = "slg/glass";
    glass.category = MaterialCategory::Window;
    glass.glass = true;
    SlgMaterials m;
    m.building = {add("slg/wall", {0.62f, 0.55f, 0.46f}, MaterialCategory::Wall), builder.findOrAddMaterial(glass),
                  add("slg/door", {0.25f, 0.16f, 0.1f}, MaterialCategory::Door),
                  add("slg/roof", {0.42f, 0.17f, 0.12f}, MaterialCategory::Roof),
                  add("slg/interior", {0.75f, 0.72f, 0.66f}, MaterialCategory::Material)};
    m.street = add("street/asphalt", {0.16f, 0.16f, 0.17f}, MaterialCategory::None);
    m.block = add("slg/yard", {0.3f, 0.33f, 0.22f}, MaterialCategory::None);
    m.sidewalk = add("street/pavement", {0.45f, 0.43f, 0.4f}, MaterialCategory::None);
    return m;
}

Polygon2d outlineOf(const SlgDesc &desc) {
    Polygon2d outline;
    for (Vec2f p : desc.outline) outline.push_back({p.x, p.y});
    if (!isSimple(outline)) throw InputError(desc.outlineLoc, "the outline crosses itself");
    if (signedArea(outline) < 0) std::reverse(outline.begin(), outline.end());
    return outline;
}

// A flat polygon of the ground at height z, facing up.
Mesh groundMesh(const Polygon2d &ccw, double z, MaterialId material) {
    Mesh mesh;
    for (auto [i, j, k] : clipEars(ccw)) {
        for (uint32_t v : {i, j, k}) {
            mesh.indices.push_back(uint32_t(mesh.positions.size()));
            mesh.positions.push_back({float(ccw[v].x), float(ccw[v].y), float(z)});
            mesh.uvs.push_back({float(ccw[v].x), float(ccw[v].y)});
        }
        mesh.triangleMaterials.push_back(material);
    }
    return mesh;
}

struct SlgBlock {
    Polygon2d outline;
    LandUseWeights weights{};
    Locality locality = Locality::Kern;
};

// Table 6's district cut into blocks along its outline, each face moved back from the streets
// between them by half their width (L1339); a block's locality is its distance from the
// district's centre (eq 38), its land uses drawn from the district's (eq 39–41, 44).
std::vector<SlgBlock> blocksOf(const SlgDesc &desc, const Polygon2d &outline, const UrbanGeography &g, uint32_t seed,
                               int &lost) {
    if (desc.level == SlgDesc::Level::Block)
        return {{outline, blockWeights(g, g.blockDefaults.weights), g.blockDefaults.locality.value_or(Locality::Kern)}};
    PlanParameters district = planParameters(g, PlanLevel::District);
    Subdivision faces = subdivide(outline, std::vector<EdgeLocation>(outline.size(), EdgeLocation::Street), district,
                                  PlanRandom(seed, desc.objectId, RandomStream::SlgPlan));
    labelEdges(faces, PlanLevel::District);
    lost += faces.deletedFaces;
    Vec2d centre = vertexMean(outline);
    double farthest = 0;
    for (Vec2d p : outline) farthest = std::max(farthest, length(p - centre));
    std::vector<SlgBlock> blocks;
    for (const PlanFace *face : faces.borderFaces()) {
        PlanShape shape = faceShape(faces, *face);
        double half = district.gapWidth / 2;
        auto moved =
            moveSides(shape, fourSides(shape.points, frontEdges(*face)), {0, half, half, half}, EdgeLocation::Street);
        if (!moved) {
            ++lost;
            continue;
        }
        uint32_t identity = hashValues({desc.objectId, uint32_t(blocks.size()), 0x424c4b53u});  // "BLKS"
        Locality locality = veduta::locality(length(vertexMean(moved->shape.points) - centre), farthest);
        LandUseWeights drawn = childWeights(g, g.districtDefaults.weights, locality, parameterRandom(seed, identity));
        blocks.push_back({std::move(moved->shape.points), blockWeights(g, drawn), locality});
    }
    return blocks;
}

BuildingLod lodAt(const SlgDesc &desc, const Camera &camera, const PlanShape &footprint, double height) {
    Vec2d c = vertexMean(footprint.points);
    Vec3f centre{float(c.x), float(c.y), float(desc.base + height / 2)};
    float distance = length(centre - camera.position);
    if (distance < desc.rooms) return BuildingLod::Rooms;
    return distance < desc.storeys ? BuildingLod::Storeys : BuildingLod::Box;
}

class SlgGenerator {
  public:
    SlgGenerator(const SlgDesc &desc, uint32_t seed, const Camera &camera, RenderSceneBuilder &builder) :
        desc_(desc),
        seed_(seed),
        camera_(camera),
        builder_(builder),
        g_(readUrbanGeography(desc.tables)),
        materials_(materialsOf(builder)) {}

    void generate(std::vector<std::string> &warnings) {
        Polygon2d outline = outlineOf(desc_);
        if (desc_.level == SlgDesc::Level::District)
            builder_.addWorldMesh(groundMesh(outline, desc_.base, materials_.street), desc_.objectId);
        std::vector<SlgBlock> blocks = blocksOf(desc_, outline, g_, seed_, lost_);
        for (size_t b = 0; b < blocks.size(); ++b) planBlock(blocks[b], uint32_t(b));
        if (lost_ > 0)
            warnings.push_back(
                fmt::format("{}: {} faces of the plans could not be made (docs/slg.md)", desc_.loc.toString(), lost_));
        if (unplanned_ > 0)
            warnings.push_back(
                fmt::format("{}: {} lots have no room for a building", desc_.loc.toString(), unplanned_));
    }

  private:
    void planBlock(const SlgBlock &block, uint32_t index) {
        DominantUse use = dominantUse(block.weights);
        Subdivision lots =
            subdivide(block.outline, std::vector<EdgeLocation>(block.outline.size(), EdgeLocation::Street),
                      blockPlanParameters(g_, use, block.locality),
                      PlanRandom(seed_, hashValues({desc_.objectId, index}), RandomStream::SlgPlan));
        labelEdges(lots, PlanLevel::Block);
        lost_ += lots.deletedFaces;
        // A block's ground and its sidewalks are one mesh.
        Mesh ground = groundMesh(block.outline, desc_.base + 0.01, materials_.block);
        uint32_t lot = 0;
        for (const PlanFace *face : lots.borderFaces())
            planLot(block, lots, *face, hashValues({desc_.objectId, index, lot++}), ground);
        builder_.addWorldMesh(std::move(ground), desc_.objectId);
    }

    void planLot(const SlgBlock &block, const Subdivision &lots, const PlanFace &face, uint32_t identity,
                 Mesh &ground) {
        LotGeography geography{lotWeights(g_, block.weights, parameterRandom(seed_, identity)), block.locality, {}};
        auto building = lotBuilding(g_, geography, seed_, identity);
        if (!building) return;  // open land
        PlanShape shape = faceShape(lots, face);
        auto plan =
            planBuilding(shape, fourSides(shape.points, frontEdges(face)), building->parameters, seed_, identity);
        if (!plan) {
            ++unplanned_;
            return;
        }
        lost_ += plan->losses.deletedFaces;
        for (const Polygon2d &quad : plan->sidewalk)
            ground.append(groundMesh(quad, desc_.base + 0.02, materials_.sidewalk), Transform());

        int corners = int(turningPoints(plan->placement.footprint.points).size());
        BuildingShape shape3d;
        shape3d.base = desc_.base;
        shape3d.roof = roofKind(geography.weights, corners,
                                PlanRandom(seed_, hashValues({identity, kRoof}), RandomStream::SlgParameters));
        shape3d.orientation = building->orientation;
        shape3d.roofHeight =
            roofDimensions(g_, PlanRandom(seed_, hashValues({identity, kRoofSize}), RandomStream::SlgParameters))
                .height;
        shape3d.windows.width = 1.2;
        shape3d.windows.spacing = 1.3;
        shape3d.windows.wallDistance = 0.8;
        shape3d.wallThickness = g_.wallThickness;
        BuildingLod lod = lodAt(desc_, camera_, plan->placement.footprint, plan->storeys * shape3d.storeyHeight);
        uint32_t buildingId =
            1 + hashValues({desc_.objectId, identity, streamTag(RandomStream::CityBuilding)}) % ((1u << 24) - 1);
        builder_.addWorldMesh(buildingMesh(*plan, shape3d, lod, materials_.building), desc_.objectId, buildingId);
    }

    const SlgDesc &desc_;
    uint32_t seed_;
    const Camera &camera_;
    RenderSceneBuilder &builder_;
    UrbanGeography g_;
    SlgMaterials materials_;
    int lost_ = 0, unplanned_ = 0;
};

}  // namespace

void generateSlg(const SlgDesc &desc, uint32_t seed, const Camera &camera, RenderSceneBuilder &builder,
                 std::vector<std::string> &warnings) {
    SlgGenerator(desc, seed, camera, builder).generate(warnings);
}

}  // namespace veduta

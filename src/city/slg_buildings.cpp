#include "city/slg_buildings.h"

#include <algorithm>
#include <array>
#include <map>

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include "core/error.h"
#include "core/hash.h"
#include "slg/building_mesh.h"
#include "slg/ear_clipping.h"
#include "slg/lot_building.h"
#include "slg/quarters.h"
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
    uint32_t element = 0;  // which <slg>
    uint32_t index = 0;    // in its element, for the identities of its lots
    Polygon2d outline;     // empty for a batch of given footprints
    LandUseWeights weights{};
    Locality locality = Locality::Kern;
    std::vector<const SlgFootprint *> footprints;  // given (level="atkis"): no lots cut
    bool onTerrain = false;                        // the terrain is the ground: no ground or sidewalk meshes
};

// A district's (or quarter's) outline cut into blocks between streets (Table 6), each face
// moved back from the streets by half their width (L1339). The level's faces run in a ring
// along the outline and leave the middle as an inner face; a middle large enough for another
// ring is moved back from its streets and cut the same way, one smaller is a block of its own
// (docs/slg.md).
std::vector<Polygon2d> ringBlocks(uint32_t identity, const Polygon2d &outline, const PlanParameters &district,
                                  uint32_t seed, int &lost) {
    double half = district.gapWidth / 2;
    std::vector<Polygon2d> blocks, parts{outline};
    for (size_t next = 0; next < parts.size(); ++next) {
        // The middle's outline has a corner where each ray of the ring ended; only its turns are
        // corners of the next ring's outline.
        Polygon2d part;
        for (size_t corner : turningPoints(parts[next])) part.push_back(parts[next][corner]);
        uint32_t ring = next == 0 ? identity : hashValues({identity, uint32_t(next), 0x52494e47u});  // "RING"
        Subdivision faces = subdivide(part, std::vector<EdgeLocation>(part.size(), EdgeLocation::Street), district,
                                      PlanRandom(seed, ring, RandomStream::SlgPlan));
        labelEdges(faces, PlanLevel::District);
        lost += faces.deletedFaces;
        if (faces.borderFaces().empty()) {
            blocks.push_back(std::move(part));
            continue;
        }
        for (const PlanFace &face : faces.faces) {
            PlanShape shape = faceShape(faces, face);
            auto moved = face.isBorder()
                ? moveSides(shape, fourSides(shape.points, frontEdges(face)), {0, half, half, half},
                            EdgeLocation::Street)
                : moveEdges(shape, std::vector<double>(shape.size(), half), EdgeLocation::Street);
            if (!moved) {
                ++lost;
                continue;
            }
            bool another = !face.isBorder() && signedArea(moved->shape.points) > 2 * district.averageArea;
            (another ? parts : blocks).push_back(std::move(moved->shape.points));
        }
    }
    return blocks;
}

// A district larger than a quarter is cut into quarters of about a kilometre by the city's
// main streets (Table 4's 20 m; quarters.h) first, and the quarters are filled on all cores.
std::vector<Polygon2d> districtBlocks(uint32_t identity, const Polygon2d &outline, const UrbanGeography &g,
                                      uint32_t seed, int &lost) {
    constexpr double kQuarterSide = 1000;
    PlanParameters district = planParameters(g, PlanLevel::District);
    std::vector<Polygon2d> parts = quarters(outline, kQuarterSide, planParameters(g, PlanLevel::City).gapWidth);
    if (parts.size() == 1) return ringBlocks(identity, outline, district, seed, lost);
    std::vector<std::vector<Polygon2d>> filled(parts.size());
    std::vector<int> losses(parts.size(), 0);
    tbb::parallel_for(size_t(0), parts.size(), [&](size_t q) {
        uint32_t quarter = hashValues({identity, uint32_t(q), 0x51525452u});  // "QRTR"
        filled[q] = ringBlocks(quarter, parts[q], district, seed, losses[q]);
    });
    std::vector<Polygon2d> blocks;
    for (size_t q = 0; q < parts.size(); ++q) {
        lost += losses[q];
        for (Polygon2d &block : filled[q]) blocks.push_back(std::move(block));
    }
    return blocks;
}

// A block's locality is its distance from the district's centre (eq 38), its land uses drawn
// from the district's (eq 39–41, 44).
void addBlocks(const SlgDesc &desc, uint32_t element, const Polygon2d &outline, const UrbanGeography &g, uint32_t seed,
               std::vector<SlgBlock> &blocks, int &lost) {
    if (desc.level == SlgDesc::Level::Block) {
        blocks.push_back({element,
                          0,
                          outline,
                          blockWeights(g, g.blockDefaults.weights),
                          g.blockDefaults.locality.value_or(Locality::Kern),
                          {},
                          false});
        return;
    }
    Vec2d centre = vertexMean(outline);
    double farthest = 0;
    for (Vec2d p : outline) farthest = std::max(farthest, length(p - centre));
    uint32_t index = 0;
    for (Polygon2d &block : districtBlocks(desc.objectId, outline, g, seed, lost)) {
        uint32_t identity = hashValues({desc.objectId, index, 0x424c4b53u});  // "BLKS"
        Locality locality = veduta::locality(length(vertexMean(block) - centre), farthest);
        LandUseWeights drawn = childWeights(g, g.districtDefaults.weights, locality, parameterRandom(seed, identity));
        blocks.push_back({element, index++, std::move(block), blockWeights(g, drawn), locality, {}, false});
    }
}

// The weights of a settlement area's land use: all of it for one use, the district's mixture
// for none.
LandUseWeights settlementWeights(const UrbanGeography &g, std::optional<LandUse> use) {
    if (!use) return g.districtDefaults.weights;
    LandUseWeights weights{};
    weights[size_t(*use)] = 1;
    return weights;
}

// level="atkis" (digest-003 §8.3): a settlement area with no given footprint in it is filled
// as a district is, ring by ring (one block when it is small); the footprints, in batches per
// settlement area they lie in, are buildings of their own with its land use. Locality is the
// distance from the middle of all settlement areas (eq 38).
void addAtkisBlocks(const SlgDesc &desc, uint32_t element, const SlgLandInput &land, const UrbanGeography &g,
                    uint32_t seed, std::vector<SlgBlock> &blocks, int &lost) {
    constexpr size_t kBatch = 64;
    const std::vector<SlgSettlement> &areas = land.settlements;
    std::vector<std::vector<const SlgFootprint *>> within(areas.size() + 1);  // the last: in none
    for (const SlgFootprint &footprint : land.footprints) {
        Vec2d middle = vertexMean(footprint.outline);
        size_t home = areas.size();
        for (size_t a = 0; a < areas.size() && home == areas.size(); ++a)
            if (sideOf(areas[a].outline, middle) == Side::Inside) home = a;
        within[home].push_back(&footprint);
    }
    Vec2d centre;
    size_t corners = 0;
    for (const SlgSettlement &area : areas)
        for (Vec2d p : area.outline) centre = centre + p, ++corners;
    centre = corners > 0 ? centre * (1.0 / double(corners)) : centre;
    double farthest = 0;
    for (const SlgSettlement &area : areas)
        for (Vec2d p : area.outline) farthest = std::max(farthest, length(p - centre));
    double districtArea = planParameters(g, PlanLevel::District).averageArea;
    uint32_t index = 0;
    for (size_t a = 0; a <= areas.size(); ++a) {
        LandUseWeights weights = settlementWeights(g, a < areas.size() ? areas[a].use : std::nullopt);
        auto blockOf = [&](Polygon2d outline, Vec2d middle) {
            uint32_t identity = hashValues({desc.objectId, index, 0x424c4b53u});  // "BLKS"
            Locality locality = farthest > 0 ? veduta::locality(length(middle - centre), farthest) : Locality::Mantel;
            LandUseWeights drawn = childWeights(g, weights, locality, parameterRandom(seed, identity));
            return SlgBlock{element, index++, std::move(outline), blockWeights(g, drawn), locality, {}, true};
        };
        for (size_t first = 0; first < within[a].size(); first += kBatch) {
            SlgBlock batch = blockOf({}, a < areas.size() ? vertexMean(areas[a].outline) : centre);
            batch.footprints.assign(within[a].begin() + first,
                                    within[a].begin() + std::min(within[a].size(), first + kBatch));
            blocks.push_back(std::move(batch));
        }
        if (a == areas.size() || !within[a].empty()) continue;
        const Polygon2d &outline = areas[a].outline;
        std::vector<Polygon2d> parts{outline};
        if (signedArea(outline) > 2 * districtArea)
            parts = districtBlocks(hashValues({desc.objectId, uint32_t(a), 0x53455454u}), outline, g, seed,
                                   lost);  // "SETT"
        for (Polygon2d &part : parts) {
            Vec2d middle = vertexMean(part);
            blocks.push_back(blockOf(std::move(part), middle));
        }
    }
}

// A lot whose building is to be planned, with what the cascade made of it.
struct SlgLot {
    PlanShape shape;  // the lot, or the given footprint
    bool given = false;
    double base = 0;  // the ground it stands on
    size_t frontEdges = 0;
    uint32_t identity = 0;
    LandUseWeights weights{};
    LotBuilding building;
    float distance = 0;  // from the camera to the middle of its building's box
    BuildingLod lod = BuildingLod::Box;
};

struct BlockLots {
    std::vector<SlgLot> lots;
    int lost = 0, unplanned = 0;
};

// What a level of detail is expected to cost, for the budget: triangles per storey at the two
// finer levels and per building as a box (Table 17's 14 for a gable on four corners), each the
// mean plus a tenth: storeys 98 and boxes 14.2 over the 8,639 buildings of a 2 × 2 km district;
// rooms 394, with corridors, stairs and the windows' reveals, over the 1,109 of a 700 m one.
double expectedTriangles(BuildingLod lod, int storeys) {
    switch (lod) {
    case BuildingLod::Rooms: return 435.0 * storeys;
    case BuildingLod::Storeys: return 110.0 * storeys;
    case BuildingLod::Box: return 16;
    }
    return 0;
}

PlanDepth depthFor(BuildingLod lod) {
    switch (lod) {
    case BuildingLod::Rooms: return PlanDepth::Rooms;
    case BuildingLod::Storeys: return PlanDepth::Entrance;
    case BuildingLod::Box: return PlanDepth::Footprint;
    }
    return PlanDepth::Rooms;
}

const char *levelName(BuildingLod lod) {
    switch (lod) {
    case BuildingLod::Rooms: return "slg/rooms";
    case BuildingLod::Storeys: return "slg/storeys";
    case BuildingLod::Box: return "slg/box";
    }
    return "slg";
}

// One block's ground with its sidewalks, its buildings drawn whole or storey by storey each as
// a mesh of its own, those drawn as boxes merged into one mesh (their materials per triangle).
struct BlockMeshes {
    Mesh ground, boxes;
    std::vector<std::pair<Mesh, uint32_t>> buildings;  // with their building ids
    std::array<LodCounts, 3> counts{};
    std::map<std::string, DensityTotals> densities;
    int lost = 0, unplanned = 0;
};

// Every <slg> of a scene in four steps: the districts cut into blocks; the blocks into lots on
// all cores; a level of detail for each lot's building, from its size in the image, its
// distance and the geometry budget; the buildings planned and built on all cores. Blocks are added in their order, so
// the scene is the same for any number of threads.
class SlgGenerator {
  public:
    SlgGenerator(const std::vector<SlgDesc> &descs, const std::vector<uint32_t> &seeds, const Camera &camera,
                 const SlgLand *land, RenderSceneBuilder &builder) :
        descs_(descs),
        seeds_(seeds),
        camera_(camera),
        land_(land),
        builder_(builder),
        materials_(materialsOf(builder)) {
        for (const SlgDesc &desc : descs) tables_.push_back(&tablesAt(desc.tables));
    }

    void generate(std::vector<std::string> &warnings) {
        std::vector<SlgBlock> blocks;
        std::vector<int> lost(descs_.size(), 0), unplanned(descs_.size(), 0);
        for (uint32_t e = 0; e < descs_.size(); ++e) {
            if (descs_[e].level == SlgDesc::Level::Atkis) {
                if (!land_)
                    throw InputError(descs_[e].loc,
                                     "level=\"atkis\" builds on the settlement areas and building "
                                     "footprints of the scene's <landscape>; the scene has none");
                addAtkisBlocks(descs_[e], e, land_->input, *tables_[e], seeds_[e], blocks, lost[e]);
                continue;
            }
            Polygon2d outline = outlineOf(descs_[e]);
            if (descs_[e].level == SlgDesc::Level::District)
                builder_.addWorldMesh(groundMesh(outline, descs_[e].base, materials_.street), descs_[e].objectId);
            addBlocks(descs_[e], e, outline, *tables_[e], seeds_[e], blocks, lost[e]);
        }
        std::vector<BlockLots> lots(blocks.size());
        tbb::parallel_for(size_t(0), blocks.size(), [&](size_t b) { lots[b] = lotsOf(blocks[b]); });
        chooseLevels(lots, warnings);
        std::vector<BlockMeshes> meshes(blocks.size());
        tbb::parallel_for(size_t(0), blocks.size(), [&](size_t b) { meshes[b] = meshesOf(blocks[b], lots[b]); });

        std::array<LodCounts, 3> counts{};
        for (size_t b = 0; b < blocks.size(); ++b) {
            uint32_t e = blocks[b].element;
            lost[e] += lots[b].lost + meshes[b].lost;
            unplanned[e] += lots[b].unplanned + meshes[b].unplanned;
            addBlock(descs_[e].objectId, std::move(meshes[b]), counts);
        }
        for (size_t l = 0; l < counts.size(); ++l)
            if (counts[l].buildings > 0) builder_.countLod(levelName(BuildingLod(l)), counts[l]);
        for (size_t e = 0; e < descs_.size(); ++e) {
            if (descs_[e].level == SlgDesc::Level::Atkis && land_->input.settlements.empty() &&
                land_->input.footprints.empty())
                warnings.push_back(
                    fmt::format("{}: the <landscape>'s layers hold no settlement area (Objektart "
                                "2101, 2111–2114) and no building footprint: nothing to build",
                                descs_[e].loc.toString()));
            if (descs_[e].level == SlgDesc::Level::Atkis && land_->input.unusable > 0)
                warnings.push_back(
                    fmt::format("{}: {} settlement areas and footprints left out: their outlines have "
                                "fewer than three corners or cross themselves",
                                descs_[e].loc.toString(), land_->input.unusable));
            if (lost[e] > 0)
                warnings.push_back(fmt::format("{}: {} faces of the plans could not be made (docs/slg.md)",
                                               descs_[e].loc.toString(), lost[e]));
            if (unplanned[e] > 0)
                warnings.push_back(
                    fmt::format("{}: {} lots have no room for a building", descs_[e].loc.toString(), unplanned[e]));
        }
    }

  private:
    const UrbanGeography &tablesAt(const std::filesystem::path &path) {
        auto [it, added] = geographies_.try_emplace(path);
        if (added) it->second = readUrbanGeography(path);
        return it->second;
    }

    BlockLots lotsOf(const SlgBlock &block) const {
        if (!block.footprints.empty()) return givenLots(block);
        const SlgDesc &desc = descs_[block.element];
        const UrbanGeography &g = *tables_[block.element];
        uint32_t seed = seeds_[block.element];
        Subdivision lots =
            subdivide(block.outline, std::vector<EdgeLocation>(block.outline.size(), EdgeLocation::Street),
                      blockPlanParameters(g, dominantUse(block.weights), block.locality),
                      PlanRandom(seed, hashValues({desc.objectId, block.index}), RandomStream::SlgPlan));
        labelEdges(lots, PlanLevel::Block);
        BlockLots out;
        out.lost = lots.deletedFaces;
        uint32_t index = 0;
        for (const PlanFace *face : lots.borderFaces()) {
            uint32_t identity = hashValues({desc.objectId, block.index, index++});
            LandUseWeights weights = lotWeights(g, block.weights, parameterRandom(seed, identity));
            auto building = lotBuilding(g, {weights, block.locality, {}}, seed, identity);
            if (!building) continue;  // open land
            SlgLot lot{faceShape(lots, *face), false, 0, frontEdges(*face), identity, weights, std::move(*building)};
            place(block, lot);
            out.lots.push_back(std::move(lot));
        }
        return out;
    }

    // Given footprints are buildings whatever the draw says: open land is not drawn for them.
    // The front is the longest edge (their streets are not known); every edge is a street's.
    BlockLots givenLots(const SlgBlock &block) const {
        const SlgDesc &desc = descs_[block.element];
        const UrbanGeography &g = *tables_[block.element];
        uint32_t seed = seeds_[block.element];
        BlockLots out;
        for (const SlgFootprint *footprint : block.footprints) {
            uint32_t identity = hashValues({desc.objectId, footprint->identity});
            LandUseWeights weights = lotWeights(g, block.weights, parameterRandom(seed, identity));
            weights[size_t(LandUse::Freiflaeche)] = 0;
            auto building = lotBuilding(g, {weights, block.locality, {}}, seed, identity);
            if (!building) {
                ++out.unplanned;
                continue;
            }
            const Polygon2d &outline = footprint->outline;
            PlanShape shape{outline, std::vector<EdgeLocation>(outline.size(), EdgeLocation::Street)};
            std::rotate(shape.points.begin(), shape.points.begin() + std::ptrdiff_t(longestEdge(outline)),
                        shape.points.end());
            SlgLot lot{std::move(shape), true, 0, 1, identity, weights, std::move(*building)};
            place(block, lot);
            out.lots.push_back(std::move(lot));
        }
        return out;
    }

    // The ground a lot stands on (the terrain's lowest point under it, or the element's base),
    // and the level of detail its size in the image and its distance from the camera ask for.
    void place(const SlgBlock &block, SlgLot &lot) const {
        const SlgDesc &desc = descs_[block.element];
        lot.base = desc.base;
        if (block.onTerrain && land_ && land_->ground) {
            std::vector<Vec2f> points;
            for (Vec2d p : lot.shape.points) points.push_back({float(p.x), float(p.y)});
            lot.base = land_->ground(points).value_or(desc.base);
        }
        Vec3f low{1e30f, 1e30f, float(lot.base)}, high{-1e30f, -1e30f, float(lot.base)};
        for (Vec2d p : lot.shape.points) {
            low.x = std::min(low.x, float(p.x)), low.y = std::min(low.y, float(p.y));
            high.x = std::max(high.x, float(p.x)), high.y = std::max(high.y, float(p.y));
        }
        high.z += float(lot.building.parameters.storeys * BuildingShape().storeyHeight);
        float pixels = camera_.pixelsSpanned(low, high);
        lot.distance = length((low + high) * 0.5f - camera_.position);
        auto shows = [&](float within, float least) { return lot.distance < within && pixels >= least; };
        lot.lod = shows(desc.rooms, desc.roomsPixels) ? BuildingLod::Rooms
            : shows(desc.storeys, desc.storeysPixels) ? BuildingLod::Storeys
                                                      : BuildingLod::Box;
    }

    // Within the budget every building keeps the level place() gave it. Past it, the farthest
    // buildings drawn with rooms lose them first, then the farthest drawn storey by storey become
    // boxes, until the expected triangles fit; the warning says how many. Farthest rather than
    // smallest in the image: what they lose is windows and rooms, alike on every building, so
    // smallest in the image where they are farthest.
    void chooseLevels(std::vector<BlockLots> &blocks, std::vector<std::string> &warnings) const {
        std::vector<SlgLot *> lots;
        for (BlockLots &block : blocks)
            for (SlgLot &lot : block.lots) lots.push_back(&lot);
        auto expected = [&] {
            double sum = 0;
            for (const SlgLot *lot : lots) sum += expectedTriangles(lot->lod, lot->building.parameters.storeys);
            return sum * double(kBytesPerTriangle);
        };
        double budget = double(builder_.geometryBytesLeft()), total = expected();
        if (total <= budget) return;
        // Farthest first; ties in the order the lots were made, so the choice is the same always.
        std::stable_sort(lots.begin(), lots.end(),
                         [](const SlgLot *a, const SlgLot *b) { return a->distance > b->distance; });
        int coarsened = 0;
        for (BuildingLod from : {BuildingLod::Rooms, BuildingLod::Storeys}) {
            for (SlgLot *lot : lots) {
                if (total <= budget) break;
                if (lot->lod != from) continue;
                int storeys = lot->building.parameters.storeys;
                BuildingLod to = BuildingLod(int(from) + 1);
                total -= (expectedTriangles(from, storeys) - expectedTriangles(to, storeys)) * kBytesPerTriangle;
                lot->lod = to;
                ++coarsened;
            }
        }
        warnings.push_back(fmt::format(
            "{}: the buildings would take more than the geometry budget of {:.1f} GB; {} of them drawn coarser{}",
            descs_.front().loc.toString(), budget / double(1ull << 30), coarsened,
            total > budget ? ", and even as boxes they do not fit" : ""));
    }

    BlockMeshes meshesOf(const SlgBlock &block, const BlockLots &lots) const {
        const SlgDesc &desc = descs_[block.element];
        BlockMeshes out;
        if (!block.onTerrain) out.ground = groundMesh(block.outline, desc.base + 0.01, materials_.block);
        for (const SlgLot &lot : lots.lots) addBuilding(block, lot, out);
        return out;
    }

    void addBuilding(const SlgBlock &block, const SlgLot &lot, BlockMeshes &out) const {
        const SlgDesc &desc = descs_[block.element];
        const UrbanGeography &g = *tables_[block.element];
        uint32_t seed = seeds_[block.element];
        FaceSides sides = fourSides(lot.shape.points, lot.frontEdges);
        auto plan = lot.given
            ? planInFootprint(lot.shape, sides, lot.building.parameters, seed, lot.identity, depthFor(lot.lod))
            : planBuilding(lot.shape, sides, lot.building.parameters, seed, lot.identity, depthFor(lot.lod));
        if (!plan) {
            ++out.unplanned;
            return;
        }
        out.lost += plan->losses.deletedFaces;
        if (!block.onTerrain)
            for (const Polygon2d &quad : plan->sidewalk)
                out.ground.append(groundMesh(quad, desc.base + 0.02, materials_.sidewalk), Transform());

        int corners = int(turningPoints(plan->placement.footprint.points).size());
        BuildingShape shape;
        shape.base = lot.base;
        shape.roof = roofKind(lot.weights, corners,
                              PlanRandom(seed, hashValues({lot.identity, kRoof}), RandomStream::SlgParameters));
        shape.orientation = lot.building.orientation;
        shape.roofHeight =
            roofDimensions(g, PlanRandom(seed, hashValues({lot.identity, kRoofSize}), RandomStream::SlgParameters))
                .height;
        shape.windows.width = 1.2;
        shape.windows.spacing = 1.3;
        shape.windows.wallDistance = 0.8;
        shape.wallThickness = g.wallThickness;
        addDensity(block, lot, *plan, out);
        Mesh mesh = buildingMesh(*plan, shape, lot.lod, materials_.building);
        LodCounts &counts = out.counts[size_t(lot.lod)];
        ++counts.buildings;
        counts.triangles += mesh.triangleCount();
        if (lot.lod == BuildingLod::Box) {
            ++counts.merged;
            out.boxes.append(mesh, Transform());
            return;
        }
        ++counts.meshes;
        uint32_t buildingId =
            1 + hashValues({desc.objectId, lot.identity, streamTag(RandomStream::CityBuilding)}) % ((1u << 24) - 1);
        out.buildings.emplace_back(std::move(mesh), buildingId);
    }

    // A lot's GRZ and GFZ (eq 1) toward its zone's totals; a given footprint has no lot.
    void addDensity(const SlgBlock &block, const SlgLot &lot, const BuildingPlan &plan, BlockMeshes &out) const {
        if (lot.given) return;
        double lotArea = signedArea(lot.shape.points), footprint = signedArea(plan.placement.footprint.points);
        std::vector<double> storeys(size_t(plan.storeys), footprint);
        DensityReport report = densityReport(*tables_[block.element], dominantUse(lot.weights), block.locality, lotArea,
                                             footprint, storeys);
        if (!report.zone) return;
        DensityTotals &totals = out.densities[report.zone->name];
        ++totals.lots;
        totals.lotArea += lotArea;
        totals.footprintArea += footprint;
        totals.floorArea += footprint * plan.storeys;
        totals.grzCap = report.zone->grz, totals.gfzCap = report.zone->gfz;
    }

    void addBlock(ObjectId objectId, BlockMeshes block, std::array<LodCounts, 3> &counts) {
        for (const auto &[zone, totals] : block.densities) builder_.countDensity(zone, totals);
        for (size_t l = 0; l < counts.size(); ++l) counts[l] += block.counts[l];
        if (block.ground.triangleCount() > 0) builder_.addWorldMesh(std::move(block.ground), objectId);
        for (auto &[mesh, id] : block.buildings) builder_.addWorldMesh(std::move(mesh), objectId, id);
        if (block.boxes.triangleCount() > 0) {
            ++counts[size_t(BuildingLod::Box)].meshes;
            builder_.addWorldMesh(std::move(block.boxes), objectId);
        }
    }

    const std::vector<SlgDesc> &descs_;
    const std::vector<uint32_t> &seeds_;
    const Camera &camera_;
    const SlgLand *land_;
    RenderSceneBuilder &builder_;
    SlgMaterials materials_;
    std::map<std::filesystem::path, UrbanGeography> geographies_;
    std::vector<const UrbanGeography *> tables_;  // each element's
};

}  // namespace

void generateSlg(const std::vector<SlgDesc> &descs, const std::vector<uint32_t> &seeds, const Camera &camera,
                 const SlgLand *land, RenderSceneBuilder &builder, std::vector<std::string> &warnings) {
    if (descs.empty()) return;
    SlgGenerator(descs, seeds, camera, land, builder).generate(warnings);
}

}  // namespace veduta

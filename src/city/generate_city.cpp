#include "city/generate_city.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <filesystem>
#include <memory>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <unordered_map>

#include <fmt/format.h>
#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

#include "city/assets.h"
#include "city/building_generator.h"
#include "city/building_rules.h"
#include "city/city_data.h"
#include "city/ground_environment.h"
#include "city/grown_city.h"
#include "city/lot_subdivision.h"
#include "city/osm_import.h"
#include "city/party_walls.h"
#include "city/plinth.h"
#include "city/street_geometry.h"
#include "city/street_trees.h"
#include "city/streets_on_terrain.h"
#include "city/warning_list.h"
#include "core/check.h"
#include "core/hash.h"
#include "core/random_streams.h"
#include "geo/tree_models.h"
#include "geo/tree_placement.h"
#include "geodesy/map_projection.h"
#include "streets/street_rule_file.h"

namespace veduta {

namespace {

// One of the city's rule files, read once, with the generator that builds with it.
struct RuleFileBuilder {
    RuleFileBuilder(const std::filesystem::path &file, RenderSceneBuilder &builder, uint32_t seed) :
        loaded(file), generator(loaded.grammar, AssetLibrary::builtIn(), builder, seed) {}
    BuildingRules loaded;
    BuildingGenerator generator;
};

std::vector<std::unique_ptr<RuleFileBuilder>> readRuleFiles(const FileLoc &fileLoc, const CityData &data, uint32_t seed,
                                                            bool modularLook, RenderSceneBuilder &builder,
                                                            std::vector<std::string> &warnings) {
    if (data.ruleFiles.empty() && !modularLook)
        throw InputError(fileLoc, "the city names no <Rulefile> to build its lots with, and its <city> no rules");
    std::vector<std::unique_ptr<RuleFileBuilder>> builders;
    for (const std::filesystem::path &file : data.ruleFiles) {
        builders.push_back(std::make_unique<RuleFileBuilder>(file, builder, seed));
        builder.addEffort({ruleFileLines(file), 0, 0, 0});
        const std::vector<std::string> &said = builders.back()->loaded.rules.warnings;
        warnings.insert(warnings.end(), said.begin(), said.end());
    }
    return builders;
}

}  // namespace

StreetNetwork streetNetworkOf(const CityData &data) {
    StreetNetwork network;
    for (const CityPoint &p : data.points) network.nodes.push_back({float(p.e), float(p.n)});
    // A street's start and end are indices into the points already (city_data.h).
    for (const CityStreet &s : data.streets)
        network.streets.push_back({s.start, s.end, s.width.value_or(data.streetWidth)});
    if (!data.points.empty()) network.height = float(data.points.front().u);
    return network;
}

std::vector<IdentifiedLot> lotsOf(const CityBlock &block, const StreetNetwork &streets,
                                  const SettingsStack &blockSettings, uint32_t seed, size_t *slivers,
                                  const StreetIndex *near) {
    std::vector<IdentifiedLot> lots;
    if (!block.lots.empty()) {
        for (const CityLot &lot : block.lots) lots.push_back({{lot.points, lot.streetEdges, lot.base}, lot.sourceId});
        return lots;
    }
    LotSettings settings = lotSettingsFrom(blockSettings);
    std::vector<BuildableArea> areas = buildableAreas(block.points, streets, {}, near);
    for (uint32_t a = 0; a < areas.size(); ++a) {
        if (!isSimplePolygon(areas[a].outline)) {
            if (slivers) ++*slivers;
            continue;
        }
        Block piece{areas[a].outline, areas[a].streetEdges, block.base};
        uint32_t pieceId = hashValues({block.sourceId, a});
        for (Footprint &lot : subdivideBlock(piece, settings, seed, pieceId, block.loc)) {
            uint32_t identity = hashValues({block.sourceId, streamTag(RandomStream::CutLot), uint32_t(lots.size())});
            lots.push_back({std::move(lot), identity});
        }
    }
    return lots;
}

namespace {

// The warning for pieces of blocks left without lots, at the city's place.
void warnOfSlivers(size_t slivers, const FileLoc &where, std::vector<std::string> &warnings) {
    if (slivers == 0) return;
    std::string place = where.file.empty() ? std::string() : where.toString() + ": ";
    warnings.push_back(
        fmt::format("{}{} pieces of blocks that the streets leave are slivers no simple polygon in "
                    "float (a few float steps wide) and were left without lots",
                    place, slivers));
}

// Every block's lots, cut on all cores: a block's lots depend on the block, the streets and the
// seed alone, so they are the same on any number of threads. An error is the first block's in
// order, as one thread would meet it. The streets near each block come from one index of them.
std::vector<std::vector<IdentifiedLot>> lotsOfBlocks(const CityData &data, const StreetNetwork &streets,
                                                     const SettingsMap &ruleFileSettings, uint32_t seed,
                                                     size_t &slivers) {
    std::vector<std::vector<IdentifiedLot>> lots(data.blocks.size());
    std::vector<std::exception_ptr> errors(data.blocks.size());
    std::vector<size_t> sliversOf(data.blocks.size(), 0);
    StreetIndex near(streets);
    tbb::parallel_for(size_t(0), data.blocks.size(), [&](size_t b) {
        try {
            const CityBlock &block = data.blocks[b];
            lots[b] =
                lotsOf(block, streets, settingsFor(data, block, nullptr, ruleFileSettings), seed, &sliversOf[b], &near);
        } catch (...) {
            errors[b] = std::current_exception();
        }
    });
    for (const std::exception_ptr &error : errors)
        if (error) std::rethrow_exception(error);
    for (size_t n : sliversOf) slivers += n;
    return lots;
}

}  // namespace

void cutLots(CityData &data, const SettingsMap &ruleFileSettings, uint32_t seed, std::vector<std::string> &warnings) {
    size_t slivers = 0;
    std::vector<std::vector<IdentifiedLot>> lots =
        lotsOfBlocks(data, streetNetworkOf(data), ruleFileSettings, seed, slivers);
    for (size_t b = 0; b < data.blocks.size(); ++b) {
        CityBlock &block = data.blocks[b];
        if (!block.lots.empty()) continue;
        for (IdentifiedLot &lot : lots[b]) {
            Footprint &f = lot.footprint;
            block.lots.push_back({std::move(f.points), std::move(f.streetEdges), f.base, {}, block.loc, lot.identity});
        }
    }
    warnOfSlivers(slivers, {}, warnings);
}

uint32_t cityBuildingId(ObjectId city, uint32_t lotIdentity) {
    constexpr uint32_t kIds = (1u << 24) - 1;
    return 1 + hashValues({city, lotIdentity, streamTag(RandomStream::CityBuilding)}) % kIds;
}

namespace {

// The street surfaces, flat or on the landscape's terrain, in the scene's materials
// "street/asphalt", "street/pavement", "street/kerb" and "street/cobblestone" (the junctions)
// when it has them.
void addStreets(const StreetNetwork &streets, const LandscapeGround *landscape, uint32_t objectId,
                RenderSceneBuilder &builder) {
    if (streets.streets.empty()) return;
    Mesh mesh = landscape ? streetsOnTerrain(streets, *landscape->surface) : streetGeometry(streets);
    // In the order of StreetSurface.
    const std::pair<const char *, Vec3f> kinds[] = {{"street/asphalt", {0.16f, 0.16f, 0.17f}},
                                                    {"street/pavement", {0.45f, 0.43f, 0.4f}},
                                                    {"street/kerb", {0.55f, 0.54f, 0.52f}},
                                                    {"street/cobblestone", {0.27f, 0.26f, 0.25f}}};
    MaterialId materials[std::size(kinds)];
    for (size_t k = 0; k < std::size(kinds); ++k)
        materials[k] = builder.findOrAddMaterial(Material::lambertian(kinds[k].first, kinds[k].second));
    for (MaterialId &m : mesh.triangleMaterials) m = materials[m];
    builder.addWorldMesh(std::move(mesh), objectId);
}

// The avenues' trees (street_trees.h), at the sidewalk's height or on the terrain.
void addStreetTrees(const StreetNetwork &streets, const LandscapeGround *landscape, uint32_t seed, ObjectId objectId,
                    RenderSceneBuilder &builder) {
    StreetStyle style;
    std::vector<PlacedTree> trees = streetTrees(streets, style, seed);
    if (trees.empty()) return;
    TreeMaterials materials = treeMaterials(builder, TreeKind::Broadleaf);
    PrototypeId prototypes[kTreeVariants];
    for (uint32_t v = 0; v < kTreeVariants; ++v)
        prototypes[v] = builder.addPrototype(treeModel(TreeKind::Broadleaf, v, seed, materials));
    for (const PlacedTree &tree : trees) {
        float ground = streets.height + style.lift + style.kerbHeight;
        if (landscape) {
            std::optional<double> z = landscape->surface->heightAt({tree.position.x, tree.position.y});
            if (!z) continue;  // off the terrain
            ground = float(*z) + style.kerbHeight;
        }
        builder.addInstance({treeTransform(tree, ground), prototypes[tree.variant], kNoMaterial, objectId, 0, 0});
    }
}

// A lot on the landscape stands on the lowest terrain under it, as a <buildings> building
// without base does (generateBuildings); off the terrain at 0 with a warning.
void seatOnGround(Footprint &footprint, const GroundHeight &ground, const FileLoc &where, uint32_t id,
                  std::vector<std::string> &warnings) {
    std::optional<float> datum = ground(footprint.points);
    if (!datum)
        warnings.push_back(
            fmt::format("{}: building {} stands off the terrain; it is placed at height 0", where.toString(), id));
    footprint.base = datum.value_or(0.0f);
}

void warnIfHeightsIgnored(const CityData &data, const FileLoc &fileLoc, std::vector<std::string> &warnings) {
    for (const CityPoint &p : data.points) {
        if (p.u == 0) continue;
        warnings.push_back(
            fmt::format("{}: the city stands on the landscape's terrain; the heights u of its points "
                        "(point {}: {}) are ignored",
                        p.loc.file.empty() ? fileLoc.toString() : p.loc.toString(), p.id, p.u));
        return;
    }
}

// Where two lots hash to one building id (cityBuildingId): a warning at the second.
void warnOfSharedId(std::unordered_map<uint32_t, FileLoc> &lotOfId, uint32_t id, const FileLoc &lot,
                    std::vector<std::string> &warnings) {
    auto [first, fresh] = lotOfId.emplace(id, lot);
    if (fresh) return;
    warnings.push_back(
        fmt::format("{}: this lot's building has the id {} of the one at {} (a hash collision): they "
                    "share their random choices and their IndexBuilding id",
                    lot.toString(), id, first->second.toString()));
}

// A lot's building, ready to be made: its spec, its rule file, where the input describes it, and
// the warnings it has had so far.
struct PlannedBuilding {
    BuildingSpec spec;
    RuleFileBuilder *rules = nullptr;
    FileLoc loc;
    std::vector<std::string> warnings;
};

std::vector<PlannedBuilding> planBuildings(const CityData &data, std::vector<std::vector<IdentifiedLot>> &lots,
                                           uint32_t seed, ObjectId objectId, const LandscapeGround *landscape,
                                           const std::vector<std::unique_ptr<RuleFileBuilder>> &ruleFiles) {
    std::vector<PlannedBuilding> planned;
    std::unordered_map<uint32_t, FileLoc> lotOfId;
    for (size_t b = 0; b < data.blocks.size(); ++b) {
        const CityBlock &block = data.blocks[b];
        for (size_t l = 0; l < lots[b].size(); ++l) {
            PlannedBuilding &p = planned.emplace_back();
            uint32_t id = cityBuildingId(objectId, lots[b][l].identity);
            const CityLot *given = block.lots.empty() ? nullptr : &block.lots[l];
            p.loc = given ? given->loc : block.loc;
            warnOfSharedId(lotOfId, id, p.loc, p.warnings);
            // Bilke 2009 picks one of several rule files at random (L1276).
            uint32_t pick = hashValues({seed, id, streamTag(RandomStream::RuleFileChoice)});
            p.rules = ruleFiles[pick % ruleFiles.size()].get();
            p.spec.id = id;
            p.spec.objectId = objectId;
            p.spec.footprint = std::move(lots[b][l].footprint);
            if (landscape) seatOnGround(p.spec.footprint, landscape->ground, p.loc, id, p.warnings);
            p.spec.settings = settingsFor(data, block, given, p.rules->loaded.rules.settings);
        }
    }
    std::vector<const Footprint *> footprints;
    for (const PlannedBuilding &p : planned) footprints.push_back(&p.spec.footprint);
    std::vector<std::vector<bool>> party = partyWalls(footprints);
    for (size_t b = 0; b < planned.size(); ++b) planned[b].spec.partyEdges = std::move(party[b]);
    return planned;
}

// What a building is expected to cost, for the geometry budget: with its facades, bytes per
// square metre of wall (its triangles and instances at kBytesPerTriangle and
// kBytesPerInstance over the wall area: 282 in scenes/gruenderzeit-district.xml, 270 in
// scenes/hillside-town.xml; plus a tenth); as a box, two triangles a wall and about as many
// for the roof.
constexpr double kFacadeBytesPerSquareMetre = 310;

double expectedBytes(const PlannedBuilding &p, uint32_t seed) {
    const std::vector<Vec2f> &points = p.spec.footprint.points;
    if (p.spec.coarse) return 4.0 * double(points.size()) * kBytesPerTriangle;
    double perimeter = p.spec.footprint.perimeterBefore(points.size());
    return perimeter * randomiseHeights(p.spec.settings, seed, p.spec.id).building * kFacadeBytesPerSquareMetre;
}

// The box a building fills: its footprint's bounds from its base up to its height.
std::pair<Vec3f, Vec3f> boundsOf(const PlannedBuilding &p, uint32_t seed) {
    const Footprint &footprint = p.spec.footprint;
    Vec3f low{1e30f, 1e30f, footprint.base}, high{-1e30f, -1e30f, footprint.base};
    for (Vec2f q : footprint.points) {
        low.x = std::min(low.x, q.x), low.y = std::min(low.y, q.y);
        high.x = std::max(high.x, q.x), high.y = std::max(high.y, q.y);
    }
    high.z += randomiseHeights(p.spec.settings, seed, p.spec.id).building;
    return {low, high};
}

// The buildings the coarse rule picks are boxes. The rest keep their facades while the budget
// lasts; past it the farthest become boxes first (ties in lot order, so the choice is always the
// same), and the warning says how many. Farthest rather than smallest in the image: a facade's
// detail, its windows and mouldings, is alike on every building.
void chooseDetail(std::vector<PlannedBuilding> &planned, uint32_t seed, const BuildingDetail &detail,
                  const RenderSceneBuilder &builder, const FileLoc &loc, std::vector<std::string> &warnings) {
    std::vector<float> distance(planned.size(), 0.0f);
    double expected = 0;
    for (size_t i = 0; i < planned.size(); ++i) {
        if (detail.camera) {
            auto [low, high] = boundsOf(planned[i], seed);
            distance[i] = length((low + high) * 0.5f - detail.camera->position);
            planned[i].spec.coarse = detail.coarse.isCoarse(*detail.camera, low, high);
        }
        expected += expectedBytes(planned[i], seed);
    }
    double budget = double(builder.geometryBytesLeft());
    if (expected <= budget) return;
    std::vector<size_t> order(planned.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return distance[a] > distance[b]; });
    size_t coarsened = 0;
    for (size_t i : order) {
        if (expected <= budget) break;
        if (planned[i].spec.coarse) continue;
        expected -= expectedBytes(planned[i], seed);
        planned[i].spec.coarse = true;
        expected += expectedBytes(planned[i], seed);
        ++coarsened;
    }
    warnings.push_back(fmt::format(
        "{}: the buildings would take more than the geometry budget of {:.1f} GB; {} of them drawn as boxes{}",
        loc.toString(), budget / double(1ull << 30), coarsened,
        expected > budget ? ", and even so they do not fit" : ""));
}

// A batch of buildings made (BuildingGenerator::make), each or the error it met.
struct MadeBatch {
    size_t first = 0;
    std::vector<std::optional<BuildingGenerator::MadeBuilding>> made;
    std::vector<std::exception_ptr> errors;
};

MadeBatch makeBatch(std::vector<PlannedBuilding> &planned, size_t first, size_t end) {
    MadeBatch batch{first, std::vector<std::optional<BuildingGenerator::MadeBuilding>>(end - first),
                    std::vector<std::exception_ptr>(end - first)};
    tbb::parallel_for(first, end, [&](size_t i) {
        try {
            batch.made[i - first] = planned[i].rules->generator.make(planned[i].spec, planned[i].warnings);
        } catch (...) {
            batch.errors[i - first] = std::current_exception();
        }
    });
    return batch;
}

// Adds a made batch to the builder in lot order: the warnings of each building, then the
// first error in order, or the building (and its plinth on a landscape).
// Distant buildings go into one mesh; what each level of detail took is counted.
struct DetailLevels {
    Mesh boxes;
    LodCounts facades, box;
};

void addBatch(std::vector<PlannedBuilding> &planned, MadeBatch &batch, const LandscapeGround *landscape,
              RenderSceneBuilder &builder, DetailLevels &levels, std::vector<std::string> &warnings) {
    for (size_t k = 0; k < batch.made.size(); ++k) {
        PlannedBuilding &p = planned[batch.first + k];
        warnings.insert(warnings.end(), p.warnings.begin(), p.warnings.end());
        if (batch.errors[k]) buildAt(p.loc, [&] { std::rethrow_exception(batch.errors[k]); });
        LodCounts &counts = p.spec.coarse ? levels.box : levels.facades;
        ++counts.buildings;
        counts.triangles += batch.made[k]->mesh.triangleCount();
        counts.instances += batch.made[k]->instances.size();
        counts.meshes += p.spec.coarse ? 0 : 1;
        counts.merged += p.spec.coarse ? 1 : 0;
        p.rules->generator.add(std::move(*batch.made[k]), p.spec.coarse ? &levels.boxes : nullptr);
        if (landscape) addPlinth(p.spec, builder);
    }
}

// Makes the buildings on all cores, a batch at a time (so that what is made waits for the
// builder only briefly), and adds them to the builder in their order: the scene is the same
// for any number of threads, the first error in order is the one thrown, with every warning
// before it. One thread adds a batch while the others make the next: adding alone was a
// twentieth of a city's build, and a core idle meanwhile. Making reads the builder's
// materials, which adding leaves alone once the plinths' material is there.
void buildAll(std::vector<PlannedBuilding> &planned, const LandscapeGround *landscape, RenderSceneBuilder &builder,
              std::vector<std::string> &warnings) {
    DetailLevels levels;
    constexpr size_t kBatch = 256;
    if (planned.empty()) return;
    // Where the first plinth would have added it: no material comes between.
    if (landscape) plinthMaterial(builder);
    MadeBatch current = makeBatch(planned, 0, std::min(planned.size(), kBatch));
    for (size_t first = 0; first < planned.size(); first += kBatch) {
        size_t next = first + kBatch, end = std::min(planned.size(), next + kBatch);
        MadeBatch following;
        tbb::task_group making;
        if (next < planned.size()) making.run([&] { following = makeBatch(planned, next, end); });
        try {
            addBatch(planned, current, landscape, builder, levels, warnings);
        } catch (...) {
            making.wait();
            throw;
        }
        making.wait();
        current = std::move(following);
    }
    if (levels.boxes.triangleCount() > 0) {
        levels.box.meshes = 1;
        builder.addWorldMesh(std::move(levels.boxes), planned.front().spec.objectId);
    }
    if (levels.facades.buildings > 0) builder.countLod("city/facades", levels.facades);
    if (levels.box.buildings > 0) builder.countLod("city/box", levels.box);
}

// The edge of a lot that faces the street: its longest street edge; none when no edge does.
std::optional<size_t> frontEdge(const Footprint &footprint) {
    std::optional<size_t> front;
    for (size_t e = 0; e < footprint.streetEdges.size(); ++e)
        if (footprint.streetEdges[e] && (!front || footprint.edgeLength(e) > footprint.edgeLength(*front))) front = e;
    return front;
}

// The lots as modular buildings (BuildingDetail's look).
uint32_t buildModular(const CityData &data, std::vector<std::vector<IdentifiedLot>> &lots, uint32_t seed,
                      ObjectId objectId, const LandscapeGround *landscape, const BuildingDetail &detail,
                      std::vector<std::string> &warnings) {
    std::vector<ModularBuildingDesc> descs;
    std::unordered_map<uint32_t, FileLoc> lotOfId;
    for (size_t b = 0; b < data.blocks.size(); ++b) {
        const CityBlock &block = data.blocks[b];
        for (size_t l = 0; l < lots[b].size(); ++l) {
            const CityLot *given = block.lots.empty() ? nullptr : &block.lots[l];
            const FileLoc &loc = given ? given->loc : block.loc;
            Footprint &footprint = lots[b][l].footprint;
            uint32_t id = cityBuildingId(objectId, lots[b][l].identity);
            warnOfSharedId(lotOfId, id, loc, warnings);
            if (landscape) seatOnGround(footprint, landscape->ground, loc, id, warnings);
            std::optional<size_t> front = frontEdge(footprint);
            ModularBuildingDesc &desc = descs.emplace_back(
                footprintBuilding(*detail.look, loc, std::move(footprint.points), front, footprint.base));
            desc.objectId = objectId;
            desc.buildingId = id;
            desc.coarse = detail.coarse;
            // The data's own height, not a rule file's default.
            const SettingsMap noRuleFile;
            std::vector<const SettingsMap *> own{&block.settings, &data.settings};
            if (given) own.insert(own.begin(), &given->settings);
            if (SettingsStack(own).find("BuildingHeight"))
                desc.eaves = randomiseHeights(settingsFor(data, block, given, noRuleFile), seed, id).building;
        }
    }
    std::vector<uint32_t> seeds(descs.size(), seed);
    detail.modular->add(
        descs, seeds, [](const FileLoc &, const std::function<void()> &add) { add(); }, warnings);
    return uint32_t(descs.size());
}

uint32_t buildCity(const CityData &data, uint32_t seed, ObjectId objectId, const FileLoc &fileLoc,
                   const LandscapeGround *landscape, const BuildingDetail &detail, RenderSceneBuilder &builder,
                   std::vector<std::string> &warnings) {
    warnings.insert(warnings.end(), data.warnings.begin(), data.warnings.end());
    if (landscape) warnIfHeightsIgnored(data, fileLoc, warnings);
    auto ruleFiles = readRuleFiles(fileLoc, data, seed, detail.look != nullptr, builder, warnings);
    if (detail.camera && detail.masonryMaps)
        for (auto &ruleFile : ruleFiles) ruleFile->generator.bakeMasonryWith(*detail.camera, detail.masonryMaps);
    StreetNetwork streets = streetNetworkOf(data);
    // The street surface while the lots are cut: neither reads what the other makes, and the
    // lots do not touch the builder. A street error comes first, as it did one after the other.
    std::vector<std::vector<IdentifiedLot>> lots;
    std::exception_ptr lotError;
    tbb::task_group streetWork;
    streetWork.run([&] { addStreets(streets, landscape, objectId, builder); });
    size_t slivers = 0;
    try {
        lots = lotsOfBlocks(data, streets, ruleFiles.empty() ? SettingsMap() : ruleFiles.front()->loaded.rules.settings,
                            seed, slivers);
    } catch (...) {
        lotError = std::current_exception();
    }
    streetWork.wait();
    if (lotError) std::rethrow_exception(lotError);
    warnOfSlivers(slivers, fileLoc, warnings);
    if (detail.look) return buildModular(data, lots, seed, objectId, landscape, detail, warnings);
    std::vector<PlannedBuilding> planned = planBuildings(data, lots, seed, objectId, landscape, ruleFiles);
    chooseDetail(planned, seed, detail, builder, fileLoc, warnings);
    buildAll(planned, landscape, builder, warnings);
    return uint32_t(planned.size());
}

}  // namespace

// Bilke's CityData XML, or OpenStreetMap data: with a georeference placed through the one
// route into the scene's frame, without in local metres (OpenStreetMap's centring on the data).
CityData readCityFile(const CityDesc &city, const std::optional<Georeference> &georeference) {
    if (city.epsg != 0 && !georeference)
        throw InputError(city.crsLoc,
                         "a city in map coordinates (crs) needs the scene's <georeference "
                         "crs=\"EPSG:…\" origin=\"E N\"> to be placed");
    if (city.file.extension() == ".osm") {
        if (city.epsg != 0)
            throw InputError(city.crsLoc, "OpenStreetMap data is WGS 84 longitude and latitude; leave out crs");
        OsmImportOptions options;
        options.georeference = georeference;
        return importOsm(city.file, options);
    }
    if (!georeference) return readCityData(city.file);
    MapProjection projection(crsByEpsg(city.epsg != 0 ? city.epsg : georeference->epsg), *georeference);
    return readCityData(city.file, &projection);
}

// The <generate>'s centre in metres from the scene origin.
Vec2f growthCentre(const CityGrowthDesc &growth, const std::optional<Georeference> &georeference) {
    MapPoint centre{growth.centreE, growth.centreN};
    if (georeference) {
        try {
            centre = MapProjection(crsByEpsg(georeference->epsg), *georeference).toLocal(centre);
        } catch (const std::out_of_range &e) {
            throw InputError(growth.centreLoc, e.what());
        }
    }
    double reach = kMaxCityReach - growth.radius;
    if (!(std::abs(centre.easting) <= reach && std::abs(centre.northing) <= reach))
        throw InputError(
            growth.centreLoc,
            fmt::format("the town's window reaches more than {:.0f} km from the scene origin{}", kMaxCityReach / 1000,
                        georeference ? "" : "; map coordinates need a <georeference>"));
    return {float(centre.easting), float(centre.northing)};
}

SceneCity growSceneCity(const CityDesc &city, const std::optional<Georeference> &georeference, uint32_t seed,
                        const LandscapeData *landscape) {
    const CityGrowthDesc &desc = *city.growth;
    GrowLevel grow;
    if (desc.tensor) {
        grow = [](const CityGrowth &growth, std::vector<std::string> &warnings) {
            return traceCity(townField(growth.seed, growth.radius), {}, growth, warnings);
        };
    } else {
        if (!std::filesystem::is_regular_file(desc.streets))
            throw InputError(desc.streetsLoc,
                             fmt::format("cannot read the street rule file {}", desc.streets.string()));
        grow = [rules = readStreetRuleFile(desc.streets)](const CityGrowth &growth,
                                                          std::vector<std::string> &warnings) {
            return growCity(rules, growth, warnings);
        };
    }
    CityGrowth growth;
    growth.centre = growthCentre(desc, georeference);
    growth.radius = desc.radius;
    growth.seed = seed;
    growth.hierarchy.majorWidth = desc.majorWidth;
    growth.hierarchy.minorWidth = desc.minorWidth;
    growth.hierarchy.majorShare = desc.majorShare;
    std::optional<GroundEnvironment> ground;
    if (landscape && georeference) {
        LocalFrame frame = MapProjection(crsByEpsg(georeference->epsg), *georeference).frame();
        Vec2d centre{growth.centre.x, growth.centre.y};
        ground.emplace(&landscape->grid, frame, streetObstacles(landscape->objects, frame), centre,
                       GroundLimits{desc.maxGrade});
        growth.environment = &*ground;
        growth.roads = existingRoads(landscape->objects, frame, centre, growth.radius);
    }
    std::vector<std::string> roadWarnings;  // the road file's own, "file: way id: message"
    if (!desc.roads.empty()) {
        if (!georeference)
            throw InputError(desc.roadsLoc, "roads from OpenStreetMap need the scene's <georeference> to be placed");
        if (!std::filesystem::is_regular_file(desc.roads))
            throw InputError(desc.roadsLoc, fmt::format("cannot read the road file {}", desc.roads.string()));
        OsmImportOptions options;
        options.georeference = georeference;
        CityData osm = importOsm(desc.roads, options);
        roadWarnings = std::move(osm.warnings);
        for (std::vector<Vec2f> &road :
             roadsInWindow(streetLines(osm), {growth.centre.x, growth.centre.y}, growth.radius))
            growth.roads.push_back(std::move(road));
    }
    SceneCity read;
    read.levels = {desc.levels, desc.levelSpacing, desc.liftReach, desc.streetThickness};
    std::vector<std::string> warnings;
    read.data = grow(growth, warnings);
    if (!desc.lots.empty()) {
        read.data.settings["LotSubdivision"] = settingValue(desc.lots, desc.lotsLoc);
        lotSettingsFrom(SettingsStack({&read.data.settings}));  // an unknown name is an error even without blocks
    }
    read.upperLevels = growUpperLevels(grow, growth, desc.levels, read.data.settings, warnings);
    for (const std::string &w : warnings) read.data.warnings.push_back(fmt::format("{}: {}", city.loc.toString(), w));
    read.data.warnings.insert(read.data.warnings.end(), roadWarnings.begin(), roadWarnings.end());
    return read;
}

SceneCity readCity(const CityDesc &city, const std::optional<Georeference> &georeference, uint32_t seed,
                   const LandscapeData *landscape) {
    if (!city.growth && !std::filesystem::is_regular_file(city.file))
        throw InputError(city.fileLoc, fmt::format("cannot read the city file {}", city.file.string()));
    SceneCity read = city.growth ? growSceneCity(city, georeference, seed, landscape)
                                 : SceneCity{readCityFile(city, georeference), {}, {}};
    if (read.data.ruleFiles.empty() && !city.rules.empty()) {
        if (!std::filesystem::is_regular_file(city.rules))
            throw InputError(city.rulesLoc, fmt::format("cannot read the rule file {}", city.rules.string()));
        read.data.ruleFiles.push_back(city.rules);
    }
    return read;
}

namespace {

// Warnings gathered before an error still reach the caller: they may say why.
template <typename Build>
uint32_t withWarnings(std::vector<std::string> &out, Build build) {
    std::vector<std::string> warnings;
    try {
        uint32_t built = build(warnings);
        appendOnce(warnings, out);
        return built;
    } catch (const InputError &) {
        appendOnce(warnings, out);
        throw;
    }
}

}  // namespace

// The ground's junctions, on the landscape's terrain where there is one.
std::vector<Vec3f> groundJunctions(const CityData &data, const LandscapeGround *landscape) {
    std::vector<Vec3f> junctions;
    for (Vec2f p : junctionsOf(streetNetworkOf(data))) {
        float z = 0;
        if (landscape)
            if (std::optional<double> ground = landscape->surface->heightAt({p.x, p.y})) z = float(*ground);
        junctions.push_back(lift(p, z));
    }
    return junctions;
}

uint32_t generateCity(const CityDesc &city, const SceneCity &read, uint32_t seed, const LandscapeGround *landscape,
                      RenderSceneBuilder &builder, std::vector<std::string> &out, const Camera &camera,
                      const MasonryOutput &masonryMaps, ModularBuildings *modular) {
    VEDUTA_CHECK(!city.modular || modular, "a city with a modular look has its modular buildings");
    return withWarnings(out, [&](std::vector<std::string> &warnings) {
        const ModularLookDesc *look = city.modular ? &*city.modular : nullptr;
        uint32_t built = buildCity(read.data, seed, city.objectId, city.fileLoc, landscape,
                                   {camera, city.coarse, masonryMaps, look, modular}, builder, warnings);
        if (city.streetTrees) addStreetTrees(streetNetworkOf(read.data), landscape, seed, city.objectId, builder);
        if (read.upperLevels.empty()) return built;
        return built +
            buildUpperLevels(read.upperLevels, groundJunctions(read.data, landscape), read.levels, seed, city.objectId,
                             builder);
    });
}

uint32_t generateCity(const CityData &data, uint32_t seed, ObjectId objectId, RenderSceneBuilder &builder,
                      std::vector<std::string> &out, const LandscapeGround *landscape, const BuildingDetail &detail) {
    return withWarnings(out, [&](std::vector<std::string> &warnings) {
        return buildCity(data, seed, objectId, {}, landscape, detail, builder, warnings);
    });
}

}  // namespace veduta

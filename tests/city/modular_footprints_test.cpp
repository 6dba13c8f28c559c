// Footprints from data as Finkenzeller's modular buildings (ModularLookDesc, docs/facades.md):
// storeys refitted to what the data counts or measures, OpenStreetMap lots, CityGML buildings and
// the ALK footprints of a real file, which others drew.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <set>
#include <string>

#include <fmt/format.h>

#include "assembly/build_scene.h"
#include "city/atkis_slg_input.h"
#include "city/modular_buildings.h"
#include "core/input_file.h"
#include "facade/building_description.h"
#include "facade/building_structure.h"
#include "facade/facade_building.h"
#include "geo/edbs.h"
#include "input_error.h"
#include "shared_data.h"
#include "test_paths.h"

namespace veduta {
namespace {

const std::filesystem::path kTownhouse = test::sourceFile("scenes/townhouse");

BuildingStructure townhouse() {
    return parseBuildingStructure(readInputFile(kTownhouse / "townhouse.structure"), "townhouse.structure");
}

BuildingStyle townhouseStyle(const std::string &name) {
    return parseBuildingStyle(readInputFile(kTownhouse / name), name, [](const std::string &file, const FileLoc &) {
        return readInputFile(kTownhouse / file);
    });
}

std::vector<Vec2d> rectangle(double w, double d) { return {{0, 0}, {w, 0}, {w, d}, {0, d}}; }

// The town house's storeys as written: shop 4.2, piano nobile 3.9, two upper 3.6, attic 3.3.
TEST(RefitStoreys, GroundAndTopStayAndTheLastMiddleStoreyRepeats) {
    const ModuleStructure prototype = townhouse().modules[0];
    ASSERT_EQ(prototype.storeyHeights, (std::vector<double>{4.2, 3.9, 3.6, 3.6, 3.3}));
    const std::map<size_t, std::vector<int>> roles{
        {1, {0}}, {2, {0, 4}}, {3, {0, 1, 4}}, {5, {0, 1, 2, 3, 4}}, {7, {0, 1, 2, 3, 3, 3, 4}}};
    const uint64_t written = structureHash(structureOnFootprint(prototype, rectangle(14, 12), {}));
    for (const auto &[count, expected] : roles) {
        BuildingStructure s = structureOnFootprint(prototype, rectangle(14, 12), {});
        refitStoreys(s, count);
        EXPECT_EQ(s.storeyRoles, expected) << count;
        EXPECT_EQ(s.storeyCount(), count);
        EXPECT_EQ(s.boundStoreyCount(), 5u);
        for (size_t k = 0; k < count; ++k)
            EXPECT_EQ(s.modules[0].storeyHeights[k], prototype.storeyHeights[size_t(expected[k])]) << count;
        EXPECT_EQ(s.storeyRole(int(count) - 1), 4 * (count > 1)) << "the top storey stays the attic";
        EXPECT_NE(structureHash(s), written) << count << ": the roles are part of the structure";
    }
    // A structure of two storeys repeats its top one; of one, that one.
    ModuleStructure two = prototype;
    two.storeyHeights = {4, 3};
    BuildingStructure s = structureOnFootprint(two, rectangle(10, 10), {});
    refitStoreys(s, 4);
    EXPECT_EQ(s.storeyRoles, (std::vector<int>{0, 1, 1, 1}));
    two.storeyHeights = {4};
    s = structureOnFootprint(two, rectangle(10, 10), {});
    refitStoreys(s, 3);
    EXPECT_EQ(s.modules[0].storeyHeights, (std::vector<double>{4, 4, 4}));
}

TEST(RefitStoreys, TheNearestCountToAnEavesHeight) {
    const std::vector<double> written = townhouse().modules[0].storeyHeights;
    // Eaves by count: 4.2, 7.5, 11.4, 15.0, 18.6, 22.2, 25.8 …
    EXPECT_EQ(storeysNearest(written, 0), 1u);
    EXPECT_EQ(storeysNearest(written, 9.4), 2u);
    EXPECT_EQ(storeysNearest(written, 9.5), 3u);
    EXPECT_EQ(storeysNearest(written, 15), 4u);
    EXPECT_EQ(storeysNearest(written, 18.6), 5u);
    EXPECT_EQ(storeysNearest(written, 25), 7u);
    EXPECT_EQ(storeysNearest(written, 1e6), kStructureStoreyLimit);
}

// The style binds the storeys as written: a seven-storey town house carries the attic's main
// cornice and its consoles on its seventh storey, not on its fifth.
TEST(RefitStoreys, TheStyleFollowsTheWrittenStoreys) {
    BuildingStructure s = structureOnFootprint(townhouse().modules[0], rectangle(14, 12), {});
    refitStoreys(s, 7);
    FacadeBuilding building = buildFacadeBuilding(
        s, townhouseStyle("ochre.style"), [](const std::string &, const FileLoc &) { return MaterialId(0); }, 3, 1);
    ASSERT_FALSE(building.consoles.empty());
    for (const ConsoleSet &set : building.consoles)
        for (const Transform &t : set.transforms) {
            float z = t.applyPoint({0, 0, 0}).z;
            EXPECT_GT(z, 22.2f) << "above the sixth storey";
            EXPECT_LT(z, 25.8f + 1) << "at the eaves";
        }
}

RenderScene sceneWith(const std::string &element, std::vector<std::string> &warnings, const std::string &more = "") {
    std::string xml = fmt::format(R"(<scene version="1">{}
        <camera position="-60 -80 60" look_at="0 0 0" resolution="320 180"/>
        <materials file="../rules/gruenderzeit/materials.xml"/>
        <material name="interior_dim" diffuse="0.05 0.045 0.04"/>
        <material name="facing_brick" category="wall" diffuse="1 1 1"/>
        {}</scene>)",
                                  more, element);
    return buildRenderScene(readSceneText(xml, "test.xml", test::sourceFile("scenes")), &warnings);
}

// The ochre town house's piano nobile has aprons (ApronStyle): their faces take a copy of the
// casing's stucco whose maps are the building's atlas, its colour the stucco's mean albedo (its
// colour times its plaster map's mean) and its normals the grown ornament's relief where the
// camera sees it closely.
TEST(ModularFootprints, TheTownhousesApronsShowTheirOrnamentThroughTheAtlas) {
    std::vector<std::string> warnings;
    // Close enough that the atlas's texel (about 3 mm) resolves the ornament's 1 cm cells.
    RenderScene scene = sceneWith(R"(<camera position="7 -2.5 4.6" look_at="7 0 4.6" resolution="640 360"/>
        <modular_building footprint="0 0 14 0 14 12 0 12" structure="townhouse/townhouse.structure"
                          style="townhouse/ochre.style" building="5"/>)",
                                  warnings);
    const Material *stucco = nullptr, *apron = nullptr;
    for (const Material &m : scene.materials) {
        if (m.name == "stucco_white") stucco = &m;
        if (m.name == "stucco_white (building 5 masonry)") apron = &m;
    }
    ASSERT_NE(stucco, nullptr);
    ASSERT_NE(apron, nullptr);
    ASSERT_NE(apron->normalMap, kNoTexture);
    float plaster[3];
    scene.textures->lookup(stucco->diffuseMap, {0.5f, 0.5f}, 1.0f, plaster, 3);
    const MaterialId id = MaterialId(apron - scene.materials.data());
    size_t faces = 0, tilted = 0, samples = 0, seen = 0, seenTilted = 0;
    for (const BakedMesh &baked : scene.meshes)
        for (size_t t = 0; t < baked.mesh.triangleCount(); ++t) {
            if (baked.mesh.triangleMaterials[t] != id) continue;
            ++faces;
            const uint32_t *v = &baked.mesh.indices[3 * t];
            Vec2f a = baked.mesh.uvs[v[0]], b = baked.mesh.uvs[v[1]], c = baked.mesh.uvs[v[2]];
            for (int i = 1; i < 20; ++i)
                for (int j = 1; i + j < 20; ++j) {
                    Vec2f uv = a + (b - a) * (i / 20.0f) + (c - a) * (j / 20.0f);
                    float colour[4], normal[3];
                    scene.textures->lookup(apron->diffuseMap, uv, 0.0f, colour, 4);
                    scene.textures->lookup(apron->normalMap, uv, 0.0f, normal, 3);
                    for (int k = 0; k < 3; ++k) EXPECT_NEAR(colour[k], plaster[k], 1e-3) << k;
                    bool tilt = normal[2] * 2 - 1 < 0.99f;
                    tilted += tilt;
                    ++samples;
                    // The front (y = 0, facing the camera) is baked fine, the back coarse.
                    if (baked.mesh.positions[v[0]].y < 0) ++seen, seenTilted += tilt;
                }
        }
    // Five windows on the front, four on the back, in the piano nobile: two triangles each.
    EXPECT_EQ(faces % 2, 0u);
    EXPECT_GE(faces, 10u);
    std::printf("apron samples: %zu of %zu tilted; on the front, %zu of %zu\n", tilted, samples, seenTilted, seen);
    ASSERT_GT(seen, 0u);
    EXPECT_GT(seenTilted, seen / 10) << "the rim and the ornament tilt the normals (a flat face: none)";
}

// tests/data/osm/small-district.osm: five buildings, one 18 m high with a 5 m roof (BuildingHeight
// 13), one of four levels (12, at the built-in 3 m floor) and one of 15 m and five levels (15, the
// height wins), two without a height.
TEST(ModularFootprints, OpenStreetMapBuildingsTakeTheirHeights) {
    std::vector<std::string> warnings;
    RenderScene scene = sceneWith(
        fmt::format(R"(<city file="{}" structure="townhouse/townhouse.structure" style="townhouse/ochre.style"/>)",
                    (test::testData() / "osm/small-district.osm").string()),
        warnings);
    ASSERT_EQ(scene.buildings.size(), 5u);
    std::vector<float> eaves;
    for (const BuildingRecord &b : scene.buildings) eaves.push_back(b.eaves - b.base);
    std::sort(eaves.begin(), eaves.end());
    for (float e : eaves) std::printf("eaves %.2f\n", e);
    // 12 and 13 m → 11.4 (3 storeys, nearer than 15.0); 15 m → 15.0 (4); no height: as written, 18.6.
    std::vector<float> expected{11.4f, 11.4f, 15.0f, 18.6f, 18.6f};
    for (size_t i = 0; i < eaves.size(); ++i) EXPECT_NEAR(eaves[i], expected[i], 1e-3f) << i;
    EXPECT_EQ(std::count_if(warnings.begin(), warnings.end(),
                            [](const std::string &w) { return w.find("left out: no partition") != std::string::npos; }),
              0);
}

// The element's coarse rule: a building it picks is a block of its modules up to its eaves, in the
// style's wall and roof materials, with no windows, consoles or atlas; the others keep their detail.
TEST(ModularFootprints, BuildingsTheCoarseRulePicksAreBlocks) {
    const std::string osm = (test::testData() / "osm/small-district.osm").string();
    auto city = [&](const std::string &coarse) {
        std::vector<std::string> warnings;
        return sceneWith(fmt::format(R"(<city file="{}" {} structure="townhouse/townhouse.structure"
                                           style="townhouse/ochre.style"/>)",
                                     osm, coarse),
                         warnings);
    };
    RenderScene detailed = city(""), blocks = city(R"(coarse_below_px="100000")");
    ASSERT_EQ(blocks.buildings.size(), 5u);
    EXPECT_TRUE(blocks.instances.empty());
    EXPECT_FALSE(detailed.instances.empty());
    size_t triangles = 0;
    std::set<std::string> materials;
    for (const BakedMesh &baked : blocks.meshes)
        if (baked.buildingId != 0) {
            triangles += baked.mesh.triangleCount();
            for (MaterialId m : baked.mesh.triangleMaterials) materials.insert(blocks.materials[m].name);
        }
    EXPECT_LT(triangles, 5u * 40) << "a few quads and a fan a module";
    EXPECT_EQ(materials, (std::set<std::string>{"plaster_ochre", "roof_slate"}))
        << "the middle storey's wall, the attic's roof";
    for (size_t b = 0; b < 5; ++b) {
        EXPECT_EQ(blocks.buildings[b].id, detailed.buildings[b].id);
        EXPECT_NEAR(blocks.buildings[b].eaves, detailed.buildings[b].eaves, 1e-4f) << "the same storeys";
        EXPECT_NEAR(blocks.buildings[b].ridge, blocks.buildings[b].eaves, 1e-4f) << "a flat top at the eaves";
    }
}

TEST(ModularFootprints, ALookTakesBothStructureAndStyle) {
    std::string error = test::inputErrorOf([] {
        readSceneText(R"(<scene version="1"><city file="x.osm" structure="a.structure"/></scene>)", "t.xml", ".");
    });
    EXPECT_EQ(error, "t.xml:1:50: a modular look takes both structure and style; style is missing");
}

TEST(ModularFootprints, CityGmlBuildingsStandOnTheirTwinsFootprints) {
    auto path = test::sharedDataFile("citygml/FZK-House-LoD2-KIT-IAI-KHH-V2.gml");
    if (!path) GTEST_SKIP() << "../shared/data is not here";
    std::vector<std::string> warnings;
    RenderScene scene = sceneWith(
        fmt::format(R"(<citygml file="{}" structure="townhouse/townhouse.structure" style="townhouse/brick.style"/>)",
                    path->string()),
        warnings, R"(<georeference crs="EPSG:25832" origin="458883 5438358"/>)");
    ASSERT_EQ(scene.buildings.size(), 1u);
    const BuildingRecord &house = scene.buildings[0];
    // The house is 12 × 10 m on the ground at −0.2 (its lowest ground surface) …
    EXPECT_NEAR(house.base, -0.2f, 0.05f);
    // … and counts two storeys above it: the shop and the attic, 4.2 + 3.3 m.
    EXPECT_NEAR(house.eaves - house.base, 7.5f, 1e-3f);
    EXPECT_GT(house.ridge, house.eaves + 1);
}

// The ochre town house's materials, plain grey, and its look as a data element would give it.
void addOchreMaterials(RenderSceneBuilder &builder) {
    for (const Style &style : townhouseStyle("ochre.style").styles)
        for (const std::optional<std::string> &name : style.materials)
            if (name && builder.findMaterial(*name) == kNoMaterial)
                builder.addMaterial(Material::lambertian(*name, {0.5f, 0.5f, 0.5f}));
}

ModularLookDesc ochreLook() {
    return {kTownhouse / "townhouse.structure", kTownhouse / "ochre.style", {"look.xml", 1, 1}, {"look.xml", 1, 2}};
}

// A footprint from data that no partition fits is left out and counted in one warning; the same
// footprint given in a scene is an error at its attribute.
TEST(ModularFootprints, AnUnusableFootprintFromDataIsLeftOutAndCounted) {
    RenderSceneBuilder builder;
    addOchreMaterials(builder);
    Camera camera;
    camera.position = {-40, -40, 20};
    camera.lookAt = {0, 0, 5};
    ModularBuildings modular(camera, builder, {false, [](Image) { return TextureId(0); }, {}});
    const ModularLookDesc look = ochreLook();
    const std::vector<Vec2f> bowTie{{0, 0}, {10, 10}, {10, 0}, {0, 10}}, box{{0, 0}, {12, 0}, {12, 10}, {0, 10}};
    std::vector<ModularBuildingDesc> descs{footprintBuilding(look, {"data", 3, 1}, bowTie, std::nullopt, 0),
                                           footprintBuilding(look, {"data", 4, 1}, box, std::nullopt, 0),
                                           footprintBuilding(look, {"data", 5, 1}, bowTie, std::nullopt, 0)};
    std::vector<std::string> warnings;
    auto run = [](const FileLoc &, const std::function<void()> &add) { add(); };
    modular.add(descs, {1, 1, 1}, run, warnings);
    const std::string said =
        "2 footprints from data left out: no partition into modules fits them (the first: data:3:1: ";
    EXPECT_EQ(
        std::count_if(warnings.begin(), warnings.end(), [&](const std::string &w) { return w.starts_with(said); }), 1)
        << ::testing::PrintToString(warnings);
    RenderScene scene = std::move(builder).build();
    EXPECT_EQ(scene.buildings.size(), 1u);

    descs[0].fromData = false;
    RenderSceneBuilder again;
    for (const Material &m : scene.materials) again.addMaterial(m);
    ModularBuildings strict(camera, again, {false, [](Image) { return TextureId(0); }, {}});
    EXPECT_EQ(test::inputErrorOf([&] { strict.add({descs[0]}, {1}, run, warnings); }).rfind("data:3:1: ", 0), 0u);
}

// Data that counts more storeys than a building may have (kStructureStoreyLimit), or gives eaves
// that high, is built at the limit and says so; nothing is clamped unsaid.
TEST(ModularFootprints, StoreysBeyondTheLimitAreBuiltAtItAndSaid) {
    RenderSceneBuilder builder;
    addOchreMaterials(builder);
    Camera camera;
    camera.position = {-900, -900, 400};
    camera.lookAt = {0, 0, 300};
    ModularBuildings modular(camera, builder, {false, [](Image) { return TextureId(0); }, {}});
    const ModularLookDesc look = ochreLook();
    const std::vector<Vec2f> box{{0, 0}, {12, 0}, {12, 10}, {0, 10}};
    std::vector<ModularBuildingDesc> descs{footprintBuilding(look, {"data", 3, 1}, box, std::nullopt, 0),
                                           footprintBuilding(look, {"data", 4, 1}, box, std::nullopt, 0),
                                           footprintBuilding(look, {"data", 5, 1}, box, std::nullopt, 0)};
    descs[0].storeys = 500;
    descs[1].eaves = 5000.0;
    descs[2].storeys = kStructureStoreyLimit;
    for (size_t i = 0; i < descs.size(); ++i) descs[i].transform = Transform::translate({40.0f * float(i), 0, 0});
    std::vector<std::string> warnings;
    auto run = [](const FileLoc &, const std::function<void()> &add) { add(); };
    modular.add(descs, {1, 2, 3}, run, warnings);
    auto said = [&](const std::string &start, const std::string &text) {
        return std::count_if(warnings.begin(), warnings.end(), [&](const std::string &w) {
            return w.starts_with(start) && w.find(text) != std::string::npos;
        });
    };
    EXPECT_EQ(said("data:3:1: ", "the data counts 500 storeys, more than a building may have; built with 200"), 1)
        << ::testing::PrintToString(warnings);
    EXPECT_EQ(said("data:4:1: ", "eaves 5000.0 m high would take more storeys than a building may have"), 1)
        << ::testing::PrintToString(warnings);
    EXPECT_EQ(said("data:5:1: ", "storeys"), 0) << ::testing::PrintToString(warnings);  // at the limit: as asked
    RenderScene scene = std::move(builder).build();
    ASSERT_EQ(scene.buildings.size(), 3u);
    for (const BuildingRecord &b : scene.buildings) {
        EXPECT_GT(b.eaves, 500.0f);  // 200 storeys of about 3.6 m
        EXPECT_EQ(b.eaves, scene.buildings[2].eaves);
    }
}

// The ALK sample of LV Sachsen: every Folie 011 footprint, as others drew it, either stands as a
// town house of modules or is refused with an InputError that says why, never a crash; nearly all
// stand.
TEST(ModularFootprints, TheFootprintsOfARealAlkFileStandAsModules) {
    auto path = test::sharedDataFile("edbs/alk_muster_part1.edbs");
    if (!path) GTEST_SKIP() << "../shared/data is not here";
    EdbsConversion data = toAtkis(readEdbs(*path), IncompleteObjects::Skip);
    SlgLandInput input = slgLandInput(data.atkis.objects, LocalFrame{{5493000, 5654500}});
    ASSERT_GT(input.footprints.size(), 10u);
    const ModuleStructure prototype = townhouse().modules[0];
    const BuildingStyle style = townhouseStyle("ochre.style");
    size_t built = 0, modules = 0;
    std::map<std::string, size_t> refused;
    for (const SlgFootprint &f : input.footprints) {
        try {
            BuildingStructure s = structureOnFootprint(prototype, f.outline, {"alk"});
            FacadeBuilding b = buildFacadeBuilding(
                s, style, [](const std::string &, const FileLoc &) { return MaterialId(0); }, 1, f.identity);
            EXPECT_GT(b.mesh.triangleCount(), 0u);
            modules += s.modules.size();
            ++built;
        } catch (const InputError &e) {
            ++refused[e.message()];
        }
    }
    std::printf("ALK sample: %zu of %zu footprints stand, in %zu modules\n", built, input.footprints.size(), modules);
    for (const auto &[why, count] : refused) std::printf("  %zu refused: %s\n", count, why.c_str());
    EXPECT_GE(double(built), 0.95 * double(input.footprints.size()));
}

}  // namespace
}  // namespace veduta

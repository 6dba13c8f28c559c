// Building generation with Bilke's Gründerzeit rules: T10 (z-scale), T11 (walls continue
// one another's texture), instancing, per-building materials and determinism.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "city/asset_fitting.h"
#include "city/building_generator.h"
#include "city/building_rules.h"
#include "city/roof_choice.h"
#include "city/rule_file.h"
#include "core/error.h"
#include "test_paths.h"

namespace veduta {
namespace {

struct Gruenderzeit {
    const AssetLibrary &assets = AssetLibrary::builtIn();
    BuildingRules loaded{test::sourceFile("rules/gruenderzeit/FacadeStructure.xml")};
    const RuleSet &rules = loaded.rules;
    const Grammar &grammar = loaded.grammar;

    BuildingSpec building(uint32_t id, float width = 16, float depth = 14) const {
        BuildingSpec spec;
        spec.id = id;
        spec.objectId = id;
        spec.footprint.points = {{0, 0}, {width, 0}, {width, depth}, {0, depth}};
        spec.footprint.streetEdges = {true, false, false, false};
        spec.settings = SettingsStack({&rules.settings, &defaultBuildingSettings()});
        return spec;
    }

    RenderScene generate(const std::vector<BuildingSpec> &buildings, uint32_t seed = 0) const {
        RenderSceneBuilder builder;
        builder.addMaterial(Material::lambertian("default", Vec3f(0.8f)));
        for (const char *name : {"ochre", "grey", "rose"}) {
            Material m = Material::lambertian(name, Vec3f(0.7f));
            m.category = MaterialCategory::Wall;
            builder.addMaterial(m);
        }
        BuildingGenerator generator(grammar, assets, builder, seed);
        std::vector<std::string> warnings;
        for (const BuildingSpec &b : buildings) generator.generate(b, warnings);
        return std::move(builder).build();
    }
};

const Gruenderzeit &gruenderzeit() {
    static Gruenderzeit g;
    return g;
}

TEST(BuildingGenerator, T10DepthFollowsTheModelTypeOrTheZScale) {
    // A HORIZONTAL model 1 × 0.3 in a 4 × 0.3 scope: sx = 4, sy = 1.
    EXPECT_FLOAT_EQ(depthScale(ModelType::Horizontal, ZScale::NotSet, 4, 1), 1);
    EXPECT_FLOAT_EQ(depthScale(ModelType::NoType, ZScale::NotSet, 4, 1), 2.5f);
    EXPECT_FLOAT_EQ(depthScale(ModelType::Horizontal, ZScale::None, 4, 1), 1);
    EXPECT_FLOAT_EQ(depthScale(ModelType::Vertical, ZScale::NotSet, 4, 1), 4);
    EXPECT_FLOAT_EQ(depthScale(ModelType::HorizontalNoDepthScale, ZScale::NotSet, 4, 1), 1);
    EXPECT_FLOAT_EQ(depthScale(ModelType::Window, ZScale::Right, 4, 1), 4);
    EXPECT_FLOAT_EQ(depthScale(ModelType::Window, ZScale::Up, 4, 1), 1);
    EXPECT_FLOAT_EQ(depthScale(ModelType::Window, ZScale::Average, 4, 1), 2.5f);

    Asset cornice;
    cornice.type = ModelType::Horizontal;
    cornice.boundsMin = {-0.5f, 0.1f, 0};
    cornice.boundsMax = {0.5f, 0.4f, 0.3f};
    Terminal terminal;
    terminal.shapeToFacade = Transform::translate({2, 5, 0});
    terminal.size = {4, 0.3f};
    Transform t = modelToFacade(cornice, terminal);
    Vec3f low = t.applyPoint(cornice.boundsMin), high = t.applyPoint(cornice.boundsMax);
    EXPECT_NEAR(low.x, 0, 1e-6);  // stretched over the scope, centre to centre
    EXPECT_NEAR(high.x, 4, 1e-6);
    EXPECT_NEAR(low.y, 4.85, 1e-6);
    EXPECT_NEAR(high.y, 5.15, 1e-6);
    EXPECT_NEAR(low.z, 0, 1e-6);  // the wall plane stays
    EXPECT_NEAR(high.z, 0.3, 1e-6);
}

TEST(BuildingGenerator, T11NeighbouringWallPiecesContinueTheirTexture) {
    RenderScene scene = gruenderzeit().generate({gruenderzeit().building(1)});
    const Mesh &mesh = scene.meshes.front().mesh;  // walls and roof; models placed once follow
    // Wall vertices at the same place on the same face must have the same texture coordinates.
    std::map<std::tuple<long, long, long, long, long, long>, Vec2f> seen;
    size_t shared = 0;
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        for (int k = 0; k < 3; ++k) {
            uint32_t v = mesh.indices[3 * t + k];
            const Vec3f &p = mesh.positions[v], &n = mesh.normals[v];
            auto key = std::make_tuple(std::lround(p.x * 1e3), std::lround(p.y * 1e3), std::lround(p.z * 1e3),
                                       std::lround(n.x * 10), std::lround(n.y * 10), std::lround(n.z * 10));
            auto [it, fresh] = seen.try_emplace(key, mesh.uvs[v]);
            if (fresh) continue;
            ++shared;
            EXPECT_NEAR(it->second.x, mesh.uvs[v].x, 1e-3) << p.x << " " << p.y << " " << p.z;
            EXPECT_NEAR(it->second.y, mesh.uvs[v].y, 1e-3) << p.x << " " << p.y << " " << p.z;
        }
    }
    EXPECT_GT(shared, 500u);  // the facades are many pieces that meet
}

TEST(BuildingGenerator, ModelsAreInstancesOfSharedPrototypes) {
    std::vector<BuildingSpec> street;
    for (uint32_t id = 1; id <= 20; ++id) street.push_back(gruenderzeit().building(id, 12 + float(id % 5) * 2));
    RenderScene scene = gruenderzeit().generate(street);
    EXPECT_EQ(scene.meshes.size(), 20u);  // one baked mesh (walls and roof) per building
    EXPECT_GT(scene.instances.size(), 20u * 60);
    EXPECT_LT(scene.prototypes.size(), 150u);
    std::set<uint32_t> buildings;
    for (const Instance &instance : scene.instances) buildings.insert(instance.buildingId);
    EXPECT_EQ(buildings.size(), 20u);
}

bool sameInstances(const RenderScene &a, const RenderScene &b) {
    if (a.instances.size() != b.instances.size()) return false;
    for (size_t i = 0; i < a.instances.size(); ++i) {
        const Instance &x = a.instances[i], &y = b.instances[i];
        if (!(x.objectToWorld == y.objectToWorld) || x.prototype != y.prototype ||
            x.materialOverride != y.materialOverride || x.objectId != y.objectId || x.buildingId != y.buildingId)
            return false;
    }
    return true;
}

bool sameMeshes(const RenderScene &a, const RenderScene &b) {
    if (a.meshes.size() != b.meshes.size()) return false;
    for (size_t m = 0; m < a.meshes.size(); ++m) {
        const Mesh &x = a.meshes[m].mesh, &y = b.meshes[m].mesh;
        if (x.indices != y.indices || x.triangleMaterials != y.triangleMaterials ||
            x.positions.size() != y.positions.size())
            return false;
        for (size_t v = 0; v < x.positions.size(); ++v)
            if (!(x.positions[v] == y.positions[v]) || x.uvs[v].x != y.uvs[v].x || x.uvs[v].y != y.uvs[v].y)
                return false;
    }
    return true;
}

TEST(BuildingGenerator, TheSameBuildingComesOutTheSameAndOthersDiffer) {
    auto a = gruenderzeit().generate({gruenderzeit().building(3)});
    auto b = gruenderzeit().generate({gruenderzeit().building(3)});
    EXPECT_TRUE(sameInstances(a, b));
    EXPECT_TRUE(sameMeshes(a, b));

    std::set<size_t> counts;
    std::set<MaterialId> walls;
    for (uint32_t id = 1; id <= 12; ++id) {
        RenderScene scene = gruenderzeit().generate({gruenderzeit().building(id)});
        counts.insert(scene.instances.size());
        walls.insert(scene.meshes[0].mesh.triangleMaterials.front());
    }
    EXPECT_GT(counts.size(), 3u);  // the buildings take different branches
    EXPECT_EQ(walls.size(), 3u);   // and pick their wall colour from the three
    auto reseeded = gruenderzeit().generate({gruenderzeit().building(3)}, 99);
    EXPECT_FALSE(sameInstances(a, reseeded) && sameMeshes(a, reseeded));
}

TEST(BuildingGenerator, WallsAndRoofStandOnTheBase) {
    BuildingSpec raised = gruenderzeit().building(5, 16, 14);
    raised.footprint.base = 2.5f;
    RenderScene scene = gruenderzeit().generate({raised});
    const Mesh &mesh = scene.meshes.front().mesh;
    float lowest = 1e9f, lowestRoof = 1e9f;
    for (const Vec3f &p : mesh.positions) lowest = std::min(lowest, p.z);
    // The roof covering is the one part whose material is none of the three walls' (ids 1-3).
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        if (mesh.triangleMaterials[t] >= 1 && mesh.triangleMaterials[t] <= 3) continue;
        for (int k = 0; k < 3; ++k)
            lowestRoof = std::min(lowestRoof, mesh.positions[mesh.indices[3 * t + size_t(k)]].z);
    }
    EXPECT_NEAR(lowest, 2.5f, 1e-4f);
    EXPECT_NEAR(lowestRoof, 2.5f + 15, 1e-4f);  // the eaves, on the walls, not above them
}

TEST(BuildingGenerator, HeightsAreChecked) {
    const Gruenderzeit &g = gruenderzeit();
    auto withSetting = [&](const char *name, float value) {
        SettingsMap lot{{name, SettingValue{"", value, FileLoc{"lot.xml", 7, 3}}}};
        BuildingSpec spec = g.building(1);
        spec.settings = SettingsStack({&lot, &g.rules.settings, &defaultBuildingSettings()});
        RenderSceneBuilder builder;
        BuildingGenerator generator(g.grammar, g.assets, builder, 0);
        std::vector<std::string> warnings;
        generator.generate(spec, warnings);
        return std::move(builder).build();
    };
    for (auto [name, value] : {std::pair{"BuildingHeight", 0.0f},
                               {"FloorHeight", -3.0f},
                               {"RoofHeight", -1.0f},
                               {"BuildingHeightVar", -1.0f}}) {
        try {
            withSetting(name, value);
            ADD_FAILURE() << name << " " << value << " was accepted";
        } catch (const InputError &e) {
            EXPECT_NE(std::string(e.what()).find("lot.xml:7:3: "), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
        }
    }
    // A roof height of 0 is a flat roof at the eaves, behind a parapet.
    RenderScene flat = withSetting("RoofHeight", 0);
    float top = 0;
    for (const Vec3f &p : flat.meshes.front().mesh.positions) top = std::max(top, p.z);
    EXPECT_NEAR(top, 15 + kDefaultParapetHeight, 0.01f);
}

TEST(BuildingGenerator, WallsWithoutAStartRuleArePlain) {
    const AssetLibrary &assets = AssetLibrary::builtIn();
    RuleSet rules = parseRuleFile(R"(<Rulefile name="fronts only"><Rule><Predecessor>FrontFacade</Predecessor>
      <Rules><Probability value="1"><Symbol>Window1.wrl</Symbol></Probability></Rules></Rule></Rulefile>)",
                                  "fronts.xml", [&](std::string_view n) { return assets.isModelName(n); });
    Grammar grammar(rules, [&](std::string_view n) { return assets.findTerminal(n); });
    RenderSceneBuilder builder;
    BuildingGenerator generator(grammar, assets, builder, 0);
    BuildingSpec spec = gruenderzeit().building(1);
    spec.settings = SettingsStack({&defaultBuildingSettings()});
    std::vector<std::string> warnings;
    BuildingStats stats = generator.generate(spec, warnings);
    EXPECT_EQ(stats.instances, 1u);  // the front's one window
    EXPECT_EQ(stats.terminals, 4u);  // and three plain walls
    ASSERT_EQ(warnings.size(), 3u);
    EXPECT_EQ(warnings[0], "fronts.xml: the rule file has no rule for 'SideFacade'; those walls are plain");
}

TEST(BuildingGenerator, NoModelStandsFarOutOfItsWall) {
    // Every branch of the rule set shows up in some of these buildings.
    std::vector<BuildingSpec> street;
    for (uint32_t id = 1; id <= 40; ++id) {
        BuildingSpec spec = gruenderzeit().building(id);
        for (Vec2f &p : spec.footprint.points) p.x += 30.0f * float(id);
        street.push_back(spec);
    }
    RenderScene scene = gruenderzeit().generate(street);
    for (const Instance &instance : scene.instances) {
        const Mesh &model = scene.prototypes[instance.prototype];
        float x0 = 30.0f * float(instance.buildingId);
        for (const Vec3f &p : model.positions) {
            Vec3f at = instance.objectToWorld.applyPoint(p);
            // Balconies reach out some 1.5 m; nothing else comes near 2.5 m.
            ASSERT_GT(at.x, x0 - 2.5f) << "building " << instance.buildingId;
            ASSERT_LT(at.x, x0 + 16 + 2.5f) << "building " << instance.buildingId;
            ASSERT_GT(at.y, -2.5f) << "building " << instance.buildingId;
            ASSERT_LT(at.y, 14 + 2.5f) << "building " << instance.buildingId;
        }
    }
}

TEST(BuildingGenerator, TheBuildingStandsOnItsFootprintUnderItsRoof) {
    RenderScene scene = gruenderzeit().generate({gruenderzeit().building(5, 16, 14)});
    Vec3f lo(1e9f), hi(-1e9f);
    auto grow = [&](const Vec3f &p) {
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], p[k]);
            hi[k] = std::max(hi[k], p[k]);
        }
    };
    for (const Vec3f &p : scene.meshes[0].mesh.positions) grow(p);
    EXPECT_NEAR(lo.z, 0, 1e-4);
    EXPECT_NEAR(lo.x, 0, 0.6);  // pieces stand out of the wall a little at most
    EXPECT_NEAR(hi.x, 16, 0.6);
    EXPECT_GT(hi.z, 15 - 0.1 + 4 - 0.1);  // walls of 15 m and a 4 m roof (no …Var set)
    for (const Instance &instance : scene.instances) {
        Vec3f at = instance.objectToWorld.applyPoint({0, 0, 0});
        EXPECT_GT(at.x, -2.5f);  // balconies reach out some 1.5 m, nothing more
        EXPECT_LT(at.x, 18.5f);
        EXPECT_GT(at.y, -2.5f);
        EXPECT_LT(at.y, 16.5f);
        EXPECT_GT(at.z, -0.5f);
        EXPECT_LT(at.z, 15.5f);
    }
}

TEST(BuildingGenerator, ALoneFacadeStandsWhereItIsPut) {
    const Gruenderzeit &g = gruenderzeit();
    RenderSceneBuilder builder;
    BuildingGenerator generator(g.grammar, g.assets, builder, 0);
    FacadeSpec facade;
    facade.id = 1;
    facade.startSymbol = "FrontFacade";
    facade.width = 12;
    facade.height = 16;
    facade.facadeToWorld = Transform{{1, 0, 0, 0, 0, 0, -1, 0, 0, 1, 0, 0}};  // on the x axis, facing −y
    facade.settings = SettingsStack({&g.rules.settings, &defaultBuildingSettings()});
    std::vector<std::string> warnings;
    BuildingStats stats = generator.generateFacade(facade, warnings);
    RenderScene scene = std::move(builder).build();
    EXPECT_GT(stats.terminals, 100u);
    for (const Vec3f &p : scene.meshes[0].mesh.positions) {
        EXPECT_GT(p.x, -0.01f);
        EXPECT_LT(p.x, 12.01f);
        EXPECT_GT(p.z, -0.01f);
        EXPECT_LT(p.z, 16.01f);
        EXPECT_LT(p.y, 1.0f);  // in front is −y
    }
}

}  // namespace
}  // namespace veduta

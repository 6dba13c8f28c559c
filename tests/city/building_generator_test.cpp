// Building generation with seed 000's Gründerzeit rules: T10 (z-scale), T11 (walls continue
// one another's texture), instancing, per-building materials and determinism.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "city/asset_fitting.h"
#include "city/building_generator.h"
#include "city/rule_file.h"

namespace veduta {
namespace {

struct Gruenderzeit {
    const AssetLibrary &assets = AssetLibrary::builtIn();
    RuleSet rules = readRuleFile(VEDUTA_SOURCE_DIR "/rules/gruenderzeit/FacadeStructure.xml",
                                 [this](std::string_view n) { return assets.isModelName(n); });
    Grammar grammar{rules, [this](std::string_view n) { return assets.find(n); }};

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

TEST(BuildingGenerator, TheSameBuildingComesOutTheSameAndOthersDiffer) {
    auto a = gruenderzeit().generate({gruenderzeit().building(3)});
    auto b = gruenderzeit().generate({gruenderzeit().building(3)});
    ASSERT_EQ(a.instances.size(), b.instances.size());
    for (size_t i = 0; i < a.instances.size(); ++i)
        ASSERT_EQ(a.instances[i].objectToWorld, b.instances[i].objectToWorld);
    EXPECT_EQ(a.meshes[0].mesh.positions.size(), b.meshes[0].mesh.positions.size());

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
    EXPECT_NE(reseeded.instances.size() * 1000 + reseeded.meshes[0].mesh.positions.size(),
              a.instances.size() * 1000 + a.meshes[0].mesh.positions.size());
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

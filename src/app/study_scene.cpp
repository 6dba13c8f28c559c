#include "app/study_scene.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "description/material_file.h"

namespace veduta {

namespace {

constexpr float kFovDegrees = 40;
const FileLoc kCommandLine{"<command line>", 0, 0};

SettingsMap settingsFrom(const std::vector<std::string> &assignments) {
    SettingsMap settings;
    for (const std::string &assignment : assignments) {
        size_t equals = assignment.find('=');
        settings[assignment.substr(0, equals)] = settingValue(assignment.substr(equals + 1), kCommandLine);
    }
    return settings;
}

// The scene around the study: materials, sky, the group with its rules.
SceneDescription studyBase(const StudyOptions &options) {
    SceneDescription scene;
    scene.source = options.rules;
    std::filesystem::path rules = options.rules;
    std::filesystem::path materials =
        options.materials.empty() ? rules.parent_path() / "materials.xml" : std::filesystem::path(options.materials);
    if (!options.materials.empty() || std::filesystem::exists(materials)) scene.materials = readMaterialFile(materials);
    MaterialDesc ground;
    ground.material = Material::lambertian("study/ground", {0.28f, 0.27f, 0.25f});
    scene.materials.push_back(ground);
    scene.environment.radiance = {0.38f, 0.5f, 0.78f};
    scene.seed = options.seed;

    BuildingGroupDesc group;
    group.rules = rules;
    group.rulesLoc = kCommandLine;
    group.settings = settingsFrom(options.settings);
    scene.buildingGroups.push_back(std::move(group));
    return scene;
}

void addGround(SceneDescription &scene, Vec3f centre, float size) {
    GeometryDesc ground;
    ShapeSpec plane;
    plane.kind = ShapeKind::Plane;
    plane.size = {size, size, 0};
    ground.shape = plane;
    ground.transform = Transform::translate({centre.x, centre.y, 0});
    ground.material = {"study/ground", kCommandLine};
    ground.objectId = 1;
    scene.geometry.push_back(ground);
}

// A camera `distance` from `target` along `towards`, raised a little, sized to the subject's aspect.
Camera frame(Vec3f target, Vec3f towards, float distance, float aspect) {
    Camera camera;
    camera.lookAt = target;
    camera.position = target + towards * distance;
    camera.verticalFovDegrees = kFovDegrees;
    camera.height = 720;
    camera.width = std::clamp(int(std::lround(720 * aspect / 2) * 2), 240, 1920);
    return camera;
}

float fitDistance(float width, float height, float aspect) {
    float halfHeight = std::max(height, width / aspect) * 0.55f;
    return halfHeight / std::tan(kFovDegrees * 0.5f * 3.14159265f / 180);
}

}  // namespace

void addStudyOptions(CLI::App &command, StudyOptions &options, bool rulesAsOption) {
    command
        .add_option(rulesAsOption ? "--rules" : "RULEFILE", options.rules,
                    "Rule file (Bilke's XML format, docs/rules.md)")
        ->required(!rulesAsOption)
        ->check(CLI::ExistingFile);
    command.add_option("--seed", options.seed, "Seed of the random choices, the building's and the sampler's [0]");
    command.add_option("--id", options.id, "Building id: with the seed, which branches the rules take [1]")
        ->check(CLI::Range(1u, 0xffffffffu));
    command
        .add_option("--set", options.settings,
                    "A building setting, Name=Value, above the rule file's (e.g. --set FloorHeight=3.4); repeatable")
        ->check([](const std::string &text) {
            size_t equals = text.find('=');
            return equals == std::string::npos || equals == 0 ? std::string("expected Name=Value") : std::string();
        });
    command
        .add_option("--materials", options.materials,
                    "Material file the buildings choose from [materials.xml beside RULEFILE, if any]")
        ->check(CLI::ExistingFile);
}

void addFootprintOptions(CLI::App &command, BuildingOptions &options, bool required) {
    command
        .add_option("--footprint", options.footprint,
                    "Ground plan: x y pairs in metres, e.g. --footprint 0 0 14 0 14 12 0 12 (either orientation)")
        ->required(required)
        ->expected(6, 2000);
    command.add_option("--street", options.street,
                       "Footprint edges on the street (edge i runs from point i to i+1) [none: the longest edge]");
}

SceneDescription facadeStudy(const StudyOptions &options, const std::string &start, float width, float height) {
    SceneDescription scene = studyBase(options);
    FacadeDesc facade;
    facade.loc = kCommandLine;
    facade.buildingId = options.id;
    facade.objectId = 2;
    facade.start = start;
    facade.width = width;
    facade.height = height;
    scene.buildingGroups[0].facades.push_back(facade);
    // The facade stands on the x axis facing −y: look at it from the south, lit from the south-west.
    float aspect = std::clamp((width + 2) / (height + 2), 0.5f, 2.5f);
    Vec3f centre{width / 2, 0, height / 2};
    scene.camera = frame(centre, normalize(Vec3f(0, -1, 0.08f)), fitDistance(width + 1, height + 1, aspect), aspect);
    scene.sun.direction = Sun::directionFromAzimuthElevation(215, 35);
    addGround(scene, centre, 4 * std::max(width, height));
    return scene;
}

SceneDescription buildingScene(const StudyOptions &options, const BuildingOptions &plan) {
    SceneDescription scene = studyBase(options);
    const std::vector<float> &xy = plan.footprint;
    if (xy.size() % 2 != 0)
        throw InputError(kCommandLine, fmt::format("--footprint needs x y pairs; {} numbers given", xy.size()));
    BuildingDesc building;
    building.loc = building.footprintLoc = building.streetLoc = kCommandLine;
    building.buildingId = options.id;
    building.objectId = 2;
    for (size_t i = 0; i + 1 < xy.size(); i += 2) building.footprint.push_back({xy[i], xy[i + 1]});
    for (uint32_t edge : plan.street) {
        if (edge >= building.footprint.size())
            throw InputError(
                kCommandLine,
                fmt::format("--street {}: the footprint has edges 0 to {}", edge, building.footprint.size() - 1));
        building.streetEdges.push_back(edge);
    }
    scene.buildingGroups[0].buildings.push_back(building);
    return scene;
}

SceneDescription buildingStudy(const StudyOptions &options, const BuildingOptions &plan) {
    SceneDescription scene = buildingScene(options, plan);
    const BuildingDesc &building = scene.buildingGroups[0].buildings[0];

    // Frame the building from the front (the first street edge, else the longest), turned 35°.
    const auto &p = building.footprint;
    size_t n = p.size(), front = building.streetEdges.empty() ? 0 : building.streetEdges.front();
    float area = 0;
    Vec3f centroid{0, 0, 0};
    float extent = 0;
    for (size_t i = 0; i < n; ++i) {
        const Vec2f &a = p[i], &b = p[(i + 1) % n];
        area += a.x * b.y - b.x * a.y;
        centroid += Vec3f(a.x, a.y, 0) * (1.0f / float(n));
        float length = std::hypot(b.x - a.x, b.y - a.y);
        if (building.streetEdges.empty() &&
            length > std::hypot(p[(front + 1) % n].x - p[front].x, p[(front + 1) % n].y - p[front].y))
            front = i;
        for (const Vec2f &c : p) extent = std::max(extent, std::hypot(c.x - a.x, c.y - a.y));
    }
    const Vec2f &a = p[front], &b = p[(front + 1) % n];
    Vec3f along = normalize(Vec3f(b.x - a.x, b.y - a.y, 0));
    Vec3f outward = area > 0 ? Vec3f(along.y, -along.x, 0) : Vec3f(-along.y, along.x, 0);
    float turn = 35 * 3.14159265f / 180;
    Vec3f towards = normalize(outward * std::cos(turn) - along * std::sin(turn) + Vec3f(0, 0, 0.45f));
    float height = 20;  // about a Gründerzeit building with its roof
    float aspect = 16.0f / 10;
    centroid.z = height * 0.4f;
    scene.camera = frame(centroid, towards, fitDistance(extent * 1.1f, height, aspect) * 1.4f, aspect);
    Vec3f sunFrom = normalize(outward * std::cos(-0.8f) - along * std::sin(-0.8f));
    float azimuth = std::atan2(sunFrom.x, sunFrom.y) * 180 / 3.14159265f;
    scene.sun.direction = Sun::directionFromAzimuthElevation(azimuth, 38);
    addGround(scene, centroid, 6 * std::max(extent, height));
    return scene;
}

}  // namespace veduta

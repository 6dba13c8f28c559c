// The scene file's materials, material files, environments, sun times and georeferences:
// what they read into, and the errors they give.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "assembly/build_scene.h"
#include "core/error.h"
#include "description/material_file.h"
#include "description/scene_description.h"
#include "input_error.h"
#include "test_paths.h"

namespace veduta {
namespace {

SceneDescription parse(const std::string &xml, const std::filesystem::path &base = test::testData()) {
    return readSceneText(xml, "s.xml", base);
}

std::string parseError(const std::string &xml, const std::filesystem::path &base = test::testData()) {
    return test::inputErrorOf([&] { parse(xml, base); });
}

std::string buildError(const std::string &xml) {
    return test::inputErrorOf([&] { buildRenderScene(parse(xml)); });
}

class TempFolder {
  public:
    TempFolder() : path_(std::filesystem::temp_directory_path() / ("veduta_materials_" + std::to_string(::getpid()))) {
        std::filesystem::create_directories(path_);
    }
    ~TempFolder() { std::filesystem::remove_all(path_); }
    const std::filesystem::path &path() const { return path_; }
    void write(const std::string &name, const std::string &text) const { std::ofstream(path_ / name) << text; }

  private:
    std::filesystem::path path_;
};

TEST(MaterialFile, ReadsEveryField) {
    SceneDescription d = parse(R"(<scene>
  <material name="brick" category="wall" diffuse_map="tex/brick.png" normal_map="tex/n.png" normal_strength="0.5"
            specular="1 0.5 0.25" specular_intensity="0.4" shininess="10" specular_map="tex/s.png"
            reflection_map="tex/r.png" opacity_map="tex/o.png" opacity_map_colorspace="Linear" texture_size="2 0.5"/>
  <material name="pane" glass="true" ior="1.52" tint="0.9"/>
</scene>)");
    ASSERT_EQ(d.materials.size(), 2u);
    const MaterialDesc &brick = d.materials[0];
    EXPECT_EQ(brick.material.category, MaterialCategory::Wall);
    EXPECT_EQ(brick.material.diffuse, Vec3f(1.0f));  // a map's colour defaults to 1
    EXPECT_EQ(brick.material.specular, Vec3f(0.4f, 0.2f, 0.1f));
    EXPECT_FLOAT_EQ(brick.material.shininess, 10);
    EXPECT_FLOAT_EQ(brick.material.normalStrength, 0.5f);
    EXPECT_EQ(brick.material.reflectivity, Vec3f(1.0f));
    EXPECT_FLOAT_EQ(brick.material.textureSize.x, 2);
    EXPECT_FLOAT_EQ(brick.material.textureSize.y, 0.5f);
    EXPECT_EQ(brick.diffuseMap.file, test::testData() / "tex/brick.png");
    EXPECT_EQ(brick.diffuseMap.colorSpace, "");          // the file's own
    EXPECT_EQ(brick.normalMap.colorSpace, "Non-Color");  // data maps are not converted
    EXPECT_EQ(brick.opacityMap.colorSpace, "Linear");
    EXPECT_EQ(brick.diffuseMap.loc.toString(), "s.xml:2:55");
    const Material &pane = d.materials[1].material;
    EXPECT_TRUE(pane.glass);
    EXPECT_FLOAT_EQ(pane.ior, 1.52f);
    EXPECT_EQ(pane.glassTint, Vec3f(0.9f));
}

TEST(MaterialFile, UnknownFieldIsAnErrorWithItsPlace) {
    EXPECT_EQ(parseError("<scene>\n  <material name=\"a\" shinyness=\"3\"/>\n</scene>"),
              "s.xml:2:22: unknown attribute 'shinyness' on <material>");
    // Glass takes no Phong fields.
    EXPECT_EQ(parseError(R"(<scene><material name="g" glass="true" diffuse="0.5"/></scene>)"),
              "s.xml:1:40: unknown attribute 'diffuse' on <material>");
    EXPECT_EQ(
        parseError(R"(<scene><material name="a" category="cellar"/></scene>)"),
        "s.xml:1:37: unknown material category 'cellar' (facade, roof, material, door, wall, window, reflection)");
    EXPECT_EQ(parseError(R"(<scene><material name="a" normal_map_colorspace="sRGB"/></scene>)"),
              "s.xml:1:50: 'normal_map_colorspace' without 'normal_map'");
}

TEST(MaterialFile, IncludesMaterialFilesWithTheirOwnFolder) {
    TempFolder folder;
    std::filesystem::create_directories(folder.path() / "lib");
    folder.write("lib/m.xml", R"(<materials version="1">
  <material name="wall" diffuse_map="textures/brick.png"/>
  <material name="roof" diffuse="0.5 0.2 0.1"/>
</materials>)");
    SceneDescription d = parse(R"(<scene><materials file="lib/m.xml"/><material name="own"/></scene>)", folder.path());
    ASSERT_EQ(d.materials.size(), 3u);
    EXPECT_EQ(d.materials[0].material.name, "wall");
    EXPECT_EQ(d.materials[0].diffuseMap.file, folder.path() / "lib/textures/brick.png");
    EXPECT_EQ(d.materials[2].material.name, "own");

    // A name defined twice across files names both places.
    std::string twice =
        parseError(R"(<scene><material name="roof"/><materials file="lib/m.xml"/></scene>)", folder.path());
    EXPECT_NE(twice.find("lib/m.xml:3:3: material 'roof' is already defined at s.xml:1:8"), std::string::npos) << twice;
    // Errors inside the material file point into it.
    folder.write("lib/bad.xml", "<materials>\n  <material name=\"x\" glossy=\"1\"/>\n</materials>");
    std::string bad = parseError(R"(<scene><materials file="lib/bad.xml"/></scene>)", folder.path());
    EXPECT_NE(bad.find("lib/bad.xml:2:22: unknown attribute 'glossy' on <material>"), std::string::npos) << bad;
    // A missing file is reported at the include.
    std::string missing = parseError(R"(<scene><materials file="lib/none.xml"/></scene>)", folder.path());
    EXPECT_EQ(missing.rfind("s.xml:1:25: ", 0), 0u) << missing;
}

TEST(MaterialFile, TheSeedLibraryReads) {
    std::vector<MaterialDesc> materials = readMaterialFile(test::sourceDir() / "materials/seed000.xml");
    std::vector<MaterialCategory> categories;
    for (const MaterialDesc &m : materials) {
        categories.push_back(m.material.category);
        for (const ImageRef *map : {&m.diffuseMap, &m.specularMap, &m.normalMap, &m.reflectionMap, &m.opacityMap}) {
            if (map->given()) {
                EXPECT_TRUE(std::filesystem::exists(map->file)) << map->file;
            }
        }
    }
    for (MaterialCategory c :
         {MaterialCategory::Facade, MaterialCategory::Roof, MaterialCategory::Material, MaterialCategory::Door,
          MaterialCategory::Wall, MaterialCategory::Window, MaterialCategory::Reflection}) {
        EXPECT_NE(std::find(categories.begin(), categories.end(), c), categories.end()) << int(c);
    }
}

TEST(EnvironmentElement, ReadsEachKind) {
    SceneDescription cube =
        parse(R"(<scene><environment cubemap="sky_{face}.exr" rotation="30" intensity="2"/></scene>)");
    EXPECT_EQ(cube.environment.cubemap.file, test::testData() / "sky_{face}.exr");
    EXPECT_FLOAT_EQ(cube.environment.rotationDegrees, 30);
    EXPECT_FLOAT_EQ(cube.environment.intensity, 2);
    SceneDescription sky = parse(R"(<scene><environment sky="preetham" turbidity="4" face_size="32"/></scene>)");
    EXPECT_TRUE(sky.environment.sky);
    EXPECT_FLOAT_EQ(sky.environment.turbidity, 4);
    EXPECT_EQ(sky.environment.faceSize, 32);
    EXPECT_EQ(parseError(R"(<scene><environment radiance="1" sky="preetham"/></scene>)"),
              "s.xml:1:8: give the environment one of 'radiance', 'cubemap' and 'sky'");
    EXPECT_EQ(parseError(R"(<scene><environment sky="hosek"/></scene>)"),
              "s.xml:1:26: unknown sky model 'hosek' (preetham)");
    EXPECT_EQ(parseError(R"(<scene><environment sky="preetham" rotation="10"/></scene>)"),
              "s.xml:1:46: the sky follows the sun; it cannot be rotated");
}

TEST(EnvironmentElement, AMissingFaceIsAnErrorAtTheAttribute) {
    std::string e = buildError(R"(<scene><environment cubemap="nowhere_{face}.exr"/></scene>)");
    EXPECT_EQ(e.rfind("s.xml:1:30: ", 0), 0u) << e;
    EXPECT_NE(e.find("nowhere_east.exr"), std::string::npos) << e;
}

TEST(SunElement, ReadsDateTimeAndPlace) {
    SceneDescription d = parse(
        R"(<scene><sun date="2026-06-21" time="12:00" utc_offset="+02:00" latitude="51.34" longitude="12.37"/></scene>)");
    ASSERT_TRUE(d.sunTime);
    EXPECT_EQ(d.sunTime->time.year, 2026);
    EXPECT_EQ(d.sunTime->time.hour, 12);
    EXPECT_DOUBLE_EQ(d.sunTime->time.utcOffsetHours, 2);
    ASSERT_TRUE(d.sunTime->place);
    EXPECT_NEAR(d.sunTime->place->latitude, 51.34, 1e-5);
    // 12:00 CEST in Leipzig in June, an hour before solar noon: high (58.8°) in the south-east.
    Sun sun = placeSun(d);
    EXPECT_NEAR(std::asin(sun.direction.z) * 180 / kPi, 58.82, 0.05);
    EXPECT_LT(sun.direction.y, 0);
    EXPECT_GT(sun.direction.x, 0);

    EXPECT_EQ(parseError(
                  R"(<scene><sun azimuth="10" elevation="20" date="2026-01-01" time="10:00" utc_offset="Z"/></scene>)"),
              "s.xml:1:8: give the sun one of 'direction', 'azimuth' and 'elevation', or 'date' and 'time'");
    std::string badDate = parseError(
        R"(<scene><sun date="2026-13-01" time="10:00" utc_offset="Z" latitude="50" longitude="10"/></scene>)");
    EXPECT_EQ(badDate.rfind("s.xml:1:19: ", 0), 0u) << badDate;
    EXPECT_EQ(buildError(R"(<scene><sun date="2026-01-01" time="10:00" utc_offset="Z"/></scene>)"),
              "s.xml:1:8: the sun needs 'latitude' and 'longitude', or a <georeference> for the scene");
}

TEST(SunElement, ErrorsPointAtThePartThatIsWrong) {
    std::string badTime = parseError(
        R"(<scene><sun date="2026-06-01" time="25:00" utc_offset="Z" latitude="50" longitude="10"/></scene>)");
    EXPECT_EQ(badTime.rfind("s.xml:1:37: ", 0), 0u) << badTime;
    std::string badOffset = parseError(
        R"(<scene><sun date="2026-06-01" time="10:00" utc_offset="+2" latitude="50" longitude="10"/></scene>)");
    EXPECT_EQ(badOffset.rfind("s.xml:1:56: ", 0), 0u) << badOffset;
}

// A later element that places the sun or gives the environment a source replaces the
// earlier one's choice, as other attributes do.
TEST(SunElement, LaterElementsReplaceEarlierChoices) {
    SceneDescription d = parse(R"(<scene>
  <sun date="2026-06-21" time="12:00" utc_offset="+02:00" latitude="51.34" longitude="12.37"/>
  <sun direction="0 0 1"/>
  <environment cubemap="sky_{face}.exr"/>
  <environment sky="preetham"/>
</scene>)");
    EXPECT_FALSE(d.sunTime);
    EXPECT_EQ(placeSun(d).direction, Vec3f(0, 0, 1));
    EXPECT_TRUE(d.environment.sky);
    EXPECT_FALSE(d.environment.cubemap.given());
}

// At night the sun of a date and time lights nothing.
TEST(SunElement, SetsAtNight) {
    Sun night = placeSun(parse(
        R"(<scene><sun date="2026-06-21" time="23:30" utc_offset="+02:00" latitude="51.34" longitude="12.37" irradiance="3"/></scene>)"));
    EXPECT_LT(night.direction.z, 0);
    EXPECT_EQ(night.irradiance, Vec3f(0.0f));
    Sun evening = placeSun(parse(
        R"(<scene><sun date="2026-06-21" time="21:00" utc_offset="+02:00" latitude="51.34" longitude="12.37" irradiance="3"/></scene>)"));
    EXPECT_GT(evening.direction.z, 0);  // still up at 21:00 in June
    EXPECT_EQ(evening.irradiance, Vec3f(3.0f));
}

// With a georeference the sun's azimuth is turned from true north to grid north.
TEST(SunElement, GridNorthFollowsTheGeoreference) {
    const char *sunAt =
        R"(<sun date="2026-06-21" time="12:00" utc_offset="+02:00" latitude="51.34" longitude="12.37"/>)";
    Sun trueNorth = placeSun(parse(fmt::format("<scene>{}</scene>", sunAt)));
    // Leipzig lies west of UTM zone 33's central meridian (15° E), so true north, towards the
    // pole on that meridian, points east of grid north: grid azimuths are larger.
    Sun grid = placeSun(
        parse(fmt::format(R"(<scene><georeference crs="EPSG:25833" origin="317000 5690000"/>{}</scene>)", sunAt)));
    float trueAzimuth = std::atan2(trueNorth.direction.x, trueNorth.direction.y);
    float gridAzimuth = std::atan2(grid.direction.x, grid.direction.y);
    // γ ≈ (λ − λ0)·sin φ ≈ −2.05°; the grid azimuth is the true one minus γ.
    EXPECT_NEAR((gridAzimuth - trueAzimuth) * 180 / kPi, 2.05, 0.1);
    EXPECT_FLOAT_EQ(grid.direction.z, trueNorth.direction.z);
}

TEST(GeoreferenceElement, ChecksItsCrs) {
    SceneDescription d = parse(R"(<scene><georeference crs="EPSG:31468" origin="4530000.25 5690000.5"/></scene>)");
    ASSERT_TRUE(d.georeference);
    EXPECT_EQ(d.georeference->epsg, 31468);
    EXPECT_DOUBLE_EQ(d.georeference->originEasting, 4530000.25);  // double: float would round to 0.25 m steps
    std::string unknown = parseError(R"(<scene><georeference crs="EPSG:4326" origin="0 0"/></scene>)");
    EXPECT_EQ(unknown.rfind("s.xml:1:27: crs 'EPSG:4326': ", 0), 0u) << unknown;
    EXPECT_EQ(parseError(R"(<scene><georeference crs="UTM33" origin="0 0"/></scene>)"),
              "s.xml:1:27: crs 'UTM33' is not of the form EPSG:<code>");
    EXPECT_EQ(parseError(R"(<scene><georeference crs="EPSG:99999999999" origin="0 0"/></scene>)"),
              "s.xml:1:27: crs 'EPSG:99999999999': not a supported EPSG code");
    std::string far = parseError(R"(<scene><georeference crs="EPSG:25833" origin="500000 9900000"/></scene>)");
    EXPECT_EQ(far.rfind("s.xml:1:47: origin 500000 9900000 lies outside the area of EPSG:25833", 0), 0u) << far;
}

}  // namespace
}  // namespace veduta

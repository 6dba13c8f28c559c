#include <gtest/gtest.h>

#include "assembly/build_scene.h"
#include "core/error.h"
#include "description/scene_description.h"
#include "input_error.h"
#include "test_paths.h"
#include "test_scenes.h"

namespace veduta {
namespace {

SceneDescription parse(const std::string &xml) { return readSceneText(xml, "s.xml", test::testData()); }

// The message of the InputError that reading and building `xml` throws.
std::string errorOf(const std::string &xml) {
    return test::inputErrorOf([&] { buildRenderScene(parse(xml)); });
}

// <scene seed> is the base; an element's own seed overrides it, and an element without one has
// none (buildRenderScene gives it the scene's).
TEST(SceneFile, ReadsTheSceneSeedAndTheElementsOwnSeeds) {
    SceneDescription d = parse(R"(<scene version="1" seed="9">
  <render spp="2"/>
  <buildings rules="r.xml" seed="3"/>
  <buildings rules="r.xml"/>
  <city file="c.xml"/>
  <city file="c.xml" seed="4294967295"/>
  <landscape seed="0"><dgm file="d.asc"/></landscape>
</scene>)");
    EXPECT_EQ(d.seed, 9u);
    EXPECT_FALSE(d.renderSeed);
    ASSERT_EQ(d.buildingGroups.size(), 2u);
    EXPECT_EQ(d.buildingGroups[0].seed, 3u);
    EXPECT_FALSE(d.buildingGroups[1].seed);
    ASSERT_EQ(d.cities.size(), 2u);
    EXPECT_FALSE(d.cities[0].seed);
    EXPECT_EQ(d.cities[1].seed, 4294967295u);
    ASSERT_TRUE(d.landscape);
    EXPECT_EQ(d.landscape->seed, 0u);
    EXPECT_EQ(parse("<scene version=\"1\"/>").seed, 0u);
}

TEST(SceneFile, ReadsEveryTopLevelElement) {
    SceneDescription d = parse(R"(<scene version="1">
  <camera position="1 2 3" look_at="0 0 0" up="0 0 1" fov="30" resolution="320 200"/>
  <sun azimuth="90" elevation="0" irradiance="2" angular_diameter="0"/>
  <environment radiance="0.1 0.2 0.3"/>
  <render spp="7" max_depth="3" seed="42" tile_size="8"/>
  <material name="red" diffuse="0.9 0.1 0.1"/>
  <box size="1 2 3" material="red" translate="1 0 0" id="17"/>
  <prototype name="p"><sphere radius="2" segments="8" rings="4"/></prototype>
  <instance prototype="p" rotate="0 0 90" scale="2"/>
</scene>)");
    EXPECT_EQ(d.camera.position, Vec3f(1, 2, 3));
    EXPECT_EQ(d.camera.width, 320);
    EXPECT_EQ(d.camera.height, 200);
    EXPECT_FLOAT_EQ(d.camera.verticalFovDegrees, 30);
    // Azimuth 90 is east, elevation 0 the horizon.
    EXPECT_NEAR(d.sun.direction.x, 1, 1e-6);
    EXPECT_NEAR(d.sun.direction.y, 0, 1e-6);
    EXPECT_NEAR(d.sun.direction.z, 0, 1e-6);
    EXPECT_EQ(d.sun.irradiance, Vec3f(2));
    EXPECT_EQ(d.environment.radiance, Vec3f(0.1f, 0.2f, 0.3f));
    EXPECT_EQ(d.settings.samplesPerPixel, 7u);
    EXPECT_EQ(d.settings.maxDepth, 3u);
    EXPECT_EQ(d.renderSeed, 42u);
    EXPECT_EQ(d.settings.tileSize, 8u);
    ASSERT_EQ(d.materials.size(), 1u);
    ASSERT_EQ(d.geometry.size(), 1u);
    EXPECT_EQ(d.geometry[0].objectId, 17u);
    EXPECT_EQ(d.geometry[0].transform.applyPoint({0, 0, 0}), Vec3f(1, 0, 0));
    ASSERT_EQ(d.prototypes.size(), 1u);
    ASSERT_EQ(d.instances.size(), 1u);
    Vec3f p = d.instances[0].transform.applyPoint({1, 0, 0});
    EXPECT_NEAR(p.x, 0, 1e-6);
    EXPECT_NEAR(p.y, 2, 1e-6);
}

TEST(SceneFile, UnknownElementNamesLineAndColumn) {
    EXPECT_EQ(errorOf("<scene>\n  <camera/>\n   <teapot/>\n</scene>"), "s.xml:3:4: unknown element <teapot>");
}

TEST(SceneFile, BadNumberPointsAtTheValue) {
    EXPECT_EQ(errorOf("<scene>\n<render spp=\"12x\"/>\n</scene>"),
              "s.xml:2:14: '12x' is not an integer (attribute 'spp')");
    EXPECT_EQ(errorOf("<scene>\n<camera fov=\"wide\"/>\n</scene>"),
              "s.xml:2:14: 'wide' is not a number (attribute 'fov')");
    EXPECT_EQ(errorOf("<scene>\n<camera fov=\"nan\"/>\n</scene>"),
              "s.xml:2:14: 'nan' is not a number (attribute 'fov')");
    EXPECT_EQ(errorOf("<scene>\n<camera position=\"0 -1e39 2\"/>\n</scene>"),
              "s.xml:2:19: '-1e39' is not a number (attribute 'position')");
    // A camera Embree's bounds cannot hold.
    EXPECT_EQ(errorOf("<scene>\n<camera position=\"0 -1e19 2\"/>\n</scene>"),
              "s.xml:2:19: 0 -1e+19 2 lies more than 10,000 km from the scene origin (attribute 'position')");
}

TEST(SceneFile, UnknownAttributeIsAnError) {
    EXPECT_EQ(errorOf("<scene>\n<box sise=\"1 1 1\"/>\n</scene>"), "s.xml:2:6: unknown attribute 'sise' on <box>");
}

TEST(SceneFile, OutOfRangeValuesAreErrors) {
    EXPECT_EQ(errorOf("<scene><render spp=\"0\"/></scene>"), "s.xml:1:21: attribute 'spp' is 0, outside [1, 16777216]");
    EXPECT_EQ(errorOf("<scene><material name=\"m\" diffuse=\"1.5\"/></scene>"),
              "s.xml:1:36: attribute 'diffuse' has 1.5, outside [0, 1]");
    EXPECT_EQ(errorOf("<scene><sun irradiance=\"1 -1 1\"/></scene>"),
              "s.xml:1:25: attribute 'irradiance' has -1, outside [0, 1000000000]");
}

TEST(SceneFile, MalformedXmlNamesThePlace) {
    std::string message = errorOf("<scene>\n<box size=\"1 1 1\">\n</scene>");
    EXPECT_EQ(message.rfind("s.xml:3:", 0), 0u) << message;
}

TEST(SceneFile, MissingMeshFileIsReportedAtTheAttribute) {
    EXPECT_EQ(errorOf("<scene>\n  <mesh file=\"nowhere.obj\"/>\n</scene>"),
              "s.xml:2:15: " + (test::testData() / "nowhere.obj").string() + ": no such mesh file");
}

TEST(SceneFile, UnreadableMeshFileIsReportedAtTheAttribute) {
    std::string message = errorOf("<scene><mesh file=\"broken.obj\"/></scene>");
    EXPECT_EQ(message.rfind("s.xml:1:20: ", 0), 0u) << message;
}

// Meshes that would crash Assimp's later steps or Embree's build: a face index past the
// vertices, a vertex beyond float (Assimp reads 1e39 as infinity).
TEST(SceneFile, BrokenMeshesAreInputErrors) {
    test::ScratchFolder folder("broken_meshes");
    std::filesystem::path index =
        folder.write("index.ply",
                     "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                     "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                     "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");
    std::filesystem::path huge = folder.write("huge.obj", "v 0 0 0\nv 1 0 1e39\nv 0 1 0\nf 1 2 3\n");
    auto errorFor = [](const std::filesystem::path &file) {
        return test::sceneErrorOf("<scene><mesh file=\"" + file.string() + "\"/></scene>");
    };
    EXPECT_NE(errorFor(index).find(index.string() + ": "), std::string::npos) << errorFor(index);
    EXPECT_NE(errorFor(huge).find(huge.string() + ": vertex 1 is not a finite point (1 0 inf)"), std::string::npos)
        << errorFor(huge);
}

TEST(SceneFile, UnknownReferencesNameTheirPlace) {
    EXPECT_EQ(errorOf("<scene>\n<box material=\"gold\"/>\n</scene>"), "s.xml:2:16: unknown material 'gold'");
    EXPECT_EQ(errorOf("<scene>\n<instance prototype=\"tree\"/>\n</scene>"), "s.xml:2:22: unknown prototype 'tree'");
}

TEST(SceneFile, DuplicateNamesAreErrors) {
    std::string message = errorOf("<scene><material name=\"a\"/>\n<material name=\"a\"/></scene>");
    EXPECT_EQ(message, "s.xml:2:17: material 'a' is already defined at s.xml:1:8");
}

TEST(SceneFile, LoadsObjAndPlyMeshes) {
    RenderScene scene = test::sceneFromXml(R"(<scene>
  <mesh file="tetra.obj"/>
  <mesh file="quad.ply" translate="5 0 0"/>
</scene>)");
    ASSERT_EQ(scene.meshes.size(), 2u);
    EXPECT_EQ(scene.meshes[0].mesh.triangleCount(), 4u);
    EXPECT_EQ(scene.meshes[1].mesh.triangleCount(), 2u);
    EXPECT_FLOAT_EQ(scene.meshes[1].mesh.positions[0].x, 5);
}

TEST(SceneFile, LeafElementsHoldNoChildren) {
    EXPECT_EQ(errorOf("<scene>\n<box>\n  <sphere/>\n</box>\n</scene>"),
              "s.xml:3:3: <sphere> cannot stand inside <box>");
}

TEST(SceneFile, RepeatedAttributeIsAnError) {
    EXPECT_EQ(errorOf("<scene><render spp=\"4\" spp=\"8\"/></scene>"), "s.xml:1:24: attribute 'spp' is given twice");
}

TEST(SceneFile, SunNeedsBothAzimuthAndElevation) {
    EXPECT_EQ(errorOf("<scene>\n<sun elevation=\"30\"/></scene>"),
              "s.xml:2:1: give the sun both 'azimuth' and 'elevation'");
}

TEST(SceneFile, ObjectIdsFollowFileOrderAroundExplicitOnes) {
    SceneDescription d = parse(R"(<scene>
  <prototype name="p"><box/></prototype>
  <instance prototype="p"/>
  <box id="2"/>
  <box/>
  <instance prototype="p"/>
</scene>)");
    EXPECT_EQ(d.instances[0].objectId, 1u);
    EXPECT_EQ(d.geometry[0].objectId, 2u);
    EXPECT_EQ(d.geometry[1].objectId, 3u);
    EXPECT_EQ(d.instances[1].objectId, 4u);
}

TEST(SceneFile, ObjectIdsAreUniqueAndBelongToWholeObjects) {
    EXPECT_EQ(errorOf("<scene><box id=\"5\"/>\n<box id=\"5\"/></scene>"),
              "s.xml:2:10: object id 5 is already used at s.xml:1:17");
    EXPECT_EQ(errorOf("<scene><prototype name=\"p\">\n<box id=\"3\"/></prototype></scene>"),
              "s.xml:2:10: parts of a prototype have no id of their own; give it to the <instance>");
}

TEST(SceneFile, AMaterialNamedDefaultReplacesTheBuiltInOne) {
    RenderScene scene = test::sceneFromXml(R"(<scene><material name="default" diffuse="0.1"/><box/></scene>)");
    EXPECT_EQ(scene.materials[scene.meshes[0].mesh.triangleMaterials[0]].diffuse, Vec3f(0.1f));
}

TEST(SceneFile, RepeatedTopLevelGeometryIsSharedAndSingleGeometryBaked) {
    RenderScene scene = test::sceneFromXml(R"(<scene>
  <material name="m"/>
  <mesh file="tetra.obj" translate="0 0 0"/>
  <mesh file="tetra.obj" translate="2 0 0"/>
  <mesh file="tetra.obj" translate="4 0 0" material="m"/>
  <box size="1 2 3"/>
  <box size="1 2 3" translate="5 0 0" id="40"/>
  <box size="1 2 4"/>
</scene>)");
    // Two plain tetrahedra and two equal boxes are shared; the red tetrahedron and the
    // taller box appear once and are baked.
    EXPECT_EQ(scene.prototypes.size(), 2u);
    EXPECT_EQ(scene.instances.size(), 4u);
    EXPECT_EQ(scene.meshes.size(), 2u);
    EXPECT_EQ(scene.instances[3].objectId, 40u);
    EXPECT_EQ(scene.effectiveTriangleCount(), 3u * 4u + 3u * 12u);
}

TEST(SceneFile, MeshFileWithLinesAfterFacesKeepsTheFaces) {
    RenderScene scene = test::sceneFromXml(R"(<scene><mesh file="faces_then_lines.obj"/></scene>)");
    ASSERT_EQ(scene.meshes.size(), 1u);
    EXPECT_EQ(scene.meshes[0].mesh.triangleCount(), 1u);
}

TEST(SceneFile, RootMustBeScene) {
    EXPECT_EQ(errorOf("<world/>"), "s.xml:1:1: the root element is <world>, expected <scene>");
}

}  // namespace
}  // namespace veduta

namespace veduta {
namespace {

TEST(SceneFile, ReadsTheCamerasFramingAndLens) {
    SceneDescription d = parse(R"(<scene version="1">
  <camera position="0 -20 1.6" look_at="0 0 1.6" projection="perspective" fov="40" shift="0.05 0.2"
          f_number="5.6" focus_distance="18" sensor_width="24"/>
</scene>)");
    EXPECT_EQ(d.camera.projection, Projection::Perspective);
    EXPECT_FLOAT_EQ(d.camera.shift.x, 0.05f);
    EXPECT_FLOAT_EQ(d.camera.shift.y, 0.2f);
    EXPECT_FLOAT_EQ(d.camera.fNumber, 5.6f);
    EXPECT_FLOAT_EQ(d.camera.focusDistance, 18);
    EXPECT_FLOAT_EQ(d.camera.sensorWidth, 24);
    SceneDescription o = parse(R"(<scene><camera projection="orthographic" ortho_scale="120"/></scene>)");
    EXPECT_EQ(o.camera.projection, Projection::Orthographic);
    EXPECT_FLOAT_EQ(o.camera.orthoScale, 120);
    EXPECT_EQ(errorOf("<scene>\n<camera projection=\"fisheye\"/>\n</scene>"),
              "s.xml:2:21: projection 'fisheye' is neither 'perspective' nor 'orthographic'");
    EXPECT_EQ(errorOf("<scene>\n<camera projection=\"orthographic\" f_number=\"2\"/>\n</scene>"),
              "s.xml:2:1: depth of field (f_number) needs a perspective camera");
    EXPECT_EQ(errorOf("<scene>\n<camera shift=\"0.1\"/>\n</scene>"),
              "s.xml:2:16: shift takes two numbers, horizontal and vertical, -10 to 10");
}

// A camera in map coordinates lands where the same map point of a mesh would: easting and
// northing less the scene origin, in the scene's CRS; from another CRS through the projection.
TEST(SceneFile, PlacesACameraGivenInMapCoordinates) {
    RenderScene scene = buildRenderScene(parse(R"(<scene version="1">
  <georeference crs="EPSG:25833" origin="390000 5820000"/>
  <camera crs="EPSG:25833" position="390012.5 5819950.25 42" look_at="390100 5820100 40"/>
</scene>)"));
    EXPECT_NEAR(scene.camera.position.x, 12.5f, 1e-3f);
    EXPECT_NEAR(scene.camera.position.y, -49.75f, 1e-3f);
    EXPECT_NEAR(scene.camera.position.z, 42, 1e-5f);
    EXPECT_NEAR(scene.camera.lookAt.x, 100, 1e-3f);
    // Another CRS (UTM 32N, far to the west of its zone here) is converted, not copied.
    RenderScene other = buildRenderScene(parse(R"(<scene version="1">
  <georeference crs="EPSG:25833" origin="390000 5820000"/>
  <camera crs="EPSG:25832" position="799000 5825000 42" look_at="799100 5825100 40"/>
</scene>)"));
    EXPECT_GT(std::abs(other.camera.position.x - 409000), 100);
    EXPECT_NEAR(other.camera.position.z, 42, 1e-5f);
    EXPECT_EQ(errorOf("<scene>\n<camera crs=\"EPSG:25832\" position=\"1 2 3\" look_at=\"4 5 6\"/>\n</scene>"),
              "s.xml:2:14: a camera in map coordinates (crs) needs the scene's <georeference crs=\"EPSG:…\" "
              "origin=\"E N\"> to be placed");
    EXPECT_EQ(errorOf("<scene>\n<camera crs=\"EPSG:25832\" position=\"1 2\" look_at=\"4 5 6\"/>\n</scene>"),
              "s.xml:2:36: position takes three numbers in map coordinates: easting, northing, height");
    // Checked as a camera given in the frame is, once placed: straight down with up along z.
    EXPECT_EQ(errorOf("<scene>\n<georeference crs=\"EPSG:25833\" origin=\"390000 5820000\"/>\n"
                      "<camera crs=\"EPSG:25833\" position=\"390010 5820010 300\" look_at=\"390010 5820010 0\"/>\n"
                      "</scene>"),
              "s.xml:3:14: camera up is parallel to the view direction in the render frame");
}

TEST(SceneFile, CameraMustFrameAView) {
    EXPECT_EQ(errorOf("<scene>\n<camera position=\"1 2 3\" look_at=\"1 2 3\"/>\n</scene>"),
              "s.xml:2:1: camera position and look_at are the same point");
    EXPECT_EQ(errorOf("<scene>\n<camera position=\"0 0 10\" look_at=\"0 0 0\" up=\"0 0 1\"/>\n</scene>"),
              "s.xml:2:1: camera up is parallel to the view direction");
}

TEST(SceneFile, ReadsFogAndGround) {
    SceneDescription d = parse(R"(<scene version="1">
  <fog visibility="20000" height="110" scale_height="900"/>
  <ground height="-0.5"/>
</scene>)");
    EXPECT_NEAR(d.fog.density, 3.912f / 20000, 1e-9f);
    EXPECT_FLOAT_EQ(d.fog.baseHeight, 110);
    EXPECT_FLOAT_EQ(d.fog.scaleHeight, 900);
    ASSERT_EQ(d.geometry.size(), 1u);
    ASSERT_TRUE(d.geometry[0].shape);
    EXPECT_EQ(d.geometry[0].shape->kind, ShapeKind::Ground);
    EXPECT_FLOAT_EQ(d.geometry[0].shape->height, -0.5f);
    EXPECT_EQ(errorOf("<scene>\n<fog density=\"0.001\" visibility=\"100\"/>\n</scene>"),
              "s.xml:2:1: give the fog one of 'density' and 'visibility'");
    EXPECT_EQ(errorOf("<scene>\n<ground translate=\"0 0 1\"/>\n</scene>"),
              "s.xml:2:9: unknown attribute 'translate' on <ground>");
    EXPECT_EQ(errorOf("<scene>\n<prototype name=\"p\"><ground/></prototype>\n</scene>"),
              "s.xml:2:21: <ground> stands at the top level of the scene, not in a <prototype>");
}

}  // namespace
}  // namespace veduta

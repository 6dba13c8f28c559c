// <mesh crs="EPSG:…">: a mesh file in map coordinates keeps its millimetres (issue 16): its
// coordinates stay double until the scene origin is subtracted.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <fstream>

#include <fmt/format.h>

#include "geodesy/crs.h"
#include "test_scenes.h"

namespace veduta {
namespace {

// A 0.33 × 0.77 × 1 m box at UTM 32 coordinates with digits below the millimetre.
constexpr double kEast = 500123.4567, kNorth = 5400234.5678, kHeight = 87.123;
constexpr double kSize[3] = {0.33, 0.77, 1.0};
// The scene origin, a few hundred metres from the box.
constexpr double kOriginEast = 500400, kOriginNorth = 5400000;

std::array<CrsCoordinate, 8> boxCorners() {
    std::array<CrsCoordinate, 8> corners;
    for (int i = 0; i < 8; ++i)
        corners[size_t(i)] = {kEast + (i & 1) * kSize[0], kNorth + ((i >> 1) & 1) * kSize[1],
                              kHeight + ((i >> 2) & 1) * kSize[2]};
    return corners;
}

struct Extent {
    Vec3f lo{1e30f}, hi{-1e30f};
    Vec3f size() const { return {hi.x - lo.x, hi.y - lo.y, hi.z - lo.z}; }
};

Extent extentOf(const Mesh &mesh) {
    Extent e;
    for (const Vec3f &p : mesh.positions) {
        e.lo = {std::min(e.lo.x, p.x), std::min(e.lo.y, p.y), std::min(e.lo.z, p.z)};
        e.hi = {std::max(e.hi.x, p.x), std::max(e.hi.y, p.y), std::max(e.hi.z, p.z)};
    }
    return e;
}

class GeoreferencedMesh : public testing::Test {
  protected:
    // The box as an OBJ of six quads, its corners given in `crs` (converted from UTM 32).
    std::filesystem::path writeBox(const std::string &name, int epsg) const {
        std::filesystem::path file = dir_ / name;
        std::ofstream out(file);
        const Crs &utm = crsByEpsg(25832), &crs = crsByEpsg(epsg);
        for (const CrsCoordinate &c : boxCorners()) {
            CrsCoordinate p = convert(utm, crs, c);
            out << fmt::format("v {:.6f} {:.6f} {:.6f}\n", p.x, p.y, p.z);
        }
        out << "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";
        return file;
    }

    std::filesystem::path write(const std::string &name, const std::string &text) const {
        return folder_.write(name, text);
    }

    static std::string scene(const std::filesystem::path &mesh, const std::string &crsAttribute,
                             bool georeferenced = true) {
        std::string georeference = georeferenced
            ? fmt::format("<georeference crs=\"EPSG:25832\" origin=\"{} {}\"/>", kOriginEast, kOriginNorth)
            : "";
        return fmt::format("<scene version=\"1\">{}<mesh file=\"{}\" {}/></scene>", georeference, mesh.string(),
                           crsAttribute);
    }

    static Mesh onlyMesh(const std::string &xml) {
        RenderScene built = test::sceneFromXml(xml);
        EXPECT_EQ(built.meshes.size(), 1u);
        return built.meshes.at(0).mesh;
    }

    static std::string errorOf(const std::string &xml) { return test::sceneErrorOf(xml); }

    test::ScratchFolder folder_{"georeferenced_mesh"};
    const std::filesystem::path &dir_ = folder_.path();
};

TEST_F(GeoreferencedMesh, UtmBoxKeepsItsSizeWithinAMillimetre) {
    Mesh mesh = onlyMesh(scene(writeBox("box.obj", 25832), "crs=\"EPSG:25832\""));
    EXPECT_EQ(mesh.triangleCount(), 12u);
    Extent e = extentOf(mesh);
    EXPECT_NEAR(e.size().x, 0.33, 1e-3);
    EXPECT_NEAR(e.size().y, 0.77, 1e-3);
    EXPECT_NEAR(e.size().z, 1.0, 1e-3);
    // And where it belongs: the corner's map coordinates less the origin.
    EXPECT_NEAR(e.lo.x, kEast - kOriginEast, 1e-3);
    EXPECT_NEAR(e.lo.y, kNorth - kOriginNorth, 1e-3);
    EXPECT_NEAR(e.lo.z, kHeight, 1e-3);
}

// What the box became before: Assimp reads float, which resolves 0.5 m at this northing.
TEST_F(GeoreferencedMesh, WithoutCrsTheFloatReaderLosesTheBoxSize) {
    Extent e = extentOf(onlyMesh(scene(writeBox("box.obj", 25832), "")));
    EXPECT_GT(std::abs(e.size().x - 0.33f), 1e-3f);
    EXPECT_GT(std::abs(e.size().y - 0.77f), 1e-3f);
}

TEST_F(GeoreferencedMesh, GaussKruegerBoxLandsWhereTheUtmBoxDoes) {
    Mesh utm = onlyMesh(scene(writeBox("utm.obj", 25832), "crs=\"EPSG:25832\""));
    Mesh gk = onlyMesh(scene(writeBox("gk.obj", 31467), "crs=\"EPSG:31467\""));
    ASSERT_EQ(gk.positions.size(), utm.positions.size());
    // Compared as sets of points: each quad is split along its shorter diagonal, and the
    // box's two diagonals are equal, so rounding may split the two boxes differently.
    for (size_t i = 0; i < gk.positions.size(); ++i) {
        float nearest = 1e30f;
        for (const Vec3f &p : utm.positions) nearest = std::min(nearest, length(gk.positions[i] - p));
        EXPECT_LT(nearest, 0.01f) << i;
    }
}

// The element's own transform applies in the local frame, after the origin is subtracted.
TEST_F(GeoreferencedMesh, TransformAppliesInTheLocalFrame) {
    std::filesystem::path box = writeBox("box.obj", 25832);
    std::string xml = fmt::format(
        "<scene version=\"1\"><georeference crs=\"EPSG:25832\" origin=\"{} {}\"/>"
        "<mesh file=\"{}\" crs=\"EPSG:25832\" translate=\"10 0 0\"/></scene>",
        kOriginEast, kOriginNorth, box.string());
    Extent e = extentOf(onlyMesh(xml));
    EXPECT_NEAR(e.lo.x, kEast - kOriginEast + 10, 1e-3);
    EXPECT_NEAR(e.size().x, 0.33, 1e-3);
}

TEST_F(GeoreferencedMesh, NormalsTurnOntoTheScenesGrid) {
    // A wall facing grid east in Gauss-Krüger zone 2 (6° E) faces some 2° off east on the grid
    // of UTM 32 (9° E): the two grids' norths differ by the difference of their convergences.
    const Crs &utm = crsByEpsg(25832), &gk = crsByEpsg(31466);
    CrsCoordinate corner = convert(utm, gk, {kEast + 300, kNorth, kHeight});
    std::filesystem::path file =
        write("wall.obj",
              fmt::format("v {0:.3f} {1:.3f} 0\nv {0:.3f} {2:.3f} 0\nv {0:.3f} {1:.3f} 3\nvn 1 0 0\n"
                          "f 1//1 2//1 3//1\n",
                          corner.x, corner.y, corner.y + 10));
    Mesh mesh = onlyMesh(scene(file, "crs=\"EPSG:31466\""));
    ASSERT_EQ(mesh.normals.size(), 3u);
    Vec3f a = mesh.positions[0], b = mesh.positions[1];
    // The normal stays perpendicular to the wall as the scene's grid draws it.
    EXPECT_NEAR(mesh.normals[0].x * (b.x - a.x) + mesh.normals[0].y * (b.y - a.y), 0, 1e-4);
    EXPECT_GT(std::abs(mesh.normals[0].y), 0.02f);  // turned, not left at (1, 0, 0)
}

// The box as a PLY whose vertices are doubles: ASCII, or binary in either byte order.
std::string plyBox(const std::string &format) {
    std::string header = fmt::format(
        "ply\nformat {} 1.0\ncomment UTM 32\nelement vertex 8\nproperty double x\n"
        "property double y\nproperty double z\nelement face 6\n"
        "property list uchar int vertex_indices\nend_header\n",
        format);
    const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    std::string body;
    bool big = format == "binary_big_endian";
    auto bytes = [&](const auto &value) {
        char b[sizeof value];
        std::memcpy(b, &value, sizeof value);
        if (big == (std::endian::native == std::endian::little)) std::reverse(b, b + sizeof value);
        body.append(b, sizeof value);
    };
    for (const CrsCoordinate &c : boxCorners()) {
        if (format == "ascii") body += fmt::format("{:.6f} {:.6f} {:.6f}\n", c.x, c.y, c.z);
        else
            for (double v : {c.x, c.y, c.z}) bytes(v);
    }
    for (const auto &f : faces) {
        if (format == "ascii") {
            body += fmt::format("4 {} {} {} {}\n", f[0], f[1], f[2], f[3]);
        } else {
            bytes(uint8_t(4));
            for (int i : f) bytes(int32_t(i));
        }
    }
    return header + body;
}

TEST_F(GeoreferencedMesh, PlyBoxesKeepTheirSizeInEveryEncoding) {
    for (std::string format : {"ascii", "binary_little_endian", "binary_big_endian"}) {
        Mesh mesh = onlyMesh(scene(write(format + ".ply", plyBox(format)), "crs=\"EPSG:25832\""));
        EXPECT_EQ(mesh.triangleCount(), 12u) << format;
        Extent e = extentOf(mesh);
        EXPECT_NEAR(e.size().x, 0.33, 1e-3) << format;
        EXPECT_NEAR(e.size().y, 0.77, 1e-3) << format;
        EXPECT_NEAR(e.size().z, 1.0, 1e-3) << format;
        EXPECT_NEAR(e.lo.x, kEast - kOriginEast, 1e-3) << format;
        EXPECT_NEAR(e.lo.y, kNorth - kOriginNorth, 1e-3) << format;
    }
}

TEST_F(GeoreferencedMesh, PlyErrorsNameTheLine) {
    std::string text = plyBox("ascii");
    text.replace(text.find("5400234"), 7, "54OO234");
    std::filesystem::path bad = write("bad.ply", text);
    EXPECT_NE(errorOf(scene(bad, "crs=\"EPSG:25832\"")).find(bad.string() + ":11: '54OO234.567800' is not a number"),
              std::string::npos)
        << errorOf(scene(bad, "crs=\"EPSG:25832\""));
    std::filesystem::path noZ = write("noz.ply",
                                      "ply\nformat ascii 1.0\nelement vertex 0\nproperty double x\n"
                                      "property double y\nend_header\n");
    EXPECT_NE(errorOf(scene(noZ, "crs=\"EPSG:25832\"")).find(":3: the vertex element needs the properties x, y and z"),
              std::string::npos)
        << errorOf(scene(noZ, "crs=\"EPSG:25832\""));
    std::string binary = plyBox("binary_little_endian");
    std::filesystem::path cut = write("cut.ply", binary.substr(0, binary.size() - 10));
    EXPECT_NE(errorOf(scene(cut, "crs=\"EPSG:25832\"")).find("the file ends before its last element"),
              std::string::npos);
}

TEST_F(GeoreferencedMesh, Errors) {
    std::filesystem::path box = writeBox("box.obj", 25832);
    EXPECT_EQ(errorOf(scene(box, "crs=\"EPSG:25832\"", false)),
              fmt::format("test.xml:1:{}: a mesh in map coordinates (crs) needs the scene's <georeference "
                          "crs=\"EPSG:…\" origin=\"E N\"> to be placed",
                          box.string().size() + 39));  // at crs's value
    EXPECT_NE(errorOf(scene(box, "crs=\"EPSG:3857\"")).find("EPSG:3857 is not supported"), std::string::npos);
    std::filesystem::path stl = write("box.stl", "solid box\nendsolid box\n");
    EXPECT_NE(errorOf(scene(stl, "crs=\"EPSG:25832\"")).find("georeferenced meshes are read from OBJ and PLY"),
              std::string::npos);
    std::filesystem::path beyond = write("beyond.obj", "v 500000 5400000 0\nv 500001 5400000 0\nf 1 2 3\n");
    EXPECT_NE(errorOf(scene(beyond, "crs=\"EPSG:25832\"")).find("face 1 refers to vertex 3, beyond the 2"),
              std::string::npos);
    // A Gauss-Krüger Rechtswert given as UTM: no point of UTM 32.
    std::filesystem::path gk = writeBox("gk.obj", 31467);
    EXPECT_NE(errorOf(scene(gk, "crs=\"EPSG:25832\"")).find("is no point of EPSG:25832"), std::string::npos);
}

}  // namespace
}  // namespace veduta

#include "geo/dgm_file.h"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <ogr_spatialref.h>
#include <unistd.h>

#include "core/error.h"
#include "esri_ascii_grid.h"
#include "geo/no_data_fill.h"
#include "geo/terrain_mesh.h"
#include "geodesy/crs.h"
#include "shared_data.h"

namespace veduta {
namespace {

namespace fs = std::filesystem;

// A small DGM as text, the way surveys write it: 3 decimals. "" is a node without data.
struct SmallDgm {
    double west = 350001, south = 5650001, spacing = 2;  // nodes (pixel centres)
    int columns = 5, rows = 4;
    std::vector<std::string> heights;  // row-major from the south

    SmallDgm() {
        for (int r = 0; r < rows; ++r)
            for (int c = 0; c < columns; ++c) heights.push_back(fmt::format("{:.3f}", 587.354 + 1.117 * c - 0.731 * r));
        heights[size_t(2 * columns + 1)] = "";
    }
    const std::string &text(int c, int r) const { return heights[size_t(r * columns + c)]; }
    float value(int c, int r) const {
        return text(c, r).empty() ? NAN : float(std::strtod(text(c, r).c_str(), nullptr));
    }
};

class DgmFileTest : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
            fmt::format("veduta_dgm_{}_{}", ::testing::UnitTest::GetInstance()->current_test_info()->name(), getpid());
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    fs::path write(const std::string &name, const std::string &text) const {
        fs::path file = dir_ / name;
        std::ofstream(file, std::ios::binary) << text;
        return file;
    }

    // North row first, as gdal_translate writes XYZ.
    fs::path writeXyz(const std::string &name, const SmallDgm &d) const {
        std::string text;
        for (int r = d.rows - 1; r >= 0; --r)
            for (int c = 0; c < d.columns; ++c)
                if (!d.text(c, r).empty())
                    text += fmt::format("{:.3f} {:.3f} {}\n", d.west + c * d.spacing, d.south + r * d.spacing,
                                        d.text(c, r));
        return write(name, text);
    }

    fs::path writeAsc(const std::string &name, const SmallDgm &d) const {
        return write(name, test::esriAsciiGrid(d.columns, d.rows, d.west, d.south, d.spacing, [&](int c, int r) {
                         return d.text(c, r).empty() ? std::string("-9999") : d.text(c, r);
                     }));
    }

    // Written by GDAL itself, float32, north-up, EPSG:25832, no-data −9999.
    fs::path writeGeoTiff(const std::string &name, const SmallDgm &d, double pixelHeight = 0) const {
        GDALAllRegister();
        fs::path file = dir_ / name;
        GDALDriver *driver = GetGDALDriverManager()->GetDriverByName("GTiff");
        GDALDatasetUniquePtr out(driver->Create(file.c_str(), d.columns, d.rows, 1, GDT_Float32, nullptr));
        double dy = pixelHeight ? pixelHeight : d.spacing;
        double transform[6] = {d.west - d.spacing / 2, d.spacing, 0, d.south + (d.rows - 1) * dy + dy / 2, 0, -dy};
        out->SetGeoTransform(transform);
        OGRSpatialReference crs;
        crs.importFromEPSG(25832);
        out->SetSpatialRef(&crs);
        std::vector<float> rows;
        for (int r = d.rows - 1; r >= 0; --r)
            for (int c = 0; c < d.columns; ++c) rows.push_back(d.text(c, r).empty() ? -9999.0f : d.value(c, r));
        GDALRasterBand *band = out->GetRasterBand(1);
        band->SetNoDataValue(-9999);
        EXPECT_EQ(band->RasterIO(GF_Write, 0, 0, d.columns, d.rows, rows.data(), d.columns, d.rows, GDT_Float32, 0, 0,
                                 nullptr),
                  CE_None);
        return file;
    }

    fs::path dir_;
};

bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0 || (std::isnan(a) && std::isnan(b)); }

void expectSameGrid(const HeightGrid &a, const HeightGrid &b, double positionTolerance) {
    ASSERT_EQ(a.columns, b.columns);
    ASSERT_EQ(a.rows, b.rows);
    EXPECT_NEAR(a.west, b.west, positionTolerance);
    EXPECT_NEAR(a.south, b.south, positionTolerance);
    EXPECT_NEAR(a.east(), b.east(), positionTolerance);
    EXPECT_NEAR(a.north(), b.north(), positionTolerance);
    int differing = 0;
    for (size_t i = 0; i < a.heights.size(); ++i) differing += !sameBits(a.heights[i], b.heights[i]);
    EXPECT_EQ(differing, 0);
}

void expectError(const std::function<void()> &read, const std::string &expected) {
    try {
        read();
        ADD_FAILURE() << "no error; expected " << expected;
    } catch (const InputError &e) {
        EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
}

TEST_F(DgmFileTest, ThreeFormatsGiveTheSameGrid) {
    SmallDgm d;
    Dgm xyz = readDgm(writeXyz("small.xyz", d));
    Dgm asc = readDgm(writeAsc("small.asc", d));
    Dgm tif = readDgm(writeGeoTiff("small.tif", d));
    EXPECT_EQ(xyz.grid.columns, 5);
    EXPECT_EQ(xyz.grid.rows, 4);
    EXPECT_DOUBLE_EQ(xyz.grid.west, 350001);
    EXPECT_DOUBLE_EQ(xyz.grid.south, 5650001);
    EXPECT_DOUBLE_EQ(xyz.grid.spacing, 2);
    for (int r = 0; r < d.rows; ++r)
        for (int c = 0; c < d.columns; ++c) EXPECT_TRUE(sameBits(xyz.grid.node(c, r), d.value(c, r))) << c << ", " << r;
    EXPECT_TRUE(std::isnan(xyz.grid.node(1, 2)));
    expectSameGrid(xyz.grid, asc.grid, 1e-6);
    expectSameGrid(xyz.grid, tif.grid, 1e-6);
    EXPECT_EQ(xyz.epsg, 0);
    EXPECT_EQ(asc.epsg, 0);
    EXPECT_EQ(tif.epsg, 25832);
}

// The acceptance: the same area in the three formats gives identical meshes, bit for bit.
TEST_F(DgmFileTest, ThreeFormatsGiveTheSameMesh) {
    SmallDgm d;
    LocalFrame frame{{350003.5, 5650002.25}};
    Mesh xyz = terrainMesh(readDgm(writeXyz("small.xyz", d)).grid, frame, {});
    Mesh asc = terrainMesh(readDgm(writeAsc("small.asc", d)).grid, frame, {});
    Mesh tif = terrainMesh(readDgm(writeGeoTiff("small.tif", d)).grid, frame, {});
    ASSERT_GT(xyz.triangleCount(), 0u);
    for (const Mesh *other : {&asc, &tif}) {
        EXPECT_EQ(other->indices, xyz.indices);
        ASSERT_EQ(other->positions.size(), xyz.positions.size());
        EXPECT_EQ(std::memcmp(other->positions.data(), xyz.positions.data(), xyz.positions.size() * sizeof(Vec3f)), 0);
        EXPECT_EQ(std::memcmp(other->normals.data(), xyz.normals.data(), xyz.normals.size() * sizeof(Vec3f)), 0);
        EXPECT_EQ(std::memcmp(other->uvs.data(), xyz.uvs.data(), xyz.uvs.size() * sizeof(Vec2f)), 0);
    }
}

TEST_F(DgmFileTest, XyzRowOrderDoesNotMatter) {
    SmallDgm d;
    HeightGrid northFirst = readDgm(writeXyz("a.xyz", d)).grid;
    std::string southFirst, columnsFirst;
    for (int r = 0; r < d.rows; ++r)
        for (int c = 0; c < d.columns; ++c)
            if (!d.text(c, r).empty())
                southFirst += fmt::format("{} {} {}\n", d.west + c * d.spacing, d.south + r * d.spacing, d.text(c, r));
    for (int c = d.columns - 1; c >= 0; --c)
        for (int r = 0; r < d.rows; ++r)
            if (!d.text(c, r).empty())
                columnsFirst +=
                    fmt::format("\t{} {}\t{}\r\n", d.west + c * d.spacing, d.south + r * d.spacing, d.text(c, r));
    expectSameGrid(northFirst, readDgm(write("b.xyz", "# a comment\n\n" + southFirst)).grid, 1e-9);
    expectSameGrid(northFirst, readDgm(write("c.txt", columnsFirst)).grid, 1e-9);
}

TEST_F(DgmFileTest, XyzGapsBecomeNaN) {
    // Two rows of four nodes at 10 m, each missing one.
    Dgm dgm = readDgm(write("gaps.xyz", "0 0 1\n10 0 2\n30 0 3\n0 10 4\n20 10 5\n30 10 6\n"));
    ASSERT_EQ(dgm.grid.columns, 4);
    ASSERT_EQ(dgm.grid.rows, 2);
    EXPECT_EQ(dgm.grid.spacing, 10);
    EXPECT_EQ(dgm.grid.node(3, 0), 3);
    EXPECT_EQ(dgm.grid.node(2, 1), 5);
    EXPECT_TRUE(std::isnan(dgm.grid.node(2, 0)));
    EXPECT_TRUE(std::isnan(dgm.grid.node(1, 1)));
    EXPECT_EQ(countNoData(dgm.grid), 2u);
}

TEST_F(DgmFileTest, XyzErrorsNameLineAndColumn) {
    fs::path file = write("bad.xyz", "1 2 3\n4  abc 5\n");
    expectError([&] { readDgm(file); }, file.string() + ":2:4: 'abc' is not a number");
    file = write("nan.xyz", "0 0 1\n10 0 nan\n");
    expectError([&] { readDgm(file); }, file.string() + ":2:6: the height is NaN");
    file = write("short.xyz", "0 0 1\n10 0\n");
    expectError([&] { readDgm(file); }, file.string() + ":2:5: 2 values where a line needs three");
    file = write("long.xyz", "0 0 1\n10 0 1 7\n");
    expectError([&] { readDgm(file); }, file.string() + ":2:8: a fourth value");
    // A double, but no float: it became infinity and rendered black.
    file = write("huge.xyz", "0 0 1\n10 0 1e39\n");
    expectError([&] { readDgm(file); }, file.string() + ":2:6: the height 1e39 m lies beyond any on Earth (±100000 m)");
}

// A text raster whose header promises more heights than its bytes can hold is refused before
// gigabytes are allocated for them.
TEST_F(DgmFileTest, AnAscHeaderPromisingTooMuchIsRefused) {
    fs::path file = write("claims.asc", "ncols 30000\nnrows 30000\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 2 3\n");
    expectError([&] { readDgm(file); },
                file.string() + ": the header promises 30000 × 30000 heights, more than the file's");
}

TEST_F(DgmFileTest, XyzMixedSpacingsAreAnError) {
    fs::path file = write("mixed.xyz", "0 0 1\n10 0 1\n20 0 1\n30 0 1\n0 10 1\n5 10 1\n");
    expectError([&] { readDgm(file); },
                file.string() + ":6:1: the point (5.000, 10.000) is off the 10 m grid of the points before it");
    file = write("shifted.xyz", "0 0 1\n10 0 1\n20 0 1\n33 0 1\n");
    expectError([&] { readDgm(file); }, file.string() + ":4:1: the point (33.000, 0.000) is off the 10 m grid");
}

TEST_F(DgmFileTest, XyzDuplicatesMustAgree) {
    fs::path file = write("twice.xyz", "0 0 1\n10 0 1\n0 10 1\n 0 0 2\n");
    expectError([&] { readDgm(file); },
                file.string() + ":4:2: the point (0.000, 0.000) has the height 2 here but 1 on line 1");
    Dgm same = readDgm(write("same.xyz", "0 0 1\n10 0 1\n0 0 1\n"));
    EXPECT_EQ(same.grid.columns, 2);
    EXPECT_EQ(same.grid.node(0, 0), 1);
}

TEST_F(DgmFileTest, XyzNeedsTwoPoints) {
    fs::path file = write("one.xyz", "5 5 5\n");
    expectError([&] { readDgm(file); }, "fewer than two points");
}

// Found by fuzz/xyz: three points 350,000 km apart on a 2 m grid asked for 1.4 GB of empty
// nodes; a grid must be covered by its points to 1 % at least, checked before allocating.
TEST_F(DgmFileTest, XyzPointsThatCoverLittleOfTheirGridAreAnError) {
    fs::path file = write("apart.xyz", "3500000 5500000 100\n3500002 5500000 101\n3502000 5500000 102\n");
    expectError([&] { readDgm(file); },
                file.string() +
                    ": the 3 points span 1001 × 1 nodes of 2 m: they cover less "
                    "than 1 % of their grid");
    // A grid with its two middle rows missing is still one.
    SmallDgm d;
    for (int r = 1; r < 3; ++r)
        for (int c = 0; c < d.columns; ++c) d.heights[size_t(r * d.columns + c)] = "";
    HeightGrid half = readDgm(writeXyz("half.xyz", d)).grid;
    EXPECT_EQ(half.columns, d.columns);
    EXPECT_EQ(half.rows, d.rows);
    EXPECT_EQ(countNoData(half), 10u);
}

TEST_F(DgmFileTest, NonSquarePixels) {
    SmallDgm d;
    Dgm nearly = readDgm(writeGeoTiff("nearly.tif", d, d.spacing * (1 + 2.5e-10)));
    EXPECT_EQ(nearly.grid.spacing, d.spacing);
    fs::path file = writeGeoTiff("oblong.tif", d, d.spacing * 1.01);
    expectError([&] { readDgm(file); }, file.string() + ": the pixels are not square");
}

TEST_F(DgmFileTest, UnreadableFile) {
    fs::path file = write("nonsense.tif", "this is no raster\n");
    expectError([&] { readDgm(file); }, file.string() + ": GDAL cannot read this as a raster");
}

// Two tiles with one column in common; with the holes their union has, filled or cut.
TEST_F(DgmFileTest, TilesMosaic) {
    SmallDgm whole;
    whole.columns = 9;
    whole.heights.clear();
    for (int r = 0; r < whole.rows; ++r)
        for (int c = 0; c < whole.columns; ++c)
            whole.heights.push_back(fmt::format("{:.3f}", 100 + 0.5 * c + 0.25 * r));
    SmallDgm west = whole, east = whole;
    west.columns = east.columns = 5;
    west.heights.clear(), east.heights.clear();
    east.west = whole.west + 4 * whole.spacing;
    for (int r = 0; r < whole.rows; ++r)
        for (int c = 0; c < 5; ++c)
            west.heights.push_back(whole.text(c, r)), east.heights.push_back(whole.text(c + 4, r));
    std::vector<std::string> warnings;
    Dgm mosaic = readDgmTiles({writeXyz("east.xyz", east), writeGeoTiff("west.tif", west)}, NoDataPolicy{0}, warnings);
    EXPECT_TRUE(warnings.empty());
    HeightGrid expected = readDgm(writeXyz("whole.xyz", whole)).grid;
    expectSameGrid(mosaic.grid, expected, 1e-6);
    EXPECT_EQ(mosaic.epsg, 25832);
}

TEST_F(DgmFileTest, TilesMustLineUp) {
    SmallDgm a, b, c;
    b.west += 0.5;
    c.spacing = 1;
    fs::path fa = writeXyz("a.xyz", a), fb = writeXyz("b.xyz", b), fc = writeAsc("c.asc", c);
    std::vector<std::string> warnings;
    expectError(
        [&] {
            readDgmTiles({fa, fb}, NoDataPolicy{0}, warnings);
        },
        fb.string() + ": the nodes are off the nodes of " + fa.string() + " by 0.5000 m east");
    expectError(
        [&] {
            readDgmTiles({fa, fc}, NoDataPolicy{0}, warnings);
        },
        fc.string() + ": the grid spacing 1 m differs from the 2 m of " + fa.string());
}

TEST_F(DgmFileTest, OverlapsKeepTheFirstTile) {
    SmallDgm a, b;
    b.heights[0] = "600.000";
    b.heights[1] = "601.000";
    std::vector<std::string> warnings;
    fs::path fb = writeAsc("b.asc", b);
    Dgm dgm = readDgmTiles({writeXyz("a.xyz", a), fb}, NoDataPolicy{0}, warnings);
    EXPECT_TRUE(sameBits(dgm.grid.node(0, 0), a.value(0, 0)));
    // The hole of tile a is a hole of b too; only the two changed nodes disagree.
    ASSERT_EQ(warnings.size(), 2u);
    EXPECT_NE(warnings[0].find(fb.string() + ": 2 nodes where it overlaps earlier tiles differ"), std::string::npos)
        << warnings[0];
    EXPECT_NE(warnings[1].find("1 of 20 DGM nodes have no data"), std::string::npos) << warnings[1];
}

TEST_F(DgmFileTest, NoDataPolicies) {
    SmallDgm d;
    fs::path file = writeXyz("hole.xyz", d);
    std::vector<std::string> warnings;
    Dgm cut = readDgmTiles({file}, NoDataPolicy{0}, warnings);
    EXPECT_TRUE(std::isnan(cut.grid.node(1, 2)));
    warnings.clear();
    Dgm filled = readDgmTiles({file}, NoDataPolicy{8}, warnings);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("1 of 20 DGM nodes had no data and were filled"), std::string::npos) << warnings[0];
    // The heights are a plane (to the 3 decimals), so the mean of the 8 neighbours is on it.
    double plane = 587.354 + 1.117 * 1 - 0.731 * 2;
    EXPECT_NEAR(filled.grid.node(1, 2), plane, 2e-3);
}

// A 40 × 40 grid of 7.5 m with a 30 × 30 hole against its west edge (15 rings deep) and, when
// asked, a 3 × 3 hole (2 rings deep) in its north-east.
HeightGrid gridWithHoles(bool smallHole) {
    HeightGrid grid;
    grid.columns = grid.rows = 40;
    grid.spacing = 1;
    grid.heights.assign(1600, 7.5f);
    for (int r = 5; r < 35; ++r)
        for (int c = 0; c < 30; ++c) grid.node(c, r) = NAN;
    if (smallHole)
        for (int r = 35; r < 38; ++r)
            for (int c = 34; c < 37; ++c) grid.node(c, r) = NAN;
    return grid;
}

TEST(NoDataFill, FillsLargeHolesRingByRingWhenAllowedTo) {
    HeightGrid grid = gridWithHoles(false);
    NoDataFill fill = fillNoData(grid, 15);
    EXPECT_EQ(fill.filled, 900u);
    EXPECT_EQ(fill.cut, 0u);
    EXPECT_EQ(countNoData(grid), 0u);
    for (float h : grid.heights) ASSERT_EQ(h, 7.5f);
}

TEST(NoDataFill, AHoleReachingFartherIsCutWhole) {
    HeightGrid grid = gridWithHoles(true);
    NoDataFill fill = fillNoData(grid, 14);
    EXPECT_EQ(fill.filled, 9u);
    EXPECT_EQ(fill.cut, 900u);
    EXPECT_EQ(fill.cutHoles, 1u);
    EXPECT_EQ(countNoData(grid), 900u);
    for (int r = 5; r < 35; ++r)
        for (int c = 0; c < 30; ++c) ASSERT_TRUE(std::isnan(grid.node(c, r))) << c << " " << r;
    EXPECT_EQ(grid.node(35, 36), 7.5f);
    EXPECT_EQ(grid.node(30, 20), 7.5f);
}

TEST_F(DgmFileTest, TheDefaultFillCutsWhatItWouldMakeUp) {
    HeightGrid grid = gridWithHoles(true);
    SmallDgm d;
    d.columns = grid.columns, d.rows = grid.rows;
    d.heights.clear();
    for (float h : grid.heights) d.heights.push_back(std::isnan(h) ? "" : fmt::format("{:.3f}", h));
    fs::path file = writeXyz("holes.xyz", d);
    std::vector<std::string> warnings;
    Dgm dgm = readDgmTiles({file}, NoDataPolicy{8}, warnings);
    EXPECT_EQ(countNoData(dgm.grid), 900u);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0],
              file.string() +
                  ": 909 of 1600 DGM nodes had no data: 9 in holes within 8 nodes of a height were "
                  "filled from their neighbours, 900 in 1 hole reaching farther than 8 nodes from any "
                  "height are cut, not made up (the terrain leaves out the cells around them; "
                  "<landscape fill_distance> fills farther)");
}

// A DEM in WGS 84 degrees, as SRTM and most global DEMs come: 60 × 40 pixels of 0.0005°
// (about 36 × 56 m) near Kaiserslautern, heights a plane in longitude and latitude.
constexpr double kWest = 7.74, kNorth = 49.45, kStep = 0.0005;
double planeHeight(double longitude, double latitude) {
    return 240 + 150 * (longitude - kWest) + 100 * (latitude - kNorth);
}

TEST_F(DgmFileTest, AGeographicDgmIsWarpedIntoTheScenesCrs) {
    GDALAllRegister();
    fs::path file = dir_ / "srtm.tif";
    {
        const int columns = 60, rows = 40;
        GDALDriver *driver = GetGDALDriverManager()->GetDriverByName("GTiff");
        GDALDatasetUniquePtr out(driver->Create(file.c_str(), columns, rows, 1, GDT_Float32, nullptr));
        double transform[6] = {kWest, kStep, 0, kNorth, 0, -kStep};
        out->SetGeoTransform(transform);
        OGRSpatialReference wgs84;
        wgs84.importFromEPSG(4326);
        out->SetSpatialRef(&wgs84);
        std::vector<float> heights;
        for (int r = 0; r < rows; ++r)
            for (int c = 0; c < columns; ++c)
                heights.push_back(float(planeHeight(kWest + (c + 0.5) * kStep, kNorth - (r + 0.5) * kStep)));
        ASSERT_EQ(out->GetRasterBand(1)->RasterIO(GF_Write, 0, 0, columns, rows, heights.data(), columns, rows,
                                                  GDT_Float32, 0, 0, nullptr),
                  CE_None);
    }
    std::vector<std::string> warnings;
    Dgm dgm = readDgmTiles({file}, NoDataPolicy{0}, warnings, 25832);
    EXPECT_EQ(dgm.epsg, 25832);
    EXPECT_EQ(dgm.warpedFrom, 4326);
    ASSERT_GE(warnings.size(), 1u);
    EXPECT_EQ(warnings[0].rfind(file.string() +
                                    ": the DGM is in EPSG:4326, a geographic CRS; GDAL warped it into "
                                    "EPSG:25832 (bilinear): ",
                                0),
              0u)
        << warnings[0];
    // The rotated footprint leaves NaN corners in the grid; every node inside holds the plane
    // at the node's longitude and latitude. Bilinear interpolation is exact on a plane (but
    // within a pixel of the footprint's edge, where it lacks neighbours: those nodes are left
    // out); what is left is GDAL's approximate transformer (0.125 px, under 7 m here, times
    // the slope of 0.0023 m per m) and float32.
    const Crs &utm = crsByEpsg(25832), &wgs84 = crsByEpsg(4326);
    size_t valid = 0;
    double worst = 0;
    for (int r = 0; r < dgm.grid.rows; ++r)
        for (int c = 0; c < dgm.grid.columns; ++c) {
            float h = dgm.grid.node(c, r);
            if (std::isnan(h)) continue;
            ++valid;
            MapPoint p = dgm.grid.nodePoint(c, r);
            CrsCoordinate geographic = convert(utm, wgs84, {p.easting, p.northing, 0});
            bool inside = geographic.x > kWest + 1.5 * kStep && geographic.x < kWest + 58.5 * kStep &&
                geographic.y < kNorth - 1.5 * kStep && geographic.y > kNorth - 38.5 * kStep;
            if (inside) worst = std::max(worst, std::abs(h - planeHeight(geographic.x, geographic.y)));
        }
    EXPECT_LT(worst, 0.02);
    EXPECT_GT(valid, 0u);
    EXPECT_LT(valid, dgm.grid.heights.size());
    // Without a CRS to warp into, the raster is read as it is.
    EXPECT_EQ(readDgm(file).epsg, 4326);
}

// The window of dem.tif that dem_window.xyz and dem_window.asc were cut from (MANIFEST.md).
TEST(DgmSharedData, WindowInThreeFormats) {
    auto tifFile = test::sharedDataFile("dgm/dem.tif");
    auto xyzFile = test::sharedDataFile("dgm/dem_window.xyz");
    auto ascFile = test::sharedDataFile("dgm/dem_window.asc");
    if (!tifFile || !xyzFile || !ascFile) GTEST_SKIP() << "../shared/data/dgm is not there";
    Dgm xyz = readDgm(*xyzFile), asc = readDgm(*ascFile), tif = readDgm(*tifFile);
    ASSERT_EQ(tif.grid.columns, 399);
    ASSERT_EQ(tif.grid.rows, 399);
    EXPECT_EQ(tif.epsg, 25832);
    EXPECT_EQ(asc.epsg, 25832);  // from the .prj beside it
    EXPECT_EQ(xyz.epsg, 0);

    // Both are text with 3 decimals, parsed to double and rounded to float: the same bits.
    // The XYZ coordinates are rounded to millimetres, the grid's spacing is not.
    expectSameGrid(xyz.grid, asc.grid, 1e-3);
    EXPECT_NEAR(xyz.grid.spacing, 24.990165, 1e-5);

    // Raster rows 100–299 from the north are grid rows 99–298 from the south.
    HeightGrid window = asc.grid;
    for (int r = 0; r < 200; ++r)
        for (int c = 0; c < 200; ++c) window.node(c, r) = tif.grid.node(100 + c, 99 + r);
    window.west = tif.grid.nodePoint(100, 99).easting;
    window.south = tif.grid.nodePoint(100, 99).northing;
    EXPECT_NEAR(window.west, asc.grid.west, 1e-6);
    EXPECT_NEAR(tif.grid.nodePoint(299, 298).easting, asc.grid.east(), 1e-6);
    // dem.tif's pixels are 24.990165413533838 m wide but 24.990164912280097 m tall (5·10⁻⁷ m
    // less); the .asc has one cellsize, the width, and gdal_translate put its yllcorner where
    // the window's south edge is. So the two files themselves place rows up to 200 · 5·10⁻⁷ m
    // = 1·10⁻⁴ m apart, whichever single spacing a grid takes.
    EXPECT_NEAR(window.south, asc.grid.south, 1e-4);
    EXPECT_NEAR(tif.grid.nodePoint(299, 298).northing, asc.grid.north(), 1e-4);
    // The text files round dem.tif's float heights to millimetres.
    double largest = 0;
    for (size_t i = 0; i < window.heights.size(); ++i)
        largest = std::max(largest, std::abs(double(window.heights[i]) - asc.grid.heights[i]));
    EXPECT_LE(largest, 0.0005 + 6.2e-5);
    EXPECT_FLOAT_EQ(asc.grid.node(0, 199), 587.354f);  // the first line of the XYZ file
}

}  // namespace
}  // namespace veduta

// GIS layers of a city, read back with GDAL as QGIS reads them.
#include "city/city_layers.h"

#include <gtest/gtest.h>

#include <gdal_priv.h>
#include <ogr_spatialref.h>
#include <ogrsf_frmts.h>

#include "io/gdal_messages.h"
#include "test_scenes.h"

namespace veduta {
namespace {

// Two blocks side by side, the left one with two lots, and the three streets between them.
CityData twoBlocks() {
    CityData city;
    city.streetWidth = 7;
    city.points = {{0, 0, 0, 0, {}},  {1, 50, 0, 0, {}},  {2, 50, 40, 0, {}},
                   {3, 0, 40, 0, {}}, {4, 100, 0, 0, {}}, {5, 100, 40, 0, {}}};
    city.streets = {{0, 0, 1, 12.0f, {}}, {1, 1, 2, {}, {}}, {2, 1, 4, {}, {}}};
    CityBlock left, right;
    left.points = {{0, 0}, {50, 0}, {50, 40}, {0, 40}};
    left.sourceId = 4000000000u;
    left.lots.push_back({{{0, 0}, {25, 0}, {25, 20}, {0, 20}}, {true, false, false, false}, 0, {}, {}, 11});
    left.lots.push_back({{{25, 0}, {50, 0}, {50, 20}, {25, 20}}, {true, true, false, false}, 0, {}, {}, 12});
    right.points = {{50, 0}, {100, 0}, {100, 40}, {50, 40}};
    right.sourceId = 7;
    city.blocks = {left, right};
    return city;
}

GDALDatasetUniquePtr open(const std::filesystem::path &file) {
    registerGdalDrivers();
    return GDALDatasetUniquePtr(GDALDataset::Open(file.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
}

// The layer's features as the tests read them.
std::vector<OGRFeatureUniquePtr> featuresOf(OGRLayer *layer) {
    std::vector<OGRFeatureUniquePtr> features;
    layer->ResetReading();
    while (OGRFeature *f = layer->GetNextFeature()) features.emplace_back(f);
    return features;
}

void expectLayers(GDALDataset &streetsFile, GDALDataset &blocksFile, GDALDataset &lotsFile, const MapOffset &offset,
                  int epsg) {
    OGRLayer *streets = streetsFile.GetLayerByName("streets");
    OGRLayer *blocks = blocksFile.GetLayerByName("blocks");
    OGRLayer *lots = lotsFile.GetLayerByName("lots");
    ASSERT_TRUE(streets && blocks && lots);
    const OGRSpatialReference *srs = streets->GetSpatialRef();
    ASSERT_NE(srs, nullptr);
    const char *code = srs->GetAuthorityCode(nullptr);
    ASSERT_NE(code, nullptr);
    EXPECT_EQ(std::string(code), std::to_string(epsg));

    auto streetFeatures = featuresOf(streets);
    ASSERT_EQ(streetFeatures.size(), 3u);
    EXPECT_EQ(streetFeatures[0]->GetFieldAsDouble("width"), 12.0);
    EXPECT_EQ(streetFeatures[1]->GetFieldAsDouble("width"), 7.0);
    EXPECT_EQ(streetFeatures[2]->GetFieldAsInteger64("end"), 4);
    const auto *line = streetFeatures[1]->GetGeometryRef()->toLineString();
    EXPECT_DOUBLE_EQ(line->getX(0), offset.east + 50);
    EXPECT_DOUBLE_EQ(line->getY(1), offset.north + 40);

    auto blockFeatures = featuresOf(blocks);
    ASSERT_EQ(blockFeatures.size(), 2u);
    EXPECT_EQ(blockFeatures[0]->GetFieldAsInteger64("id"), 4000000000);
    EXPECT_DOUBLE_EQ(blockFeatures[1]->GetFieldAsDouble("area"), 2000);
    OGREnvelope box;
    blockFeatures[1]->GetGeometryRef()->getEnvelope(&box);
    EXPECT_DOUBLE_EQ(box.MinX, offset.east + 50);
    EXPECT_DOUBLE_EQ(box.MaxY, offset.north + 40);

    auto lotFeatures = featuresOf(lots);
    ASSERT_EQ(lotFeatures.size(), 2u);
    EXPECT_EQ(lotFeatures[1]->GetFieldAsInteger64("block"), 4000000000);
    EXPECT_EQ(lotFeatures[1]->GetFieldAsInteger("lot"), 1);
    EXPECT_EQ(lotFeatures[1]->GetFieldAsInteger64("id"), 12);
    EXPECT_EQ(std::string(lotFeatures[1]->GetFieldAsString("street_edges")), "0 1");
    EXPECT_DOUBLE_EQ(lotFeatures[0]->GetFieldAsDouble("area"), 500);
}

TEST(CityLayers, AGeoPackageHoldsStreetsBlocksAndLotsInTheirCrs) {
    test::ScratchFolder folder("layers-gpkg");
    MapOffset offset{487000, 5425000};
    writeCityLayers(twoBlocks(), {offset, 25832}, folder.path() / "town.gpkg");
    GDALDatasetUniquePtr file = open(folder.path() / "town.gpkg");
    ASSERT_TRUE(file);
    EXPECT_EQ(file->GetLayerCount(), 3);
    expectLayers(*file, *file, *file, offset, 25832);
}

TEST(CityLayers, GeoJsonIsAFileALayer) {
    test::ScratchFolder folder("layers-geojson");
    MapOffset offset{3487000, 5425000};
    std::filesystem::path target = folder.path() / "town";
    writeCityLayers(twoBlocks(), {offset, 31467}, target);
    std::vector<std::filesystem::path> files = cityLayerFiles(target);
    ASSERT_EQ(files.size(), 3u);
    GDALDatasetUniquePtr streets = open(files[0]), blocks = open(files[1]), lots = open(files[2]);
    ASSERT_TRUE(streets && blocks && lots);
    expectLayers(*streets, *blocks, *lots, offset, 31467);
    // Nothing but the three files: the temporaries are gone.
    size_t entries = 0;
    for (const auto &entry : std::filesystem::directory_iterator(target)) entries += entry.is_regular_file();
    EXPECT_EQ(entries, 3u);
}

TEST(CityLayers, AFileThatCannotBeWrittenIsAnErrorNamingIt) {
    test::ScratchFolder folder("layers-bad");
    std::filesystem::path blocked = folder.write("plain-file", "") / "town.gpkg";
    try {
        writeCityLayers(twoBlocks(), {}, blocked);
        FAIL() << "no error";
    } catch (const std::exception &e) {
        EXPECT_NE(std::string(e.what()).find("plain-file"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace veduta

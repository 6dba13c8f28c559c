// ATKIS objects through GDAL/OGR (src/geo/vector_file.*): the NAS samples in ../shared/data
// when present, and a GeoPackage and a Shapefile written here as ATKIS Shape exports look.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include <fmt/format.h>
#include <gdal_priv.h>
#include <ogrsf_frmts.h>

#include "core/error.h"
#include "geo/vector_file.h"
#include "shared_data.h"

namespace veduta {
namespace {

namespace fs = std::filesystem;

// A scratch folder removed after the test.
struct TempFolder {
    fs::path path;
    TempFolder() {
        path = fs::temp_directory_path() /
            fmt::format("veduta-vector-{}", ::testing::UnitTest::GetInstance()->random_seed());
        path += fmt::format("-{}", ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempFolder() { fs::remove_all(path); }
};

// A road, a forest with a hole and a lake of two parts, with the fields of an ATKIS Shape
// export (OBJART, here in lower case, and BRF), in EPSG:31467.
void writeAtkisLayer(const fs::path &file, const char *driverName) {
    GDALAllRegister();
    GDALDriver *driver = GetGDALDriverManager()->GetDriverByName(driverName);
    ASSERT_NE(driver, nullptr);
    GDALDatasetUniquePtr dataset(driver->Create(file.c_str(), 0, 0, 0, GDT_Unknown, nullptr));
    ASSERT_NE(dataset, nullptr);
    OGRSpatialReference srs;
    srs.importFromEPSG(31467);
    OGRLayer *layer = dataset->CreateLayer("atkis", &srs, wkbUnknown, nullptr);
    ASSERT_NE(layer, nullptr);
    OGRFieldDefn objart("objart", OFTString), brf("BRF", OFTString);
    layer->CreateField(&objart);
    layer->CreateField(&brf);
    auto add = [&](const char *wkt, const char *type, const char *width) {
        OGRFeatureUniquePtr feature(OGRFeature::CreateFeature(layer->GetLayerDefn()));
        feature->SetField("objart", type);
        if (width) feature->SetField("BRF", width);
        OGRGeometry *geometry = nullptr;
        OGRGeometryFactory::createFromWkt(wkt, &srs, &geometry);
        feature->SetGeometryDirectly(geometry);
        ASSERT_EQ(layer->CreateFeature(feature.get()), OGRERR_NONE);
    };
    add("LINESTRING (3397000 5579000, 3397100 5579000, 3397100 5579050)", "3101", "0065");
    add("POLYGON ((3397000 5579000, 3397100 5579000, 3397100 5579100, 3397000 5579100, 3397000 5579000),"
        " (3397040 5579040, 3397060 5579040, 3397060 5579060, 3397040 5579040))",
        "4107", nullptr);
    add("MULTIPOLYGON (((3398000 5579000, 3398010 5579000, 3398010 5579010, 3398000 5579000)),"
        " ((3398100 5579000, 3398110 5579000, 3398110 5579010, 3398100 5579000)))",
        "5112", nullptr);
}

void checkAtkisLayer(const AtkisData &data, const std::vector<std::string> &warnings) {
    EXPECT_EQ(data.epsg, 31467);
    ASSERT_EQ(data.objects.size(), 3u);
    const AtkisObject &road = data.objects[0], &forest = data.objects[1], &lake = data.objects[2];
    EXPECT_EQ(road.type, 3101);
    EXPECT_EQ(road.geometry, AtkisGeometry::Line);
    EXPECT_EQ(road.attributes.at("BRF"), "0065");
    EXPECT_EQ(road.attributes.count("OBJART"), 0u);
    EXPECT_EQ(ribbonWidth(road), 6.5);
    ASSERT_EQ(road.lines.size(), 1u);
    EXPECT_EQ(road.lines[0].size(), 3u);
    EXPECT_EQ(forest.type, 4107);
    EXPECT_EQ(forest.geometry, AtkisGeometry::Area);
    ASSERT_EQ(forest.areas.size(), 1u);
    EXPECT_EQ(forest.areas[0].size(), 4u);  // the closing point dropped, the hole left out
    EXPECT_EQ(forest.areas[0][2], MapPoint({3397100, 5579100}));
    EXPECT_EQ(lake.type, 5112);
    EXPECT_EQ(lake.areas.size(), 2u);
    EXPECT_EQ(std::count_if(warnings.begin(), warnings.end(),
                            [](const std::string &w) { return w.find("1 hole left out") != std::string::npos; }),
              1);
}

TEST(VectorFile, GeoPackage) {
    TempFolder folder;
    fs::path file = folder.path / "atkis.gpkg";
    writeAtkisLayer(file, "GPKG");
    std::vector<std::string> warnings;
    AtkisData data = readVectorFile(file, warnings);
    checkAtkisLayer(data, warnings);
    EXPECT_NE(data.objects[0].where.find("atkis.gpkg: layer atkis, feature"), std::string::npos);
}

TEST(VectorFile, Shapefile) {
    TempFolder folder;
    GDALAllRegister();
    // One Shapefile holds one geometry kind: lines here, with OBJART upper-case as exports write it.
    fs::path file = folder.path / "strassen.shp";
    GDALDriver *driver = GetGDALDriverManager()->GetDriverByName("ESRI Shapefile");
    ASSERT_NE(driver, nullptr);
    {
        GDALDatasetUniquePtr dataset(driver->Create(file.c_str(), 0, 0, 0, GDT_Unknown, nullptr));
        OGRSpatialReference srs;
        srs.importFromEPSG(31467);
        OGRLayer *layer = dataset->CreateLayer("strassen", &srs, wkbLineString, nullptr);
        OGRFieldDefn objart("OBJART", OFTString), brf("BRF", OFTString), brv("brv", OFTString);
        layer->CreateField(&objart);
        layer->CreateField(&brf);
        layer->CreateField(&brv);
        OGRFeatureUniquePtr feature(OGRFeature::CreateFeature(layer->GetLayerDefn()));
        feature->SetField("OBJART", "3102");
        feature->SetField("brv", "0030");
        OGRGeometry *geometry = nullptr;
        OGRGeometryFactory::createFromWkt("LINESTRING (3397000 5579000, 3397100 5579000)", &srs, &geometry);
        feature->SetGeometryDirectly(geometry);
        ASSERT_EQ(layer->CreateFeature(feature.get()), OGRERR_NONE);
    }
    std::vector<std::string> warnings;
    AtkisData data = readVectorFile(file, warnings);
    EXPECT_EQ(data.epsg, 31467);
    ASSERT_EQ(data.objects.size(), 1u);
    EXPECT_EQ(data.objects[0].type, 3102);
    EXPECT_EQ(data.objects[0].attributes.count("BRF"), 0u);  // not set: left out
    EXPECT_EQ(data.objects[0].attributes.at("BRV"), "0030");
    EXPECT_EQ(ribbonWidth(data.objects[0]), 3.0);
}

TEST(VectorFile, NasReplace) {
    auto nas = test::sharedDataFile("nas/replace_nas.xml");
    if (!nas) GTEST_SKIP() << "../shared/data is not here";
    fs::path folder = nas->parent_path();
    auto before = std::distance(fs::directory_iterator(folder), fs::directory_iterator());
    std::vector<std::string> warnings;
    AtkisData data = readVectorFile(*nas, warnings);
    // Nothing written beside the input (GDAL's NAS reader saves a .gfs schema otherwise).
    EXPECT_EQ(std::distance(fs::directory_iterator(folder), fs::directory_iterator()), before);
    EXPECT_EQ(data.epsg, 25832);
    ASSERT_EQ(data.objects.size(), 1u);
    const AtkisObject &parcel = data.objects[0];
    EXPECT_EQ(parcel.type, 0);
    EXPECT_EQ(parcel.typeName, "AX_Flurstueck");
    EXPECT_EQ(parcel.id, "DENW44AL00003IkM20110429T070635Z");
    EXPECT_EQ(parcel.geometry, AtkisGeometry::Area);
    ASSERT_EQ(parcel.areas.size(), 1u);
    double minE = 1e9, minN = 1e9, maxE = 0, maxN = 0;
    for (const MapPoint &p : parcel.areas[0]) {
        minE = std::min(minE, p.easting), maxE = std::max(maxE, p.easting);
        minN = std::min(minN, p.northing), maxN = std::max(maxN, p.northing);
    }
    EXPECT_EQ(minE, 405587.077);
    EXPECT_EQ(minN, 5645088.037);
    EXPECT_EQ(maxE, 405624.623);
    EXPECT_EQ(maxN, 5645148.000);
    EXPECT_NE(parcel.areas[0].front(), parcel.areas[0].back());
}

TEST(VectorFile, NasWithoutFeatures) {
    auto nas = test::sharedDataFile("nas/empty_nas.xml");
    if (!nas) GTEST_SKIP() << "../shared/data is not here";
    std::vector<std::string> warnings;
    AtkisData data = readVectorFile(*nas, warnings);
    EXPECT_TRUE(data.objects.empty());
}

TEST(VectorFile, NasClassesAndCrsNames) {
    EXPECT_EQ(nasClassType("AX_Wald"), 4107);
    EXPECT_EQ(nasClassType("AX_Gehoelz"), 4108);
    EXPECT_EQ(nasClassType("AX_Strassenachse"), 3101);
    EXPECT_EQ(nasClassType("AX_Wegachse"), 3102);
    EXPECT_EQ(nasClassType("AX_Bahnstrecke"), 3201);
    EXPECT_EQ(nasClassType("AX_StehendesGewaesser"), 5112);
    EXPECT_EQ(nasClassType("AX_Ortslage"), 2101);
    EXPECT_EQ(nasClassType("AX_Flurstueck"), 0);
    EXPECT_EQ(advCrsEpsg("urn:adv:crs:ETRS89_UTM32"), 25832);
    EXPECT_EQ(advCrsEpsg("urn:adv:crs:ETRS89_UTM32*DE_DHHN2016_NH"), 25832);
    EXPECT_EQ(advCrsEpsg("urn:adv:crs:DE_DHDN_3GK3_NW101"), 31467);
    EXPECT_EQ(advCrsEpsg("urn:adv:crs:ETRS89_UTM320"), 0);
    EXPECT_EQ(advCrsEpsg("EPSG:4326"), 0);
}

// One file, one CRS: a GeoPackage whose second layer is in UTM 32 after a Gauss-Krüger one.
TEST(VectorFile, LayersInTwoCrssAreAnError) {
    TempFolder folder;
    fs::path file = folder.path / "mixed.gpkg";
    writeAtkisLayer(file, "GPKG");
    {
        GDALDatasetUniquePtr dataset(GDALDataset::Open(file.c_str(), GDAL_OF_VECTOR | GDAL_OF_UPDATE));
        ASSERT_NE(dataset, nullptr);
        OGRSpatialReference utm;
        utm.importFromEPSG(25832);
        OGRLayer *layer = dataset->CreateLayer("utm", &utm, wkbPoint, nullptr);
        ASSERT_NE(layer, nullptr);
        OGRFeatureUniquePtr feature(OGRFeature::CreateFeature(layer->GetLayerDefn()));
        feature->SetGeometryDirectly(new OGRPoint(500000, 5600000));
        ASSERT_EQ(layer->CreateFeature(feature.get()), OGRERR_NONE);
    }
    std::vector<std::string> warnings;
    try {
        readVectorFile(file, warnings);
        FAIL() << "no error";
    } catch (const InputError &e) {
        EXPECT_NE(std::string(e.what()).find("layer utm is in EPSG:25832, an earlier layer in EPSG:31467"),
                  std::string::npos)
            << e.what();
    }
}

TEST(VectorFile, UnreadableFile) {
    TempFolder folder;
    std::vector<std::string> warnings;
    EXPECT_THROW(readVectorFile(folder.path / "missing.gpkg", warnings), InputError);
    fs::path junk = folder.path / "junk.gpkg";
    std::FILE *f = std::fopen(junk.c_str(), "w");
    std::fputs("not a geopackage", f);
    std::fclose(f);
    EXPECT_THROW(readVectorFile(junk, warnings), InputError);
}

// Today's Basis-DLM Shape delivery: 5-digit AAA codes in OBJART, the class name in
// OBJART_TXT, Grünland as AX_Landwirtschaft with VEG 1020.
TEST(VectorFile, AaaCodesAndClassNamesAreMapped) {
    TempFolder folder;
    fs::path file = folder.path / "dlm.shp";
    GDALAllRegister();
    GDALDatasetUniquePtr dataset(
        GetGDALDriverManager()->GetDriverByName("ESRI Shapefile")->Create(file.c_str(), 0, 0, 0, GDT_Unknown, nullptr));
    ASSERT_NE(dataset, nullptr);
    OGRSpatialReference srs;
    srs.importFromEPSG(25832);
    OGRLayer *layer = dataset->CreateLayer("dlm", &srs, wkbPolygon, nullptr);
    for (const char *name : {"OBJART", "OBJART_TXT", "VEG"}) {
        OGRFieldDefn field(name, OFTString);
        layer->CreateField(&field);
    }
    auto add = [&](const char *code, const char *text, const char *vegetation) {
        OGRFeatureUniquePtr feature(OGRFeature::CreateFeature(layer->GetLayerDefn()));
        feature->SetField("OBJART", code);
        feature->SetField("OBJART_TXT", text);
        if (vegetation) feature->SetField("VEG", vegetation);
        OGRGeometry *geometry = nullptr;
        OGRGeometryFactory::createFromWkt("POLYGON ((400000 5500000, 400100 5500000, 400100 5500100, 400000 5500000))",
                                          &srs, &geometry);
        feature->SetGeometryDirectly(geometry);
        ASSERT_EQ(layer->CreateFeature(feature.get()), OGRERR_NONE);
    };
    add("43002", "AX_Wald", nullptr);
    add("43001", "AX_Landwirtschaft", "1010");
    add("43001", "AX_Landwirtschaft", "1020");
    add("41009", "AX_Friedhof", nullptr);
    add("", "AX_Gehoelz", nullptr);
    dataset.reset();
    std::vector<std::string> warnings;
    AtkisData data = readVectorFile(file, warnings);
    ASSERT_EQ(data.objects.size(), 5u);
    EXPECT_EQ(data.objects[0].type, 4107);
    EXPECT_EQ(data.objects[0].typeName, "AX_Wald");
    EXPECT_EQ(landClass(data.objects[0]), LandClass::Forest);
    EXPECT_EQ(data.objects[1].type, 4101);
    EXPECT_EQ(data.objects[2].type, 4102);
    EXPECT_EQ(data.objects[3].type, 41009) << "a class without an ATKIS-OK successor keeps its code";
    EXPECT_EQ(landClass(data.objects[3]), LandClass::Other);
    EXPECT_EQ(data.objects[4].type, 4108) << "the name alone is enough";
    EXPECT_TRUE(warnings.empty()) << warnings.front();
}

// CityGML reads through GDAL's GML driver as features without an Objektart: it is refused
// with what it is instead of giving an empty layer.
TEST(VectorFile, CityGmlIsNoAtkisLayer) {
    TempFolder folder;
    fs::path file = folder.path / "tile.gml";
    std::FILE *f = std::fopen(file.c_str(), "w");
    std::fputs(R"(<?xml version="1.0" encoding="UTF-8"?>
<core:CityModel xmlns:core="http://www.opengis.net/citygml/2.0" xmlns:bldg="http://www.opengis.net/citygml/building/2.0"
    xmlns:gml="http://www.opengis.net/gml">
  <core:cityObjectMember><bldg:Building gml:id="b1"><bldg:measuredHeight uom="m">10</bldg:measuredHeight>
  </bldg:Building></core:cityObjectMember>
</core:CityModel>
)",
               f);
    std::fclose(f);
    std::vector<std::string> warnings;
    try {
        readVectorFile(file, warnings);
        FAIL() << "CityGML was read as an ATKIS layer";
    } catch (const InputError &e) {
        EXPECT_EQ(std::string(e.what()),
                  file.string() +
                      ": is CityGML (3D city models), not an ATKIS file: a scene reads it with "
                      "<citygml file=\"…\"/> (docs/citygml.md); an ATKIS layer is NAS, EDBS, a "
                      "Shapefile or a GeoPackage of the Basis-DLM");
    }
}

}  // namespace
}  // namespace veduta

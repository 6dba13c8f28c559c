// Nothing that could make GDAL run away reaches it: XML with a document type declaration (the
// "billion laughs" of GDAL's own NAS tests, built here), directories and devices. Every reader
// that hands files to GDAL refuses them with the file's name. A read that GDAL does not finish
// in time ends the program with a message naming the file.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <thread>

#include "city/osm_import.h"
#include "geo/raster_grid.h"
#include "geo/vector_file.h"
#include "input_error.h"
#include "io/gdal_guard.h"
#include "test_scenes.h"

namespace veduta {
namespace {

// Ten levels of ten references: expanded, 10^9 copies of "lol".
std::string billionLaughs(const std::string &root) {
    std::string text = "<?xml version=\"1.0\"?>\n<!DOCTYPE lolz [\n  <!ENTITY lol \"lol\">\n";
    for (int level = 1; level <= 9; ++level) {
        text += "  <!ENTITY lol" + std::to_string(level) + " \"";
        std::string previous = level == 1 ? "lol" : "lol" + std::to_string(level - 1);
        for (int k = 0; k < 10; ++k) text += "&" + previous + ";";
        text += "\">\n";
    }
    return text + "]>\n<" + root + ">&lol9;</" + root + ">\n";
}

const std::string kDoctype = ":2:1: the XML file has a document type declaration (<!DOCTYPE>)";

class GdalGuard : public testing::Test {
  protected:
    test::ScratchFolder folder_{"gdal_guard"};
};

TEST_F(GdalGuard, EveryReaderRefusesADocumentTypeDeclaration) {
    std::string nas = folder_.write("laughs.xml", billionLaughs("AX_Bestandsdatenauszug")).string();
    std::string osm = folder_.write("laughs.osm", billionLaughs("osm")).string();
    std::string vrt = folder_.write("laughs.vrt", billionLaughs("VRTDataset")).string();
    std::vector<std::string> warnings;
    EXPECT_EQ(test::inputErrorOf([&] { readVectorFile(nas, warnings); }).rfind(nas + kDoctype, 0), 0u);
    EXPECT_EQ(test::inputErrorOf([&] { importOsm(osm, {}); }).rfind(osm + kDoctype, 0), 0u);
    EXPECT_EQ(test::inputErrorOf([&] { readRasterGrid(vrt); }).rfind(vrt + kDoctype, 0), 0u);
}

TEST_F(GdalGuard, TheDeclarationIsFoundBehindCommentsAndABom) {
    std::string file = folder_
                           .write("late.xml",
                                  "\xEF\xBB\xBF<?xml version=\"1.0\"?>\n<!-- a\ncomment -->\n  <!DOCTYPE x>\n"
                                  "<x/>\n")
                           .string();
    EXPECT_EQ(test::inputErrorOf([&] { checkFileForGdal(file); }).rfind(file + ":4:3: the XML file has", 0), 0u);
    std::string open = folder_.write("open.xml", "<?xml version=\"1.0\"?>\n<!-- never closed\n").string();
    EXPECT_EQ(test::inputErrorOf([&] { checkFileForGdal(open); }),
              open +
                  ":2:1: a comment or processing instruction before the XML root element does not end (within "
                  "the first MiB); veduta does not give such a file to GDAL");
}

TEST_F(GdalGuard, PlainXmlAndOtherFilesPass) {
    EXPECT_EQ(test::inputErrorOf([&] {
                  checkFileForGdal(folder_.write("plain.xml", "<?xml version=\"1.0\"?>\n<!-- c -->\n<osm/>\n"));
              }),
              "no error");
    EXPECT_EQ(test::inputErrorOf([&] { checkFileForGdal(folder_.write("a.geojson", "{\"type\": 1}")); }), "no error");
    EXPECT_EQ(test::inputErrorOf([&] { checkFileForGdal(folder_.write("empty.xml", "")); }), "no error");
}

TEST_F(GdalGuard, DirectoriesDevicesAndMissingFilesAreRefused) {
    const std::string notAFile = ": is not a regular file (a directory or a device); veduta reads only files";
    EXPECT_EQ(test::inputErrorOf([&] { checkFileForGdal(folder_.path()); }), folder_.path().string() + notAFile);
    EXPECT_EQ(test::inputErrorOf([&] { checkFileForGdal("/dev/zero"); }), "/dev/zero" + notAFile);
    std::vector<std::string> warnings;
    EXPECT_EQ(test::inputErrorOf([&] { readVectorFile("/dev/zero", warnings); }), "/dev/zero" + notAFile);
    EXPECT_EQ(test::inputErrorOf([&] { checkFileForGdal(folder_.path() / "missing.tif"); }),
              (folder_.path() / "missing.tif").string() + ": cannot open file");
}

TEST(GdalDeadline, AReadPastTheLimitEndsTheProgramNamingTheFile) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    using namespace std::chrono_literals;
    EXPECT_EXIT(
        {
            GdalDeadline deadline("slow.xml", 50ms);
            std::this_thread::sleep_for(10s);
        },
        testing::ExitedWithCode(1), "veduta: slow.xml: GDAL has read this file for 0.05 s without finishing");
}

TEST(GdalDeadline, AReadWithinTheLimitGoesOnAtOnce) {
    auto start = std::chrono::steady_clock::now();
    { GdalDeadline deadline("quick.xml", std::chrono::seconds(60)); }
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
}

TEST(GdalDeadline, TheLimitComesFromTheEnvironment) {
    using std::chrono::milliseconds;
    unsetenv("VEDUTA_GDAL_TIME_LIMIT");
    EXPECT_EQ(gdalTimeLimit(), milliseconds(300'000));
    setenv("VEDUTA_GDAL_TIME_LIMIT", "2.5", 1);
    EXPECT_EQ(gdalTimeLimit(), milliseconds(2500));
    for (const char *bad : {"", "ten", "-1", "0", "5s", "nan"}) {
        setenv("VEDUTA_GDAL_TIME_LIMIT", bad, 1);
        EXPECT_THROW(gdalTimeLimit(), std::invalid_argument) << bad;
    }
    unsetenv("VEDUTA_GDAL_TIME_LIMIT");
}

}  // namespace
}  // namespace veduta

// Inputs are read only from regular files, and only up to their limit: a device or a folder
// named as a scene, rule, material, CityData, EDBS or XYZ file is refused at once.
#include <gtest/gtest.h>

#include <string>

#include "city/city_data.h"
#include "core/input_file.h"
#include "description/material_file.h"
#include "description/scene_description.h"
#include "geo/dgm_file.h"
#include "geo/edbs.h"
#include "input_error.h"
#include "test_scenes.h"

namespace veduta {
namespace {

const std::string kNotAFile = ": is not a regular file (a directory or a device); veduta reads only files";

TEST(InputFile, DevicesAndFoldersAreRefusedByEveryReader) {
    EXPECT_EQ(test::inputErrorOf([] { readSceneFile("/dev/zero"); }), "/dev/zero" + kNotAFile);
    EXPECT_EQ(test::inputErrorOf([] { readMaterialFile("/dev/zero"); }), "/dev/zero" + kNotAFile);
    EXPECT_EQ(test::inputErrorOf([] { readCityData("/dev/zero"); }), "/dev/zero" + kNotAFile);
    EXPECT_EQ(test::inputErrorOf([] { readEdbs("/dev/zero"); }), "/dev/zero" + kNotAFile);
    EXPECT_EQ(test::inputErrorOf([] { readDgm("/dev/zero"); }), "/dev/zero" + kNotAFile);
    test::ScratchFolder folder("input_file");
    EXPECT_EQ(test::inputErrorOf([&] { readSceneFile(folder.path()); }), folder.path().string() + kNotAFile);
    EXPECT_EQ(test::inputErrorOf([&] { readSceneFile(folder.path() / "none.xml"); }),
              (folder.path() / "none.xml").string() + ": cannot open file");
}

TEST(InputFile, TheSizeIsCheckedBeforeReading) {
    test::ScratchFolder folder("input_file_size");
    std::filesystem::path file = folder.write("big.xml", std::string(3000, 'x'));
    EXPECT_EQ(test::inputErrorOf([&] { readInputFile(file, 2048); }),
              file.string() + ": is 3000 bytes; veduta reads files of this kind up to 2048 bytes");
    EXPECT_EQ(readInputFile(file, 4096).size(), 3000u);
}

}  // namespace
}  // namespace veduta

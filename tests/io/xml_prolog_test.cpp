// The root element's name past the prolog: what `veduta compare` tells CityGML from scenes by.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "io/xml_prolog.h"

namespace veduta {
namespace {

std::filesystem::path written(const std::string &name, const std::string &text) {
    std::filesystem::path file = std::filesystem::temp_directory_path() / ("veduta-xml-prolog-" + name);
    std::ofstream(file, std::ios::binary) << text;
    return file;
}

TEST(XmlProlog, RootElementNamePastCommentsAndInstructions) {
    EXPECT_EQ(rootElementName(written("a.gml",
                                      "\xEF\xBB\xBF<?xml version=\"1.0\"?>\n<!-- a <b> c -->\n"
                                      "<core:CityModel xmlns:core=\"x\">")),
              "core:CityModel");
    EXPECT_EQ(rootElementName(written("b.xml", "<scene version=\"1\"/>")), "scene");
    EXPECT_EQ(rootElementName(written("c.xml", "<CityModel>")), "CityModel");
}

TEST(XmlProlog, NoRootElementName) {
    EXPECT_EQ(rootElementName(written("d.txt", "not xml")), "");
    EXPECT_EQ(rootElementName(written("e.xml", "<?xml version=\"1.0\"?><!DOCTYPE x><x/>")), "");
    EXPECT_THROW(rootElementName(written("f.xml", "<!-- never closed")), InputError);
}

}  // namespace
}  // namespace veduta

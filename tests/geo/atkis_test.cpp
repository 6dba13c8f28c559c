// The ATKIS code table and what a renderer makes of an object (src/geo/atkis.*).
#include <gtest/gtest.h>

#include "geo/atkis.h"

namespace veduta {
namespace {

AtkisObject object(int type, std::map<std::string, std::string> attributes = {}) {
    AtkisObject o;
    o.type = type;
    o.attributes = std::move(attributes);
    return o;
}

TEST(Atkis, TypeNames) {
    EXPECT_EQ(atkisTypeName(3101), "Straße");
    EXPECT_EQ(atkisTypeName(3102), "Weg");
    EXPECT_EQ(atkisTypeName(4107), "Wald, Forst");
    EXPECT_EQ(atkisTypeName(2000), "Siedlung");
    EXPECT_EQ(atkisTypeName(3204), "Bahnstrecke");
    EXPECT_EQ(atkisTypeName(5112), "Binnensee, Stausee, Teich");
    EXPECT_EQ(atkisTypeName(1234), "");
    EXPECT_EQ(atkisTypeName(0), "");
}

TEST(Atkis, LandClasses) {
    EXPECT_EQ(landClass(object(3101)), LandClass::Road);
    EXPECT_EQ(landClass(object(3102)), LandClass::Path);
    for (int rail : {3201, 3203, 3204}) EXPECT_EQ(landClass(object(rail)), LandClass::Rail);
    for (int s : {2101, 2111, 2112, 2113, 2114}) EXPECT_EQ(landClass(object(s)), LandClass::Settlement);
    EXPECT_EQ(landClass(object(2227)), LandClass::Park);
    EXPECT_EQ(landClass(object(4101)), LandClass::Farmland);
    for (int g : {4102, 4104, 4105, 4106}) EXPECT_EQ(landClass(object(g)), LandClass::Grassland);
    EXPECT_EQ(landClass(object(4107)), LandClass::Forest);
    EXPECT_EQ(landClass(object(4108)), LandClass::Shrubs);
    EXPECT_EQ(landClass(object(5101)), LandClass::River);
    EXPECT_EQ(landClass(object(5112)), LandClass::Water);
    EXPECT_EQ(landClass(object(4202)), LandClass::TreeRow);
    EXPECT_EQ(landClass(object(4203)), LandClass::Hedge);
    EXPECT_EQ(landClass(object(3202)), LandClass::Other);
    EXPECT_EQ(landClass(object(0)), LandClass::Other);
    EXPECT_EQ(landClassName(LandClass::Forest), "forest");
    EXPECT_EQ(landClassName(LandClass::TreeRow), "tree_row");
}

// ALK Objektarten overlap ATKIS ones (ALK 5101 is no river): the Folie classes ALK objects.
TEST(Atkis, AlkObjectsAreClassedByTheirFolie) {
    auto alk = [](const std::string &folie, const std::string &type) {
        AtkisObject o;
        o.typeName = "ALK " + type;
        o.attributes = {{"OBJART", type}, {"FOLIE", folie}};
        return o;
    };
    EXPECT_EQ(landClass(alk("011", "1003")), LandClass::Building);
    EXPECT_EQ(landClass(alk("001", "0233")), LandClass::Parcel);
    EXPECT_EQ(landClass(alk("041", "5101")), LandClass::Other);
    EXPECT_EQ(landClassName(LandClass::Building), "building");
    EXPECT_EQ(landClassName(LandClass::Parcel), "parcel");
}

TEST(Atkis, TreeKinds) {
    EXPECT_EQ(treeKind(object(4107, {{"VEG", "1000"}})), TreeKind::Broadleaf);
    EXPECT_EQ(treeKind(object(4107, {{"VEG", "2000"}})), TreeKind::Conifer);
    EXPECT_EQ(treeKind(object(4107, {{"VEG", "3000"}})), TreeKind::Mixed);
    EXPECT_EQ(treeKind(object(4107)), TreeKind::Mixed);
    EXPECT_EQ(treeKind(object(4107, {{"VEGETATIONSMERKMAL", "1200"}})), TreeKind::Conifer);
    EXPECT_EQ(treeKind(object(4107, {{"VEG", "nonsense"}})), TreeKind::Mixed);
}

TEST(Atkis, RibbonWidths) {
    EXPECT_EQ(ribbonWidth(object(3101, {{"BRF", "0065"}})), 6.5);
    EXPECT_EQ(ribbonWidth(object(3101, {{"BRF", "0000"}, {"BRV", "0120"}})), 12.0);
    EXPECT_EQ(ribbonWidth(object(3101, {{"BRF", "abc"}})), 5.5);
    EXPECT_EQ(ribbonWidth(object(3101)), 5.5);
    EXPECT_EQ(ribbonWidth(object(3102)), 2.5);
    EXPECT_EQ(ribbonWidth(object(3201)), 4.5);
    EXPECT_EQ(ribbonWidth(object(3201, {{"GLS", "2000"}})), 9.0);
    EXPECT_EQ(ribbonWidth(object(3201, {{"GLS", "2"}})), 9.0);
    EXPECT_EQ(ribbonWidth(object(3101, {{"BREITEDERFAHRBAHN", "7.25"}})), 7.25);
    EXPECT_EQ(ribbonWidth(object(4107)), 0.0);
}

}  // namespace
}  // namespace veduta

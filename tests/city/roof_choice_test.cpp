#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include "city/roof_choice.h"
#include "city/roofs.h"
#include "core/error.h"
#include "input_error.h"

namespace veduta {
namespace {

const FileLoc kAt{"city.xml", 12, 5};

// A 16 m × 12 m house with its street along the first edge.
Footprint house() { return {{{0, 0}, {16, 0}, {16, 12}, {0, 12}}, {true, false, false, false}, 0}; }

RoofOptions optionsWith(const SettingsMap &settings, uint32_t buildingId = 1, float roofHeight = 4,
                        const Footprint &footprint = house()) {
    BuildingHeights heights{15, 3, roofHeight};
    return roofOptionsFor(footprint, SettingsStack({&settings}), heights, 7, buildingId);
}

std::string errorWith(const SettingsMap &settings) {
    return test::inputErrorOf([&] { optionsWith(settings); });
}

TEST(RoofChoice, WithoutRoofTypeSeed000sChoiceStands) {
    RoofOptions gable = optionsWith({});
    EXPECT_EQ(gable.type, RoofType::Gable);
    EXPECT_EQ(gable.gableEdge, -1);  // gables on both ends of the ridge
    // RoofHeight 4 over half the 12 m depth.
    EXPECT_NEAR(std::tan(radians(gable.pitchDegrees)) * 6, 4, 1e-4);
    Footprint corner{{{0, 0}, {16, 0}, {16, 12}, {0, 12}}, {true, true, false, false}, 0};
    RoofOptions mansard = optionsWith({}, 1, 4, corner);
    EXPECT_EQ(mansard.type, RoofType::Mansard);
    EXPECT_NEAR(std::tan(radians(mansard.pitchDegrees)) * kMansardInset, 4, 1e-4);
    EXPECT_EQ(optionsWith({}, 1, 0).type, RoofType::Flat);
    EXPECT_EQ(optionsWith({}, 1, 0).parapetHeight, kDefaultParapetHeight);
}

TEST(RoofChoice, SettingsNameTypePitchOverhangAndParapet) {
    SettingsMap settings{{"RoofType", settingValue("Hip", kAt)},
                         {"RoofPitch", settingValue("35", kAt)},
                         {"RoofOverhang", settingValue("0.4", kAt)},
                         {"ParapetHeight", settingValue("1.1", kAt)}};
    RoofOptions options = optionsWith(settings);
    EXPECT_EQ(options.type, RoofType::Hip);
    EXPECT_EQ(options.pitchDegrees, 35);
    EXPECT_FLOAT_EQ(options.overhang, 0.4f);
    EXPECT_FLOAT_EQ(options.parapetHeight, 1.1f);
}

TEST(RoofChoice, AListIsDrawnFromPerBuilding) {
    SettingsMap settings{{"RoofType", settingValue("gable, hip mansard", kAt)}};
    std::map<RoofType, int> counts;
    for (uint32_t id = 0; id < 300; ++id) {
        RoofType type = optionsWith(settings, id).type;
        EXPECT_EQ(type, optionsWith(settings, id).type);  // a pure function of seed and id
        ++counts[type];
    }
    ASSERT_EQ(counts.size(), 3u);
    for (auto [type, count] : counts) EXPECT_GT(count, 60) << roofTypeName(type);
}

TEST(RoofChoice, BadSettingsAreErrorsAtTheSetting) {
    EXPECT_NE(errorWith({{"RoofType", settingValue("onion", kAt)}}).find("city.xml:12:5: RoofType 'onion' is none of"),
              std::string::npos);
    EXPECT_NE(errorWith({{"RoofType", settingValue(" , ", kAt)}}).find("city.xml:12:5: RoofType names no roof type"),
              std::string::npos);
    EXPECT_NE(errorWith({{"RoofPitch", settingValue("90", kAt)}}).find("city.xml:12:5: RoofPitch must be between"),
              std::string::npos);
    EXPECT_NE(
        errorWith({{"RoofOverhang", settingValue("-1", kAt)}}).find("city.xml:12:5: RoofOverhang must be zero or more"),
        std::string::npos);
    EXPECT_NE(errorWith({{"ParapetHeight", settingValue("high", kAt)}})
                  .find("city.xml:12:5: setting ParapetHeight must be a number"),
              std::string::npos);
}

}  // namespace
}  // namespace veduta

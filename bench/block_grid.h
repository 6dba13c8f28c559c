// A grid of Gründerzeit blocks made in memory, as the issues measure districts and cities: a
// street grid of `columns` × `rows` cells of 125 × 100 m (street centre to centre), 10 m
// streets, one block in each cell, the blocks taking turns at the roof lists, built with
// rules/gruenderzeit. 8 × 10 cells are one square kilometre (bench_district), 16 × 20 four and
// 32 × 40 sixteen (bench_city_scale).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "city/city_data.h"
#include "description/material_file.h"
#include "scene/material.h"

namespace veduta {

inline constexpr float kGridBlockWidth = 125, kGridBlockDepth = 100;

inline CityData gruenderzeitGrid(int columns, int rows) {
    auto value = [](const std::string &text) { return settingValue(text, {}); };
    CityData city;
    for (int row = 0; row <= rows; ++row) {
        for (int column = 0; column <= columns; ++column) {
            uint32_t id = uint32_t(city.points.size());
            city.points.push_back({id, column * kGridBlockWidth, row * kGridBlockDepth, 0, {}});
        }
    }
    auto point = [&](int column, int row) { return uint32_t(row * (columns + 1) + column); };
    for (int row = 0; row <= rows; ++row) {
        for (int column = 0; column <= columns; ++column) {
            uint32_t id = uint32_t(city.streets.size());
            if (column < columns) city.streets.push_back({id, point(column, row), point(column + 1, row), {}, {}});
            if (row < rows) city.streets.push_back({id + 1, point(column, row), point(column, row + 1), {}, {}});
        }
    }
    city.streetWidth = 10;
    const char *roofs[] = {"gable mansard", "mansard", "hip", "gable hip"};
    for (int row = 0; row < rows; ++row) {
        for (int column = 0; column < columns; ++column) {
            CityBlock block;
            for (auto [c, r] : {std::pair{column, row}, {column + 1, row}, {column + 1, row + 1}, {column, row + 1}}) {
                const CityPoint &p = city.points[point(c, r)];
                block.points.push_back({float(p.e), float(p.n)});
            }
            block.settings["RoofType"] = value(roofs[(row * columns + column) % 4]);
            city.blocks.push_back(std::move(block));
        }
    }
    for (auto [name, text] : {std::pair{"BuildingHeight", "17"},
                              {"BuildingHeightVar", "1.5"},
                              {"FloorHeight", "3.6"},
                              {"RoofHeight", "4.5"},
                              {"MinBuildingLength", "12"},
                              {"MaxBuildingLength", "22"},
                              {"MinBuildingDepth", "13"}}) {
        city.settings[name] = value(text);
    }
    city.ruleFiles = {std::string(VEDUTA_SOURCE_DIR) + "/rules/gruenderzeit/FacadeStructure.xml"};
    return city;
}

// rules/gruenderzeit's materials as a scene would hold them: their normal maps read as none, but
// marked, so that the scene build makes tangents as it would for the real scene.
inline std::vector<Material> gruenderzeitMaterials() {
    std::vector<Material> result;
    for (const MaterialDesc &desc :
         readMaterialFile(std::string(VEDUTA_SOURCE_DIR) + "/rules/gruenderzeit/materials.xml")) {
        Material m = desc.material;
        if (desc.normalMap.given()) m.normalMap = 0;
        result.push_back(m);
    }
    return result;
}

}  // namespace veduta

// The files that come with veduta (rules/gruenderzeit/, rules/streets/), found beside the
// program: upwards from its folder to the source tree it was built in.
#pragma once

#include <filesystem>
#include <string>

namespace veduta {

// `relative` (such as rules/streets/grid.txt) in the nearest folder above the program's that
// holds it. Throws InputError at `option` when none does.
std::filesystem::path shippedFile(const std::filesystem::path &relative, const std::string &option);

// The Gründerzeit rules, rules/gruenderzeit/FacadeStructure.xml.
std::filesystem::path shippedBuildingRules(const std::string &option);

}  // namespace veduta

// The files that come with veduta (rules/gruenderzeit/, rules/streets/, rules/slg/), found where
// ProgramPart::Data says: installed in ../share/veduta, or upwards from the program's folder to
// the source tree it was built in.
#pragma once

#include <filesystem>
#include <string>

namespace veduta {

// `relative` (such as rules/streets/grid.txt) in the first of the data folders that holds it.
// Throws InputError at `option`, naming every folder looked in, when none does.
std::filesystem::path shippedFile(const std::filesystem::path &relative, const std::string &option);

// The Gründerzeit rules, rules/gruenderzeit/FacadeStructure.xml.
std::filesystem::path shippedBuildingRules(const std::string &option);

// The tables of Schrader's urban geography, rules/slg/urban-geography.xml, for
// readUrbanGeography (slg/urban_geography_file.h).
std::filesystem::path shippedUrbanGeography(const std::string &option);

}  // namespace veduta

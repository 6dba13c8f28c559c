// Reading the tables of Schrader's urban geography (rules/slg/urban-geography.xml) into an
// UrbanGeography. docs/urban-geography.md documents the format and every check; each bad value
// is an InputError "file:line:col: what is wrong".
#pragma once

#include <filesystem>
#include <string>

#include "slg/urban_geography.h"

namespace veduta {

// What a file may ask for, so that a hostile file is refused with a message, not a plan that
// never ends.
inline constexpr int kMaxStoreys = 200;  // base + extra of eq 59–61
inline constexpr int kMaxLandmarks = 10000;
inline constexpr int kMaxReflexCorners = 100;

UrbanGeography readUrbanGeography(const std::filesystem::path &file);
// The same for text in memory; `name` is what messages call it.
UrbanGeography parseUrbanGeography(std::string text, std::string name);

}  // namespace veduta

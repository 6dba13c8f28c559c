// Reading materials: the <material> element, which scene files and material files
// (materials/*.xml, root <materials>) share. docs/materials.md documents both.
#pragma once

#include <filesystem>
#include <vector>

#include "description/scene_description.h"
#include "io/xml_reader.h"

namespace veduta {

// One <material> element; map files resolve against `baseDirectory`.
MaterialDesc readMaterialElement(const XmlElement &e, const std::filesystem::path &baseDirectory);
// A material file: <materials version="1"> holding <material> elements.
std::vector<MaterialDesc> readMaterialFile(const std::filesystem::path &file);

}  // namespace veduta

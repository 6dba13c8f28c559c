// Reading triangle meshes from files others wrote (OBJ, PLY, and what else Assimp reads).
#pragma once

#include <filesystem>

#include "scene/mesh.h"

namespace veduta {

// Loads every mesh of the file into one, triangulated, with the file's own transforms applied.
// Materials in the file are ignored: the scene assigns them. Throws InputError naming the
// file when it cannot be read or holds no triangles.
Mesh importMesh(const std::filesystem::path &file);

}  // namespace veduta

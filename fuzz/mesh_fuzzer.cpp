// Mesh import (docs/meshes.md) of one format, the file name's extension VEDUTA_MESH_EXTENSION
// (".obj", ".ply", ".gltf"), set by fuzz/CMakeLists.txt: one target per format, so that
// each keeps a corpus of its own.
#include <cmath>
#include <cstdlib>

#include "fuzz_input.h"
#include "io/mesh_import.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    using namespace veduta;
    auto file = fuzz::inputFile(data, size, VEDUTA_MESH_EXTENSION);
    fuzz::expectInputError([&] {
        Mesh mesh = importMesh(file);
        for (const Vec3f &p : mesh.positions) {
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) std::abort();
        }
        for (uint32_t index : mesh.indices) {
            if (index >= mesh.positions.size()) std::abort();
        }
    });
    return 0;
}

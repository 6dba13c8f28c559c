// The material file reader (docs/materials.md) on any file.
#include "description/material_file.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    using namespace veduta;
    auto file = fuzz::inputFile(data, size, ".xml");
    fuzz::expectInputError([&] { readMaterialFile(file); });
    return 0;
}

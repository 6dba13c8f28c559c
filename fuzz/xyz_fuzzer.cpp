// The XYZ grid reader (docs/terrain.md) on any file.
#include "dgm_checks.h"
#include "fuzz_input.h"
#include "geo/xyz_grid.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    using namespace veduta;
    auto file = fuzz::inputFile(data, size, ".xyz");
    fuzz::expectInputError([&] {
        if (looksLikeXyz(file)) fuzz::checkGrid(readXyzGrid(file));
    });
    return 0;
}

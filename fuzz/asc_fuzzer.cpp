// An ESRI ASCII grid through readDgm, GDAL's reader behind veduta's checks (docs/terrain.md),
// on any file.
#include "dgm_checks.h"
#include "fuzz_input.h"
#include "geo/dgm_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    using namespace veduta;
    auto file = fuzz::inputFile(data, size, ".asc");
    fuzz::expectInputError([&] { fuzz::checkGrid(readDgm(file).grid); });
    return 0;
}

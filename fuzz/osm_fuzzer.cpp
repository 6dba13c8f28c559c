// The OpenStreetMap import (docs/osm.md), GDAL's OSM driver behind veduta's checks, on any
// file, and the streets and lots of what it imports.
#include "city/osm_import.h"
#include "city_layout.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    using namespace veduta;
    auto file = fuzz::inputFile(data, size, ".osm");
    fuzz::expectInputError([&] { fuzz::layOutCity(importOsm(file, {})); });
    return 0;
}

// The CityData reader (docs/citydata.md) on any text, and the streets and lots of what it reads.
#include "city_layout.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    using namespace veduta;
    fuzz::expectInputError(
        [&] { fuzz::layOutCity(parseCityData(fuzz::inputText(data, size), "input.xml", fuzz::emptyFolder())); });
    return 0;
}

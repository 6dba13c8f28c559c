// The EDBS reader (docs/atkis.md) and its conversion to ATKIS objects, both ways of treating
// incomplete objects, on any text.
#include "fuzz_input.h"
#include "geo/edbs.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    using namespace veduta;
    fuzz::expectInputError([&] {
        EdbsFile file = parseEdbs(fuzz::inputText(data, size), "input.edbs");
        fuzz::expectInputError([&] { toAtkis(file, IncompleteObjects::Error); });
        toAtkis(file, IncompleteObjects::Skip);
    });
    return 0;
}

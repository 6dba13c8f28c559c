// The scene file reader (docs/scene.md) on any text.
#include "description/scene_description.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    using namespace veduta;
    fuzz::expectInputError([&] { readSceneText(fuzz::inputText(data, size), "input.xml", fuzz::emptyFolder()); });
    return 0;
}

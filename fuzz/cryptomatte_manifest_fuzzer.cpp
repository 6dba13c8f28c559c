// The Cryptomatte manifest reader (docs/output.md, "Cryptomatte") on any text: the JSON that
// `veduta merge` reads from every part's header. A bad manifest is a std::runtime_error, which
// the merge reports as an InputError naming the file; any other exception is a crash. What it
// reads must write back to JSON that reads back the same.
#include <cstdlib>
#include <stdexcept>

#include "film/cryptomatte.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    using namespace veduta;
    std::map<std::string, std::string> manifest;
    try {
        manifest = parseManifest(fuzz::inputText(data, size));
    } catch (const std::runtime_error &) {
        return 0;
    }
    if (parseManifest(manifestJson(manifest)) != manifest) std::abort();
    return 0;
}

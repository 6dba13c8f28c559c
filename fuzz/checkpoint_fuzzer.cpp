// The checkpoint reader (docs/output.md) on any file. Nearly every mutation breaks the CRC,
// which the fuzzer cannot solve, so the harness writes the CRC that makes each input whole
// over its last four bytes: then the checks behind the CRC are fuzzed too. (That the CRC
// refuses every one-byte change is the unit test's: tests/io/checkpoint_file_test.cpp.)
#include <zlib.h>
#include <cstdlib>
#include <vector>

#include "fuzz_input.h"
#include "io/checkpoint_file.h"

namespace {

// The render every input is read for: a small film and a fixed identity.
const veduta::RenderIdentity kIdentity = {{"scene", "fuzz"}, {"samples", "4"}};
veduta::Film fuzzFilm() { return veduta::Film(8, 6, veduta::PixelWindow{0, 0, 8, 6}); }

}  // namespace

// The seed corpus is a checkpoint of that render, written by this program itself (so it
// follows the format): fuzz/run_fuzzers.sh sets VEDUTA_FUZZ_SEED_FOLDER to the corpus folder.
extern "C" int LLVMFuzzerInitialize(int *, char ***) {
    if (const char *folder = std::getenv("VEDUTA_FUZZ_SEED_FOLDER")) {
        veduta::Film film = fuzzFilm();
        veduta::RenderStats stats;
        stats.samplesDone = 4;
        veduta::writeCheckpoint(std::filesystem::path(folder) / "written.checkpoint", kIdentity, film, stats);
    }
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    using namespace veduta;
    std::vector<uint8_t> bytes(data, data + size);
    if (size >= 4) {
        uint32_t crc = uint32_t(crc32(0, bytes.data(), uInt(size - 4)));
        for (int i = 0; i < 4; ++i) bytes[size - 4 + i] = uint8_t(crc >> (8 * i));
    }
    auto file = fuzz::inputFile(bytes.data(), bytes.size(), ".checkpoint");
    Film film = fuzzFilm();
    RenderStats stats;
    fuzz::expectInputError([&] { readCheckpoint(file, kIdentity, film, stats); });
    return 0;
}

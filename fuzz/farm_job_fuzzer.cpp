// The farm job file reader (docs/farm.md) on any file: `veduta farm status` reads farm.job,
// which users may edit. Bad input is an InputError.
#include <unistd.h>

#include <fstream>
#include <string>

#include "app/farm_job.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    using namespace veduta;
    // A job folder of this process holding the input as its farm.job.
    static const std::filesystem::path folder = [] {
        auto path = std::filesystem::temp_directory_path() / ("veduta-fuzz-farm-" + std::to_string(getpid()));
        std::filesystem::create_directories(path);
        return path;
    }();
    std::ofstream(jobFilePath(folder), std::ios::binary)
        .write(reinterpret_cast<const char *>(data), std::streamsize(size));
    fuzz::expectInputError([&] { readJobFile(folder); });
    return 0;
}

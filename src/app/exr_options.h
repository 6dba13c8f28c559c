// What goes into a render's EXR and how it is stored: the options --passes, --half,
// --compression, --rgba and --cryptomatte-depth, shared by `veduta render` and `veduta farm
// submit`, which hands them on to every task's render (docs/output.md).
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "core/layered_image.h"
#include "film/cryptomatte.h"
#include "film/passes.h"
#include "io/exr_file.h"

namespace veduta {

struct ExrArgs {
    std::vector<std::string> passes = defaultPasses();
    bool half = false;
    bool rgba = false;
    std::string compression = "zip";
    int cryptomatteRanks = kDefaultCryptomatteRanks;

    bool wantsCryptomatte() const;
};

void addExrOptions(CLI::App &cmd, ExrArgs &args);

// A codec that changes 32-bit floats would change depth, positions, ids and counts; one file has
// one codec, so such a codec is refused with those passes. Throws CLI::ValidationError.
void checkCompression(const ExrArgs &args);

// Data passes stay 32-bit floats; colour passes become half with --half.
ExrFormat exrFormatOf(const ExrArgs &args, const LayeredImage &image);

// The options again, as `veduta render` takes them; those at their default are left out.
std::vector<std::string> exrArguments(const ExrArgs &args);

}  // namespace veduta

#include "app/exr_options.h"

#include <algorithm>
#include <iterator>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace veduta {

bool ExrArgs::wantsCryptomatte() const {
    return std::any_of(kCryptomatteKinds, std::end(kCryptomatteKinds), [&](CryptomatteKind kind) {
        return std::find(passes.begin(), passes.end(), cryptomattePass(kind)) != passes.end();
    });
}

void addExrOptions(CLI::App &cmd, ExrArgs &args) {
    auto passList = [&args](const std::string &text) {
        try {
            args.passes = parsePassList(text);
            return std::string();
        } catch (const std::invalid_argument &e) {
            return std::string(e.what());
        }
    };
    cmd.add_option("--passes",
                   "Passes to write, separated by commas, or all [every pass but CryptoObject, "
                   "CryptoMaterial]")
        ->check(CLI::Validator(passList, "LIST"));
    cmd.add_flag("--half", args.half, "Colour passes as half floats (depth, positions, ids, counts stay 32-bit)");
    cmd.add_option("--compression", args.compression, "EXR codec [zip]")->check(CLI::IsMember(exrCompressionNames()));
    cmd.add_flag("--rgba", args.rgba, "Also write Combined as top-level R, G, B, A channels");
    cmd.add_option("--cryptomatte-depth", args.cryptomatteRanks,
                   "Ids ranked per pixel in the Crypto passes, two per layer [6]")
        ->check(CLI::Range(1, kMaxCryptomatteRanks));
}

void checkCompression(const ExrArgs &args) {
    if (!changesFloatChannels(*exrCompressionNamed(args.compression))) return;
    std::vector<std::string> data;
    for (const std::string &pass : args.passes) {
        if (isDataChannel(passChannel(pass, "X"))) data.push_back(pass);
    }
    if (data.empty()) return;
    throw CLI::ValidationError(
        "--compression",
        fmt::format("{} would change the data passes {}: pick colour passes only with --passes "
                    "(Combined, CombinedEven, CombinedOdd, Normal, DiffCol) or a codec that keeps "
                    "32-bit floats exact (none, rle, zips, zip, piz, b44, b44a)",
                    args.compression, fmt::join(data, ", ")));
}

ExrFormat exrFormatOf(const ExrArgs &args, const LayeredImage &image) {
    ExrFormat format;
    format.compression = *exrCompressionNamed(args.compression);
    for (const LayeredImage::Channel &c : image.channels) {
        if (args.half && !isDataChannel(c.name)) format.halfChannels.insert(c.name);
    }
    return format;
}

std::vector<std::string> exrArguments(const ExrArgs &args) {
    const ExrArgs defaults;
    std::vector<std::string> arguments;
    if (args.passes != defaults.passes)
        arguments.insert(arguments.end(), {"--passes", fmt::format("{}", fmt::join(args.passes, ","))});
    if (args.half) arguments.push_back("--half");
    if (args.compression != defaults.compression)
        arguments.insert(arguments.end(), {"--compression", args.compression});
    if (args.rgba) arguments.push_back("--rgba");
    if (args.cryptomatteRanks != defaults.cryptomatteRanks)
        arguments.insert(arguments.end(), {"--cryptomatte-depth", std::to_string(args.cryptomatteRanks)});
    return arguments;
}

}  // namespace veduta

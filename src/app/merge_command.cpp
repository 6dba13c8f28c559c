#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "app/command_options.h"
#include "app/commands.h"
#include "app/run_guarded.h"
#include "core/error.h"
#include "core/render_attributes.h"
#include "film/film_merge.h"
#include "io/exr_file.h"
#include "io/output_files.h"

namespace veduta {

namespace {

struct MergeArgs {
    std::string output;
    std::vector<std::string> inputs;
    bool quiet = false;
};

// A file that is no readable EXR is bad input, not a failure of ours.
LayeredImage readInput(const std::string &file, ExrFormat &format) {
    try {
        return readExr(file, &format);
    } catch (const std::runtime_error &e) {
        std::string message = e.what();
        // readExr's message starts with the file name, which InputError adds again.
        if (message.starts_with(file + ": ")) message.erase(0, file.size() + 2);
        throw InputError(FileLoc{file}, message);
    }
}

// The output stores its channels as the first file does; a channel half in one file and float in
// another would make the merged values depend on the order of the files.
void checkSameStorage(const std::vector<ExrFormat> &formats, const std::vector<std::string> &files) {
    for (size_t i = 1; i < formats.size(); ++i) {
        for (const auto &[a, b] : {std::pair{i, size_t(0)}, std::pair{size_t(0), i}}) {
            for (const std::string &channel : formats[a].halfChannels) {
                if (!formats[b].halfChannels.contains(channel)) {
                    throw InputError(FileLoc{files[i]},
                                     fmt::format("{} stores {} as half, {} as float: render every part with or "
                                                 "without --half",
                                                 files[a], channel, files[b]));
                }
            }
        }
    }
}

void runMerge(const MergeArgs &args) {
    prepareOutputFile(args.output);
    std::vector<LayeredImage> parts;
    std::vector<ExrFormat> formats(args.inputs.size());
    for (size_t i = 0; i < args.inputs.size(); ++i) parts.push_back(readInput(args.inputs[i], formats[i]));
    checkSameStorage(formats, args.inputs);
    LayeredImage merged = mergeFilms(parts, args.inputs);
    writeExr(merged, args.output, formats[0]);
    if (args.quiet) return;
    const PixelWindow &w = merged.dataWindow;
    int offset = std::get<int>(merged.metadata.at(kSampleOffsetAttribute));
    int samples = std::get<int>(merged.metadata.at(kSamplesAttribute));
    std::fprintf(stderr, "%s: %zu files, window %d %d %d %d of %dx%d, samples [%d, %d), %s rendering\n",
                 args.output.c_str(), parts.size(), w.x0, w.y0, w.x1, w.y1, merged.fullWidth, merged.fullHeight, offset,
                 offset + samples, std::get<std::string>(merged.metadata.at("RenderTime")).c_str());
}

}  // namespace

void addMergeCommand(CLI::App &app, int &exitCode) {
    auto args = std::make_shared<MergeArgs>();
    CLI::App *cmd = app.add_subcommand(
        "merge", "Assemble tiles (--region) and sum sample ranges (--sample-offset) of one render into one EXR");
    cmd->add_option("output", args->output, "EXR file to write")->required()->check(fileWithExtension(".exr"));
    cmd->add_option("inputs", args->inputs, "EXR files of `veduta render` to merge")
        ->required()
        ->check(CLI::ExistingFile);
    cmd->add_flag("-q,--quiet", args->quiet, "No summary");
    cmd->callback([args, &exitCode] { exitCode = runGuarded([&] { runMerge(*args); }); });
}

}  // namespace veduta

#include <cstdio>
#include <exception>
#include <filesystem>
#include <map>
#include <memory>
#include <string>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "app/commands.h"
#include "app/number_option.h"
#include "io/image_compare.h"
#include "io/output_files.h"

namespace veduta {

namespace {

// idiff's exit codes, which scripts that compare images expect; they differ from the other
// subcommands' codes in commands.h.
enum DiffExitCode : int {
    kDiffPass = 0,
    kDiffFail = 1,
    kDiffError = 2,  // a file that cannot be read or written, sizes that differ, a bad option
};

const std::map<std::string, DiffMetric> kMetrics{
    {"fail", DiffMetric::Fail}, {"relmse", DiffMetric::RelMse}, {"ztest", DiffMetric::ZTest}};

struct DiffArgs {
    std::string a, b, output, variance;
    std::string metric = "fail";  // a key of kMetrics
    ImageDiffOptions options;
};

std::string checkPngName(const std::string &text) {
    return std::filesystem::path(text).extension() == ".png" ? std::string() : "the diff image must be a .png file";
}

// What a metric needs, reported like any other command-line error (exit 2).
void checkMetricInputs(const DiffArgs &args) {
    if (args.options.metric == DiffMetric::RelMse && !args.options.maxRelMse) {
        throw CLI::RequiresError("--metric relmse", "--max-relmse");
    }
    if (args.options.metric == DiffMetric::ZTest && args.variance.empty()) {
        throw CLI::RequiresError("--metric ztest", "--reference-variance");
    }
}

void printFigures(const ImageDiff &diff, const DiffArgs &args) {
    fmt::print("size: {}x{}\n", diff.width, diff.height);
    fmt::print("channels: {}\n", fmt::join(diff.channels, ","));
    fmt::print("pixels: {}\n", diff.pixels);
    fmt::print("failed_pixels: {}\n", diff.failedPixels);
    fmt::print("failed_percent: {:.6g}\n", diff.failedPercent);
    if (args.options.warnThreshold) {
        fmt::print("warned_pixels: {}\n", diff.warnedPixels);
        fmt::print("warned_percent: {:.6g}\n", diff.warnedPercent);
    }
    fmt::print("mean_error: {:.6g}\n", diff.meanError);
    fmt::print("max_error: {:.6g}\n", diff.maxError);
    fmt::print("max_error_at: {},{}\n", diff.maxErrorX, diff.maxErrorY);
    fmt::print("rmse: {:.6g}\n", diff.rmse);
    fmt::print("relmse: {:.6g}\n", diff.relMse);
    fmt::print("psnr_db: {:.6g}\n", diff.psnrDb);
    if (diff.zTestPassFraction) fmt::print("ztest_pass_fraction: {:.6g}\n", *diff.zTestPassFraction);
    fmt::print("metric: {}\n", args.metric);
    fmt::print("verdict: {}\n", diff.passed ? "pass" : "fail");
}

int runDiff(const DiffArgs &args) {
    if (!args.output.empty()) prepareOutputFile(args.output);
    OIIO::ImageBuf a = readImage(args.a), b = readImage(args.b), variance;
    ImageDiffOptions options = args.options;
    if (!args.variance.empty()) {
        variance = readImage(args.variance);
        options.referenceVariance = &variance;
    }
    ImageDiff diff = compareImages(a, b, options);
    if (!args.output.empty()) writeDiffImage(a, b, args.output);
    printFigures(diff, args);
    if (diff.warned) {
        std::fprintf(stderr, "veduta: warning: %.6g%% of the pixels differ by more than %g\n", diff.warnedPercent,
                     *options.warnThreshold);
    }
    return diff.passed ? kDiffPass : kDiffFail;
}

// Like runGuarded, but every error is exit code 2, as in idiff: 1 means "the images differ".
int runDiffGuarded(const DiffArgs &args) {
    try {
        return runDiff(args);
    } catch (const std::exception &e) {
        std::fprintf(stderr, "veduta: error: %s\n", e.what());
        return kDiffError;
    }
}

}  // namespace

void addDiffCommand(CLI::App &app, int &exitCode) {
    auto args = std::make_shared<DiffArgs>();
    CLI::App *cmd = app.add_subcommand("diff", "Compare image A with reference image B and say whether they agree");
    cmd->add_option("A", args->a, "Image under test (any format OpenImageIO reads)")
        ->required()
        ->check(CLI::ExistingFile);
    cmd->add_option("B", args->b, "Reference image")->required()->check(CLI::ExistingFile);
    cmd->add_option("--metric", args->metric,
                    "What decides the verdict: fail (idiff's rule, with --fail and --failpercent), relmse (with "
                    "--max-relmse) or ztest (with --reference-variance and --spp)")
        ->check(CLI::IsMember(kMetrics))
        ->capture_default_str();
    cmd->add_option("--fail", args->options.failThreshold, "A pixel fails when a channel differs by more")
        ->check(finiteIn(0, 1e30))
        ->capture_default_str();
    cmd->add_option("--failpercent", args->options.failPercent, "The images differ when more pixels fail (percent)")
        ->check(finiteIn(0, 100))
        ->capture_default_str();
    cmd->add_option("--warn", args->options.warnThreshold, "Count pixels differing by more, and warn")
        ->check(finiteIn(0, 1e30));
    cmd->add_option("--warnpercent", args->options.warnPercent, "Warn when more pixels than this exceed --warn")
        ->check(finiteIn(0, 100))
        ->capture_default_str();
    cmd->add_option("--max-relmse", args->options.maxRelMse, "Largest relMSE that passes, for --metric relmse")
        ->check(finiteIn(0, 1e30));
    CLI::Option *variance =
        cmd->add_option("--reference-variance", args->variance, "Variance of one sample of B, per pixel (for ztest)")
            ->check(CLI::ExistingFile);
    CLI::Option *spp = cmd->add_option("--spp", args->options.samplesPerPixel, "Samples per pixel of A (for ztest)")
                           ->check(CLI::Range(1u, 1u << 24));
    variance->needs(spp);
    spp->needs(variance);
    cmd->add_option("-o,--output", args->output, "Write |A - B| x 16 as an 8-bit PNG here")
        ->check(CLI::Validator(checkPngName, "FILE.png"));
    cmd->footer(
        "Exit codes, as idiff's: 0 the images agree, 1 they differ, 2 an error (a file that cannot be read or "
        "written, sizes that differ, a bad option). Details: docs/diff.md");
    cmd->callback([args, &exitCode] {
        args->options.metric = kMetrics.at(args->metric);
        checkMetricInputs(*args);
        exitCode = runDiffGuarded(*args);
    });
}

}  // namespace veduta

// Comparing a test image A with a reference image B, pixel by pixel: the figures and the
// pass/fail verdict of `veduta diff`, shared with golden-image tests. Values are compared as
// stored, as float, with no colour transform. The channels compared are those both images
// (and a reference variance, when given) have by name; R, G and B must be among them. Of a
// multilayer EXR with Blender's pass names only the pass `<layer>.Combined` is compared, its
// channels `<layer>.Combined.R` … standing for R …, so that either kind compares with either.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <OpenImageIO/imagebuf.h>

namespace veduta {

// Which figure decides the verdict.
enum class DiffMetric {
    Fail,    // oiiotool/idiff: no more than failPercent of the pixels differ by more than failThreshold
    RelMse,  // relMSE no larger than maxRelMse
    ZTest,   // A agrees with B within the noise its sample count allows (Mitsuba 3's render tests)
};

struct ImageDiffOptions {
    DiffMetric metric = DiffMetric::Fail;
    double failThreshold = 0.016;  // a pixel fails when any channel differs by more than this
    double failPercent = 1.0;      // the comparison fails when more than this percentage of pixels fail
    // idiff's warnings: pixels differing by more than warnThreshold are counted only when it is set.
    std::optional<double> warnThreshold;
    double warnPercent = 0.0;
    std::optional<double> maxRelMse;  // needed by DiffMetric::RelMse
    // For the Z-test (needed by DiffMetric::ZTest, computed whenever given): the variance of
    // one sample of B's pixels (not of their mean), and the samples per pixel A was made with.
    const OIIO::ImageBuf *referenceVariance = nullptr;
    uint32_t samplesPerPixel = 0;
};

// Means are over all pixels and compared channels. A value that is NaN or infinite in one
// image and not the same in the other counts as an infinite difference.
struct ImageDiff {
    int width = 0, height = 0;
    std::vector<std::string> channels;  // the channels compared (R, G, B, A, never a pass prefix), in A's order
    uint64_t pixels = 0;
    uint64_t failedPixels = 0;
    double failedPercent = 0;
    uint64_t warnedPixels = 0;  // zero unless a warning threshold was set
    double warnedPercent = 0;
    double meanError = 0;
    double maxError = 0;
    int maxErrorX = 0, maxErrorY = 0;  // the pixel of maxError, from the top left
    double rmse = 0;
    double relMse = 0;                        // mean of (a - b)² / (b² + 0.01)
    double psnrDb = 0;                        // for a peak of 1; infinite for identical images
    std::optional<double> zTestPassFraction;  // of the values whose p-value exceeds the corrected alpha
    bool warned = false;                      // more than warnPercent of the pixels exceed the warning threshold
    bool passed = false;                      // the verdict of the chosen metric
};

// The Z-test passes when at least this fraction of the values pass (as in Mitsuba 3).
inline constexpr double kZTestMinPassFraction = 0.9975;

// Reads the first subimage of any file OpenImageIO reads into memory, as float. Throws
// InputError naming the file when it cannot be read.
OIIO::ImageBuf readImage(const std::string &path);

// Throws std::runtime_error when the sizes differ ("sizes differ: A is WxH, B is WxH") or a
// needed channel is missing, and std::invalid_argument when the chosen metric lacks its inputs.
ImageDiff compareImages(const OIIO::ImageBuf &a, const OIIO::ImageBuf &b, const ImageDiffOptions &options = {});
ImageDiff compareImages(const std::string &a, const std::string &b, const ImageDiffOptions &options = {});

// Writes |A - B| · 16 of the R, G and B channels, clamped to [0, 1], with 8 bits per channel
// in the format the file's extension names (PNG in practice), under a temporary name that is
// renamed when complete. Throws std::runtime_error naming the file when it cannot.
void writeDiffImage(const OIIO::ImageBuf &a, const OIIO::ImageBuf &b, const std::filesystem::path &file);

}  // namespace veduta

#include "io/image_compare.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string_view>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/error.h"
#include "core/rel_mse.h"
#include "io/output_files.h"

namespace veduta {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// As in Mitsuba 3: a pixel without noise in the reference still allows a small difference.
constexpr double kMinVariance = 1e-4;
constexpr double kZTestSignificance = 0.01;
constexpr double kDiffImageScale = 16.0;  // as Cycles' test reports, so that small errors show

// Blender's multilayer EXRs (veduta's renders among them) hold many passes; the picture is the
// pass `<layer>.Combined`. Its channels are compared as plain R, G, B and A, so that a new render
// compares with an old plain RGBA golden. The channel-name prefix of that pass, or "" for a plain image.
std::string combinedPrefix(const OIIO::ImageSpec &spec) {
    constexpr std::string_view kCombined = ".Combined.";
    for (const std::string &name : spec.channelnames) {
        size_t at = name.find(kCombined);
        if (at != std::string::npos && at > 0) return name.substr(0, at + kCombined.size());
    }
    return "";
}

// An image that takes part in a comparison, with the name messages give it and the prefix of the
// channels it is compared through.
struct Role {
    Role(const OIIO::ImageBuf *buffer, const char *messageName) :
        image(buffer), name(messageName), prefix(combinedPrefix(buffer->spec())) {}

    // The index of `channel` (R, G, …) of the compared pass; -1 when there is none.
    int channelIndex(const std::string &channel) const { return image->spec().channelindex(prefix + channel); }

    // The names of the compared pass's channels without the prefix, in the image's order.
    std::vector<std::string> channels() const {
        std::vector<std::string> names;
        for (const std::string &full : image->spec().channelnames) {
            if (full.starts_with(prefix)) names.push_back(full.substr(prefix.size()));
        }
        return names;
    }

    const OIIO::ImageBuf *image;
    const char *name;
    std::string prefix;
};

void checkSameSize(const Role &a, const Role &b) {
    const OIIO::ImageSpec &sa = a.image->spec(), &sb = b.image->spec();
    if (sa.width != sb.width || sa.height != sb.height) {
        throw std::runtime_error(fmt::format("sizes differ: {} is {}x{}, {} is {}x{}", a.name, sa.width, sa.height,
                                             b.name, sb.width, sb.height));
    }
}

void requireRgb(const std::vector<Role> &roles) {
    for (const Role &role : roles) {
        for (const char *channel : {"R", "G", "B"}) {
            if (role.channelIndex(channel) < 0) {
                throw std::runtime_error(fmt::format("{} has no {}{} channel (it has {})", role.name, role.prefix,
                                                     channel, fmt::join(role.image->spec().channelnames, ", ")));
            }
        }
    }
}

// The channels of the first image that all the others have too, in the first image's order.
std::vector<std::string> sharedChannels(const std::vector<Role> &roles) {
    std::vector<std::string> shared;
    for (const std::string &name : roles.front().channels()) {
        bool everywhere =
            std::all_of(roles.begin() + 1, roles.end(), [&](const Role &r) { return r.channelIndex(name) >= 0; });
        if (everywhere) shared.push_back(name);
    }
    return shared;
}

// One image's pixels as float, whatever the buffer stores, read through the compared channels.
class ChannelReader {
  public:
    ChannelReader(const Role &role, const std::vector<std::string> &channels) :
        stride_(size_t(role.image->nchannels())) {
        OIIO::ROI roi = role.image->roi();
        values_.resize(roi.npixels() * stride_);
        if (!role.image->get_pixels(roi, OIIO::TypeFloat, values_.data())) {
            throw std::runtime_error(role.image->geterror());
        }
        for (const std::string &name : channels) index_.push_back(size_t(role.channelIndex(name)));
    }

    // `pixel` counts from the top left, row by row.
    float at(size_t pixel, size_t channel) const { return values_[pixel * stride_ + index_[channel]]; }

  private:
    size_t stride_;
    std::vector<float> values_;
    std::vector<size_t> index_;
};

// A value that is NaN or infinite in one image and not the same in the other differs infinitely,
// so that it fails every threshold instead of slipping through comparisons with NaN.
double valueError(float a, float b) {
    if (a == b || (std::isnan(a) && std::isnan(b))) return 0;
    double error = std::abs(double(a) - double(b));
    return std::isnan(error) ? kInfinity : error;
}

double relativeSquaredError(double error, float reference) {
    if (error == 0) return 0;
    if (!std::isfinite(reference)) return kInfinity;
    return error * error / (double(reference) * reference + kRelMseEpsilon);
}

// Mitsuba 3's per-value Z-test: is A's mean within the noise of its sample count around B?
class ZTest {
  public:
    // Šidák correction: with `valueCount` tests, all pass by chance with probability 1 - significance.
    ZTest(uint32_t samplesPerPixel, uint64_t valueCount) :
        sqrtSpp_(std::sqrt(double(samplesPerPixel))),
        alpha_(-std::expm1(std::log1p(-kZTestSignificance) / double(valueCount))) {}

    // A NaN variance gives a NaN p-value, which fails.
    bool passes(double error, float variance) const {
        double z = error * sqrtSpp_ / std::sqrt(std::max(double(variance), kMinVariance));
        double p = std::erfc(z / std::numbers::sqrt2);  // 2 (1 - Φ(z))
        return p > alpha_;
    }

  private:
    double sqrtSpp_, alpha_;
};

void checkOptions(const ImageDiffOptions &options) {
    if (options.metric == DiffMetric::RelMse && !options.maxRelMse) {
        throw std::invalid_argument("the relMSE metric needs a largest relMSE");
    }
    if (options.metric == DiffMetric::ZTest && !options.referenceVariance) {
        throw std::invalid_argument("the Z-test needs the reference variance");
    }
    if (options.referenceVariance && options.samplesPerPixel == 0) {
        throw std::invalid_argument("the Z-test needs the samples per pixel of A");
    }
}

// Sums and counts over all pixels and channels; the figures are made from them.
struct Totals {
    double absolute = 0, squared = 0, relativeSquared = 0;
    uint64_t failedPixels = 0, warnedPixels = 0, zTestPassed = 0;
    double maxError = 0;
    size_t maxErrorPixel = 0;
};

Totals sumErrors(const std::vector<Role> &roles, const std::vector<std::string> &channels,
                 const ImageDiffOptions &options) {
    ChannelReader a(roles[0], channels), b(roles[1], channels);
    std::optional<ChannelReader> variance;
    if (options.referenceVariance) variance.emplace(roles[2], channels);
    const size_t pixels = size_t(roles[0].image->spec().width) * size_t(roles[0].image->spec().height);
    const ZTest zTest(options.samplesPerPixel, pixels * channels.size());
    const double warnThreshold = options.warnThreshold.value_or(kInfinity);

    Totals t;
    for (size_t p = 0; p < pixels; ++p) {
        double pixelError = 0;
        for (size_t c = 0; c < channels.size(); ++c) {
            float reference = b.at(p, c);
            double error = valueError(a.at(p, c), reference);
            pixelError = std::max(pixelError, error);
            t.absolute += error;
            t.squared += error * error;
            t.relativeSquared += relativeSquaredError(error, reference);
            if (variance && zTest.passes(error, variance->at(p, c))) ++t.zTestPassed;
        }
        if (pixelError > t.maxError) {
            t.maxError = pixelError;
            t.maxErrorPixel = p;
        }
        if (pixelError > options.failThreshold) ++t.failedPixels;
        if (pixelError > warnThreshold) ++t.warnedPixels;
    }
    return t;
}

bool verdict(const ImageDiff &diff, const ImageDiffOptions &options) {
    switch (options.metric) {
    case DiffMetric::Fail: return diff.failedPercent <= options.failPercent;
    case DiffMetric::RelMse: return diff.relMse <= *options.maxRelMse;
    case DiffMetric::ZTest: return *diff.zTestPassFraction >= kZTestMinPassFraction;
    }
    throw std::invalid_argument("unknown metric");
}

ImageDiff summarize(const Totals &t, const OIIO::ImageSpec &spec, const std::vector<std::string> &channels,
                    const ImageDiffOptions &options) {
    ImageDiff diff;
    diff.width = spec.width;
    diff.height = spec.height;
    diff.channels = channels;
    const uint64_t pixels = uint64_t(spec.width) * uint64_t(spec.height);
    diff.pixels = pixels;
    diff.failedPixels = t.failedPixels;
    diff.failedPercent = 100.0 * double(t.failedPixels) / double(pixels);
    diff.warnedPixels = t.warnedPixels;
    diff.warnedPercent = 100.0 * double(t.warnedPixels) / double(pixels);
    diff.warned = options.warnThreshold && diff.warnedPercent > options.warnPercent;
    const double values = double(pixels * channels.size());
    diff.meanError = t.absolute / values;
    diff.maxError = t.maxError;
    diff.maxErrorX = int(t.maxErrorPixel % size_t(spec.width));
    diff.maxErrorY = int(t.maxErrorPixel / size_t(spec.width));
    double mse = t.squared / values;
    diff.rmse = std::sqrt(mse);
    diff.relMse = t.relativeSquared / values;
    diff.psnrDb = -10.0 * std::log10(mse);  // +inf when mse is 0
    if (options.referenceVariance) diff.zTestPassFraction = double(t.zTestPassed) / values;
    diff.passed = verdict(diff, options);
    return diff;
}

}  // namespace

OIIO::ImageBuf readImage(const std::string &path) {
    OIIO::ImageBuf image(path);
    if (!image.read(0, 0, true, OIIO::TypeFloat)) throw InputError(FileLoc{path, 0, 0}, image.geterror());
    if (image.deep()) throw InputError(FileLoc{path, 0, 0}, "deep images cannot be compared");
    return image;
}

ImageDiff compareImages(const OIIO::ImageBuf &a, const OIIO::ImageBuf &b, const ImageDiffOptions &options) {
    checkOptions(options);
    std::vector<Role> roles{{&a, "A"}, {&b, "B"}};
    if (options.referenceVariance) roles.push_back({options.referenceVariance, "the reference variance"});
    for (size_t i = 1; i < roles.size(); ++i) checkSameSize(roles[0], roles[i]);
    requireRgb(roles);
    // The images under comparison decide the channels; a variance image must have them all.
    std::vector<std::string> channels = sharedChannels({roles[0], roles[1]});
    if (options.referenceVariance) {
        for (const std::string &name : channels) {
            if (roles[2].channelIndex(name) < 0) {
                throw std::runtime_error(fmt::format("the reference variance has no {} channel", name));
            }
        }
    }
    return summarize(sumErrors(roles, channels, options), a.spec(), channels, options);
}

ImageDiff compareImages(const std::string &a, const std::string &b, const ImageDiffOptions &options) {
    return compareImages(readImage(a), readImage(b), options);
}

void writeDiffImage(const OIIO::ImageBuf &a, const OIIO::ImageBuf &b, const std::filesystem::path &file) {
    std::vector<Role> roles{{&a, "A"}, {&b, "B"}};
    checkSameSize(roles[0], roles[1]);
    requireRgb(roles);
    const std::vector<std::string> rgb{"R", "G", "B"};
    ChannelReader ra(roles[0], rgb), rb(roles[1], rgb);
    const size_t pixels = size_t(a.spec().width) * size_t(a.spec().height);
    std::vector<uint8_t> out(pixels * 3);
    for (size_t p = 0; p < pixels; ++p) {
        for (size_t c = 0; c < 3; ++c) {
            double v = std::min(valueError(ra.at(p, c), rb.at(p, c)) * kDiffImageScale, 1.0);
            out[p * 3 + c] = uint8_t(std::lround(v * 255));
        }
    }
    // Through libpng in memory, every write checked: OpenImageIO's PNG writer misses a full
    // disk, and would leave a cut file in the older one's place.
    writeEncodedPng(out, a.spec().width, a.spec().height, 3, file);
}

}  // namespace veduta

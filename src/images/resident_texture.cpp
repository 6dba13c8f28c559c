#include "images/resident_texture.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include <OpenImageIO/imageio.h>
#include <fmt/format.h>
#include <tbb/parallel_for.h>

namespace veduta {

namespace {

// The fractional part, in [0, 1): periodic wrapping, before any conversion to integers.
float wrapped(float x) {
    if (!std::isfinite(x)) return 0.0f;
    float f = x - std::floor(x);
    return f < 1.0f ? f : 0.0f;
}

int wrap(int i, int size) { return i < 0 ? i + size : (i >= size ? i - size : i); }

int halved(int size) { return std::max(1, size / 2); }

// The weights by which the texels of a row of `from` make each of the `to` texels covering it
// (to ≤ from): the box filter's, each source texel's share of the target texel's span.
struct Tap {
    int source;
    float weight;
};
std::vector<std::vector<Tap>> boxTaps(int from, int to) {
    std::vector<std::vector<Tap>> taps(static_cast<size_t>(to));
    double ratio = double(from) / double(to);
    for (int i = 0; i < to; ++i) {
        double low = i * ratio, high = (i + 1) * ratio;
        for (int s = int(std::floor(low)); s < std::min(from, int(std::ceil(high))); ++s) {
            double covered = std::min(high, double(s + 1)) - std::max(low, double(s));
            if (covered > 0) taps[size_t(i)].push_back({s, float(covered / ratio)});
        }
    }
    return taps;
}

}  // namespace

std::optional<ResidentTexture> ResidentTexture::read(const std::filesystem::path &texture, int64_t maxTexels) {
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(texture.string());
    if (!in) throw std::runtime_error(fmt::format("{}: {}", texture.string(), OIIO::geterror()));
    const OIIO::ImageSpec &first = in->spec();
    if (int64_t(first.width) * first.height > maxTexels || first.nchannels > 4) return std::nullopt;
    ResidentTexture result;
    result.channels_ = first.nchannels;
    for (int miplevel = 0; in->seek_subimage(0, miplevel); ++miplevel) {
        const OIIO::ImageSpec &spec = in->spec();
        Level &level = result.levels_.emplace_back();
        level.width = spec.width;
        level.height = spec.height;
        level.texels.resize(size_t(spec.width) * size_t(spec.height) * size_t(spec.nchannels));
        if (spec.nchannels != result.channels_ ||
            !in->read_image(0, miplevel, 0, spec.nchannels, OIIO::TypeFloat, level.texels.data()))
            throw std::runtime_error(
                fmt::format("{}: cannot read mip level {}: {}", texture.string(), miplevel, in->geterror()));
    }
    if (result.levels_.empty()) throw std::runtime_error(fmt::format("{}: no image in it", texture.string()));
    return result;
}

ResidentTexture ResidentTexture::fromImage(Image image) {
    if (image.empty() || image.channels < 1 || image.channels > 4)
        throw std::invalid_argument(
            fmt::format("a texture of {} × {} texels in {} channels", image.width, image.height, image.channels));
    ResidentTexture result;
    const size_t channels = size_t(image.channels);
    result.channels_ = image.channels;
    result.levels_.push_back({image.width, image.height, std::move(image.pixels)});
    while (result.levels_.back().width > 1 || result.levels_.back().height > 1) {
        const Level &above = result.levels_.back();
        Level level{halved(above.width), halved(above.height), {}};
        // Separable: rows first, into a level as wide as the new one and as high as the old.
        std::vector<std::vector<Tap>> across = boxTaps(above.width, level.width);
        std::vector<std::vector<Tap>> down = boxTaps(above.height, level.height);
        // Rows in parallel: each writes only its own, so the sums are those of one thread. Each
        // sum starts from its first tap and adds the others in order, as one from zero would,
        // so that no buffer needs clearing first.
        const size_t row = size_t(level.width) * channels;
        std::unique_ptr<float[]> narrow(new float[row * size_t(above.height)]);
        tbb::parallel_for(size_t(0), size_t(above.height), [&](size_t y) {
            const float *from = &above.texels[y * size_t(above.width) * channels];
            float *to = &narrow[y * row];
            if (above.width == 2 * level.width) {  // the taps are (2x, ½) and (2x + 1, ½): the same sums
                for (size_t x = 0; x < size_t(level.width); ++x, from += 2 * channels, to += channels)
                    for (size_t c = 0; c < channels; ++c) {
                        float sum = 0.0f;
                        sum += 0.5f * from[c];
                        sum += 0.5f * from[channels + c];
                        to[c] = sum;
                    }
                return;
            }
            for (size_t x = 0; x < size_t(level.width); ++x)
                for (size_t c = 0; c < channels; ++c) {
                    float sum = 0.0f;
                    for (const Tap &tap : across[x]) sum += tap.weight * from[size_t(tap.source) * channels + c];
                    to[x * channels + c] = sum;
                }
        });
        level.texels.resize(row * size_t(level.height));
        tbb::parallel_for(size_t(0), size_t(level.height), [&](size_t y) {
            float *to = &level.texels[y * row];
            const float *first = &narrow[size_t(down[y].front().source) * row];
            for (size_t i = 0; i < row; ++i) to[i] = 0.0f + down[y].front().weight * first[i];
            for (size_t t = 1; t < down[y].size(); ++t) {
                const float *from = &narrow[size_t(down[y][t].source) * row];
                for (size_t i = 0; i < row; ++i) to[i] += down[y][t].weight * from[i];
            }
        });
        result.levels_.push_back(std::move(level));
    }
    return result;
}

int64_t ResidentTexture::bytesFor(int width, int height, int channels) {
    int64_t bytes = 0;
    for (;;) {
        bytes += int64_t(width) * height * channels * int64_t(sizeof(float));
        if (width == 1 && height == 1) return bytes;
        width = halved(width), height = halved(height);
    }
}

int64_t ResidentTexture::bytes() const {
    int64_t bytes = 0;
    for (const Level &level : levels_) bytes += int64_t(level.texels.size() * sizeof(float));
    return bytes;
}

void ResidentTexture::lookup(Vec2f uv, float footprint, float *out, int count) const {
    count = std::min(count, channels_);
    // OpenImageIO's s and t: t runs down from the top row, v up.
    float s = wrapped(uv.x), t = wrapped(1.0f - uv.y);
    const Level &finest = levels_.front();
    float texels = footprint * float(std::max(finest.width, finest.height));
    float level = texels > 1.0f ? std::log2(texels) : 0.0f;
    auto last = float(levels_.size() - 1);
    if (!(level < last)) {
        bilinear(levels_.back(), s, t, out, count);
        return;
    }
    auto lower = size_t(level);
    float blend = level - float(lower);
    bilinear(levels_[lower], s, t, out, count);
    if (blend == 0.0f) return;
    float coarser[4];
    bilinear(levels_[lower + 1], s, t, coarser, count);
    for (int c = 0; c < count; ++c) out[c] = (1.0f - blend) * out[c] + blend * coarser[c];
}

void ResidentTexture::bilinear(const Level &level, float s, float t, float *out, int count) const {
    float x = s * float(level.width) - 0.5f, y = t * float(level.height) - 0.5f;
    float x0f = std::floor(x), y0f = std::floor(y);
    float wx = x - x0f, wy = y - y0f;
    int x0 = wrap(int(x0f), level.width), y0 = wrap(int(y0f), level.height);
    int x1 = wrap(x0 + 1, level.width), y1 = wrap(y0 + 1, level.height);
    auto texel = [&](int tx, int ty) {
        return &level.texels[(size_t(ty) * size_t(level.width) + size_t(tx)) * size_t(channels_)];
    };
    const float *a = texel(x0, y0), *b = texel(x1, y0), *c = texel(x0, y1), *d = texel(x1, y1);
    for (int k = 0; k < count; ++k)
        out[k] = (1.0f - wy) * ((1.0f - wx) * a[k] + wx * b[k]) + wy * ((1.0f - wx) * c[k] + wx * d[k]);
}

}  // namespace veduta

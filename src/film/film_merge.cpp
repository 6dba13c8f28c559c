#include "film/film_merge.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <map>
#include <stdexcept>

#include <fmt/format.h>

#include "core/check.h"
#include "core/error.h"
#include "core/render_attributes.h"
#include "film/cryptomatte.h"
#include "film/passes.h"

namespace veduta {

namespace {

// A part with what the merge reads from its metadata: its samples are [offset, offset + samples)
// of each pixel's sequence.
struct Part {
    const LayeredImage *image;
    const std::string *name;
    int offset, samples;

    int end() const { return offset + samples; }
};

// The parts sharing one data window, by offset.
using SampleRanges = std::vector<Part>;

// How a channel's values combine over the sample ranges of one pixel.
enum class Combine {
    Mean,         // weighted by the pixel's sample counts
    EvenMean,     // weighted by the counts of even-numbered samples
    OddMean,      // weighted by the counts of odd-numbered samples
    Sum,          // the sample counts themselves
    FirstSample,  // data of the sequence's sample 0, which every range computes
};

Combine combineOf(const std::string &channel) {
    auto inPass = [&](const char *pass) { return channel.starts_with(passChannel(pass, "")); };
    if (inPass("SampleCount")) return Combine::Sum;
    if (inPass("CombinedEven")) return Combine::EvenMean;
    if (inPass("CombinedOdd")) return Combine::OddMean;
    if (inPass("Depth") || inPass("Position") || channel.starts_with(fmt::format("{}.Index", kViewLayer))) {
        return Combine::FirstSample;
    }
    return Combine::Mean;
}

template <typename T>
const T &attribute(const LayeredImage &image, const std::string &name, const char *key) {
    auto it = image.metadata.find(key);
    if (it == image.metadata.end()) {
        throw InputError(FileLoc{name}, fmt::format("has no {} attribute; is it a veduta render?", key));
    }
    const T *value = std::get_if<T>(&it->second);
    if (!value) throw InputError(FileLoc{name}, fmt::format("its {} attribute has an unexpected type", key));
    return *value;
}

std::string windowText(const PixelWindow &w) { return fmt::format("{} {} {} {}", w.x0, w.y0, w.x1, w.y1); }
std::string rangeText(int begin, int end) { return fmt::format("[{}, {})", begin, end); }

std::vector<std::string> sortedChannelNames(const LayeredImage &image) {
    std::vector<std::string> names;
    for (const LayeredImage::Channel &c : image.channels) names.push_back(c.name);
    std::sort(names.begin(), names.end());
    return names;
}

// Everything that must be the same in every part: image size, channels, scene and seed.
void checkSameRender(const Part &part, const Part &first) {
    const LayeredImage &a = *part.image, &b = *first.image;
    const std::string &name = *part.name, &firstName = *first.name;
    if (a.fullWidth != b.fullWidth || a.fullHeight != b.fullHeight) {
        throw InputError(FileLoc{name},
                         fmt::format("is a {}x{} image, {} is {}x{}", a.fullWidth, a.fullHeight, firstName, b.fullWidth,
                                     b.fullHeight));
    }
    std::vector<std::string> channels = sortedChannelNames(a), firstChannels = sortedChannelNames(b);
    for (const std::string &c : channels) {
        if (!b.find(c)) throw InputError(FileLoc{name}, fmt::format("has a channel {}, {} has not", c, firstName));
    }
    for (const std::string &c : firstChannels) {
        if (!a.find(c)) throw InputError(FileLoc{name}, fmt::format("lacks the channel {} that {} has", c, firstName));
    }
    for (const char *key : {kSceneHashAttribute, kSeedAttribute}) {
        if (a.metadata.at(key) != b.metadata.at(key)) {
            throw InputError(FileLoc{name},
                             fmt::format("has a different {} from {}: not the same render", key, firstName));
        }
    }
}

Part readPart(const LayeredImage &image, const std::string &name) {
    attribute<std::string>(image, name, kSceneHashAttribute);
    attribute<int>(image, name, kSeedAttribute);
    attribute<double>(image, name, kRenderSecondsAttribute);
    Part part{&image, &name, attribute<int>(image, name, kSampleOffsetAttribute),
              attribute<int>(image, name, kSamplesAttribute)};
    if (part.offset < 0 || part.samples < 0) {
        throw InputError(FileLoc{name}, fmt::format("has the sample range {}", rangeText(part.offset, part.end())));
    }
    if (!image.find(passChannel("SampleCount", "X"))) {
        throw InputError(FileLoc{name}, "has no SampleCount pass to weigh its pixels by");
    }
    return part;
}

// The parts grouped by data window, each group sorted by offset and checked to be one run of
// consecutive samples.
std::vector<SampleRanges> groupByWindow(const std::vector<Part> &parts) {
    std::vector<SampleRanges> groups;
    for (const Part &part : parts) {
        auto same = [&](const SampleRanges &g) { return g[0].image->dataWindow == part.image->dataWindow; };
        auto group = std::find_if(groups.begin(), groups.end(), same);
        if (group == groups.end()) {
            groups.push_back({part});
        } else {
            group->push_back(part);
        }
    }
    for (SampleRanges &group : groups) {
        std::stable_sort(group.begin(), group.end(), [](const Part &a, const Part &b) { return a.offset < b.offset; });
        for (size_t i = 1; i < group.size(); ++i) {
            const Part &before = group[i - 1], &part = group[i];
            if (part.offset < before.end()) {
                throw InputError(
                    FileLoc{*part.name},
                    fmt::format("its samples {} overlap the samples {} of {}", rangeText(part.offset, part.end()),
                                rangeText(before.offset, before.end()), *before.name));
            }
            if (part.offset > before.end()) {
                throw InputError(FileLoc{*part.name},
                                 fmt::format("its samples {} do not continue the samples {} of {}: samples {} are in "
                                             "none of the files",
                                             rangeText(part.offset, part.end()), rangeText(before.offset, before.end()),
                                             *before.name, rangeText(before.end(), part.offset)));
            }
        }
    }
    return groups;
}

// Tiles must have the same samples, must not overlap, and must cover their bounding box, which
// is returned.
PixelWindow checkTiles(const std::vector<SampleRanges> &groups) {
    const SampleRanges &first = groups[0];
    PixelWindow box = first[0].image->dataWindow;
    size_t covered = 0;
    for (size_t i = 0; i < groups.size(); ++i) {
        const SampleRanges &group = groups[i];
        const PixelWindow &w = group[0].image->dataWindow;
        if (group[0].offset != first[0].offset || group.back().end() != first.back().end()) {
            throw InputError(FileLoc{*group[0].name},
                             fmt::format("its tile has the samples {}, the tile of {} has {}",
                                         rangeText(group[0].offset, group.back().end()), *first[0].name,
                                         rangeText(first[0].offset, first.back().end())));
        }
        for (size_t j = 0; j < i; ++j) {
            const PixelWindow &other = groups[j][0].image->dataWindow;
            if (w.overlaps(other)) {
                throw InputError(FileLoc{*group[0].name},
                                 fmt::format("its data window {} overlaps the data window {} "
                                             "of {}",
                                             windowText(w), windowText(other), *groups[j][0].name));
            }
        }
        box = {std::min(box.x0, w.x0), std::min(box.y0, w.y0), std::max(box.x1, w.x1), std::max(box.y1, w.y1)};
        covered += w.area();
    }
    if (covered != box.area()) {
        throw InputError(FileLoc{*first[0].name},
                         fmt::format("the tiles leave {} of the {} pixels of their bounding box {} uncovered",
                                     box.area() - covered, box.area(), windowText(box)));
    }
    return box;
}

// Even indices in [offset, offset + count).
uint64_t evenSamples(int offset, uint64_t count) {
    return (uint64_t(offset) + count + 1) / 2 - (uint64_t(offset) + 1) / 2;
}

double weightOf(Combine combine, const Part &part, float sampleCount) {
    uint64_t n = uint64_t(sampleCount);
    if (combine == Combine::EvenMean) return double(evenSamples(part.offset, n));
    if (combine == Combine::OddMean) return double(n - evenSamples(part.offset, n));
    return double(n);
}

// One channel of a group's merged image. Sums are in double and rounded once, so that a single
// part comes back exactly: m·n/n is exact in double for a float m and an integer n < 2^24.
std::vector<float> mergeChannel(const SampleRanges &group, const std::string &channel) {
    Combine combine = combineOf(channel);
    std::vector<const std::vector<float> *> values, counts;
    for (const Part &part : group) {
        values.push_back(&part.image->find(channel)->values);
        counts.push_back(&part.image->find(passChannel("SampleCount", "X"))->values);
    }
    const std::vector<float> &first = *values[0];
    std::vector<float> merged(first.size());
    for (size_t p = 0; p < merged.size(); ++p) {
        double sum = 0, weights = 0;
        for (size_t i = 0; i < group.size(); ++i) {
            float v = (*values[i])[p];
            if (combine == Combine::FirstSample && std::bit_cast<uint32_t>(v) != std::bit_cast<uint32_t>(first[p])) {
                const PixelWindow &w = group[0].image->dataWindow;
                throw InputError(FileLoc{*group[i].name},
                                 fmt::format("{} at pixel {} {} is {}, in {} it is {}: they come from different "
                                             "scenes",
                                             channel, w.x0 + int(p % size_t(w.width())),
                                             w.y0 + int(p / size_t(w.width())), v, *group[0].name, first[p]));
            }
            double n = weightOf(combine, group[i], (*counts[i])[p]);
            sum += combine == Combine::Sum ? double(v) : double(v) * n;
            weights += n;
        }
        switch (combine) {
        case Combine::Sum: merged[p] = float(sum); break;
        case Combine::FirstSample: merged[p] = first[p]; break;
        // A pixel without samples keeps the first part's value (the film's 0, or alpha 1).
        default: merged[p] = weights > 0 ? float(sum / weights) : first[p];
        }
    }
    return merged;
}

// One kind's Cryptomatte layers over a group's sample ranges: each range's coverages as sample
// counts, summed per id over the ranges and ranked again.
LayeredImage mergeCryptomatte(const SampleRanges &group, CryptomatteKind kind, int ranks) {
    LayeredImage merged;
    merged.dataWindow = group[0].image->dataWindow;
    addCryptomatteLayers(merged, kind, ranks, {});
    std::vector<std::vector<float> *> out = rankChannels(merged, kind);
    std::vector<std::vector<const std::vector<float> *>> in;
    std::vector<const std::vector<float> *> counts;
    for (const Part &part : group) {
        in.push_back(rankChannels(*part.image, kind));
        counts.push_back(&part.image->find(passChannel("SampleCount", "X"))->values);
    }
    for (size_t p = 0; p < merged.dataWindow.area(); ++p) {
        std::map<uint32_t, double> weights;
        double samples = 0;
        for (size_t i = 0; i < group.size(); ++i) {
            double n = (*counts[i])[p];
            for (const CryptomatteEntry &e : readRanks(in[i], p, n)) weights[e.idBits] += e.weight;
            samples += n;
        }
        std::vector<CryptomatteEntry> entries;
        for (const auto &[id, weight] : weights) entries.push_back({id, weight});
        storeRanks(out, p, rankEntries(std::move(entries), ranks), samples);
    }
    return merged;
}

// Every part's names: a name may show in one range's pixels and not in another's.
std::string mergedManifest(const std::vector<Part> &parts, CryptomatteKind kind) {
    std::map<std::string, std::string> manifest;
    for (const Part &part : parts) {
        try {
            manifest.merge(storedManifest(*part.image, kind));
        } catch (const std::exception &e) {
            throw InputError(FileLoc{*part.name}, e.what());
        }
    }
    return manifestJson(manifest);
}

void copyWindow(const std::vector<float> &from, const PixelWindow &fromWindow, std::vector<float> &to,
                const PixelWindow &toWindow) {
    size_t width = size_t(fromWindow.width());
    for (int y = fromWindow.y0; y < fromWindow.y1; ++y) {
        auto row = from.begin() + std::ptrdiff_t(size_t(y - fromWindow.y0) * width);
        size_t start = size_t(y - toWindow.y0) * size_t(toWindow.width()) + size_t(fromWindow.x0 - toWindow.x0);
        std::copy(row, row + std::ptrdiff_t(width), to.begin() + std::ptrdiff_t(start));
    }
}

}  // namespace

LayeredImage mergeFilms(const std::vector<LayeredImage> &images, const std::vector<std::string> &names) {
    VEDUTA_CHECK(!images.empty() && images.size() == names.size(),
                 "mergeFilms needs one name per part and at least one part");
    std::vector<Part> parts;
    for (size_t i = 0; i < images.size(); ++i) parts.push_back(readPart(images[i], names[i]));
    for (const Part &part : parts) checkSameRender(part, parts[0]);
    std::vector<SampleRanges> groups = groupByWindow(parts);
    PixelWindow box = checkTiles(groups);

    const LayeredImage &first = images[0];
    LayeredImage merged;
    merged.fullWidth = first.fullWidth;
    merged.fullHeight = first.fullHeight;
    merged.dataWindow = box;
    for (const LayeredImage::Channel &channel : first.channels) {
        std::vector<float> &values = merged.addChannel(channel.name);
        if (isCryptomatteChannel(channel.name)) continue;
        for (const SampleRanges &group : groups) {
            copyWindow(mergeChannel(group, channel.name), group[0].image->dataWindow, values, box);
        }
    }
    merged.metadata = first.metadata;
    for (CryptomatteKind kind : kCryptomatteKinds) {
        int ranks = storedRanks(first, kind);
        if (ranks == 0) continue;
        for (const SampleRanges &group : groups) {
            for (const LayeredImage::Channel &channel : mergeCryptomatte(group, kind, ranks).channels) {
                copyWindow(channel.values, group[0].image->dataWindow, merged.find(channel.name)->values, box);
            }
        }
        merged.metadata[cryptomatteMetadataPrefix(cryptomatteTypeName(kind)) + "manifest"] =
            mergedManifest(parts, kind);
    }

    double seconds = 0;
    for (const Part &part : parts) seconds += attribute<double>(*part.image, *part.name, kRenderSecondsAttribute);
    const SampleRanges &ranges = groups[0];
    merged.metadata[kSamplesAttribute] = ranges.back().end() - ranges[0].offset;
    merged.metadata[kSampleOffsetAttribute] = ranges[0].offset;
    merged.metadata[kRenderSecondsAttribute] = seconds;
    merged.metadata["RenderTime"] = blenderRenderTime(seconds);
    return merged;
}

}  // namespace veduta

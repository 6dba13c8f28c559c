// writeExr / readExr: every codec, half and float channels, and which codecs change 32-bit floats
// (as changesFloatChannels says, which decides what `veduta render` refuses).
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <filesystem>

#include <Imath/half.h>

#include "core/hash.h"
#include "io/exr_file.h"
#include "test_scenes.h"

namespace veduta {
namespace {

LayeredImage testImage() {
    LayeredImage image;
    image.fullWidth = 40;
    image.fullHeight = 30;
    image.dataWindow = {3, 2, 35, 26};
    // Names that DWA compresses lossily (R, G, B) and ones it keeps (Z, X), with values that
    // need all 32 bits: ids as Cryptomatte stores them, depths of a far landscape.
    for (const char *name : {"ViewLayer.CryptoObject00.R", "ViewLayer.Depth.Z", "ViewLayer.IndexOB.X", "R"}) {
        std::vector<float> &values = image.addChannel(name);
        for (size_t p = 0; p < values.size(); ++p) {
            uint32_t bits = hashValues({uint32_t(p), uint32_t(image.channels.size())});
            values[p] = 1.0f + float(bits >> 8) / float(1 << 10);
        }
    }
    image.metadata["veduta.samples"] = 4;
    return image;
}

bool sameBits(const std::vector<float> &a, const std::vector<float> &b) {
    for (size_t p = 0; p < a.size(); ++p) {
        if (std::bit_cast<uint32_t>(a[p]) != std::bit_cast<uint32_t>(b[p])) return false;
    }
    return a.size() == b.size();
}

TEST(ExrFile, EveryCodecKeepsOrChangesFloatsAsDeclared) {
    test::ScratchFolder folder("exr_codecs");
    LayeredImage image = testImage();
    for (const std::string &name : exrCompressionNames()) {
        ExrFormat format;
        format.compression = *exrCompressionNamed(name);
        std::filesystem::path file = folder.path() / (name + ".exr");
        writeExr(image, file, format);
        ExrFormat read;
        LayeredImage back = readExr(file, &read);
        EXPECT_EQ(read.compression, format.compression) << name;
        EXPECT_TRUE(read.halfChannels.empty()) << name;
        EXPECT_EQ(back.dataWindow, image.dataWindow);
        EXPECT_EQ(std::get<int>(back.metadata.at("veduta.samples")), 4);
        bool changed = false;
        for (const LayeredImage::Channel &c : image.channels) changed |= !sameBits(c.values, back.find(c.name)->values);
        EXPECT_EQ(changed, changesFloatChannels(format.compression)) << name;
    }
}

TEST(ExrFile, HalfChannelsHoldHalfValuesAndStayHalf) {
    test::ScratchFolder folder("exr_half");
    LayeredImage image = testImage();
    ExrFormat format;
    format.halfChannels = {"R"};
    writeExr(image, folder.path() / "half.exr", format);
    ExrFormat read;
    LayeredImage back = readExr(folder.path() / "half.exr", &read);
    EXPECT_EQ(read.halfChannels, format.halfChannels);
    const std::vector<float> &original = image.find("R")->values, &halves = back.find("R")->values;
    for (size_t p = 0; p < original.size(); ++p) ASSERT_EQ(halves[p], float(Imath::half(original[p])));
    EXPECT_TRUE(sameBits(image.find("ViewLayer.Depth.Z")->values, back.find("ViewLayer.Depth.Z")->values));
}

}  // namespace
}  // namespace veduta

// Textures held in memory filter as OpenImageIO's TextureSystem does on the same cached file:
// texel for texel at a tiny footprint and on one mip level, within a few thousandths where two blend
// (OpenImageIO weighs its two levels a little differently).
#include <gtest/gtest.h>

#include <OpenImageIO/texture.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include <unistd.h>

#include "core/hash.h"
#include "images/color_config.h"
#include "images/resident_texture.h"
#include "images/texture_cache.h"
#include "test_paths.h"

namespace veduta {
namespace {

TEST(ResidentTexture, FiltersAsOpenImageIoDoes) {
    std::filesystem::path cache =
        std::filesystem::temp_directory_path() / ("veduta-resident-texture-" + std::to_string(::getpid()));
    std::filesystem::path source = test::sourceFile("materials/textures/plaster_diffuse.png");
    std::shared_ptr<const ColorConfig> config = ColorConfig::load();
    std::filesystem::path tx = cachedTexture(cache, source, *config->find("sRGB"), *config);
    std::optional<ResidentTexture> resident = ResidentTexture::read(tx, 1 << 20);
    ASSERT_TRUE(resident);
    ASSERT_EQ(resident->channels(), 3);
    EXPECT_FALSE(ResidentTexture::read(tx, 1000)) << "a 256 x 256 texture is over 1000 texels";

    OIIO::TextureSystem *system = OIIO::TextureSystem::create(false);
    OIIO::TextureOpt options;
    options.swrap = options.twrap = OIIO::TextureOpt::WrapPeriodic;
    options.mipmode = OIIO::TextureOpt::MipModeTrilinear;
    options.interpmode = OIIO::TextureOpt::InterpBilinear;
    OIIO::ustring name(tx.string());
    double worst = 0, worstTiny = 0;
    for (uint32_t i = 0; i < 4000; ++i) {
        float u = bitsToUnitFloat(hashValues({1, i})) * 4 - 2, v = bitsToUnitFloat(hashValues({2, i})) * 4 - 2;
        // Between two levels as often as on one.
        float between = i % 2 == 0 ? 1.0f : 1.0f + bitsToUnitFloat(hashValues({3, i}));
        float footprint = i % 4 == 0 ? 1e-5f : std::ldexp(between, -2 - int(i % 9));
        float ours[3], theirs[3];
        resident->lookup({u, v}, footprint, ours, 3);
        ASSERT_TRUE(system->texture(name, options, u, 1 - v, footprint, 0, 0, footprint, 3, theirs));
        for (int c = 0; c < 3; ++c) {
            double difference = std::abs(ours[c] - theirs[c]);
            (footprint < 1e-4f ? worstTiny : worst) = std::max(footprint < 1e-4f ? worstTiny : worst, difference);
        }
    }
    OIIO::TextureSystem::destroy(system);
    std::filesystem::remove_all(cache);
    std::printf("largest difference: %.2e at a tiny footprint, %.2e over all\n", worstTiny, worst);
    EXPECT_LT(worstTiny, 1e-5);
    EXPECT_LT(worst, 0.01);  // 2.2e-3 measured, on texels of about 0.5
}

}  // namespace
}  // namespace veduta

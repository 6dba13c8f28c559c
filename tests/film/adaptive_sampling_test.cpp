// Adaptive sampling's decisions on hand-made films: the noise estimate, when a pixel takes more
// samples, and where the passes end.
#include <cmath>

#include <gtest/gtest.h>

#include "film/adaptive_sampling.h"

namespace veduta {
namespace {

// A one-pixel film whose pixel took `count` samples, the even-numbered ones `even` and the odd
// ones `odd`.
Film filmWith(uint32_t count, Vec3f even, Vec3f odd) {
    Film film(1, 1, PixelWindow{0, 0, 1, 1});
    for (uint32_t i = 0; i < count; ++i) film.addSample(0, i, i % 2 == 0 ? even : odd, FirstHit{});
    return film;
}

RenderSettings adaptiveSettings(uint32_t samples, float threshold, uint32_t minSamples = 0) {
    RenderSettings settings;
    settings.samplesPerPixel = samples;
    settings.noiseThreshold = threshold;
    settings.minSamples = minSamples;
    return settings;
}

TEST(AdaptiveSampling, AgreeingHalvesConverge) {
    Film film = filmWith(16, Vec3f(0.5f, 0.4f, 0.3f), Vec3f(0.5f, 0.4f, 0.3f));
    EXPECT_EQ(pixelNoise(film, 0), 0.0f);
    EXPECT_FALSE(pixelNeedsSamples(film, 0, 16, 64, adaptiveSettings(64, 0.01f, 16)));
}

TEST(AdaptiveSampling, DisagreeingHalvesDoNotConverge) {
    Film film = filmWith(16, Vec3f(1.0f), Vec3f(0.0f));
    EXPECT_GT(pixelNoise(film, 0), 0.1f);
    EXPECT_TRUE(pixelNeedsSamples(film, 0, 16, 64, adaptiveSettings(64, 0.01f, 16)));
}

TEST(AdaptiveSampling, NoiseIsRelativeDeviationOverSamples) {
    // Halves 1 and 0: the mean 0.5 has variance (1 − 0)² / 4 per half-pair, relative to
    // 0.5² + ε; per sample that is 16 times more, and √v / n = √(relative variance of the mean / n).
    Film film = filmWith(16, Vec3f(1.0f), Vec3f(0.0f));
    EXPECT_NEAR(pixelNoise(film, 0), std::sqrt(0.25 / (0.25 + kRelMseEpsilon) / 16), 1e-6);
}

TEST(AdaptiveSampling, OddCountsCompareTheHalvesMeans) {
    // 9 even and 8 odd samples of the same value: no noise (the sum minus twice the even sum
    // would see one sample's worth).
    EXPECT_EQ(pixelNoise(filmWith(17, Vec3f(0.5f), Vec3f(0.5f)), 0), 0.0f);
}

TEST(AdaptiveSampling, FewerThanTwoSamplesAreInfinitelyNoisy) {
    EXPECT_EQ(pixelNoise(filmWith(0, Vec3f(0.5f), Vec3f(0.5f)), 0), INFINITY);
    EXPECT_EQ(pixelNoise(filmWith(1, Vec3f(0.5f), Vec3f(0.5f)), 0), INFINITY);
}

TEST(AdaptiveSampling, MinimumIsRespected) {
    Film film = filmWith(12, Vec3f(0.5f), Vec3f(0.5f));  // converged, but below the minimum
    EXPECT_TRUE(pixelNeedsSamples(film, 0, 12, 64, adaptiveSettings(64, 0.01f, 16)));
    EXPECT_FALSE(pixelNeedsSamples(film, 0, 12, 64, adaptiveSettings(64, 0.01f, 12)));
}

TEST(AdaptiveSampling, StoppedPixelStaysStopped) {
    // The pixel stopped after 16 samples; the render went on to 20 and 24. Even though its halves
    // disagree, a later check does not wake it: it was not checked after those passes.
    Film film = filmWith(16, Vec3f(1.0f), Vec3f(0.0f));
    RenderSettings settings = adaptiveSettings(64, 0.01f, 16);
    EXPECT_FALSE(pixelNeedsSamples(film, 0, 20, 64, settings));
    EXPECT_FALSE(pixelNeedsSamples(film, 0, 24, 64, settings));
}

TEST(AdaptiveSampling, NoPixelTakesMoreThanAsked) {
    Film film = filmWith(64, Vec3f(1.0f), Vec3f(0.0f));
    EXPECT_FALSE(pixelNeedsSamples(film, 0, 64, 64, adaptiveSettings(64, 0.01f, 16)));
    EXPECT_FALSE(pixelNeedsSamples(film, 0, 64, 64, adaptiveSettings(64, 0)));
}

TEST(AdaptiveSampling, WithoutThresholdEveryPixelTakesAll) {
    Film film = filmWith(32, Vec3f(0.5f), Vec3f(0.5f));
    EXPECT_TRUE(pixelNeedsSamples(film, 0, 32, 64, adaptiveSettings(64, 0)));
}

TEST(AdaptiveSampling, AutomaticMinimum) {
    EXPECT_EQ(adaptiveMinSamples(adaptiveSettings(128, 0.01f)), 16u);
    EXPECT_EQ(adaptiveMinSamples(adaptiveSettings(1024, 0.01f)), 64u);
    EXPECT_EQ(adaptiveMinSamples(adaptiveSettings(8, 0.01f)), 8u);  // never more than asked
    EXPECT_EQ(adaptiveMinSamples(adaptiveSettings(128, 0.01f, 40)), 40u);
}

TEST(AdaptiveSampling, PassesEndAtTheMinimumThenEveryStep) {
    RenderSettings settings = adaptiveSettings(30, 0.01f, 16);
    EXPECT_EQ(passEnd(0, 30, 1000, settings), 16u);
    EXPECT_EQ(passEnd(16, 30, 1000, settings), 16u + kAdaptiveStep);
    EXPECT_EQ(passEnd(28, 30, 1000, settings), 30u);  // the last pass is cut at the total
}

TEST(AdaptiveSampling, PassesWithoutThresholdTakeTheStep) {
    RenderSettings settings = adaptiveSettings(30, 0);
    EXPECT_EQ(passEnd(0, 30, 8, settings), 8u);
    EXPECT_EQ(passEnd(24, 30, 8, settings), 30u);
    EXPECT_EQ(passEnd(5, 30, 0, settings), 6u);  // a step of 0 still advances
}

}  // namespace
}  // namespace veduta

// How far one rendering of a view is from another (docs/compare.md): the measures of pbrt and
// Mitsuba's tests (relMSE), of image codecs (PSNR) and of perception (SSIM), and the overlap
// of two silhouettes. The first image is the reference.
#pragma once

#include <cstdint>
#include <vector>

#include "core/rgba_image.h"

namespace veduta {

struct ImageMetrics {
    double relMse = 0;  // of the linear colours, averaged over pixels and channels (core/rel_mse.h)
    double psnr = 0;    // dB, of the sRGB-encoded colours in [0, 1]; +infinity for equal images
    double ssim = 1;    // of the sRGB-encoded luma, 11 × 11 Gaussian window (σ 1.5), mean over the image
};

// Both images must have the same size (std::invalid_argument otherwise).
ImageMetrics compareRenderings(const RgbaImage &reference, const RgbaImage &test);

// Wang, Bovik, Sheikh and Simoncelli's SSIM (2004) of two grey images in [0, 1], with their
// constants K1 = 0.01, K2 = 0.03; the window is clipped at the image's borders.
double ssim(const std::vector<float> &a, const std::vector<float> &b, int width, int height);

// The intersection over the union of two masks (nonzero ids): 1 when both are empty.
double silhouetteIou(const std::vector<uint32_t> &a, const std::vector<uint32_t> &b);

// The sRGB-encoded luma (Rec. 709 weights) of each pixel, clamped to [0, 1].
std::vector<float> displayLuma(const RgbaImage &image);

}  // namespace veduta

// relMSE as pbrt, Mitsuba and `veduta diff` (src/io/image_compare.cpp) measure it, for bench
// programs that render in-process: the mean over pixels and colour channels of
// (x − ref)² / (ref² + 10⁻²), alpha left out.
#pragma once

#include <cstddef>

#include "core/rel_mse.h"
#include "core/rgba_image.h"

namespace veduta {

inline double relMse(const RgbaImage &image, const RgbaImage &reference) {
    double sum = 0;
    size_t count = 0;
    for (size_t i = 0; i < image.pixels().size(); ++i) {
        if (i % 4 == 3) continue;
        sum += relMseTerm(image.pixels()[i], reference.pixels()[i]);
        ++count;
    }
    return sum / double(count);
}

}  // namespace veduta

// The pixel reconstruction filter, by filter importance sampling (Ernst et al. 2006): each
// camera ray's offset from the pixel centre is drawn with the filter's density, so every
// sample has weight 1 and stays within its own pixel's sum. Unlike splatting, a pixel then
// depends on its own samples only, which keeps images identical for any tile size or region.
#pragma once

#include <cstdint>
#include <vector>

#include "core/vecmath.h"
#include "scene/render_settings.h"

namespace veduta {

// The 4-term Blackman–Harris window over [−window/2, window/2], unnormalised (1 at the centre).
float blackmanHarris(float x, float window);

// How far the filter reaches from the pixel centre, in pixels, by Cycles' reading of its width:
// a box of width w covers ±w/2, a Blackman–Harris window of width w covers ±w (Cycles' film
// doubles that width before it builds its table), so `filter_width` means the same in both.
float filterRadius(const PixelFilter &filter);

class FilterSampler {
  public:
    explicit FilterSampler(const PixelFilter &filter);
    // Offset from the pixel centre, in pixels, for a point of the unit square.
    Vec2f sample(Vec2f u) const { return {offset(u.x), offset(u.y)}; }

  private:
    float offset(float u) const;

    float radius_;
    // The filter's 1D distribution function at evenly spaced offsets, inverted at sample time
    // by a short search from the guide; the filter is separable, so x and y share it. (An inverse table at
    // evenly spaced probabilities, as Cycles keeps, spreads its first and last entries
    // uniformly over the tails and samples them far too often.)
    std::vector<double> cdf_;
    std::vector<double> inverseMass_;  // 1 / each cell's share, 0 for an empty one: no division per sample
    // For probability k/size(), the cell where the search for it starts.
    std::vector<uint16_t> guide_;
};

}  // namespace veduta

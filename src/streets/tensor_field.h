// A tensor field of street directions (Chen, Esch, Wonka, Müller & Zhang 2008, "Interactive
// Procedural Street Modeling", §4): the outlook Goitowski names for patterns beyond the
// L-system's (digest-002 §1, §9). Each point has a symmetric traceless tensor whose major
// eigenvector is the direction of the main streets there and whose minor one, at right angles,
// that of the side streets. Basis fields (a grid of one orientation, rings round a centre) are
// summed with weights that fall off with distance, and a seeded noise turns the sum a little,
// so that straight grids bend as old towns do. docs/tensor-streets.md.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "core/vecmath.h"

namespace veduta {

struct TensorBasis {
    enum class Kind {
        Grid,    // main streets along `angleDegrees` (counter-clockwise from east), side streets across
        Radial,  // main streets in rings round `centre`, side streets out from it
    };
    Kind kind = Kind::Grid;
    Vec2f centre;  // where its weight is `weight`
    float angleDegrees = 0;
    float weight = 1;
    // How fast its weight falls off: weight · exp(−decay · distance²), per square metre; 0: not at all.
    float decay = 0;
};

class TensorField {
  public:
    // `noiseDegrees`: the most the seeded noise turns the directions, varying over `noiseScale` metres.
    explicit TensorField(std::vector<TensorBasis> bases, uint32_t seed = 0, float noiseDegrees = 0,
                         float noiseScale = 300);

    // The unit direction of the main streets at p, or none where the field vanishes (bases
    // cancel there: a degenerate point, where streamlines stop). The side streets' is the same
    // turned 90° counter-clockwise. A direction and its opposite are one.
    std::optional<Vec2f> majorDirection(Vec2f p) const;

  private:
    float noiseRadians(Vec2f p) const;

    std::vector<TensorBasis> bases_;
    uint32_t seed_;
    float noiseRadians_, noiseScale_;
};

// The field `veduta generate --pattern tensor` and <generate pattern="tensor"> trace: a grid
// over the whole window at the origin, turned U[0°, 90°), and rings round a point U within half
// the radius of the origin that rule within about a third of the radius, the directions turned
// by up to 12° of noise varying over half the radius; all drawn from the seed.
TensorField townField(uint32_t seed, float radius);

}  // namespace veduta

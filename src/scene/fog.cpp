#include "scene/fog.h"

#include <cmath>
#include <limits>

namespace veduta {

// The optical depth ∫ σ(z(t)) dt of the exponential atmosphere in closed form: along a ray
// rising by dz per metre it is σ(z₀) · H / dz · (1 − exp(−dz·d / H)). Near-level rays take
// the series of that expression, which tends to σ(z₀) · d.
float Fog::transmittance(const Vec3f &origin, const Vec3f &direction, float distance) const {
    if (!enabled()) return 1;
    double h = scaleHeight;
    double sigma0 = double(density) * std::exp(-(double(origin.z) - baseHeight) / h);
    double k = double(direction.z) / h;  // how fast the extinction falls along the ray, per metre
    double d = distance;
    double depth;
    if (std::isinf(d)) {
        if (k <= 0) return 0;  // level or downward to infinity: nothing gets through
        depth = sigma0 / k;
    } else if (std::abs(k * d) < 1e-4) {
        depth = sigma0 * d * (1 - 0.5 * k * d);
    } else {
        depth = sigma0 * -std::expm1(-k * d) / k;
    }
    return float(std::exp(-depth));
}

}  // namespace veduta

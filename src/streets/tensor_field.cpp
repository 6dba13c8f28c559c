#include "streets/tensor_field.h"

#include <cmath>

#include "core/hash.h"
#include "core/random_streams.h"

namespace veduta {

namespace {

constexpr float kDegrees = 3.14159265358979f / 180;

// A sum of tensors shorter than this fraction of their weights has no direction worth following.
constexpr float kDegenerate = 1e-4f;

float smooth(float t) { return t * t * (3 - 2 * t); }

}  // namespace

TensorField::TensorField(std::vector<TensorBasis> bases, uint32_t seed, float noiseDegrees, float noiseScale) :
    bases_(std::move(bases)), seed_(seed), noiseRadians_(noiseDegrees * kDegrees), noiseScale_(noiseScale) {}

// Value noise in [−1, 1]: seeded values at the corners of a lattice of noiseScale_ metres,
// blended smoothly between them.
float TensorField::noiseRadians(Vec2f p) const {
    if (noiseRadians_ == 0) return 0;
    float x = p.x / noiseScale_, y = p.y / noiseScale_;
    float fx = std::floor(x), fy = std::floor(y);
    auto corner = [&](float cx, float cy) {
        uint32_t h =
            hashValues({seed_, uint32_t(int32_t(cx)), uint32_t(int32_t(cy)), streamTag(RandomStream::TensorNoise)});
        return 2 * bitsToUnitFloat(h) - 1;
    };
    float tx = smooth(x - fx), ty = smooth(y - fy);
    float bottom = corner(fx, fy) + (corner(fx + 1, fy) - corner(fx, fy)) * tx;
    float top = corner(fx, fy + 1) + (corner(fx + 1, fy + 1) - corner(fx, fy + 1)) * tx;
    return noiseRadians_ * (bottom + (top - bottom) * ty);
}

std::optional<Vec2f> TensorField::majorDirection(Vec2f p) const {
    // A traceless symmetric tensor [[a, b], [b, −a]] of a direction θ is (a, b) = (cos 2θ, sin 2θ):
    // doubling the angle makes θ and θ + 180° one, and the sum of tensors is the sum of these.
    float a = 0, b = 0, weights = 0;
    for (const TensorBasis &basis : bases_) {
        Vec2f d = p - basis.centre;
        float weight = basis.weight * std::exp(-basis.decay * dot(d, d));
        weights += std::abs(weight);
        float theta = basis.angleDegrees * kDegrees;
        if (basis.kind == TensorBasis::Kind::Radial) {
            if (dot(d, d) == 0) continue;  // the centre itself has no ring
            theta = std::atan2(d.y, d.x) + 90 * kDegrees;
        }
        a += weight * std::cos(2 * theta);
        b += weight * std::sin(2 * theta);
    }
    if (!(std::hypot(a, b) > kDegenerate * weights)) return std::nullopt;
    float theta = std::atan2(b, a) / 2 + noiseRadians(p);
    return Vec2f{std::cos(theta), std::sin(theta)};
}

TensorField townField(uint32_t seed, float radius) {
    auto draw = [&](uint32_t index) {
        return bitsToUnitFloat(hashValues({seed, index, streamTag(RandomStream::TensorLayout)}));
    };
    float ringAngle = 2 * 3.14159265f * draw(1), ringDistance = 0.5f * radius * std::sqrt(draw(2));
    Vec2f ringCentre{ringDistance * std::cos(ringAngle), ringDistance * std::sin(ringAngle)};
    float reach = radius / 3;
    std::vector<TensorBasis> bases{
        {TensorBasis::Kind::Grid, {0, 0}, 90 * draw(0), 1, 0},
        // At `reach` from its centre the rings weigh e² ≈ 7 times less than there, where they weigh 4.
        {TensorBasis::Kind::Radial, ringCentre, 0, 4, 2 / (reach * reach)},
    };
    return TensorField(std::move(bases), seed, 12, radius / 2);
}

}  // namespace veduta

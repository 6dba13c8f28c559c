#include "geo/pavement_texture.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/hash.h"
#include "core/noise.h"

namespace veduta {

namespace {

// How much of a pattern of feature size `size` a footprint still resolves: all of it up to
// half the size, none from the size on.
double resolved(double footprint, double size) { return std::clamp(2 - 2 * footprint / size, 0.0, 1.0); }

Vec3f mix(Vec3f a, Vec3f b, double t) { return a + (b - a) * float(t); }

// A surface's colour and relief at one point: its height in metres above the pavement's plane.
struct Surface {
    Vec3f colour;
    double height = 0;
};

// Variation common to every pavement: broad patches (wear, repairs, dirt) and a mottle.
double mottle(Vec2d p, uint32_t seed, double footprint) {
    return 0.12 * fractalNoise({p.x / 25, p.y / 25}, seed, 3, 0.5f, footprint / 25) +
        0.18 * fractalNoise(p, seed + 1, 4, 0.55f, footprint);
}

Surface asphalt(Vec2d p, uint32_t seed, double footprint) {
    const Vec3f base{0.105f, 0.105f, 0.115f};
    double light = 1 + mottle(p, seed, footprint);
    // The aggregate: chips of about 1 cm, some lighter, some darker than the binder.
    double chips = resolved(footprint, 0.012);
    CellDistances c = cellDistances({p.x / 0.012, p.y / 0.012}, seed + 2);
    double chip = chips * (bitsToUnitFloat(c.cell) - 0.5) * 0.5;
    double height = chips * 0.002 * std::min(1.0, (c.second - c.nearest) * 2);
    return {base * float(light * (1 + chip)), height};
}

// Setts (Kleinpflaster) in rows across the road, 16 cm deep along it, 14 cm wide, each row
// shifted by its own amount, in joints of 1.6 cm.
Surface cobbles(Vec2d p, uint32_t seed, double footprint) {
    constexpr double kLength = 0.14, kDepth = 0.16, kJoint = 0.008;
    const Vec3f stoneMean{0.2f, 0.185f, 0.17f}, joint{0.07f, 0.065f, 0.06f};
    constexpr double kStoneShare = (kLength - 2 * kJoint) * (kDepth - 2 * kJoint) / (kLength * kDepth);
    Vec3f mean = mix(joint, stoneMean, kStoneShare);
    double light = 1 + mottle(p, seed, footprint);
    double detail = resolved(footprint, kDepth);
    if (detail == 0) return {mean * float(light), 0};
    int64_t row = int64_t(std::floor(p.y / kDepth));
    double shift = bitsToUnitFloat(hashValues({seed, uint32_t(row), uint32_t(row >> 32)})) * kLength;
    double along = p.x + shift;
    int64_t column = int64_t(std::floor(along / kLength));
    double a = along - double(column) * kLength, b = p.y - double(row) * kDepth;
    double edge = std::min({a, kLength - a, b, kDepth - b});
    uint32_t stone = hashValues({seed, uint32_t(row), uint32_t(column), uint32_t(column >> 32)});
    Vec3f colour = stoneMean * float(0.7 + 0.6 * bitsToUnitFloat(stone));
    double inStone = std::clamp((edge - kJoint) / std::max(footprint, 1e-4) + 0.5, 0.0, 1.0);
    // Worn round: a stone rises by 1 cm over the 2 cm next to its joint.
    double rise = std::clamp((edge - kJoint) / 0.02, 0.0, 1.0);
    double height = 0.01 * rise * (2 - rise);
    return {mix(mean, mix(joint, colour, inStone), detail) * float(light), detail * height};
}

// Slabs 5 m long, the joints sawn across and along the middle.
Surface concrete(Vec2d p, uint32_t seed, double footprint) {
    const Vec3f base{0.36f, 0.35f, 0.33f};
    double light = 1 + 0.6 * mottle(p, seed, footprint);
    double across = std::abs(p.y - 5 * std::round(p.y / 5)), middle = std::abs(p.x);
    double joint = std::max(1 - std::min(across, middle) / 0.006, 0.0) * resolved(footprint, 0.05);
    return {base * float(light * (1 - 0.6 * joint)), -0.005 * joint};
}

// Loose stones as cells (cellular noise): `size` metres across, each its own shade in
// [shade, shade + spread], darker toward its edges (d2 − d1 below `edgeWidth` of a cell), the
// edges `depth` metres below the stones' tops. `mean` is what shade × edge term averages to over
// many stones (measured; the edge term is near 1 on most of a stone), taken off so that the
// stones average to the base colour and a far look sees what close ones do.
struct Stones {
    Vec3f base;
    double size, edgeWidth, shade, spread, edgeDarkness, mean, depth;
    uint32_t salt;
};

Surface stones(Vec2d p, uint32_t seed, double footprint, const Stones &s) {
    double light = 1 + mottle(p, seed, footprint);
    double detail = resolved(footprint, s.size);
    CellDistances c = cellDistances({p.x / s.size, p.y / s.size}, seed + s.salt);
    double edge = std::clamp((c.second - c.nearest) / s.edgeWidth, 0.0, 1.0);
    double shade = s.shade + s.spread * bitsToUnitFloat(c.cell);
    double stone = detail * (shade * (1 - s.edgeDarkness + s.edgeDarkness * edge) - s.mean);
    return {s.base * float(light * (1 + stone)), detail * s.depth * edge};
}

// Gravel: pebbles of about 3 cm, the gaps between them dark.
Surface gravel(Vec2d p, uint32_t seed, double footprint) {
    return stones(p, seed, footprint, {{0.42f, 0.38f, 0.31f}, 0.03, 0.15, 0.75, 0.5, 0.45, 0.85, 0.006, 3});
}

// Ballast: dark reddish stones of about 5 cm, their edges (d2 − d1) dark.
Surface ballastStones(Vec2d p, uint32_t seed, double footprint) {
    return stones(p, seed, footprint, {{0.27f, 0.235f, 0.215f}, 0.05, 0.2, 0.8, 0.4, 0.4, 0.88, 0.015, 4});
}

// A standard-gauge track on ballast: concrete sleepers 2.6 m × 0.26 m every 0.6 m and two
// rails 1.435 m apart (inner edges), 7 cm wide at the head.
Surface track(Vec2d p, double centre, Surface under, double footprint) {
    constexpr double kSleeperHalf = 1.3, kSleeperDepth = 0.26, kSleeperPitch = 0.6;
    constexpr double kGaugeHalf = 0.7175 + 0.035, kRailHalf = 0.035;
    const Vec3f sleeperColour{0.42f, 0.41f, 0.39f}, railColour{0.22f, 0.15f, 0.11f};
    double x = p.x - centre;
    double detail = resolved(footprint, kSleeperDepth);
    if (std::abs(x) <= kSleeperHalf) {
        double share = kSleeperDepth / kSleeperPitch;
        double along = p.y - kSleeperPitch * std::floor(p.y / kSleeperPitch);
        double onSleeper = along < kSleeperDepth ? 1 : 0;
        double weight = detail * onSleeper + (1 - detail) * share;
        under = {mix(under.colour, sleeperColour, weight), under.height + 0.05 * detail * onSleeper};
    }
    double rail = std::abs(std::abs(x) - kGaugeHalf);
    double railDetail = resolved(footprint, 2 * kRailHalf);
    double onRail = rail < kRailHalf ? 1.0 : 0.0;
    double railWeight = railDetail * onRail + (1 - railDetail) * std::clamp(2 * kRailHalf / footprint, 0.0, 1.0);
    if (std::abs(x) <= kGaugeHalf + kRailHalf + footprint)
        under = {mix(under.colour, railColour, railWeight), under.height + 0.15 * railDetail * onRail};
    return under;
}

Surface ballast(Vec2d p, uint32_t seed, double footprint, int tracks) {
    Surface s = ballastStones(p, seed, footprint);
    constexpr double kTrackSpacing = 4.5;
    for (int t = 0; t < tracks; ++t) s = track(p, (t - 0.5 * (tracks - 1)) * kTrackSpacing, s, footprint);
    return s;
}

}  // namespace

PavementTexture::PavementTexture(Pavement pavement, PavementMap map, uint32_t seed, int tracks) :
    pavement_(pavement), map_(map), seed_(seed), tracks_(std::max(tracks, 1)) {}

std::string PavementTexture::fingerprint() const {
    return fmt::format("pavement {} {} {} {}", pavementName(pavement_),
                       map_ == PavementMap::Colour ? "colour" : "normal", seed_, tracks_);
}

void PavementTexture::lookup(Vec2f uv, float footprint, float *out, int count) const {
    auto surfaceAt = [&](Vec2d p) -> Surface {
        double f = std::max(double(footprint), 0.0);
        switch (pavement_) {
        case Pavement::Asphalt: return asphalt(p, seed_, f);
        case Pavement::Cobbles: return cobbles(p, seed_, f);
        case Pavement::Concrete: return concrete(p, seed_, f);
        case Pavement::Gravel: return gravel(p, seed_, f);
        case Pavement::Ballast: return ballast(p, seed_, f, tracks_);
        }
        return asphalt(p, seed_, f);
    };
    Vec2d p{uv.x, uv.y};
    float value[3];
    if (map_ == PavementMap::Colour) {
        Vec3f c = surfaceAt(p).colour;
        value[0] = c.x, value[1] = c.y, value[2] = c.z;
    } else {
        // The relief's slope by central differences over the footprint (at least 2 mm).
        double step = std::max(0.5 * double(footprint), 0.002);
        double du = (surfaceAt({p.x + step, p.y}).height - surfaceAt({p.x - step, p.y}).height) / (2 * step);
        double dv = (surfaceAt({p.x, p.y + step}).height - surfaceAt({p.x, p.y - step}).height) / (2 * step);
        Vec3f n = normalize(Vec3f(float(-du), float(-dv), 1));
        value[0] = n.x * 0.5f + 0.5f, value[1] = n.y * 0.5f + 0.5f, value[2] = n.z * 0.5f + 0.5f;
    }
    for (int c = 0; c < count && c < 3; ++c) out[c] = value[c];
}

}  // namespace veduta

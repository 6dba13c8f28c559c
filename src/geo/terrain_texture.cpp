#include "geo/terrain_texture.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/noise.h"
#include "geo/height_queries.h"

namespace veduta {

namespace {

double smoothstep(double edge0, double edge1, double x) {
    double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
    return t * t * (3 - 2 * t);
}

Vec3f mix(Vec3f a, Vec3f b, double t) { return a + (b - a) * float(t); }

// Noise of one scale: `period` metres, band-limited to the footprint.
double scale(Vec2d p, uint32_t seed, double period, int octaves, double footprint) {
    return fractalNoise({p.x / period, p.y / period}, seed, octaves, 0.5f, footprint / period);
}

// Classes whose ground is soil and plants, and so turns to rock on steep slopes and to alpine
// ground high up; water, traffic areas and footprints keep their colour.
bool natural(LandClass c) {
    switch (c) {
    case LandClass::Other:
    case LandClass::Settlement:
    case LandClass::Park:
    case LandClass::Farmland:
    case LandClass::Grassland:
    case LandClass::Forest:
    case LandClass::Shrubs:
    case LandClass::TreeRow:
    case LandClass::Hedge: return true;
    default: return false;
    }
}

const Vec3f kSilt{0.16f, 0.14f, 0.1f};
const Vec3f kRock{0.23f, 0.22f, 0.21f}, kScree{0.3f, 0.29f, 0.27f}, kAlpine{0.27f, 0.26f, 0.18f},
    kSnow{0.82f, 0.84f, 0.88f};

}  // namespace

TerrainTexture::TerrainTexture(LandClass landClass, Vec3f albedo, std::shared_ptr<const HeightGrid> grid,
                               LocalFrame frame, std::shared_ptr<const ShoreDistance> shore, uint32_t seed,
                               TerrainLook look) :
    landClass_(landClass),
    albedo_(albedo),
    grid_(std::move(grid)),
    frame_(frame),
    shore_(std::move(shore)),
    seed_(seed),
    look_(look) {}

std::string TerrainTexture::fingerprint() const {
    // The grid's identity is its extent and a sample of heights: the same DGM file gives the same.
    size_t n = grid_->heights.size();
    return fmt::format("terrain {} {} {} {} {} {} {} {} {} {} {} {} {} {}", landClassName(landClass_), albedo_.x,
                       albedo_.y, albedo_.z, seed_, grid_->west, grid_->south, grid_->spacing, grid_->columns,
                       grid_->rows, n ? grid_->heights[n / 3] : 0.0f, n ? grid_->heights[2 * n / 3] : 0.0f,
                       look_.rockSlope, look_.treeLine);
}

Vec3f TerrainTexture::ground(Vec2d p, double footprint) const {
    if (!natural(landClass_)) return albedo_;
    double broad = scale(p, seed_, 400, 2, footprint), middle = scale(p, seed_ + 1, 25, 3, footprint);
    double fine = scale(p, seed_ + 2, 1.5, 3, footprint), speck = scale(p, seed_ + 3, 0.15, 2, footprint);
    Vec3f colour = albedo_;
    switch (landClass_) {
    case LandClass::Farmland: {
        // Fields of bare soil and of green crop in patches of a few hundred metres, furrows
        // 0.8 m apart whose direction turns slowly across the land.
        Vec3f crop{0.17f, 0.26f, 0.07f};
        colour = mix(albedo_, crop, smoothstep(-0.15, 0.15, scale(p, seed_ + 4, 300, 2, footprint)));
        double angle = M_PI * scale(p, seed_ + 5, 800, 1, footprint);
        double across = p.x * std::cos(angle) + p.y * std::sin(angle);
        double furrows =
            std::clamp(2 - 2 * footprint / 0.8, 0.0, 1.0) * (0.5 + 0.5 * std::sin(2 * M_PI * across / 0.8));
        colour = colour * float(1 + 0.3 * broad + 0.2 * middle + 0.15 * fine - 0.18 * furrows);
        break;
    }
    case LandClass::Forest:  // litter: needles, leaves and moss
        colour = colour * float(1 + 0.2 * broad + 0.25 * middle + 0.3 * fine + 0.35 * speck);
        break;
    default: {  // grass: drier, yellower patches; tussocks; blades
        Vec3f dry = albedo_ * Vec3f(1.35f, 1.2f, 0.7f);
        colour = mix(albedo_, dry, smoothstep(-0.2, 0.3, broad + 0.5 * middle));
        colour = colour * float(1 + 0.15 * middle + 0.2 * fine + 0.2 * speck);
        break;
    }
    }
    MapPoint at = frame_.toMap(Vec2f{float(p.x), float(p.y)});
    double slope = slopeDegrees(*grid_, at).value_or(0);
    double height = bilinearHeight(*grid_, at).value_or(0);
    // Ragged edges: the thresholds wander with the medium scale.
    double steep = slope + 6 * middle;
    double rock = smoothstep(look_.rockSlope, look_.bareRockSlope, steep);
    double scree = smoothstep(look_.screeSlope, look_.rockSlope, steep) * (1 - rock);
    double alpine = smoothstep(look_.treeLine - 100, look_.treeLine + 250, height + 60 * broad);
    double snow = smoothstep(look_.snowLine, look_.snowLine + 200, height + 80 * broad) * (1 - rock);
    colour = mix(colour, kAlpine * float(1 + 0.2 * fine), alpine);
    colour = mix(colour, kScree * float(1 + 0.3 * speck), scree);
    colour = mix(colour, kRock * float(1 + 0.25 * fine + 0.15 * middle), rock);
    colour = mix(colour, kSnow * float(1 + 0.05 * fine), snow);
    if (shore_) {  // wet silt along the water, its edge wandering by a metre
        double reach = look_.shoreWidth + 1;
        double wet = smoothstep(look_.shoreWidth, 0, shore_->distance(p, reach) + middle);
        colour = mix(colour, kSilt * float(1 + 0.3 * speck), 0.9 * wet);
    }
    return {std::clamp(colour.x, 0.0f, 1.0f), std::clamp(colour.y, 0.0f, 1.0f), std::clamp(colour.z, 0.0f, 1.0f)};
}

void TerrainTexture::lookup(Vec2f uv, float footprint, float *out, int count) const {
    Vec3f c = ground({uv.x, uv.y}, std::max(double(footprint), 0.0));
    float value[3] = {c.x, c.y, c.z};
    for (int k = 0; k < count && k < 3; ++k) out[k] = value[k];
}

bool treeMayGrow(const HeightGrid &grid, const LocalFrame &frame, Vec2d p, const TerrainLook &look) {
    MapPoint at = frame.toMap(Vec2f{float(p.x), float(p.y)});
    return slopeDegrees(grid, at).value_or(0) < look.rockSlope && bilinearHeight(grid, at).value_or(0) < look.treeLine;
}

}  // namespace veduta

#include "core/noise.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/hash.h"

namespace veduta {

namespace {

uint32_t latticeHash(int64_t x, int64_t y, uint32_t seed) {
    return hashValues({seed, uint32_t(x), uint32_t(x >> 32), uint32_t(y), uint32_t(y >> 32)});
}

// One of eight unit gradients, evenly spread, dotted with the offset from the lattice point.
double gradientDot(uint32_t hash, double dx, double dy) {
    constexpr double kDiagonal = 0.7071067811865476;
    switch (hash & 7u) {
    case 0: return dx;
    case 1: return -dx;
    case 2: return dy;
    case 3: return -dy;
    case 4: return kDiagonal * (dx + dy);
    case 5: return kDiagonal * (dx - dy);
    case 6: return kDiagonal * (-dx + dy);
    default: return -kDiagonal * (dx + dy);
    }
}

double fade(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }

}  // namespace

float gradientNoise(Vec2d p, uint32_t seed) {
    double fx = std::floor(p.x), fy = std::floor(p.y);
    int64_t x = int64_t(fx), y = int64_t(fy);
    double dx = p.x - fx, dy = p.y - fy;
    double n00 = gradientDot(latticeHash(x, y, seed), dx, dy);
    double n10 = gradientDot(latticeHash(x + 1, y, seed), dx - 1, dy);
    double n01 = gradientDot(latticeHash(x, y + 1, seed), dx, dy - 1);
    double n11 = gradientDot(latticeHash(x + 1, y + 1, seed), dx - 1, dy - 1);
    double u = fade(dx), v = fade(dy);
    double bottom = n00 + u * (n10 - n00), top = n01 + u * (n11 - n01);
    return float(bottom + v * (top - bottom));
}

float fractalNoise(Vec2d p, uint32_t seed, int octaves, float persistence, double footprint) {
    double sum = 0, amplitude = 1, total = 0, frequency = 1;
    for (int k = 0; k < octaves; ++k) {
        double period = 1 / frequency;
        // Full weight while the period is two footprints or more, none at one footprint.
        double weight = footprint <= 0 ? 1 : std::clamp(period / footprint - 1, 0.0, 1.0);
        if (weight > 0)
            sum += weight * amplitude *
                gradientNoise({p.x * frequency, p.y * frequency}, seed + uint32_t(k) * 0x9e3779b9u);
        total += amplitude;
        amplitude *= persistence;
        frequency *= 2;
    }
    return float(sum / total);
}

CellDistances cellDistances(Vec2d p, uint32_t seed) {
    double fx = std::floor(p.x), fy = std::floor(p.y);
    int64_t x = int64_t(fx), y = int64_t(fy);
    CellDistances d;
    d.nearest = d.second = std::numeric_limits<double>::infinity();
    for (int64_t j = y - 1; j <= y + 1; ++j) {
        for (int64_t i = x - 1; i <= x + 1; ++i) {
            uint32_t h = latticeHash(i, j, seed);
            Vec2d point{double(i) + bitsToUnitFloat(mix32(h)), double(j) + bitsToUnitFloat(mix32(h ^ 0x5bd1e995u))};
            double distance = length(point - p);
            if (distance < d.nearest) {
                d.second = d.nearest;
                d.nearest = distance;
                d.cell = h;
            } else if (distance < d.second) {
                d.second = distance;
            }
        }
    }
    return d;
}

}  // namespace veduta

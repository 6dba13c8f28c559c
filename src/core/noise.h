// Procedural noise for textures computed where they are looked up (land and pavement): gradient
// noise on a hashed lattice (Perlin's, with his quintic fade), its fractal sum band-limited to a
// footprint, and cellular distances (Worley). Each is a pure function of the point and a seed,
// so a texture is the same on every run and thread.
#pragma once

#include <cstdint>

#include "core/vecmath.h"

namespace veduta {

// Gradient noise with one lattice point per unit: 0 at lattice points, within about ±0.7,
// smooth (C2) between.
float gradientNoise(Vec2d p, uint32_t seed);

// The sum of `octaves` octaves of gradientNoise, octave k at frequency 2^k and amplitude
// persistence^k, normalised so that the sum's amplitude is that of one octave. An octave
// whose period (1 / 2^k units) is at most `footprint` averages to its mean 0 over the
// footprint and is left out, one an octave coarser fades out linearly towards it: a wide
// footprint sees the broad variation without the aliasing of the fine.
float fractalNoise(Vec2d p, uint32_t seed, int octaves, float persistence, double footprint);

// The distances from p to the nearest and the second nearest of a set of points, one jittered
// point in each unit cell, and the nearest point's cell as a hash (for a per-cell colour).
struct CellDistances {
    double nearest = 0, second = 0;
    uint32_t cell = 0;
};
CellDistances cellDistances(Vec2d p, uint32_t seed);

}  // namespace veduta

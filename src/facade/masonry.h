// What every kind of masonry produces (digest-001 §2.5): the stones of one wall face, laid in the
// wall's own plane, and the mortar between them. The wall is a polygon with holes (its openings)
// in metres: x along the wall seen from outside, y up, the origin where the caller puts it.
// Masonry is a texture of the wall, not geometry (L1013: stones as geometry would "explode" the
// triangle count): these polygons are baked to images, while the wall's mesh stays coarse.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "core/image.h"
#include "core/vecmath.h"

namespace veduta {

// A wall face to be filled: its outline and its openings, both counter-clockwise.
struct WallFace {
    std::vector<Vec2d> outline;
    std::vector<std::vector<Vec2d>> openings;
};

struct Stone {
    std::vector<Vec2d> outline;  // counter-clockwise, convex or not as its kind allows
    Vec3f colour;                // linear RGB in [0, 1]
    double depth = 0;            // how far it stands out of the mortar (Brick `tiefe`), metres
};

// A relief over part of a wall (an ornament's height map, ornament_growth.h): `heights`, one
// channel of metres, top row first, covers [origin.x, origin.x + width · cellSize] ×
// [origin.y, origin.y + height · cellSize] of the wall. Baked, it raises the wall's height field,
// whose slopes give the normals.
struct MasonryRelief {
    Vec2d origin;
    double cellSize = 0;
    std::shared_ptr<const Image> heights;
};

struct Masonry {
    std::vector<Stone> stones;
    Vec3f mortarColour;
    double mortarThickness = 0;  // metres
    std::optional<MasonryRelief> relief = {};
};

// A wall's masonry before it is laid: what lays it on the wall's face (which the holder keeps), and
// a hash of all it lays from besides the face (the description's text and scale, the seed, the
// wall's identity). Its errors were reported when
// it was made (checkStyleMasonry), so that the laying can wait until the stones are needed: a bake
// lays every wall, a MasonryShader a wall when a lookup first reaches it, so that walls nobody sees
// (party walls, the backs of a row) are never laid.
struct MasonryRecipe {
    std::function<Masonry(const WallFace &face)> lay;
    uint64_t hash = 0;
};

}  // namespace veduta

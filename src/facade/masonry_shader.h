// Masonry shaded where the renderer looks it up, instead of baked to images (masonry_texture.h):
// the other way issue 22's Deliver 4 allows (digest-001 §2.5). Measured (docs/facades.md), a
// shaded point costs less than the three filtered lookups of baked maps and nothing is baked, so a
// scene builds faster and holds less, while a whole render takes as long. A wall given as a recipe
// is laid when a lookup first reaches it (once, whichever thread asks; the stones are the same
// whenever they are laid), so a wall no ray meets costs nothing. Each lookup finds the stone under
// its point through a grid of the stones' boxes and shades it as bakeMasonry would a texel there:
// * diffuse: the stone's colour, else the mortar's;
// * normal: a stone's edge falls to the mortar over the look's bevel (its depth over the bevel, the
//   slope toward the nearest edge), the relief's slope added;
// * specular: the look's stone or mortar value.
// Footprints: where a pixel spans more than the bevel, the slope spreads over the footprint, as the
// bake's finite differences spread it over two texels. Finer joints are left to the renderer's
// samples, which a pixel averages; only where a footprint spans more than a stone do colour,
// normal and specular blend toward the wall's means, reaching them at four stones, as the bake's
// coarser mip levels do. (The bake takes what lies under a texel's centre, so its joints alias
// where a texel is wider than a joint: the shader's do not.)
//
// Texture space: walls are stacked in v, each `pitch` metres above the one before, so one texture
// serves a building: wall w's point (x, y) lies at (x, y − lowest + w · pitch), u and v in metres
// (a material reads it with textureSize 1).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "core/vecmath.h"
#include "facade/masonry.h"
#include "facade/masonry_texture.h"
#include "scene/textures.h"

namespace veduta {

// A wall's masonry as laid, or, while `recipe.lay` is set, empty: the recipe lays it.
struct ShadedWall {
    Masonry masonry;
    WallFace face;
    MasonryRecipe recipe = {};
};

struct MasonrySample {
    Vec3f colour;
    Vec3f normal{0, 0, 1};  // tangent space: x along the wall, y up, z out
    float specular = 0;
};

class MasonryShader {
  public:
    // Throws std::invalid_argument for a face with fewer than three corners.
    explicit MasonryShader(std::vector<ShadedWall> walls, const MasonryLook &look = {});

    // Where wall `wall`'s point lies in the texture.
    Vec2f uvOf(size_t wall, Vec2d point) const;
    // The masonry at `uv`, filtered over `footprint` metres. A point beside every stone of its
    // wall (or outside the wall) is mortar. A footprint over the whole texture (all its walls)
    // gives the mean of all walls, by their areas.
    MasonrySample shade(Vec2f uv, float footprint) const;
    // Changes when a stone, the mortar, a relief or the look would.
    const std::string &fingerprint() const { return fingerprint_; }
    // Unique to this shader in the process (never 0).
    uint64_t serial() const { return serial_; }

  private:
    // A wall's stones sorted for lookups, with their means.
    struct Laid {
        Masonry masonry;
        double stoneSize = 0;  // the side of a mean stone's box
        double cell = 0;
        int columns = 0, rows = 0;
        std::vector<std::vector<uint32_t>> stonesByCell;
        MasonrySample mean;
        double area = 0;  // of the wall less its openings, or of its stones where they cover more
    };
    struct Wall {
        ShadedWall given;  // until laid
        Vec2d low, high;
        std::once_flag once;
        Laid laid;
    };

    static Laid prepare(const Wall &wall, Masonry masonry, const MasonryLook &look);
    const Laid &laid(Wall &wall) const;
    const MasonrySample &wholeMean() const;
    MasonrySample pointSample(const Wall &wall, const Laid &laid, Vec2d p, double footprint) const;

    // Pointers: a wall's once_flag does not move. The walls are laid in const lookups (each once,
    // under its flag).
    std::vector<std::unique_ptr<Wall>> walls_;
    MasonryLook look_;
    double lowest_ = 0, pitch_ = 1;
    double wholeTexture_ = 0;  // the footprint that spans every wall
    mutable std::once_flag wholeMeanOnce_;
    mutable MasonrySample wholeMean_;
    std::string fingerprint_;
    uint64_t serial_ = 0;
};

enum class MasonryMap { Diffuse, Normal, Specular };

// One of a shader's three maps as a texture: diffuse RGB, normal RGB stored n · 0.5 + 0.5 as
// normal maps are, specular one channel.
class MasonryTexture final : public ProceduralTexture {
  public:
    MasonryTexture(std::shared_ptr<const MasonryShader> shader, MasonryMap map) :
        shader_(std::move(shader)), map_(map) {}

    int channels() const override { return map_ == MasonryMap::Specular ? 1 : 3; }
    std::string fingerprint() const override;
    void lookup(Vec2f uv, float footprint, float *out, int count) const override;

  private:
    std::shared_ptr<const MasonryShader> shader_;
    MasonryMap map_;
};

}  // namespace veduta

// Deliver 4 of issue 22 asks to bake masonry or shade it procedurally, "measure which". The same
// brick wall (gruenderzeit_front.h) three ways, one thread each:
//   * BM_BakeBrickWall: baked once to diffuse, normal and specular images at 1 cm a texel
//     (texels/s), what veduta does;
//   * BM_LookUpBakedBrickWall: what each shaded point then costs the renderer, three filtered
//     lookups of those images in the texture registry (points/s);
//   * BM_ShadeBrickWallProcedurally: what each shaded point would cost a procedural shader
//     (points/s).
// A still pays the bake once per texel (about one a pixel, masonry_maps.h) and the lookup or the
// procedural shading at every sample that hits a wall (pixels × spp × bounces); the closing note
// of issue 22 sets these rates against the street's texels and samples.
//
//   build/release/bench/bench_masonry_shading --benchmark_repetitions=5
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <vector>

#include "facade/brick_bond.h"
#include "facade/masonry_texture.h"
#include "gruenderzeit_front.h"
#include "io/image_library.h"

namespace veduta {
namespace {

using namespace bench;

constexpr double kTexel = 0.01;

// 65536 points over the 15 × 16 m wall: scattered (state.range(0) = 0), as a path's bounces reach
// it, or in rows (1), as a tile of camera samples does, one jittered point a cell of a 256 × 256
// grid.
std::vector<Vec2d> shadedPoints(bool inRows) {
    std::vector<Vec2d> points;
    uint32_t state = 1871;
    auto next = [&] { return double(state = state * 1664525u + 1013904223u) / 4294967296.0; };
    for (int row = 0; row < 256; ++row)
        for (int column = 0; column < 256; ++column) {
            double x = inRows ? (column + next()) / 256 : next(), y = inRows ? (row + next()) / 256 : next();
            points.push_back({15 * x, 16 * y});
        }
    return points;
}

void countPoints(benchmark::State &state, size_t points) {
    state.SetLabel(state.range(0) ? "in rows" : "scattered");
    state.counters["points/s"] = benchmark::Counter(double(points), benchmark::Counter::kIsIterationInvariantRate);
}

Masonry frontBricks() {
    return layBrickBond(parseBrickBond(kFigure5_7, "figure-5.7"), gruenderzeitFront(), {0.125, 1871, 1});
}

void BM_BakeBrickWall(benchmark::State &state) {
    WallFace front = gruenderzeitFront();
    Masonry bricks = frontBricks();
    size_t texels = 0;
    for (auto _ : state) {
        MasonryTextures textures = bakeMasonry(bricks, front, kTexel);
        texels = size_t(textures.diffuse.width) * size_t(textures.diffuse.height);
    }
    state.counters["texels"] = double(texels);
    state.counters["texels/s"] = benchmark::Counter(double(texels), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_BakeBrickWall)->Unit(benchmark::kMillisecond);

void BM_LookUpBakedBrickWall(benchmark::State &state) {
    WallFace front = gruenderzeitFront();
    MasonryTextures baked = bakeMasonry(frontBricks(), front, kTexel);
    std::filesystem::path cache = std::filesystem::temp_directory_path() / "veduta-bench-masonry-shading";
    std::shared_ptr<Textures> textures = imageLibrary().makeTextures(cache);
    int width = baked.diffuse.width, height = baked.diffuse.height;
    TextureId diffuse = textures->add(std::move(baked.diffuse)), normal = textures->add(std::move(baked.normal)),
              specular = textures->add(std::move(baked.specular));
    std::vector<Vec2d> points = shadedPoints(state.range(0) != 0);
    float footprint = float(1.0 / width);  // a pixel a texel, as the atlas is sized
    float sum = 0;
    for (auto _ : state)
        for (Vec2d p : points) {
            Vec2f uv{float(p.x / (kTexel * width)), float(p.y / (kTexel * height))};
            float values[4];
            textures->lookup(diffuse, uv, footprint, values, 4);
            sum += values[0];
            textures->lookup(normal, uv, footprint, values, 3);
            sum += values[0];
            textures->lookup(specular, uv, footprint, values, 1);
            sum += values[0];
        }
    benchmark::DoNotOptimize(sum);
    countPoints(state, points.size());
}
BENCHMARK(BM_LookUpBakedBrickWall)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// Shading procedurally: what a shader would do at each point it shades on the wall, with the
// stones laid beforehand. It finds the stone under the point through a grid of the stones' boxes
// (cells of one brick's size), and the stone's nearest edge: within the bevel, the colour fades
// to the mortar's and the normal tilts toward that edge (the bake's chamfer bevel). A lower
// bound for a real shader: no specular, no relief, no filtering of joints finer than a pixel.
class StoneGrid {
  public:
    StoneGrid(const Masonry &masonry, const WallFace &face, double cell) : masonry_(masonry), cell_(cell) {
        for (Vec2d p : face.outline) {
            low_ = {std::min(low_.x, p.x), std::min(low_.y, p.y)};
            high_ = {std::max(high_.x, p.x), std::max(high_.y, p.y)};
        }
        columns_ = int(std::ceil((high_.x - low_.x) / cell)) + 1;
        rows_ = int(std::ceil((high_.y - low_.y) / cell)) + 1;
        cells_.resize(size_t(columns_) * size_t(rows_));
        for (uint32_t s = 0; s < masonry.stones.size(); ++s) {
            Vec2d a{INFINITY, INFINITY}, b{-INFINITY, -INFINITY};
            for (Vec2d p : masonry.stones[s].outline) {
                a = {std::min(a.x, p.x), std::min(a.y, p.y)};
                b = {std::max(b.x, p.x), std::max(b.y, p.y)};
            }
            for (int y = row(a.y); y <= row(b.y); ++y)
                for (int x = column(a.x); x <= column(b.x); ++x)
                    cells_[size_t(y) * size_t(columns_) + size_t(x)].push_back(s);
        }
    }

    struct Shaded {
        Vec3f colour;
        Vec3f normal{0, 0, 1};
    };

    Shaded shade(Vec2d p, double bevel) const {
        for (uint32_t s : cells_[size_t(row(p.y)) * size_t(columns_) + size_t(column(p.x))]) {
            const Stone &stone = masonry_.stones[s];
            Edge edge = nearestEdge(stone.outline, p);
            if (edge.distance < 0) continue;
            if (edge.distance >= bevel) return {stone.colour};
            float t = float(edge.distance / bevel);
            Vec3f colour = masonry_.mortarColour + (stone.colour - masonry_.mortarColour) * t;
            return {colour, normalize(Vec3f(float(edge.outward.x), float(edge.outward.y), 1.0f + t))};
        }
        return {masonry_.mortarColour};
    }

  private:
    int column(double x) const { return std::clamp(int((x - low_.x) / cell_), 0, columns_ - 1); }
    int row(double y) const { return std::clamp(int((y - low_.y) / cell_), 0, rows_ - 1); }

    struct Edge {
        double distance = INFINITY;  // −1: outside the stone
        Vec2d outward;
    };

    // The nearest edge of the convex counter-clockwise `outline` to `p` inside it.
    static Edge nearestEdge(const std::vector<Vec2d> &outline, Vec2d p) {
        Edge nearest;
        for (size_t i = 0; i < outline.size(); ++i) {
            Vec2d a = outline[i], b = outline[(i + 1) % outline.size()];
            Vec2d d = b - a;
            double side = cross(d, p - a);
            if (side < 0) return {-1, {}};
            double distance = side / length(d);
            if (distance < nearest.distance) nearest = {distance, Vec2d{d.y, -d.x} * (1 / length(d))};
        }
        return nearest;
    }

    const Masonry &masonry_;
    double cell_;
    Vec2d low_{INFINITY, INFINITY}, high_{-INFINITY, -INFINITY};
    int columns_ = 0, rows_ = 0;
    std::vector<std::vector<uint32_t>> cells_;
};

void BM_ShadeBrickWallProcedurally(benchmark::State &state) {
    WallFace front = gruenderzeitFront();
    Masonry bricks = layBrickBond(parseBrickBond(kFigure5_7, "figure-5.7"), front, {0.125, 1871, 1});
    StoneGrid grid(bricks, front, 0.25);
    std::vector<Vec2d> points = shadedPoints(state.range(0) != 0);
    float sum = 0;
    for (auto _ : state)
        for (Vec2d p : points) {
            StoneGrid::Shaded shaded = grid.shade(p, 0.004);
            sum += shaded.colour.x + shaded.normal.x;
        }
    benchmark::DoNotOptimize(sum);
    countPoints(state, points.size());
}
BENCHMARK(BM_ShadeBrickWallProcedurally)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace veduta

int main(int argc, char **argv) {
    // The image plugin of this build unless the caller names one.
    setenv("VEDUTA_IMAGE_PLUGIN", VEDUTA_IMAGE_PLUGIN_FILE, 0);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}

#include "facade/masonry_shader.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <map>
#include <stdexcept>
#include <tuple>
#include <utility>

#include <fmt/format.h>

#include "core/polygon_area.h"
#include "core/polygon_bounds.h"
#include "core/word_hasher.h"

namespace veduta {
namespace {

// The most grid cells one wall's stones are sorted into; a finer grid is made coarser.
constexpr double kMaxCells = double(1 << 22);
// A footprint of one stone starts to blend toward the wall's mean, one of this many reaches it.
constexpr double kStonesToMean = 4;

// Whether `p` lies inside `polygon` (even-odd), and its distance to the nearest edge with that
// edge's outward normal (to the right of a counter-clockwise edge).
struct Inside {
    bool inside = false;
    double distance = INFINITY;
    Vec2d outward;
};

Inside insideOf(const std::vector<Vec2d> &polygon, Vec2d p) {
    Inside result;
    for (size_t i = 0; i < polygon.size(); ++i) {
        Vec2d a = polygon[i], b = polygon[(i + 1) % polygon.size()], d = b - a;
        if ((a.y <= p.y) != (b.y <= p.y) && p.x < a.x + (p.y - a.y) * d.x / d.y) result.inside = !result.inside;
        double lengthSquared = dot(d, d);
        if (lengthSquared == 0) continue;
        double t = std::clamp(dot(p - a, d) / lengthSquared, 0.0, 1.0);
        double distance = length(p - (a + d * t));
        if (distance < result.distance) {
            result.distance = distance;
            result.outward = Vec2d{d.y, -d.x} * (1 / std::sqrt(lengthSquared));
        }
    }
    return result;
}

}  // namespace

MasonryShader::Laid MasonryShader::prepare(const Wall &wall, Masonry masonry, const MasonryLook &look) {
    const WallFace &face = wall.given.face;
    Laid laid;
    Vec2d extent{std::max(wall.high.x - wall.low.x, 1e-6), std::max(wall.high.y - wall.low.y, 1e-6)};
    // Cells about a stone's box: a lookup tests a stone or two.
    double boxes = 0, stoneArea = 0;
    Vec3f stoneColour(0.0f);
    for (const Stone &stone : masonry.stones) {
        auto [a, b] = polygonBounds(stone.outline);
        boxes += (b.x - a.x) * (b.y - a.y);
        double area = std::abs(signedArea(stone.outline));
        stoneArea += area;
        stoneColour += stone.colour * float(area);
    }
    const size_t stones = masonry.stones.size();
    laid.stoneSize = stones ? std::max(std::sqrt(boxes / double(stones)), 1e-3) : std::max(extent.x, extent.y);
    laid.cell = std::max(laid.stoneSize, std::sqrt(extent.x * extent.y / kMaxCells));
    laid.columns = std::max(1, int(std::ceil(extent.x / laid.cell)));
    laid.rows = std::max(1, int(std::ceil(extent.y / laid.cell)));
    laid.stonesByCell.resize(size_t(laid.columns) * size_t(laid.rows));
    auto column = [&](double x) { return std::clamp(int((x - wall.low.x) / laid.cell), 0, laid.columns - 1); };
    auto row = [&](double y) { return std::clamp(int((y - wall.low.y) / laid.cell), 0, laid.rows - 1); };
    for (uint32_t s = 0; s < stones; ++s) {
        auto [a, b] = polygonBounds(masonry.stones[s].outline);
        for (int y = row(a.y); y <= row(b.y); ++y)
            for (int x = column(a.x); x <= column(b.x); ++x)
                laid.stonesByCell[size_t(y) * size_t(laid.columns) + size_t(x)].push_back(s);
    }
    // The means over the wall less its openings: stones by their area, the rest mortar.
    double area = std::abs(signedArea(face.outline));
    for (const std::vector<Vec2d> &opening : face.openings) area -= std::abs(signedArea(opening));
    double mortarArea = std::max(0.0, area - stoneArea), total = std::max(area, stoneArea);
    const Vec3f &mortar = masonry.mortarColour;
    laid.area = total;
    if (total > 0) {
        laid.mean.colour = (stoneColour + mortar * float(mortarArea)) * float(1 / total);
        laid.mean.specular = float((stoneArea * look.stoneSpecular + mortarArea * look.mortarSpecular) / total);
    } else {
        laid.mean.colour = mortar;
        laid.mean.specular = look.mortarSpecular;
    }
    laid.masonry = std::move(masonry);
    return laid;
}

MasonryShader::MasonryShader(std::vector<ShadedWall> walls, const MasonryLook &look) : look_(look) {
    static std::atomic<uint64_t> shaders{0};
    serial_ = ++shaders;
    WordHasher print;
    auto addPolygon = [&](const std::vector<Vec2d> &polygon) {
        print.add(uint64_t(polygon.size()));
        for (Vec2d p : polygon) print.add(p);
    };
    auto addColour = [&](Vec3f c) { print.add(Vec2d{c.x, c.y}), print.add(double(c.z)); };
    print.add(double(look.stoneSpecular)), print.add(double(look.mortarSpecular)), print.add(look.bevel);
    std::map<const Image *, uint64_t> reliefHashes;
    for (const ShadedWall &w : walls) {
        addPolygon(w.face.outline);
        for (const auto &opening : w.face.openings) addPolygon(opening);
        print.add(w.recipe.lay ? w.recipe.hash : 0);
        addColour(w.masonry.mortarColour), print.add(w.masonry.mortarThickness);
        for (const Stone &stone : w.masonry.stones)
            addPolygon(stone.outline), addColour(stone.colour), print.add(stone.depth);
        if (w.masonry.relief) {
            const MasonryRelief &relief = *w.masonry.relief;
            print.add(relief.origin), print.add(relief.cellSize);
            // The aprons of one window style share their heights: each image is hashed once.
            auto [at, fresh] = reliefHashes.try_emplace(relief.heights.get(), 0);
            if (fresh) {
                WordHasher heights;
                heights.add(relief.heights->width), heights.add(relief.heights->height);
                for (float h : relief.heights->pixels) heights.add(double(h));
                at->second = heights.value();
            }
            print.add(at->second);
        }
    }
    fingerprint_ = fmt::format("{:016x}", print.value());
    for (ShadedWall &given : walls) {
        if (given.face.outline.size() < 3) throw std::invalid_argument("a wall face with fewer than three corners");
        auto wall = std::make_unique<Wall>();
        std::tie(wall->low, wall->high) = polygonBounds(given.face.outline);
        wall->given = std::move(given);
        walls_.push_back(std::move(wall));
    }
    if (walls_.empty()) return;
    lowest_ = walls_[0]->low.y;
    double highest = walls_[0]->high.y;
    for (const auto &w : walls_) lowest_ = std::min(lowest_, w->low.y), highest = std::max(highest, w->high.y);
    pitch_ = std::ceil(highest - lowest_) + 1;
    wholeTexture_ = pitch_ * double(walls_.size());
    for (const auto &w : walls_) wholeTexture_ = std::max(wholeTexture_, w->high.x - w->low.x);
}

const MasonrySample &MasonryShader::wholeMean() const {
    std::call_once(wholeMeanOnce_, [&] {
        double area = 0, specular = 0;
        Vec3f colour(0.0f);
        for (const auto &w : walls_) {
            const Laid &wall = laid(*w);
            area += wall.area;
            colour += wall.mean.colour * float(wall.area);
            specular += wall.mean.specular * wall.area;
        }
        if (area > 0) wholeMean_ = {colour * float(1 / area), {0, 0, 1}, float(specular / area)};
        else wholeMean_ = laid(*walls_[0]).mean;
    });
    return wholeMean_;
}

const MasonryShader::Laid &MasonryShader::laid(Wall &wall) const {
    std::call_once(wall.once, [&] {
        // A recipe that throws (an internal error) leaves the wall to be laid by the next lookup.
        Masonry masonry =
            wall.given.recipe.lay ? wall.given.recipe.lay(wall.given.face) : std::move(wall.given.masonry);
        wall.given.recipe = {};
        wall.laid = prepare(wall, std::move(masonry), look_);
    });
    return wall.laid;
}

Vec2f MasonryShader::uvOf(size_t wall, Vec2d point) const {
    return {float(point.x), float(point.y - lowest_ + double(wall) * pitch_)};
}

MasonrySample MasonryShader::pointSample(const Wall &wall, const Laid &laid, Vec2d p, double footprint) const {
    const Masonry &masonry = laid.masonry;
    MasonrySample sample{masonry.mortarColour, {0, 0, 1}, look_.mortarSpecular};
    Vec2d slope{0, 0};  // the height's gradient, metres per metre
    int column = std::clamp(int((p.x - wall.low.x) / laid.cell), 0, laid.columns - 1);
    int row = std::clamp(int((p.y - wall.low.y) / laid.cell), 0, laid.rows - 1);
    for (uint32_t s : laid.stonesByCell[size_t(row) * size_t(laid.columns) + size_t(column)]) {
        const Stone &stone = masonry.stones[s];
        Inside inside = insideOf(stone.outline, p);
        if (!inside.inside) continue;
        sample.colour = stone.colour;
        sample.specular = look_.stoneSpecular;
        // The bevel, or the footprint where it is wider: the height falls by the stone's depth
        // toward its nearest edge.
        double bevel = std::max(look_.bevel, footprint);
        if (bevel > 0 && inside.distance < bevel) slope = inside.outward * (-stone.depth / bevel);
        break;
    }
    if (masonry.relief) {
        const MasonryRelief &relief = *masonry.relief;
        double h = std::max(relief.cellSize, footprint) / 2;
        slope = slope +
            Vec2d{reliefHeightAt(relief, p + Vec2d{h, 0}) - reliefHeightAt(relief, p - Vec2d{h, 0}),
                  reliefHeightAt(relief, p + Vec2d{0, h}) - reliefHeightAt(relief, p - Vec2d{0, h})} *
                (1 / (2 * h));
    }
    sample.normal = normalize(Vec3f(float(-slope.x), float(-slope.y), 1.0f));
    return sample;
}

MasonrySample MasonryShader::shade(Vec2f uv, float footprint) const {
    if (walls_.empty()) return {};
    if (footprint >= wholeTexture_) return wholeMean();
    int w = std::clamp(int(std::floor(double(uv.y) / pitch_)), 0, int(walls_.size()) - 1);
    Wall &wall = *walls_[size_t(w)];
    const Laid &laid = this->laid(wall);
    Vec2d p{uv.x, double(uv.y) - double(w) * pitch_ + lowest_};
    double toMean = std::clamp((footprint - laid.stoneSize) / ((kStonesToMean - 1) * laid.stoneSize), 0.0, 1.0);
    if (toMean >= 1) return laid.mean;
    MasonrySample point = pointSample(wall, laid, p, footprint);
    if (toMean <= 0) return point;
    auto t = float(toMean);
    return {point.colour + (laid.mean.colour - point.colour) * t,
            normalize(point.normal + (laid.mean.normal - point.normal) * t),
            point.specular + (laid.mean.specular - point.specular) * t};
}

std::string MasonryTexture::fingerprint() const {
    const char *maps[] = {"diffuse", "normal", "specular"};
    return fmt::format("masonry {} {}", shader_->fingerprint(), maps[int(map_)]);
}

void MasonryTexture::lookup(Vec2f uv, float footprint, float *out, int count) const {
    // A material reads the diffuse, normal and specular maps at one point one after the other:
    // the point is shaded once.
    struct Last {
        uint64_t shader = 0;  // its serial: an address may be a later shader's
        Vec2f uv;
        float footprint = 0;
        MasonrySample sample;
    };
    thread_local Last last;
    if (last.shader != shader_->serial() || last.uv.x != uv.x || last.uv.y != uv.y || last.footprint != footprint)
        last = {shader_->serial(), uv, footprint, shader_->shade(uv, footprint)};
    const MasonrySample &sample = last.sample;
    float values[3];
    switch (map_) {
    case MasonryMap::Diffuse:
        values[0] = sample.colour.x, values[1] = sample.colour.y, values[2] = sample.colour.z;
        break;
    case MasonryMap::Normal:
        values[0] = sample.normal.x * 0.5f + 0.5f, values[1] = sample.normal.y * 0.5f + 0.5f;
        values[2] = sample.normal.z * 0.5f + 0.5f;
        break;
    case MasonryMap::Specular: values[0] = sample.specular; break;
    }
    std::copy_n(values, std::min(count, channels()), out);
}

}  // namespace veduta

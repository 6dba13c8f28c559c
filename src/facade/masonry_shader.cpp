#include "facade/masonry_shader.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "core/polygon_area.h"
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

MasonryShader::Wall MasonryShader::prepare(ShadedWall shaded, const MasonryLook &look) {
    const WallFace &face = shaded.face;
    if (face.outline.size() < 3) throw std::invalid_argument("a wall face with fewer than three corners");
    Wall wall;
    wall.low = wall.high = face.outline[0];
    for (Vec2d p : face.outline) {
        wall.low = {std::min(wall.low.x, p.x), std::min(wall.low.y, p.y)};
        wall.high = {std::max(wall.high.x, p.x), std::max(wall.high.y, p.y)};
    }
    Vec2d extent{std::max(wall.high.x - wall.low.x, 1e-6), std::max(wall.high.y - wall.low.y, 1e-6)};
    // Cells about a stone's box: a lookup tests a stone or two.
    double boxes = 0, stoneArea = 0;
    Vec3f stoneColour(0.0f);
    for (const Stone &stone : shaded.masonry.stones) {
        Vec2d a = stone.outline[0], b = stone.outline[0];
        for (Vec2d p : stone.outline)
            a = {std::min(a.x, p.x), std::min(a.y, p.y)}, b = {std::max(b.x, p.x), std::max(b.y, p.y)};
        boxes += (b.x - a.x) * (b.y - a.y);
        double area = std::abs(signedArea(stone.outline));
        stoneArea += area;
        stoneColour += stone.colour * float(area);
    }
    const size_t stones = shaded.masonry.stones.size();
    wall.stoneSize = stones ? std::max(std::sqrt(boxes / double(stones)), 1e-3) : std::max(extent.x, extent.y);
    wall.cell = std::max(wall.stoneSize, std::sqrt(extent.x * extent.y / kMaxCells));
    wall.columns = std::max(1, int(std::ceil(extent.x / wall.cell)));
    wall.rows = std::max(1, int(std::ceil(extent.y / wall.cell)));
    wall.stonesByCell.resize(size_t(wall.columns) * size_t(wall.rows));
    auto column = [&](double x) { return std::clamp(int((x - wall.low.x) / wall.cell), 0, wall.columns - 1); };
    auto row = [&](double y) { return std::clamp(int((y - wall.low.y) / wall.cell), 0, wall.rows - 1); };
    for (uint32_t s = 0; s < stones; ++s) {
        const std::vector<Vec2d> &outline = shaded.masonry.stones[s].outline;
        Vec2d a = outline[0], b = outline[0];
        for (Vec2d p : outline)
            a = {std::min(a.x, p.x), std::min(a.y, p.y)}, b = {std::max(b.x, p.x), std::max(b.y, p.y)};
        for (int y = row(a.y); y <= row(b.y); ++y)
            for (int x = column(a.x); x <= column(b.x); ++x)
                wall.stonesByCell[size_t(y) * size_t(wall.columns) + size_t(x)].push_back(s);
    }
    // The means over the wall less its openings: stones by their area, the rest mortar.
    double area = std::abs(signedArea(face.outline));
    for (const std::vector<Vec2d> &opening : face.openings) area -= std::abs(signedArea(opening));
    double mortarArea = std::max(0.0, area - stoneArea), total = std::max(area, stoneArea);
    const Vec3f &mortar = shaded.masonry.mortarColour;
    if (total > 0) {
        wall.mean.colour = (stoneColour + mortar * float(mortarArea)) * float(1 / total);
        wall.mean.specular = float((stoneArea * look.stoneSpecular + mortarArea * look.mortarSpecular) / total);
    } else {
        wall.mean.colour = mortar;
        wall.mean.specular = look.mortarSpecular;
    }
    wall.masonry = std::move(shaded.masonry);
    return wall;
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
    for (const ShadedWall &w : walls) {
        addPolygon(w.face.outline);
        for (const auto &opening : w.face.openings) addPolygon(opening);
        addColour(w.masonry.mortarColour), print.add(w.masonry.mortarThickness);
        for (const Stone &stone : w.masonry.stones)
            addPolygon(stone.outline), addColour(stone.colour), print.add(stone.depth);
        if (w.masonry.relief) {
            const MasonryRelief &relief = *w.masonry.relief;
            print.add(relief.origin), print.add(relief.cellSize);
            for (float h : relief.heights->pixels) print.add(double(h));
        }
    }
    fingerprint_ = fmt::format("{:016x}", print.value());
    for (ShadedWall &w : walls) walls_.push_back(prepare(std::move(w), look));
    if (walls_.empty()) return;
    lowest_ = walls_[0].low.y;
    double highest = walls_[0].high.y;
    for (const Wall &w : walls_) lowest_ = std::min(lowest_, w.low.y), highest = std::max(highest, w.high.y);
    pitch_ = std::ceil(highest - lowest_) + 1;
}

Vec2f MasonryShader::uvOf(size_t wall, Vec2d point) const {
    return {float(point.x), float(point.y - lowest_ + double(wall) * pitch_)};
}

MasonrySample MasonryShader::pointSample(const Wall &wall, Vec2d p, double footprint) const {
    MasonrySample sample{wall.masonry.mortarColour, {0, 0, 1}, look_.mortarSpecular};
    Vec2d slope{0, 0};  // the height's gradient, metres per metre
    int column = std::clamp(int((p.x - wall.low.x) / wall.cell), 0, wall.columns - 1);
    int row = std::clamp(int((p.y - wall.low.y) / wall.cell), 0, wall.rows - 1);
    for (uint32_t s : wall.stonesByCell[size_t(row) * size_t(wall.columns) + size_t(column)]) {
        const Stone &stone = wall.masonry.stones[s];
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
    if (wall.masonry.relief) {
        const MasonryRelief &relief = *wall.masonry.relief;
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
    int w = std::clamp(int(std::floor(double(uv.y) / pitch_)), 0, int(walls_.size()) - 1);
    const Wall &wall = walls_[size_t(w)];
    Vec2d p{uv.x, double(uv.y) - double(w) * pitch_ + lowest_};
    double toMean = std::clamp((footprint - wall.stoneSize) / ((kStonesToMean - 1) * wall.stoneSize), 0.0, 1.0);
    if (toMean >= 1) return wall.mean;
    MasonrySample point = pointSample(wall, p, footprint);
    if (toMean <= 0) return point;
    auto t = float(toMean);
    return {point.colour + (wall.mean.colour - point.colour) * t,
            normalize(point.normal + (wall.mean.normal - point.normal) * t),
            point.specular + (wall.mean.specular - point.specular) * t};
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

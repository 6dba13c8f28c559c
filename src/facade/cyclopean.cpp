#include "facade/cyclopean.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include <fmt/format.h>

#include "core/hash.h"
#include "core/random_streams.h"
#include "facade/brick_bond.h"
#include "facade/convex_pieces.h"
#include "facade/description_text.h"

namespace veduta {

namespace {

// Seeds per grid cell on average (L1094 says only "equally many"): enough that a cell's seeds lie
// irregularly, few enough that the grid still spreads them evenly before Lloyd.
constexpr double kSeedsPerCell = 4;
// How often a seed is drawn in its cell before it is given up: cells are mostly wall, so a draw
// misses with odds below one half.
constexpr uint32_t kSeedDraws = 64;
// The most grid cells per seed the wall asks for (see gridSeeds).
constexpr double kMaxCellsPerSeed = 16;
// The 20 % fewer stones than hexagonal packing holds (L1091).
constexpr double kPackingShare = 0.8;
// Counts are whole numbers of double; larger ones saturate (and are refused by the limits).
constexpr double kLargestCount = 1e15;

// What each hash draws, so that the draws for one stone or cell never share numbers.
enum Draw : uint32_t { SeedX, SeedY, StoneColour, JointWidth };

float draw(uint32_t seed, uint32_t wallId, Draw what, uint32_t index, uint32_t second = 0, uint32_t third = 0) {
    return bitsToUnitFloat(
        hashValues({seed, wallId, streamTag(RandomStream::MasonryCyclopean), what, index, second, third}));
}

Vec2d unit(Vec2d v) { return v * (1 / length(v)); }

// A count from the thesis' formula: floored, with a nanometre's slack so that a wall of exactly
// k courses is not rounded down to k − 1, never negative.
int64_t wholeCount(double value) { return int64_t(std::clamp(std::floor(value + 1e-9), 0.0, kLargestCount)); }

void checkDescription(const CyclopeanMasonry &d) {
    if ((d.stones > 0) == (d.spacing > 0)) {
        throw InputError(d.loc, "a cyclopean wall needs either a stone count (Steine) or a spacing (Abstand) above 0");
    }
    if (d.stones < 0 || d.spacing < 0 || !std::isfinite(d.spacing)) {
        throw InputError(d.loc, "a cyclopean wall's stone count and spacing must not be negative");
    }
    if (d.stones > kMaxCyclopeanStones) {
        throw InputError(
            d.loc,
            fmt::format("{} stones on a cyclopean wall are more than the {} allowed", d.stones, kMaxCyclopeanStones));
    }
    if (d.lloyd < 0 || d.lloyd > kMaxLloydSteps) {
        throw InputError(d.loc, fmt::format("Lloyd steps must lie in 0..{}, not {}", kMaxLloydSteps, d.lloyd));
    }
    if (!(d.joint >= 0) || !std::isfinite(d.joint) || !(d.depth >= 0) || !std::isfinite(d.depth)) {
        throw InputError(d.loc, "a cyclopean wall's joint and depth must be finite and not negative");
    }
    for (const Vec3f &colour : {d.startColour, d.endColour, d.mortarColour}) {
        for (int c = 0; c < 3; ++c) {
            if (!(colour[c] >= 0 && colour[c] <= 1)) throw InputError(d.loc, "colours must lie in [0, 1]");
        }
    }
}

// r from `Abstand`, or from `Steine` by the hexagonal cells they fill (see the header).
double meanRadius(const WallRegion &region, const CyclopeanMasonry &d) {
    if (d.spacing > 0) return d.spacing / 2;
    return std::sqrt(kPackingShare * region.area() / (2 * std::sqrt(3.0) * d.stones));
}

int64_t targetCount(const WallRegion &region, const CyclopeanMasonry &d, double radius) {
    if (d.stones > 0) return d.stones;
    Vec2d size = region.upper() - region.lower();
    double share = region.area() / (size.x * size.y);
    int64_t count =
        std::max<int64_t>(1, std::llround(double(cyclopeanStoneCount(size.x, size.y, radius).stones) * share));
    if (count > kMaxCyclopeanStones) {
        throw InputError(d.loc,
                         fmt::format("a spacing of {} m puts {} stones on a {:.3g} × {:.3g} m wall, more than the "
                                     "{} allowed",
                                     d.spacing, count, size.x, size.y, kMaxCyclopeanStones));
    }
    return count;
}

double segmentDistance(Vec2d point, Vec2d a, Vec2d b) {
    Vec2d span = b - a;
    double t = std::clamp(dot(point - a, span) / dot(span, span), 0.0, 1.0);
    return length(point - (a + span * t));
}

struct ReflexCorner {
    Vec2d corner;
    Vec2d across;             // unit, perpendicular to the bisector
    double boundaryDistance;  // to the nearest boundary edge not at the corner
};

// The region's corners whose inside angle exceeds 180°. The region lies left of every ring (outline
// counter-clockwise, holes clockwise), so these are the right turns.
std::vector<ReflexCorner> reflexCorners(const WallRegion &region) {
    std::vector<const std::vector<Vec2d> *> rings;
    for (const RegionPiece &piece : region.pieces()) {
        rings.push_back(&piece.outline);
        for (const auto &hole : piece.holes) rings.push_back(&hole);
    }
    std::vector<ReflexCorner> corners;
    for (const auto *r : rings) {
        size_t n = r->size();
        for (size_t i = 0; i < n; ++i) {
            Vec2d previous = (*r)[(i + n - 1) % n], corner = (*r)[i], next = (*r)[(i + 1) % n];
            if (cross(corner - previous, next - corner) >= 0) continue;
            // With u, w the unit edge directions away from the corner, the bisector runs along
            // u + w and the line of the seeds along w − u, which stays exact for near-straight corners.
            Vec2d across = unit(unit(next - corner) - unit(previous - corner));
            double distance = 1e300;
            for (const auto *other : rings) {
                for (size_t j = 0; j < other->size(); ++j) {
                    Vec2d a = (*other)[j], b = (*other)[(j + 1) % other->size()];
                    if (a == corner || b == corner) continue;
                    distance = std::min(distance, segmentDistance(corner, a, b));
                }
            }
            corners.push_back({corner, across, distance});
        }
    }
    return corners;
}

// Seeds spread over the cells of a grid that lie mostly in the wall (L1094), about `count` in all.
std::vector<Vec2d> gridSeeds(const WallRegion &region, int64_t count, uint32_t seed, uint32_t wallId) {
    Vec2d lower = region.lower(), size = region.upper() - region.lower();
    double side = std::sqrt(kSeedsPerCell * region.area() / double(count));
    // A thin frame round a large opening has little area in a large box: cells of its share would
    // number far more than the seeds, each measured against every ring. Coarser cells keep the
    // work in proportion to the seeds; the lone seed per cell still spreads them.
    double cap = kMaxCellsPerSeed * double(count);
    double across = std::max(1.0, std::round(size.x / side)), up = std::max(1.0, std::round(size.y / side));
    while (across * up > cap) {
        side *= std::max(1.25, std::sqrt(across * up / cap));
        across = std::max(1.0, std::round(size.x / side)), up = std::max(1.0, std::round(size.y / side));
    }
    int64_t columns = int64_t(across), rows = int64_t(up);
    Vec2d cell{size.x / double(columns), size.y / double(rows)};

    struct GridCell {
        uint32_t index;
        Vec2d lower;
        double share;  // of it in the wall
    };
    std::vector<GridCell> cells;
    for (int64_t row = 0; row < rows; ++row) {
        for (int64_t column = 0; column < columns; ++column) {
            Vec2d at = lower + Vec2d{cell.x * double(column), cell.y * double(row)};
            std::vector<Vec2d> square{at, at + Vec2d{cell.x, 0}, at + cell, at + Vec2d{0, cell.y}};
            double share = region.moments(square, at).area / (cell.x * cell.y);
            if (share > 0) cells.push_back({uint32_t(row * columns + column), at, share});
        }
    }
    auto mostlyWall = [](const GridCell &c) { return c.share >= 0.5; };
    if (std::any_of(cells.begin(), cells.end(), mostlyWall)) std::erase_if(cells, std::not_fn(mostlyWall));

    int64_t perCell = std::max<int64_t>(1, std::llround(double(count) / double(cells.size())));
    std::vector<Vec2d> seeds;
    for (const GridCell &c : cells) {
        for (uint32_t k = 0; k < uint32_t(perCell); ++k) {
            for (uint32_t attempt = 0; attempt < kSeedDraws; ++attempt) {
                Vec2d p = c.lower +
                    Vec2d{cell.x * draw(seed, wallId, SeedX, c.index, k, attempt),
                          cell.y * draw(seed, wallId, SeedY, c.index, k, attempt)};
                if (region.contains(p)) {
                    seeds.push_back(p);
                    break;
                }
            }
        }
    }
    return seeds;
}

// The convex stone a cell part leaves when each of its edges moves inwards by its half joint.
std::vector<Vec2d> shrunkStone(const std::vector<Vec2d> &part, double halfJoint, uint32_t seed, uint32_t wallId,
                               uint32_t stone) {
    std::vector<Vec2d> outline = part;
    for (size_t i = 0; i < part.size() && !outline.empty(); ++i) {
        Vec2d a = part[i], b = part[(i + 1) % part.size()];
        Vec2d inward = unit(Vec2d{a.y - b.y, b.x - a.x});
        double offset = halfJoint * (0.5 + draw(seed, wallId, JointWidth, stone, uint32_t(i)));
        // Keep dot(x − a, inward) >= offset.
        outline = clipToHalfPlane(outline, inward * -1, -(dot(a, inward) + offset));
    }
    return outline;
}

}  // namespace

CyclopeanStoneCount cyclopeanStoneCount(double width, double height, double radius) {
    CyclopeanStoneCount count;
    count.firstCourse = wholeCount(width / (2 * radius));
    count.secondCourse = wholeCount((width - radius) / (2 * radius));
    count.courses = wholeCount((height - 2 * radius) / (std::sqrt(3.0) * radius) + 1);
    double packed = double((count.courses + 1) / 2) * double(count.firstCourse) +
        double(count.courses / 2) * double(count.secondCourse);
    count.packed = int64_t(std::min(packed, kLargestCount));
    count.stones = std::llround(kPackingShare * double(count.packed));
    return count;
}

std::vector<CornerSeeds> cornerSeeds(const WallRegion &region, double pointDistance) {
    std::vector<ReflexCorner> corners = reflexCorners(region);
    std::vector<CornerSeeds> result;
    for (const ReflexCorner &c : corners) {
        // Shrink PD so that the PD circles of two corners touch at most (L1103), and so that the
        // fixed seeds stay inside the wall.
        double distance = std::min(pointDistance, c.boundaryDistance);
        for (const ReflexCorner &other : corners) {
            if (&other != &c) distance = std::min(distance, length(other.corner - c.corner) / 2);
        }
        result.push_back(
            {c.corner, distance, c.corner + c.across * (distance / 2), c.corner - c.across * (distance / 2)});
    }
    return result;
}

CyclopeanLayout layOutCyclopean(const WallRegion &region, const CyclopeanMasonry &description, uint32_t seed,
                                uint32_t wallId) {
    checkDescription(description);
    CyclopeanLayout layout;
    if (region.area() <= 0) return layout;
    layout.radius = meanRadius(region, description);
    layout.targetCount = targetCount(region, description, layout.radius);
    layout.corners = cornerSeeds(region, 2 * layout.radius);

    std::vector<Vec2d> seeds;
    for (const CornerSeeds &c : layout.corners) {
        seeds.push_back(c.first);
        seeds.push_back(c.second);
    }
    size_t fixedCount = seeds.size();
    for (Vec2d p : gridSeeds(region, layout.targetCount, seed, wallId)) {
        bool nearCorner = std::any_of(layout.corners.begin(), layout.corners.end(),
                                      [&](const CornerSeeds &c) { return length(p - c.corner) < c.distance; });
        if (!nearCorner) seeds.push_back(p);
    }
    layout.relaxed = relaxLloyd(region, std::move(seeds), fixedCount, {description.lloyd, layout.radius / 1000});
    return layout;
}

void checkCyclopean(const WallFace &wall, const CyclopeanMasonry &description) {
    checkDescription(description);
    WallRegion region(wall);
    if (region.area() > 0) targetCount(region, description, meanRadius(region, description));
}

Masonry cyclopeanMasonry(const WallFace &wall, const CyclopeanMasonry &description, uint32_t seed, uint32_t wallId) {
    WallRegion region(wall);
    CyclopeanLayout layout = layOutCyclopean(region, description, seed, wallId);
    Masonry masonry{{}, description.mortarColour, description.joint};
    uint32_t stone = 0;
    for (const ClippedCell &cell : layout.relaxed.cells) {
        for (const RegionPiece &piece : cell) {
            for (const std::vector<Vec2d> &part : convexPieces(piece.outline, piece.holes)) {
                std::vector<Vec2d> outline = shrunkStone(part, description.joint / 2, seed, wallId, stone);
                if (!outline.empty()) {
                    float t = draw(seed, wallId, StoneColour, stone);
                    Vec3f colour = description.startColour + (description.endColour - description.startColour) * t;
                    masonry.stones.push_back({std::move(outline), colour, description.depth});
                }
                ++stone;
            }
        }
    }
    return masonry;
}

namespace {

// The item as a length in metres: one number in [0, kMasonryLengthLimit].
double readLength(const DescriptionItem &item, std::string_view what) {
    item.expectFieldCount(1, 1, what);
    double value = item.number(0, what);
    if (!(value >= 0 && value <= kMasonryLengthLimit))
        throw InputError(item.fields[0].loc,
                         fmt::format("{} {} is outside [0, {}] m", what, item.fields[0].text, kMasonryLengthLimit));
    return value;
}

// The item as a whole number in [least, most].
int readCount(const DescriptionItem &item, size_t index, std::string_view what, int64_t least, int64_t most) {
    double value = item.number(index, what);
    if (!(value >= double(least) && value <= double(most)) || std::floor(value) != value)
        throw InputError(
            item.fields[index].loc,
            fmt::format("{} {} is not a whole number from {} to {}", what, item.fields[index].text, least, most));
    return int(value);
}

Vec3f readLinearColour(const DescriptionItem &item, std::string_view what) {
    Vec3f colour = readColour(item, what);
    return ColourRange{colour, colour}.at(0);
}

// `spacing, metres` or `stones, count` into the description.
void readStoneCount(const DescriptionItem &item, CyclopeanMasonry &d) {
    item.expectFieldCount(2, 2, "the stones (spacing, metres; or stones, count)");
    const std::string &kind = item.word(0, "'spacing' or 'stones'");
    if (kind == "stones") {
        d.stones = readCount(item, 1, "the stone count", 1, kMaxCyclopeanStones);
    } else if (kind == "spacing") {
        d.spacing = item.number(1, "the spacing");
        if (!(d.spacing > 0 && d.spacing <= kMasonryLengthLimit))
            throw InputError(
                item.fields[1].loc,
                fmt::format("the spacing {} is outside (0, {}] m", item.fields[1].text, kMasonryLengthLimit));
    } else {
        throw InputError(item.fields[0].loc, fmt::format("expected 'spacing' or 'stones', found '{}'", kind));
    }
}

}  // namespace

CyclopeanMasonry parseCyclopeanMasonry(std::string_view text, const std::string &file) {
    std::vector<DescriptionBlock> blocks = readDescriptionBlocks(text, file);
    if (blocks.empty()) throw InputError({file, 1, 1}, "the description has no block named 'CyclopeanMasonry'");
    for (const DescriptionBlock &block : blocks) {
        if (block.name != "CyclopeanMasonry" || &block != &blocks.front())
            throw InputError(block.loc,
                             fmt::format("expected one block, named 'CyclopeanMasonry', found '{}'", block.name));
    }
    const DescriptionBlock &block = blocks.front();
    if (block.items.size() != 7)
        throw InputError(block.loc,
                         fmt::format("CyclopeanMasonry takes 7 items (spacing or stones; Lloyd steps; start "
                                     "colour; end colour; joint; mortar colour; depth), found {}",
                                     block.items.size()));
    CyclopeanMasonry d;
    d.loc = block.loc;
    readStoneCount(block.items[0], d);
    block.items[1].expectFieldCount(1, 1, "the Lloyd steps");
    d.lloyd = readCount(block.items[1], 0, "the Lloyd steps", 0, kMaxLloydSteps);
    d.startColour = readLinearColour(block.items[2], "the stones' start colour");
    d.endColour = readLinearColour(block.items[3], "the stones' end colour");
    d.joint = readLength(block.items[4], "the joint");
    d.mortarColour = readLinearColour(block.items[5], "the mortar colour");
    d.depth = readLength(block.items[6], "the depth");
    return d;
}

}  // namespace veduta

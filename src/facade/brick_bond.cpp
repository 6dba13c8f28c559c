#include "facade/brick_bond.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include <fmt/format.h>

#include "core/check.h"
#include "core/hash.h"
#include "core/polygon_bounds.h"
#include "core/random_streams.h"
#include "facade/convex_pieces.h"
#include "facade/wall_mask.h"

namespace veduta {
namespace {

// The sRGB transfer undone: the thesis's colours are 8-bit display values.
float decodeSrgb(float value) {
    float c = value / 255.0f;
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

using BlockIndex = std::map<std::string, const DescriptionBlock *>;

BlockIndex indexBlocks(const std::vector<DescriptionBlock> &blocks) {
    BlockIndex index;
    for (const DescriptionBlock &block : blocks) {
        auto [at, added] = index.emplace(block.name, &block);
        if (!added)
            throw InputError(
                block.loc,
                fmt::format("a second block named '{}' (the first is on line {})", block.name, at->second->loc.line));
    }
    return index;
}

const DescriptionBlock &blockNamed(const BlockIndex &index, const DescriptionField &reference) {
    auto at = index.find(reference.text);
    if (at == index.end()) throw InputError(reference.loc, fmt::format("no block named '{}'", reference.text));
    return *at->second;
}

void expectItemCount(const DescriptionBlock &block, size_t count, std::string_view what) {
    if (block.items.size() == count) return;
    throw InputError(
        block.loc,
        fmt::format("the block '{}' ({}) takes {} items, found {}", block.name, what, count, block.items.size()));
}

BrickKind readBrick(const DescriptionBlock &block) {
    expectItemCount(block, 3, "a brick: size; start colour; end colour");
    return {block.name,
            readStoneSize(block.items[0], "a brick's length, height and depth"),
            {readColour(block.items[1], "a brick's start colour"), readColour(block.items[2], "a brick's end colour")},
            block.loc};
}

// The bricks and gaps of one pattern item after its offset; bricks are read the first time they
// are named.
BondCourse readCourse(const DescriptionItem &item, const BlockIndex &index, std::map<std::string, int> &brickIndex,
                      std::vector<BrickKind> &bricks) {
    if (item.fields.size() < 2) throw InputError(item.loc, "a course takes its offset and at least one brick or gap");
    if (item.fields.size() - 1 > kBondUnitLimit)
        throw InputError(item.loc, fmt::format("a course lists more than {} bricks and gaps", kBondUnitLimit));
    BondCourse course;
    course.loc = item.loc;
    course.offset = item.number(0, "the course's offset (versatz)");
    if (std::abs(course.offset) > kMasonryLengthLimit)
        throw InputError(item.fields[0].loc,
                         fmt::format("the course's offset {} is beyond the ±{} units allowed", item.fields[0].text,
                                     kMasonryLengthLimit));
    for (size_t i = 1; i < item.fields.size(); ++i) {
        const DescriptionField &field = item.fields[i];
        BondUnit unit;
        unit.loc = field.loc;
        if (field.kind == DescriptionField::Kind::Number) {
            if (!(field.number > 0))
                throw InputError(field.loc, fmt::format("a gap of {} is not positive", field.text));
            if (field.number > kMasonryLengthLimit)
                throw InputError(
                    field.loc,
                    fmt::format("a gap of {} is above the {} units allowed", field.text, kMasonryLengthLimit));
            unit.length = field.number;
        } else {
            const std::string &name = item.string(i, "a brick's name or a gap length");
            auto [at, added] = brickIndex.emplace(name, int(bricks.size()));
            if (added) bricks.push_back(readBrick(blockNamed(index, field)));
            unit.brick = at->second;
            unit.length = bricks[size_t(unit.brick)].size.length;
            unit.height = bricks[size_t(unit.brick)].size.height;
        }
        course.units.push_back(unit);
    }
    return course;
}

double unitStart(const BondCourse &course, size_t unit, double mortar) {
    double x = 0;
    for (size_t u = 0; u < unit; ++u) x += course.units[u].length + mortar;
    return x;
}

// Whether course `below` has a gap under [start, start + length] of course `above` (both within
// one repetition of equal length, the start taken modulo it).
bool gapUnder(const BondCourse &above, double start, double length, const BondCourse &below, double mortar) {
    double period = below.length, tolerance = 1e-9 * std::max(period, 1.0);
    double a = std::fmod(start + above.offset - below.offset, period);
    if (a < 0) a += period;
    double x = 0;
    for (const BondUnit &unit : below.units) {
        for (double candidate : {a, a - period}) {
            if (unit.brick < 0 && candidate >= x - tolerance && candidate + length <= x + unit.length + tolerance)
                return true;
        }
        x += unit.length + mortar;
    }
    return false;
}

// Offsets, heights and lengths of the courses, then each brick's span (see the header).
void settleCourses(BrickBond &bond) {
    double mortar = bond.mortarThickness, offset = 0;
    for (BondCourse &course : bond.courses) {
        offset += course.offset;
        course.offset = offset;
        course.height = 0;
        course.length = unitStart(course, course.units.size(), mortar);
        for (const BondUnit &unit : course.units) {
            if (unit.brick >= 0 && (course.height == 0 || unit.height < course.height)) course.height = unit.height;
        }
        if (course.height == 0) throw InputError(course.loc, "a course needs at least one brick");
    }
    size_t count = bond.courses.size();
    for (size_t k = 0; k < count; ++k) {
        BondCourse &course = bond.courses[k];
        for (size_t u = 0; u < course.units.size(); ++u) {
            BondUnit &unit = course.units[u];
            if (unit.brick < 0) continue;
            double nominal = unit.height, spanned = course.height, best = spanned;
            int spans = 1;
            for (size_t n = 2; spanned < nominal && n <= count + 1; ++n) {
                spanned += mortar + bond.courses[(k + n - 1) % count].height;
                if (std::abs(spanned - nominal) < std::abs(best - nominal)) best = spanned, spans = int(n);
            }
            unit.spans = spans, unit.height = best;
            double start = unitStart(course, u, mortar);
            for (int i = 1; i < spans; ++i) {
                const BondCourse &below = bond.courses[(k + size_t(i)) % count];
                const std::string &name = bond.bricks[size_t(unit.brick)].name;
                if (std::abs(below.length - course.length) > 1e-9 * std::max(course.length, 1.0))
                    throw InputError(unit.loc,
                                     fmt::format("the brick '{}' reaches down into the course on line {}, "
                                                 "whose repetition ({}) is not as long as its own ({})",
                                                 name, below.loc.line, below.length, course.length));
                if (!gapUnder(course, start, unit.length, below, mortar))
                    throw InputError(unit.loc,
                                     fmt::format("the brick '{}' reaches down into the course on line {}, "
                                                 "which has no gap under it",
                                                 name, below.loc.line));
            }
        }
    }
}

Stone stoneOf(std::vector<Vec2d> outline, const BrickKind &brick, float t, double metresPerUnit) {
    return {std::move(outline), brick.colour.at(t), brick.size.depth * metresPerUnit};
}

}  // namespace

Vec3f ColourRange::at(float t) const {
    Vec3f c = start + (end - start) * t;
    return {decodeSrgb(c.x), decodeSrgb(c.y), decodeSrgb(c.z)};
}

Vec3f readColour(const DescriptionItem &item, std::string_view what) {
    item.expectFieldCount(3, 3, what);
    Vec3f colour;
    for (int i = 0; i < 3; ++i) {
        double value = item.number(size_t(i), what);
        if (value < 0 || value > 255 || std::floor(value) != value)
            throw InputError(
                item.fields[size_t(i)].loc,
                fmt::format("{}: {} is not a whole number from 0 to 255", what, item.fields[size_t(i)].text));
        colour[i] = float(value);
    }
    return colour;
}

StoneSize readStoneSize(const DescriptionItem &item, std::string_view what) {
    item.expectFieldCount(3, 3, what);
    StoneSize size{item.number(0, "a length"), item.number(1, "a height"), item.number(2, "a depth")};
    if (!(size.length > 0)) throw InputError(item.fields[0].loc, fmt::format("{}: the length is not positive", what));
    if (!(size.height > 0)) throw InputError(item.fields[1].loc, fmt::format("{}: the height is not positive", what));
    if (size.depth < 0) throw InputError(item.fields[2].loc, fmt::format("{}: the depth is negative", what));
    const char *names[] = {"length", "height", "depth"};
    double values[] = {size.length, size.height, size.depth};
    for (size_t i = 0; i < 3; ++i) {
        if (values[i] > kMasonryLengthLimit)
            throw InputError(item.fields[i].loc,
                             fmt::format("{}: the {} {} is above the {} units allowed", what, names[i],
                                         item.fields[i].text, kMasonryLengthLimit));
    }
    return size;
}

double readMortarThickness(const DescriptionItem &item) {
    item.expectFieldCount(1, 1, "the mortar thickness");
    double thickness = item.number(0, "the mortar thickness");
    if (thickness < 0) throw InputError(item.loc, "the mortar thickness is negative");
    if (thickness > kMasonryLengthLimit)
        throw InputError(item.fields[0].loc,
                         fmt::format("the mortar thickness {} is above the {} units allowed", item.fields[0].text,
                                     kMasonryLengthLimit));
    return thickness;
}

void checkScaledSizes(const WallFace &wall, double least, double largest, const FileLoc &loc) {
    if (wall.outline.empty()) return;  // no wall: WallMask reports it, an internal error
    Vec2d low = wall.outline.front(), high = low;
    for (Vec2d p : wall.outline) {
        low = {std::min(low.x, p.x), std::min(low.y, p.y)};
        high = {std::max(high.x, p.x), std::max(high.y, p.y)};
    }
    Vec2d size = high - low;
    double extent = std::max(size.x, size.y);
    double distance = std::max({std::abs(low.x), std::abs(low.y), std::abs(high.x), std::abs(high.y)});
    if (!std::isfinite(largest) || !std::isfinite(least))
        throw InputError(loc, "the masonry's sizes are not finite in metres");
    if (largest > kScaledSizeLimit * extent)
        throw InputError(
            loc,
            fmt::format("a size of {} m is out of all proportion to a wall of {} × {} m", largest, size.x, size.y));
    if (least < kScaledSizeResolution * (distance + extent))
        throw InputError(loc,
                         fmt::format("stones of {} m are too small to lay on a wall reaching {} m from the origin",
                                     least, distance));
}

BrickBond parseBrickBond(std::string_view text, const std::string &file) {
    std::vector<DescriptionBlock> blocks = readDescriptionBlocks(text, file);
    BlockIndex index = indexBlocks(blocks);
    auto masonryAt = index.find("BrickMasonry");
    if (masonryAt == index.end()) throw InputError({file, 1, 1}, "the description has no block named 'BrickMasonry'");
    const DescriptionBlock &masonry = *masonryAt->second;
    expectItemCount(masonry, 3, "the masonry: pattern; mortar thickness; mortar colour");
    BrickBond bond;
    bond.loc = masonry.loc;
    masonry.items[0].expectFieldCount(1, 1, "the masonry's pattern");
    masonry.items[0].string(0, "the pattern's name");
    const DescriptionBlock &pattern = blockNamed(index, masonry.items[0].fields[0]);
    bond.mortarThickness = readMortarThickness(masonry.items[1]);
    bond.mortarColour = readColour(masonry.items[2], "the mortar colour");

    if (pattern.items.empty())
        throw InputError(pattern.loc, fmt::format("the pattern '{}' has no course", pattern.name));
    if (pattern.items.size() > kBondCourseLimit)
        throw InputError(pattern.loc,
                         fmt::format("the pattern '{}' has more than {} courses", pattern.name, kBondCourseLimit));
    std::map<std::string, int> brickIndex;
    for (const DescriptionItem &item : pattern.items)
        bond.courses.push_back(readCourse(item, index, brickIndex, bond.bricks));
    for (const DescriptionBlock &block : blocks) {
        if (&block != &masonry && &block != &pattern && !brickIndex.count(block.name))
            throw InputError(block.loc, fmt::format("the block '{}' is not used by the BrickMasonry", block.name));
    }
    settleCourses(bond);
    return bond;
}

namespace {

double lowestCourse(const BrickBond &bond) {
    double lowest = bond.courses.front().height;
    for (const BondCourse &course : bond.courses) lowest = std::min(lowest, course.height);
    return lowest;
}

// How far a tall brick reaches below its course's bottom, units.
double longestHang(const BrickBond &bond) {
    double hang = 0;
    for (const BondCourse &course : bond.courses)
        for (const BondUnit &unit : course.units) hang = std::max(hang, unit.height - course.height);
    return hang;
}

}  // namespace

void checkBrickBond(const BrickBond &bond, const WallFace &wall, double metresPerUnit) {
    double scale = metresPerUnit;
    VEDUTA_CHECK(std::isfinite(scale) && scale > 0, fmt::format("metres per unit {}", scale));
    // Every size the walk adds or multiplies, scaled: the bricks, gaps, offsets and mortar.
    const double lowest = lowestCourse(bond);
    double least = lowest, largest = bond.mortarThickness;
    for (const BrickKind &brick : bond.bricks) {
        least = std::min(least, brick.size.length);
        largest = std::max({largest, brick.size.length, brick.size.height, brick.size.depth});
    }
    for (const BondCourse &course : bond.courses) {
        largest = std::max({largest, course.length, std::abs(course.offset)});
        for (const BondUnit &unit : course.units) largest = std::max(largest, unit.height);
    }
    checkScaledSizes(wall, least * scale, largest * scale, bond.loc);
    VEDUTA_CHECK(wall.outline.size() >= 3, "a wall face with fewer than three corners");
    // The most bricks the walk below can try: the courses up the wall and those above it whose tall
    // bricks reach down into it, each with its repetitions over the width and two more.
    auto [low, high] = polygonBounds(wall.outline);
    Vec2d size = high - low;
    double courses = (size.y + longestHang(bond) * scale) / ((lowest + bond.mortarThickness) * scale) + 2;
    double perCourse = 0;
    for (const BondCourse &course : bond.courses)
        perCourse = std::max(perCourse, (size.x / (course.length * scale) + 2) * double(course.units.size()));
    if (courses * perCourse > double(kBrickLimit))
        throw InputError(
            bond.loc,
            fmt::format("the bond would lay more than {} bricks on a wall of {} × {} m", kBrickLimit, size.x, size.y));
}

Masonry layBrickBond(const BrickBond &bond, const WallFace &wall, const MasonryPlacement &placement) {
    checkBrickBond(bond, wall, placement.metresPerUnit);
    double scale = placement.metresPerUnit, mortar = bond.mortarThickness * scale;
    double hang = longestHang(bond) * scale;
    WallMask mask(wall, mortar, lowestCourse(bond) * scale);
    Masonry masonry{{}, ColourRange{bond.mortarColour, bond.mortarColour}.at(0), mortar};

    size_t count = bond.courses.size();
    double bottom = mask.low().y;
    // Courses from the wall's bottom up, the list in reverse; the courses just above the wall
    // still reach into it with their tall bricks.
    for (uint32_t c = 0; bottom - hang < mask.high().y; ++c) {
        const BondCourse &course = bond.courses[count - 1 - c % count];
        double top = bottom + course.height * scale, period = course.length * scale;
        double start = mask.low().x - period + std::fmod(course.offset * scale, period);
        for (uint32_t j = 0; start + j * period < mask.high().x; ++j) {
            double x = start + j * period;
            for (size_t u = 0; u < course.units.size(); x += (course.units[u].length * scale + mortar), ++u) {
                const BondUnit &unit = course.units[u];
                if (unit.brick < 0) continue;
                Vec2d low{x, top - unit.height * scale}, high{x + unit.length * scale, top};
                MaskCover cover = mask.cover(low, high);
                if (cover == MaskCover::Blocked) continue;
                const BrickKind &brick = bond.bricks[size_t(unit.brick)];
                float t = bitsToUnitFloat(hashValues(
                    {placement.seed, placement.wallId, streamTag(RandomStream::MasonryBricks), c, j, uint32_t(u)}));
                std::vector<Vec2d> outline{low, {high.x, low.y}, high, {low.x, high.y}};
                if (cover == MaskCover::Free) {
                    masonry.stones.push_back(stoneOf(std::move(outline), brick, t, scale));
                    continue;
                }
                double sliver = 1e-9 * signedArea(outline);
                for (auto &piece : mask.clip(outline)) {
                    if (signedArea(piece) > sliver)
                        masonry.stones.push_back(stoneOf(std::move(piece), brick, t, scale));
                }
            }
        }
        bottom = top + mortar;
    }
    return masonry;
}

}  // namespace veduta

#include "facade/ashlar.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "core/check.h"
#include "core/hash.h"
#include "core/polygon_bounds.h"
#include "core/random_streams.h"
#include "facade/convex_pieces.h"
#include "facade/description_text.h"
#include "facade/wall_mask.h"

namespace veduta {
namespace {

double lerp(double a, double b, double t) { return a + (b - a) * t; }

// A stretch of one course, laid left to right; `free` when the whole strip is free there.
struct Run {
    double start = 0, end = 0;
    bool free = false;
};

// The course's x-range split at its free spans; a run that is not free keeps a joint's distance
// from the free runs beside it.
std::vector<Run> runsOf(const std::vector<Span> &spans, double low, double high, double mortar) {
    std::vector<Run> runs;
    double x = low;
    auto addCut = [&](double end) {
        double start = x > low ? x + mortar : x;
        double stop = end < high ? end - mortar : end;
        if (stop > start) runs.push_back({start, stop, false});
    };
    for (Span span : spans) {
        if (span.low > x) addCut(span.low);
        runs.push_back({span.low, span.high, true});
        x = span.high;
    }
    if (x < high) addCut(high);
    return runs;
}

// The length of the next stone with `rest` left in its run (see the header): the drawn length,
// shortened to leave room for a smallest next stone, or all the rest where that fits.
double nextLength(double drawn, double rest, double least, double most, double mortar) {
    if (rest <= most) return rest;
    if (rest - drawn - mortar >= least) return drawn;
    return std::max(least, rest - mortar - least);
}

// The calliper width of a convex polygon: over its edges, the least of the greatest distance of a
// vertex from the edge's line.
double narrowestWidth(const std::vector<Vec2d> &convex) {
    double narrowest = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < convex.size(); ++i) {
        Vec2d a = convex[i], edge = convex[(i + 1) % convex.size()] - a;
        double widest = 0;
        for (Vec2d p : convex) widest = std::max(widest, cross(edge, p - a) / length(edge));
        narrowest = std::min(narrowest, widest);
    }
    return narrowest;
}

}  // namespace

AshlarMasonry parseAshlarMasonry(std::string_view text, const std::string &file) {
    std::vector<DescriptionBlock> blocks = readDescriptionBlocks(text, file);
    if (blocks.empty()) throw InputError({file, 1, 1}, "the description has no block named 'AshlarMasonry'");
    for (const DescriptionBlock &block : blocks) {
        if (block.name != "AshlarMasonry" || &block != &blocks.front())
            throw InputError(block.loc,
                             fmt::format("expected one block, named 'AshlarMasonry', found '{}'", block.name));
    }
    const DescriptionBlock &block = blocks.front();
    if (block.items.size() != 6)
        throw InputError(block.loc,
                         fmt::format("AshlarMasonry takes 6 items (min size; max size; start colour; end "
                                     "colour; mortar thickness; mortar colour), found {}",
                                     block.items.size()));
    AshlarMasonry ashlar;
    ashlar.loc = block.loc;
    ashlar.minSize = readStoneSize(block.items[0], "the minimum stone size");
    ashlar.maxSize = readStoneSize(block.items[1], "the maximum stone size");
    const char *names[] = {"length", "height", "depth"};
    double least[] = {ashlar.minSize.length, ashlar.minSize.height, ashlar.minSize.depth};
    double most[] = {ashlar.maxSize.length, ashlar.maxSize.height, ashlar.maxSize.depth};
    for (size_t i = 0; i < 3; ++i) {
        if (most[i] < least[i])
            throw InputError(block.items[1].fields[i].loc,
                             fmt::format("the maximum {} {} is below the minimum {}", names[i], most[i], least[i]));
    }
    ashlar.colour = {readColour(block.items[2], "the stones' start colour"),
                     readColour(block.items[3], "the stones' end colour")};
    ashlar.mortarThickness = readMortarThickness(block.items[4]);
    ashlar.mortarColour = readColour(block.items[5], "the mortar colour");
    return ashlar;
}

void checkAshlar(const AshlarMasonry &ashlar, const WallFace &wall, double metresPerUnit) {
    double scale = metresPerUnit;
    VEDUTA_CHECK(std::isfinite(scale) && scale > 0, fmt::format("metres per unit {}", scale));
    const StoneSize &least = ashlar.minSize, &most = ashlar.maxSize;
    checkScaledSizes(wall, std::min(least.length, least.height) * scale,
                     std::max({most.length, most.height, most.depth, ashlar.mortarThickness}) * scale, ashlar.loc);
    VEDUTA_CHECK(wall.outline.size() >= 3, "a wall face with fewer than three corners");
    // The most stones the walk below can try, counting a short rest at both ends of every run and
    // the runs an opening can make in a course.
    auto [low, high] = polygonBounds(wall.outline);
    Vec2d size = high - low;
    double mortar = ashlar.mortarThickness * scale;
    double courses = size.y / (least.height * scale + mortar) + 1;
    double perCourse = size.x / (least.length * scale + mortar) + 2 + 4 * double(wall.openings.size());
    if (courses * perCourse > double(kBrickLimit))
        throw InputError(ashlar.loc,
                         fmt::format("the ashlar would lay more than {} stones on a wall of {} × {} m", kBrickLimit,
                                     size.x, size.y));
}

Masonry layAshlar(const AshlarMasonry &ashlar, const WallFace &wall, const MasonryPlacement &placement) {
    checkAshlar(ashlar, wall, placement.metresPerUnit);
    double scale = placement.metresPerUnit;
    const StoneSize &least = ashlar.minSize, &most = ashlar.maxSize;
    double mortar = ashlar.mortarThickness * scale;
    double minLength = least.length * scale, maxLength = most.length * scale;
    double minWidth = kAshlarMinPieceFraction * std::min(least.length, least.height) * scale;
    WallMask mask(wall, mortar, std::min(least.length, least.height) * scale);
    Masonry masonry{{}, ColourRange{ashlar.mortarColour, ashlar.mortarColour}.at(0), mortar};
    uint32_t tag = streamTag(RandomStream::MasonryAshlar);

    double bottom = mask.low().y;
    for (uint32_t course = 0; bottom < mask.high().y; ++course) {
        float u = bitsToUnitFloat(hashValues({placement.seed, placement.wallId, tag, course}));
        double top = bottom + lerp(least.height, most.height, u) * scale;
        uint32_t index = 0;
        for (Run run : runsOf(mask.freeSpans(bottom, top), mask.low().x, mask.high().x, mortar)) {
            for (double x = run.start; run.end - x > 0; ++index) {
                uint32_t key = hashValues({placement.seed, placement.wallId, tag, course, index + 1});
                float v = bitsToUnitFloat(key), shade = bitsToUnitFloat(mix32(key));
                double rest = run.end - x;
                double length = rest < minLength
                    ? rest
                    : nextLength(lerp(least.length, most.length, v) * scale, rest, minLength, maxLength, mortar);
                std::vector<Vec2d> outline{{x, bottom}, {x + length, bottom}, {x + length, top}, {x, top}};
                Stone stone{{}, ashlar.colour.at(shade), lerp(least.depth, most.depth, v) * scale};
                x += length + mortar;
                MaskCover cover = mask.cover(outline[0], outline[2]);
                if (cover == MaskCover::Blocked) continue;
                if (run.free && length >= minLength && cover == MaskCover::Free) {
                    stone.outline = std::move(outline);
                    masonry.stones.push_back(std::move(stone));
                    continue;
                }
                for (const auto &part : mask.clip(outline)) {
                    for (auto &piece : convexPieces(part)) {
                        if (narrowestWidth(piece) < minWidth) continue;
                        stone.outline = std::move(piece);
                        masonry.stones.push_back(stone);
                    }
                }
            }
        }
        bottom = top + mortar;
    }
    return masonry;
}

}  // namespace veduta

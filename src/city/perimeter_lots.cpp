// Bilke's subdivideLotRectangular (thesis L376–402): lots in the ring between a block and its
// inset, along the street edges.
#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "city/lot_subdivision.h"
#include "core/hash.h"
#include "core/random_streams.h"

namespace veduta {

namespace {

Vec2f leftNormal(Vec2f d) { return {-d.y, d.x}; }

Vec2f edgeDirection(const std::vector<Vec2f> &ring, size_t edge) {
    Vec2f d = ring[(edge + 1) % ring.size()] - ring[edge];
    return d * (1 / std::sqrt(dot(d, d)));
}

// The block's inset by `depth`: point i is where the lines of edges i − 1 and i, moved `depth`
// inwards, meet (a mitre). None when that ring is not a simple polygon inside the block with
// every edge running the way its block edge runs (an edge shrunk past zero turns round): the
// thesis' precondition 4, the block cannot be inset.
std::optional<std::vector<Vec2f>> insetRing(const std::vector<Vec2f> &block, float depth) {
    std::vector<Vec2f> inset = offsetPolygon(block, -depth);
    size_t n = block.size();
    for (size_t i = 0; i < n; ++i) {
        if (!(dot(edgeDirection(inset, i), edgeDirection(block, i)) > 0)) return std::nullopt;
    }
    if (!isSimplePolygon(inset) || !liesInside(inset, block)) return std::nullopt;
    return inset;
}

// A lot is built from sections across the ring: a point on the street and the point opposite
// on the inset ring. Its outline runs along the street points, then back along the inset ones.
struct Section {
    Vec2f outer, inner;
};

Footprint footprintOf(const std::vector<Section> &sections, float base) {
    Footprint lot{{}, {}, base};
    for (const Section &s : sections) lot.points.push_back(s.outer);
    for (auto s = sections.rbegin(); s != sections.rend(); ++s) lot.points.push_back(s->inner);
    // Between street points the outline follows a street edge; the cuts and the courtyard side
    // face no street.
    lot.streetEdges.assign(lot.points.size(), false);
    for (size_t i = 0; i + 1 < sections.size(); ++i) lot.streetEdges[i] = true;
    return lot;
}

// The walk along the street edges (thesis steps 1–9). The lot being built is `open`; a cut
// closes it and starts the next one.
class PerimeterWalk {
  public:
    PerimeterWalk(const Block &block, std::vector<Vec2f> inset, const LotSettings &settings, uint32_t seed,
                  uint32_t blockId, const std::optional<FileLoc> &loc) :
        block_(block), inset_(std::move(inset)), settings_(settings), seed_(seed), blockId_(blockId), loc_(loc) {}

    std::vector<Footprint> run() {
        size_t n = block_.points.size();
        bool ring = std::find(block_.streetEdges.begin(), block_.streetEdges.end(), false) == block_.streetEdges.end();
        if (ring) return walkRing();
        for (size_t edge = 0; edge < n; ++edge) {
            if (block_.streetEdges[edge] && !block_.streetEdges[(edge + n - 1) % n]) walkStreet(edge);
        }
        return std::move(lots_);
    }

  private:
    // Streets all round: the walk starts at point 0, and the lot that reaches it at the end is
    // joined to the first lot (step 6), the corner lot there.
    std::vector<Footprint> walkRing() {
        holdFirst_ = true;
        open_ = {section(0)};
        for (size_t edge = 0; edge < block_.points.size(); ++edge) walkEdge(edge);
        // With fewer than two cuts the "lot" would be the whole ring around the courtyard.
        if (!first_ || lots_.empty()) return {};
        open_.insert(open_.end(), first_->begin() + 1, first_->end());
        closeOpen();
        return std::move(lots_);
    }

    // A run of street edges from `edge` on, up to the next edge that is no street. Its first and
    // last lots end on the mitre from the block point to its inset point.
    void walkStreet(size_t edge) {
        size_t n = block_.points.size();
        open_ = {section(edge)};
        for (; block_.streetEdges[edge]; edge = (edge + 1) % n) walkEdge(edge);
        closeOpen();
    }

    void walkEdge(size_t edge) {
        Vec2f start = block_.points[edge], direction = edgeDirection(block_.points, edge);
        size_t next = (edge + 1) % block_.points.size();
        float length = std::sqrt(dot(block_.points[next] - start, block_.points[next] - start));
        // The stretch of the edge whose perpendicular meets the inset edge.
        float insetFrom = dot(inset_[edge] - start, direction), insetTo = dot(inset_[next] - start, direction);
        for (float from = 0, lotStart = 0;;) {
            float cut = from + frontage();
            if (!(cut > from)) {
                lots::fail(loc_,
                           fmt::format("block {}: a frontage of {} m does not move the walk along an edge {} m "
                                       "long (MinBuildingLength is too small)",
                                       blockId_, cut - from, length));
            }
            // Steps 1–2 → 8: the rest is too short for a lot; it joins the lot at the corner.
            if (length - cut <= settings_.minBuildingLength) break;
            from = cut;
            // Step 3 → 8: the perpendicular misses the inset edge; the lot grows.
            if (cut < insetFrom || cut > insetTo) continue;
            // Step 4: the cut would leave a courtyard side shorter than MinBuildingInnerLength
            // beside an inset corner. The thesis then builds no lot up to it (step 9), which
            // leaves a gap beside nearly every corner; veduta moves the cut away from that inset
            // corner instead, as far as the lots on either side keep MinBuildingLength.
            float lowest = insetFrom + settings_.minBuildingInnerLength,
                  highest = insetTo - settings_.minBuildingInnerLength;
            if (lowest > highest) continue;
            cut = std::clamp(cut, lowest, highest);
            if (cut - lotStart < settings_.minBuildingLength || length - cut <= settings_.minBuildingLength) continue;
            from = lotStart = cut;
            Vec2f outer = start + direction * cut;
            Section s{outer, outer + leftNormal(direction) * settings_.minBuildingDepth};
            open_.push_back(s);
            closeOpen();
            open_ = {s};
        }
        open_.push_back(section(next));
    }

    Section section(size_t point) const { return {block_.points[point], inset_[point]}; }

    float frontage() {
        uint32_t key = hashValues({seed_, blockId_, streamTag(RandomStream::LotPerimeterFrontage), draws_++});
        return lots::normalBetween(settings_.minBuildingLength, settings_.maxBuildingLength, key);
    }

    void closeOpen() {
        if (++pieces_ > kMaxLotsPerBlock) {
            lots::fail(loc_,
                       fmt::format("block {} would be cut into more than {} perimeter lots (MinBuildingLength {} m)",
                                   blockId_, kMaxLotsPerBlock, settings_.minBuildingLength));
        }
        if (holdFirst_) {
            first_ = open_;
            holdFirst_ = false;
        } else {
            lots_.push_back(footprintOf(open_, block_.base));
        }
    }

    const Block &block_;
    std::vector<Vec2f> inset_;
    const LotSettings &settings_;
    uint32_t seed_, blockId_;
    const std::optional<FileLoc> &loc_;

    uint32_t draws_ = 0;  // the step: each frontage drawn is keyed by its number
    size_t pieces_ = 0;
    std::vector<Section> open_;
    bool holdFirst_ = false;  // the next closed lot is the first of a ring: kept for the corner
    std::optional<std::vector<Section>> first_;
    std::vector<Footprint> lots_;
};

}  // namespace

std::vector<Footprint> lots::perimeterPieces(const Block &block, const LotSettings &settings, uint32_t seed,
                                             uint32_t blockId, const std::optional<FileLoc> &loc) {
    if (!checkedAndOnAStreet(block, settings, loc)) return {};
    std::optional<std::vector<Vec2f>> inset = insetRing(block.points, settings.minBuildingDepth);
    if (!inset) return {};
    return PerimeterWalk(block, std::move(*inset), settings, seed, blockId, loc).run();
}

std::vector<Footprint> perimeterLots(const Block &block, const LotSettings &settings, uint32_t seed, uint32_t blockId,
                                     const std::optional<FileLoc> &loc) {
    return filterLots(lots::perimeterPieces(block, settings, seed, blockId, loc), settings, seed, blockId);
}

}  // namespace veduta

#include "city/recursive_split.h"

#include <algorithm>

#include <fmt/format.h>

#include "core/hash.h"
#include "core/random_streams.h"

namespace veduta::lots {

namespace {

class RecursiveSplit {
  public:
    RecursiveSplit(const Block &block, const LotSettings &settings, uint32_t blockId, const std::optional<FileLoc> &loc,
                   const SplitRule &rule) :
        block_(block), settings_(settings), blockId_(blockId), loc_(loc), rule_(rule) {}

    void split(const Piece &piece, uint32_t key, int depth) {
        std::vector<bool> flags = streetFlags(piece, block_);
        // Thesis step 1: only pieces with a street edge are split, and only they are kept.
        if (std::find(flags.begin(), flags.end(), true) == flags.end()) return;
        if (signedArea(piece) <= settings_.maxLotArea) {
            if (lots_.size() == kMaxLotsPerBlock) {
                fail(loc_,
                     fmt::format("block {} would be cut into more than {} lots (MaxLotArea {} m²)", blockId_,
                                 kMaxLotsPerBlock, settings_.maxLotArea));
            }
            lots_.push_back({piece, std::move(flags), block_.base});
            return;
        }
        if (depth == kMaxLotRecursion) {
            fail(loc_,
                 fmt::format("block {} needs lots split more than {} times to reach MaxLotArea {} m²", blockId_,
                             kMaxLotRecursion, settings_.maxLotArea));
        }
        std::vector<Piece> parts = rule_(piece, key);
        for (size_t i = 0; i < parts.size(); ++i) split(parts[i], hashValues({key, uint32_t(i)}), depth + 1);
    }

    std::vector<Footprint> takeLots() { return std::move(lots_); }

  private:
    const Block &block_;
    const LotSettings &settings_;
    uint32_t blockId_;
    const std::optional<FileLoc> &loc_;
    const SplitRule &rule_;
    std::vector<Footprint> lots_;
};

}  // namespace

std::vector<Footprint> splitRecursively(const Block &block, const LotSettings &settings, uint32_t seed,
                                        uint32_t blockId, const std::optional<FileLoc> &loc, const SplitRule &rule) {
    RecursiveSplit split(block, settings, blockId, loc, rule);
    split.split(block.points, hashValues({seed, blockId, streamTag(RandomStream::LotRecursiveSplit)}), 0);
    return split.takeLots();
}

}  // namespace veduta::lots

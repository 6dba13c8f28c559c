// The recursion shared by the subdivisions that split pieces until they are small enough
// (Müller's and CityEngine's OBB split, docs/lots.md): only pieces with a street edge are split
// or kept, and the limits of lot_subdivision.h hold.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "city/lot_pieces.h"

namespace veduta::lots {

// How one piece is split: its parts, from the piece and the hash `key` that identifies it.
using SplitRule = std::function<std::vector<Piece>(const Piece &piece, uint32_t key)>;

// Splits the block by `rule` until every piece is at most MaxLotArea; pieces without a street
// edge are dropped and not split further. The root's key comes from seed and block id, each
// part's from its parent's and its place among the parent's parts, so every split is a pure
// function of them. Unfiltered (filterLots is the caller's).
std::vector<Footprint> splitRecursively(const Block &block, const LotSettings &settings, uint32_t seed,
                                        uint32_t blockId, const std::optional<FileLoc> &loc, const SplitRule &rule);

}  // namespace veduta::lots

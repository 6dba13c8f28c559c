// Checkpoints of a render: the film's accumulators and the render's progress, exactly, so that
// a render killed at any moment continues from its last checkpoint to the very image an
// uninterrupted render makes. Written atomically (the old checkpoint stays until the new one
// is whole). The file starts with text lines naming the render it belongs to, then holds the
// film's buffers in this machine's byte order, and ends in a CRC-32 of all before it.
// docs/output.md describes the use.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "film/film.h"
#include "film/render_stats.h"

namespace veduta {

// What identifies a render: ("scene", hash), ("samples", "64"), … in a fixed order.
using RenderIdentity = std::vector<std::pair<std::string, std::string>>;

void writeCheckpoint(const std::filesystem::path &file, const RenderIdentity &identity, Film &film,
                     const RenderStats &stats);

// Restores `film` (made for the same window) and `stats` from `file`. Throws InputError naming
// the file if it is not a checkpoint, is damaged (any changed byte: the CRC), or was written
// for another render (then the message lists every entry that differs, there and here); the
// film's contents are then undefined.
void readCheckpoint(const std::filesystem::path &file, const RenderIdentity &identity, Film &film, RenderStats &stats);

}  // namespace veduta

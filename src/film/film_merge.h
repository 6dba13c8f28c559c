// `veduta merge` without the files: renders of one scene combined into one image. Tiles (parts
// with different data windows) are assembled into their bounding box; sample ranges (parts with
// the same data window and consecutive ranges of each pixel's sample sequence) are combined per
// pixel, weighted by their sample counts; Cryptomatte's ranks are summed as sample counts and
// ranked again. docs/output.md, "Merging", says what is checked.
#pragma once

#include <string>
#include <vector>

#include "core/layered_image.h"

namespace veduta {

// `parts` as developFilm makes them, with the render metadata; `names` (one per part, the file
// names) are only for messages. Throws InputError at the offending part's name when the parts
// are not pieces of one render: different image sizes, channels, scenes or seeds, sample ranges
// that overlap or leave a gap, tiles that overlap, differ in their ranges or leave pixels of
// their bounding box uncovered. A single part comes back bit-identical.
LayeredImage mergeFilms(const std::vector<LayeredImage> &parts, const std::vector<std::string> &names);

}  // namespace veduta

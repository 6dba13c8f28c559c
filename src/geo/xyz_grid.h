// ASCII XYZ terrain files, as the German surveys publish their DGMs: one node a line,
// "Rechtswert Hochwert Höhe" (easting northing height) separated by blanks or tabs.
#pragma once

#include <filesystem>

#include "geo/height_grid.h"

namespace veduta {

// Whether the file's first line that is not blank or a # comment holds three numbers.
bool looksLikeXyz(const std::filesystem::path &file);

// The nodes of an XYZ file as a grid. Lines may come in any order (rows north→south or
// south→north, columns first) and nodes may be missing (they become NaN). The spacing is the
// smallest positive step between successive points, refined over the points' extent (files
// round coordinates to millimetres); the grid is the points' bounding box. Blank lines and
// lines starting with # are skipped. Errors (InputError with file:line:column): a value that
// is not a number, a NaN or infinite value, a line without exactly three values, a point off
// the grid of the points before it (mixed spacings, shifted tiles), a point given twice with
// two heights, fewer than two points.
HeightGrid readXyzGrid(const std::filesystem::path &file);

}  // namespace veduta

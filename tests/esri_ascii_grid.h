// An ESRI ASCII grid (.asc), the text DGM most German states deliver, for the tests that need a
// terrain: `columns` × `rows` nodes `spacing` metres apart, node (0, 0) at (west, south), each
// cell's text from `cell` (the format's header puts the cell's corner half a spacing off the
// node; rows are written north first).
#pragma once

#include <functional>
#include <string>

#include <fmt/format.h>

namespace veduta::test {

inline std::string esriAsciiGrid(int columns, int rows, double west, double south, double spacing,
                                 const std::function<std::string(int column, int row)> &cell) {
    std::string text = fmt::format("ncols {}\nnrows {}\nxllcorner {}\nyllcorner {}\ncellsize {}\nNODATA_value -9999\n",
                                   columns, rows, west - spacing / 2, south - spacing / 2, spacing);
    for (int r = rows - 1; r >= 0; --r) {
        for (int c = 0; c < columns; ++c) {
            if (c > 0) text += ' ';
            text += cell(c, r);
        }
        text += "\n";
    }
    return text;
}

}  // namespace veduta::test

// The front of a Gründerzeit house that the facade benchmarks lay masonry on: 15 × 16 m, four
// storeys of five 1.2 × 2 m windows and a 1.6 × 3 m door, and the brick bond of Fig. 5.7.
#pragma once

#include <vector>

#include "facade/masonry.h"

namespace veduta::bench {

inline std::vector<Vec2d> rectangle(double x0, double y0, double x1, double y1) {
    return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

inline WallFace gruenderzeitFront() {
    WallFace front{rectangle(0, 0, 15, 16), {rectangle(6.7, 0, 8.3, 3)}};
    for (int storey = 0; storey < 4; ++storey)
        for (int column = 0; column < 5; ++column) {
            if (storey == 0 && column == 2) continue;  // the door
            double x = 1.2 + 3 * column, y = 1 + 4 * storey;
            front.openings.push_back(rectangle(x, y, x + 1.2, y + 2));
        }
    return front;
}

// Fig. 5.7 with bricks of 25 × 6.25 cm (Reichsformat is 25 × 6.5).
inline const char *const kFigure5_7 = R"(Brick1 { 2.0, 0.5, 0.1; 206,78,51; 255,147,124; }
Brick2 { 2.0, 1.0, 0.1; 206,78,51; 255,147,124; }
Pattern { -1.0, "Brick1", "Brick2"; 0.0, "Brick1", 2.0; 1.0, "Brick1"; }
BrickMasonry { "Pattern"; 0.05; 102,102,102; })";

}  // namespace veduta::bench

// The relief of a window's apron panel (Brüstungsfeld, building_style.h's ApronStyle): an ornament
// grown by Finkenzeller's placement loop (ornament_growth.h, §2.7) and a moulded rim, as the stucco
// panels under Gründerzeit windows have them.
//
// Choices where the thesis is open (it grows ornaments into given regions, not onto buildings):
// * Mirror symmetry, as cast stucco is: the ornament grows in the panel's left half, inside the
//   rim, from a boss on the middle axis, and is mirrored onto the right half.
// * Cells of 1 cm, the thesis's "one element a cell" at the scale a window is seen from the street.
// * The rim: a band of kApronRimWidth round the edge, raised kApronRimHeight with a rounded inner
//   edge; the ornament stands on the field inside it.
#pragma once

#include "core/image.h"

namespace veduta {

inline constexpr double kApronCell = 0.01;        // metres
inline constexpr double kApronRimWidth = 0.04;    // metres
inline constexpr double kApronRimHeight = 0.008;  // metres

// The panel's relief over width × height metres: one channel of metres, top row first, a pixel
// per kApronCell (at least one). Throws std::invalid_argument for a panel narrower or lower than
// three rims, or more than 10 m either way.
Image apronRelief(double width, double height);

}  // namespace veduta

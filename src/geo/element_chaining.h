// Vector elements (polylines sharing end points exactly) joined into outlines and polylines,
// whatever the order and direction they come in (Rilling 2006, §3.4, Listing 1, with its gaps
// closed: the first element's end point kept, the closing duplicate dropped, and an open
// outline reported instead of looping).
#pragma once

#include <cstddef>
#include <vector>

#include "geodesy/map_point.h"

namespace veduta {

struct RingChaining {
    std::vector<MapRing> rings;  // closed outlines, no point repeated in a row, none closing
    bool closed = true;          // false: the elements do not close; rings then holds those that did
    MapPoint openEnd;            // where the walk stopped when not closed
    size_t unusedElements = 0;   // elements left when it stopped, the stuck walk's included
};

// Every element used once. Elements of fewer than two points are ignored; rings that come
// out with fewer than three distinct points (an element and its duplicate) are left out.
RingChaining chainRings(const std::vector<MapLine> &elements);

// Polylines, each as long as the elements allow: walks start at loose ends (points where an
// odd number of elements meet), so a single path comes out as one polyline whatever its order.
std::vector<MapLine> chainLines(const std::vector<MapLine> &elements);

}  // namespace veduta

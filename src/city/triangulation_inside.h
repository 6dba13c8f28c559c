// Which faces of a constrained triangulation of polygon outlines lie inside the polygon: the
// float triangulation of footprints (city/footprint.cpp) and the exact one of street surfaces
// (city/street_geometry.cpp) both ask. The faces carry a bool as their info.
#pragma once

#include <set>
#include <vector>

namespace veduta {

// A face lies inside when reaching it from the infinite face crosses the outlines an odd number
// of times: the outline's interior is inside, a hole's interior outside again. Flood fill region
// by region, each across the constraints of the one before.
template <typename Cdt>
void markInside(Cdt &cdt) {
    using Face = typename Cdt::Face_handle;
    for (Face f : cdt.all_face_handles()) f->info() = false;
    std::vector<Face> frontier{cdt.infinite_face()}, next;
    std::set<Face> visited{cdt.infinite_face()};
    for (bool inside = false; !frontier.empty(); inside = !inside, frontier.swap(next), next.clear()) {
        std::vector<Face> stack = frontier;
        while (!stack.empty()) {
            Face f = stack.back();
            stack.pop_back();
            f->info() = inside;
            for (int i = 0; i < 3; ++i) {
                Face neighbour = f->neighbor(i);
                if (visited.count(neighbour)) continue;
                visited.insert(neighbour);
                (f->is_constrained(i) ? next : stack).push_back(neighbour);
            }
        }
    }
}

}  // namespace veduta

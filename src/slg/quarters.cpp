#include "slg/quarters.h"

#include <algorithm>
#include <cmath>

#include "slg/exact_region.h"

namespace veduta {

std::vector<Polygon2d> quarters(const Polygon2d &outline, double side, double street) {
    size_t longest = longestEdge(outline);
    Vec2d origin = outline[longest];
    Vec2d u = normalized(outline[(longest + 1) % outline.size()] - origin), v = leftNormal(u);
    double lowU = 0, highU = 0, lowV = 0, highV = 0;
    for (Vec2d p : outline) {
        lowU = std::min(lowU, dot(p - origin, u)), highU = std::max(highU, dot(p - origin, u));
        lowV = std::min(lowV, dot(p - origin, v)), highV = std::max(highV, dot(p - origin, v));
    }
    // As many cells as fit, stretched to cover the outline's extent exactly.
    int across = std::max(1, int(std::lround((highU - lowU) / side)));
    int up = std::max(1, int(std::lround((highV - lowV) / side)));
    if (across == 1 && up == 1) return {outline};
    double width = (highU - lowU) / across, depth = (highV - lowV) / up, half = street / 2;
    ExactRegion whole(exactPolygon(outline));
    std::vector<Polygon2d> pieces;
    for (int row = 0; row < up; ++row) {
        for (int column = 0; column < across; ++column) {
            // Cells on the outline's edge keep it: only the lines between cells are streets.
            double u0 = lowU + column * width + (column > 0 ? half : 0);
            double u1 = lowU + (column + 1) * width - (column + 1 < across ? half : 0);
            double v0 = lowV + row * depth + (row > 0 ? half : 0);
            double v1 = lowV + (row + 1) * depth - (row + 1 < up ? half : 0);
            auto at = [&](double a, double b) { return origin + u * a + v * b; };
            ExactRegion cell(exactPolygon({at(u0, v0), at(u1, v0), at(u1, v1), at(u0, v1)}));
            cell.intersection(whole);
            std::vector<CGAL::Polygon_with_holes_2<ExactKernel>> parts;
            cell.polygons_with_holes(std::back_inserter(parts));
            for (const auto &part : parts) {
                Polygon2d piece = inexactPolygon(part.outer_boundary());
                if (signedArea(piece) < 0) std::reverse(piece.begin(), piece.end());
                if (signedArea(piece) > 1) pieces.push_back(std::move(piece));
            }
        }
    }
    return pieces;
}

}  // namespace veduta

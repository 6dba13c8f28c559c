#include "facade/consoles.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace veduta {
namespace {

// Where along an edge the centres go: a pattern centred between the margins.
std::vector<double> centresOn(const RunEdge &edge, double spacing, double halfWidth, double depth) {
    // At a concave corner the mitre plane cuts into the edge, by `depth` times the slope at the
    // console's front; startSlope is positive there but endSlope negative (profile_sweep.h). At a
    // convex corner the mitre lies beyond the edge and takes nothing.
    double from = halfWidth + std::max(0.0, depth * edge.startSlope);
    double to = edge.length - halfWidth - std::max(0.0, -depth * edge.endSlope);
    std::vector<double> centres;
    if (to < from) return centres;
    size_t count = size_t(std::floor((to - from) / spacing)) + 1;
    double first = (from + to - double(count - 1) * spacing) / 2;
    for (size_t i = 0; i < count; ++i) centres.push_back(first + double(i) * spacing);
    return centres;
}

// Maps the unit console box (consoles.h) onto a width × height rectangle centred `along` metres
// along the edge, `depth` deep.
Transform boxTransform(const RunEdge &edge, double along, double baseHeight, double width, double height,
                       double depth) {
    Vec2d foot = edge.start + edge.direction * along;
    Vec2d right = edge.direction * width, out = edge.normal * depth;
    return {{float(right.x), 0, float(out.x), float(foot.x),  //
             float(right.y), 0, float(out.y), float(foot.y),  //
             0, float(height), 0, float(baseHeight)}};
}

}  // namespace

std::vector<Transform> placeConsoles(const SweepPath &path, const Console &console, const ProfileOutline &outline,
                                     double scale) {
    double width = console.width * scale, height = console.height * scale;
    double reach = 0;
    for (Vec2d point : outline.points) reach = std::max(reach, point.x);
    double depth = reach > 0 ? reach : width;
    std::vector<Transform> transforms;
    for (const RunEdge &edge : runEdges(path)) {
        if (edge.length / console.spacing > double(kConsoleLimit))
            throw InputError(console.loc,
                             fmt::format("consoles {} m apart would be more than {} on a {} m wall", console.spacing,
                                         kConsoleLimit, edge.length));
        for (double along : centresOn(edge, console.spacing, width / 2, depth)) {
            if (transforms.size() == kConsoleLimit)
                throw InputError(console.loc, fmt::format("the run would take more than {} consoles", kConsoleLimit));
            transforms.push_back(boxTransform(edge, along, path.baseHeight, width, height, depth));
        }
    }
    return transforms;
}

}  // namespace veduta

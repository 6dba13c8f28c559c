#include "city/lot_test_blocks.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/convex_hull_2.h>

#include <cmath>

#include "core/hash.h"

namespace veduta {

namespace {

Block allStreets(std::vector<Vec2f> points) {
    std::vector<bool> streets(points.size(), true);
    return {std::move(points), std::move(streets), 0};
}

// Random numbers for block `index`: the k-th draw in [lo, hi).
class Draws {
  public:
    explicit Draws(uint32_t index) : index_(index) {}
    float between(float lo, float hi) { return lo + (hi - lo) * bitsToUnitFloat(hashValues({index_, next_++})); }

  private:
    uint32_t index_, next_ = 0;
};

// One point in each of `count` equal sectors round the centre (count ≥ 4 keeps every gap
// between neighbours below 180°, so the centre lies inside and the outline is simple).
std::vector<Vec2f> starPoints(Draws &draws, int count) {
    std::vector<Vec2f> points;
    for (int i = 0; i < count; ++i) {
        float angle = (float(i) + draws.between(0, 0.8f)) * 2 * kPi / float(count);
        float radius = draws.between(25, 75);
        points.push_back({radius * std::cos(angle), radius * std::sin(angle)});
    }
    return points;
}

std::vector<Vec2f> convexPoints(Draws &draws, int count) {
    using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_2;
    std::vector<Point> scattered, hull;
    for (int i = 0; i < count; ++i) scattered.emplace_back(draws.between(-75, 75), draws.between(-75, 75));
    CGAL::convex_hull_2(scattered.begin(), scattered.end(), std::back_inserter(hull));
    std::vector<Vec2f> points;
    for (const Point &p : hull) points.push_back({float(p.x()), float(p.y())});
    return points;
}

}  // namespace

const std::vector<NamedBlock> &shapeBlocks() {
    static const std::vector<NamedBlock> blocks{
        {"rectangle", allStreets({{0, 0}, {100, 0}, {100, 80}, {0, 80}})},
        {"one street", {{{0, 0}, {70, 0}, {70, 50}, {0, 50}}, {true, false, false, false}, 0}},
        {"two streets", {{{0, 0}, {90, 0}, {90, 60}, {0, 60}}, {true, true, false, false}, 0}},
        {"L", allStreets({{0, 0}, {90, 0}, {90, 40}, {45, 40}, {45, 90}, {0, 90}})},
        {"U", allStreets({{0, 0}, {120, 0}, {120, 90}, {80, 90}, {80, 40}, {40, 40}, {40, 90}, {0, 90}})},
        {"pentagon", allStreets({{0, 0}, {100, 0}, {120, 60}, {50, 100}, {-20, 60}})},
        {"hexagon", allStreets({{0, 0}, {60, -10}, {100, 30}, {90, 80}, {30, 90}, {-10, 50}})},
        {"heptagon",
         {{{0, 0}, {70, -5}, {110, 30}, {100, 70}, {60, 95}, {10, 85}, {-15, 40}},
          {true, true, false, true, true, false, true},
          0}},
        {"octagon", allStreets({{6, 0}, {94, 0}, {100, 6}, {100, 74}, {94, 80}, {6, 80}, {0, 74}, {0, 6}})},
    };
    return blocks;
}

Block randomBlock(uint32_t index) {
    Draws draws(index);
    std::vector<Vec2f> points =
        index % 2 ? starPoints(draws, 4 + int(draws.between(0, 7))) : convexPoints(draws, 3 + int(draws.between(0, 8)));
    std::vector<bool> streets;
    for (size_t e = 0; e < points.size(); ++e) streets.push_back(draws.between(0, 1) < 0.75f);
    return {std::move(points), std::move(streets), 0};
}

}  // namespace veduta

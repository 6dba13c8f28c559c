#include "slg/plan_parameters.h"

#include <algorithm>
#include <cmath>

namespace veduta {

LengthLimits lengthLimits(const PlanParameters &p) {
    return {std::sqrt(p.averageArea * p.sideRatio), std::sqrt(p.averageArea) / p.sideRatio};
}

int landmarkCount(const PlanParameters &p, double area, double perimeter, int corners) {
    if (p.count) return std::max(*p.count, 0);
    // Roots of whole numbers (∛343 = 7) come out a rounding under them; the epsilon keeps the
    // floor from taking a whole face away.
    constexpr double kFloorSlack = 1e-9;
    double exact = 0;
    if (p.rule == LandmarkRule::Perimeter) exact = perimeter / std::sqrt(p.averageArea) - corners;
    else exact = std::pow(area / p.scale, 1 / p.exponent);
    int count = exact > 0 ? int(std::floor(exact + kFloorSlack)) : 0;
    return std::max(count, p.minimumCount);
}

int reflexLimit(const PlanParameters &p, SlgPathType type) {
    switch (type) {
    case SlgPathType::Border: return p.reflexLimits[0];
    case SlgPathType::BorderWithCorner: return p.reflexLimits[1];
    case SlgPathType::BorderWithConcaveCorner: return p.reflexLimits[2];
    default: return 0;
    }
}

}  // namespace veduta

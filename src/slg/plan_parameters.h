// The plan parameters every SLG level has (digest-003 §2.3, Tables 4, 6, 9, 13 and 16): how
// many landmarks, how far they jitter, the limits a face's sides keep, how many reflex corners
// its path may add, and the gap that separates the faces.
#pragma once

#include <array>
#include <optional>

#include "slg/slg_graph.h"

namespace veduta {

enum class LandmarkRule : uint8_t {
    Perimeter,  // eq 17–19: faces of about the average area in a row along the outline
    Growth,     // eq 20: the exp-th root of the area over the scale
};

enum class GapType : uint8_t { None, Street, HouseCorridor, ApartmentCorridor };

struct PlanParameters {
    LandmarkRule rule = LandmarkRule::Perimeter;
    double averageArea = 0;  // A, m²
    double sideRatio = 0.5;  // short side over long side of a face
    double scale = 1, exponent = 1;
    int minimumCount = 1;
    std::optional<int> count;  // given instead of computed
    double jitter = 0;         // δ of eq 16, a fraction of the landmarks' spacing
    // Reflex corners a path may add beyond the outline's own, by path type: border, border with
    // a corner, border with a concave corner (eq 11).
    std::array<int, 3> reflexLimits = {0, 0, 0};
    GapType gap = GapType::None;
    double gapWidth = 0;
};

// Eq 21–22: no side of a face under length_min = √(A·ratio), none over length_max = √A/ratio.
struct LengthLimits {
    double minimum = 0, maximum = 0;
};
LengthLimits lengthLimits(const PlanParameters &parameters);

// The number of landmarks for an outline of this area, perimeter and corner count: the given
// count, or the rule's (rounded down, eq 17–20), never under the minimum.
int landmarkCount(const PlanParameters &parameters, double area, double perimeter, int corners);

int reflexLimit(const PlanParameters &parameters, SlgPathType type);

}  // namespace veduta

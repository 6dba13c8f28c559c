#include "slg/building_placement.h"

#include <algorithm>
#include <cmath>

namespace veduta {

namespace {

enum Draw : uint32_t { kOpenSide, kOpenDepth };

// L1397–1405: the band along the front as deep as the shorter side. Where the lot is not that
// deep all along its front (a slanted or bent back), the band is made shallower until it fits.
std::optional<FrontStrip> rectify(const PlanShape &lot, const FaceSides &sides, double minimumSide, double &depth) {
    depth = std::min(sideLength(lot, sides.left), sideLength(lot, sides.right));
    for (int attempt = 0; attempt < 24 && depth >= minimumSide; ++attempt, depth *= 0.9)
        if (auto band = cutFrontStrip(lot, sides, depth, EdgeLocation::Gap)) return band;
    return std::nullopt;
}

// Eq 49 and the open rows of the eq 52–56 table: the share of the spare depth in front of the
// building.
double frontShare(const PlacementParameters &p, const PlanRandom &random) {
    if (p.bauweise != Bauweise::Open)
        return p.alignment == Alignment::Front ? 0 : p.alignment == Alignment::Middle ? 0.5 : 1;
    switch (p.alignment) {
    case Alignment::Front: return random.uniform(0.1, 0.3, kOpenDepth);
    case Alignment::Middle: return random.uniform(0.4, 0.6, kOpenDepth);
    default: return random.uniform(0.7, 0.8, kOpenDepth);
    }
}

// The distances by which the band's sides move: the depth the footprint aims at, √(A·ratio),
// and its width √(A/ratio) (eq 52's l_opt with the digest's reading of the ratio), both within
// the band; a building clear of a side keeps sideDistance from it (the Landesbauordnungen's
// 3 m Abstandsfläche), and an open or semi-open one on a lot too narrow for that falls back to
// semi-open, then closed (footnote 36).
std::optional<SideDistances> distancesIn(double frontage, double depth, PlacementParameters p, Bauweise &built,
                                         const PlanRandom &random) {
    double aimedDepth = std::clamp(std::sqrt(p.buildingArea * p.sideRatio), p.minimumSide, depth);
    if (depth < p.minimumSide) return std::nullopt;
    double width = std::max(std::sqrt(p.buildingArea / p.sideRatio), p.minimumSide);
    double clear = 0;
    built = p.bauweise;
    if (built == Bauweise::Open && frontage - 2 * p.sideDistance < p.minimumSide) built = Bauweise::SemiOpen;
    if (built == Bauweise::SemiOpen && frontage - p.sideDistance < p.minimumSide) built = Bauweise::Closed;
    if (built == Bauweise::Open) clear = std::max((frontage - width) / 2, p.sideDistance);
    if (built == Bauweise::SemiOpen) clear = std::max(frontage - width, p.sideDistance);
    p.bauweise = built;
    double spare = depth - aimedDepth, share = frontShare(p, random);
    SideDistances d{spare * share, 0, spare * (1 - share), 0};
    if (built == Bauweise::Open) d.left = d.right = clear;
    if (built == Bauweise::SemiOpen) (random.unit(kOpenSide) < 0.5 ? d.left : d.right) = clear;
    return d;
}

}  // namespace

std::optional<Placement> placeBuilding(const PlanShape &lot, const FaceSides &sides,
                                       const PlacementParameters &parameters, const PlanRandom &random) {
    Placement placement;
    auto band = rectify(lot, sides, parameters.minimumSide, placement.bandDepth);
    if (!band) return std::nullopt;
    double frontage = sideLength(band->strip, band->stripSides.bottom);
    auto distances = distancesIn(frontage, placement.bandDepth, parameters, placement.bauweise, random);
    if (!distances) return std::nullopt;
    auto moved = moveSides(band->strip, band->stripSides, *distances, EdgeLocation::Gap);
    if (!moved) return std::nullopt;
    placement.footprint = std::move(moved->shape);
    placement.sides = sidesAfterMove(band->stripSides, moved->source);
    return placement;
}

}  // namespace veduta

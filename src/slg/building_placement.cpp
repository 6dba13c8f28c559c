#include "slg/building_placement.h"

#include <algorithm>
#include <cmath>

namespace veduta {

namespace {

// Purposes of its draws, apart from those of the parameter cascade under the same identity.
enum Draw : uint32_t { kOpenSide = 0x504c4353u, kOpenDepth = 0x504c4344u };  // "PLCS", "PLCD"

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

// Footnote 36: an open building on a lot too narrow to keep clear of both sides is built
// semi-open, and a semi-open one on a lot too narrow for that closed.
Bauweise fitting(Bauweise wanted, double frontage, const PlacementParameters &p) {
    if (wanted == Bauweise::Open && frontage - 2 * p.sideDistance < p.minimumSide) wanted = Bauweise::SemiOpen;
    if (wanted == Bauweise::SemiOpen && frontage - p.sideDistance < p.minimumSide) wanted = Bauweise::Closed;
    return wanted;
}

Bauweise weaker(Bauweise b) { return b == Bauweise::Open ? Bauweise::SemiOpen : Bauweise::Closed; }

// The distances by which the band's sides move: the depth the footprint aims at, √(A·ratio),
// and its width √(A/ratio) (eq 52's l_opt with the digest's reading of the ratio), both within
// the band; a building clear of a side keeps sideDistance from it (the Landesbauordnungen's
// 3 m Abstandsfläche).
SideDistances distancesFor(Bauweise built, double frontage, double depth, PlacementParameters p,
                           const PlanRandom &random) {
    double aimedDepth = std::clamp(std::sqrt(p.buildingArea * p.sideRatio), p.minimumSide, depth);
    double width = std::max(std::sqrt(p.buildingArea / p.sideRatio), p.minimumSide);
    p.bauweise = built;
    double spare = depth - aimedDepth, share = frontShare(p, random);
    SideDistances d{spare * share, 0, spare * (1 - share), 0};
    if (built == Bauweise::Open) d.left = d.right = std::max((frontage - width) / 2, p.sideDistance);
    if (built == Bauweise::SemiOpen)
        (random.unit(kOpenSide) < 0.5 ? d.left : d.right) = std::max(frontage - width, p.sideDistance);
    return d;
}

}  // namespace

std::optional<Placement> placeBuilding(const PlanShape &lot, const FaceSides &sides,
                                       const PlacementParameters &parameters, const PlanRandom &random) {
    Placement placement;
    auto band = rectify(lot, sides, parameters.minimumSide, placement.bandDepth);
    if (!band) return std::nullopt;
    double frontage = sideLength(band->strip, band->stripSides.bottom);
    // A lot whose sides are too short for the distances (a corner lot's, along two streets)
    // falls back as a narrow one does; a closed building that does not fit fills the band.
    for (Bauweise built = fitting(parameters.bauweise, frontage, parameters);; built = weaker(built)) {
        SideDistances distances = distancesFor(built, frontage, placement.bandDepth, parameters, random);
        auto moved = moveSides(band->strip, band->stripSides, distances, EdgeLocation::Gap);
        if (!moved && built == Bauweise::Closed)
            moved = moveSides(band->strip, band->stripSides, {}, EdgeLocation::Gap);
        if (moved) {
            placement.bauweise = built;
            placement.footprint = std::move(moved->shape);
            placement.sides = sidesAfterMove(band->stripSides, moved->source);
            return placement;
        }
        if (built == Bauweise::Closed) return std::nullopt;
    }
}

}  // namespace veduta

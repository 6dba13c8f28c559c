#include "city/atkis_slg_input.h"

#include <algorithm>

#include "core/hash.h"

namespace veduta {

namespace {

// What the Objektart says of the land use (the AdV's Objektartenkatalog): housing, industry
// and commerce, special functions (offices and public buildings); Ortslage and mixed use are
// the tables' mixture.
std::optional<LandUse> useOf(int type) {
    switch (type) {
    case 2111: return LandUse::Wohnen;
    case 2112: return LandUse::Industrie;
    case 2114: return LandUse::Buero;
    default: return std::nullopt;
    }
}

// A ring in local metres, subtracted in double, counter-clockwise; none when it cannot be one.
std::optional<Polygon2d> localRing(const MapRing &ring, const LocalFrame &frame) {
    Polygon2d local;
    for (const MapPoint &p : ring) {
        Vec2d q{p.easting - frame.origin.easting, p.northing - frame.origin.northing};
        if (local.empty() || length(q - local.back()) > 1e-3) local.push_back(q);
    }
    while (local.size() > 1 && length(local.front() - local.back()) <= 1e-3) local.pop_back();
    if (local.size() < 3 || !isSimple(local) || signedArea(local) == 0) return std::nullopt;
    if (signedArea(local) < 0) std::reverse(local.begin(), local.end());
    return local;
}

uint32_t identityOf(const std::string &id, size_t part) {
    std::vector<uint32_t> values(id.begin(), id.end());
    values.push_back(uint32_t(part));
    return hashSequence(values);
}

}  // namespace

SlgLandInput slgLandInput(const std::vector<AtkisObject> &objects, const LocalFrame &frame) {
    SlgLandInput input;
    for (const AtkisObject &object : objects) {
        LandClass c = landClass(object);
        if (c != LandClass::Settlement && c != LandClass::Building) continue;
        for (size_t part = 0; part < object.areas.size(); ++part) {
            std::optional<Polygon2d> ring = localRing(object.areas[part], frame);
            if (!ring) {
                ++input.unusable;
                continue;
            }
            if (c == LandClass::Settlement) input.settlements.push_back({std::move(*ring), useOf(object.type)});
            else input.footprints.push_back({std::move(*ring), identityOf(object.id, part)});
        }
    }
    return input;
}

}  // namespace veduta

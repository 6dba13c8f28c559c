// Mouldings: the cornices (profiles extruded along the facade, HORIZONTAL: 1 m long, x from
// -0.5 to 0.5), the window pediments and the Doric column. Profiles are written as (height
// above the bottom, projection from the wall), from the bottom at the wall to the top.
#include <cmath>

#include "city/asset_builder.h"
#include "city/asset_shapes.h"

namespace veduta {

namespace {

using Profile = std::vector<Vec2f>;

// Arc segments per quarter turn of a curved moulding.
constexpr int kArcSegments = 6;

// The profile seen upside down, for a moulding that closes a band from above.
Profile flipped(const Profile &profile, float height) {
    Profile out;
    for (auto it = profile.rbegin(); it != profile.rend(); ++it) out.push_back({height - it->x, it->y});
    return out;
}

Asset cornice(std::string name, const Profile &profile, float height) {
    AssetBuilder b;
    b.prism(mouldingOutline(profile, -height / 2), PrismAxis::X, -0.5f, 0.5f, MaterialCategory::Material);
    return std::move(b).finish(std::move(name), ModelType::Horizontal);
}

// A plain band, 0.3 m high and 0.16 m deep, whose soffit falls to a drip at the front edge
// so that rain leaves the wall; a weathered top.
Profile plainBand() { return {{0.04f, 0}, {0, 0.14f}, {0, 0.16f}, {0.26f, 0.16f}, {0.3f, 0.02f}, {0.3f, 0}}; }

// A band with its lower and upper front edges chamfered.
Profile chamferedBand() { return {{0, 0}, {0, 0.1f}, {0.1f, 0.25f}, {0.22f, 0.25f}, {0.3f, 0.12f}, {0.3f, 0}}; }

// Nasengesims: a half-round nose standing out of a flat band.
Profile noseMoulding() {
    Profile p{{0, 0}};
    appendArc(p, {0.15f, 0.08f}, 0.15f, 180, 0, 2 * kArcSegments);
    p.push_back({0.3f, 0});
    return p;
}

// Fallender Karnies: a cyma recta, 0.15 m high, an S (half a cosine wave) from the wall out
// to its full depth at the top. Only 0.05 m deep: the ornament band scales its depth by 3.5 (L2401-L2405)
// to meet the 0.17 m relief between the two.
Profile cymaRecta() {
    constexpr float height = 0.15f, depth = 0.05f;
    Profile p{{0, 0}};
    for (int i = 0; i <= 2 * kArcSegments; ++i) {
        float t = float(i) / float(2 * kArcSegments);
        p.push_back({0.01f + (height - 0.02f) * t, 0.005f + (depth - 0.005f) * (1 - std::cos(kPi * t)) / 2});
    }
    p.push_back({height, depth});
    p.push_back({height, 0});
    return p;
}

// The plinth moulding of the basement: a socle 1 m high, 0.1 m proud, with a sloped top.
Profile basementPlinth() { return {{0, 0}, {0, 0.1f}, {0.86f, 0.1f}, {0.94f, 0.04f}, {1.0f, 0.04f}, {1.0f, 0}}; }

// Kranzleiste, the main crown moulding, 0.4 × 0.45 m: a fillet and an ovolo for the bed
// moulding, the corona (a deep plain face with a soffit), and a cyma on top.
Profile crownMoulding() {
    Profile p{{0, 0}, {0, 0.05f}};
    appendArc(p, {0.12f, 0.05f}, 0.08f, 180, 90, kArcSegments);  // the ovolo, bulging out
    p.push_back({0.12f, 0.36f});
    p.push_back({0.27f, 0.36f});
    p.push_back({0.27f, 0.38f});
    for (int i = 1; i <= 2 * kArcSegments; ++i) {
        float t = float(i) / float(2 * kArcSegments);
        p.push_back({0.27f + 0.13f * t, 0.38f + 0.07f * (1 - std::cos(kPi * t)) / 2});
    }
    p.push_back({0.4f, 0});
    return p;
}

// A window head, 1.4 × 0.2 m, 0.2 m deep: a fascia under a projecting cap with a weathered top.
Asset straightHead() {
    const Profile profile{{0, 0},        {0, 0.1f},     {0.08f, 0.1f}, {0.08f, 0.16f},
                          {0.12f, 0.2f}, {0.16f, 0.2f}, {0.2f, 0.05f}, {0.2f, 0}};
    AssetBuilder b;
    b.prism(mouldingOutline(profile, -0.1f), PrismAxis::X, -0.7f, 0.7f, MaterialCategory::Material);
    return std::move(b).finish("SmallRoof1", ModelType::SmallRoof);
}

// A pediment 1.4 × 0.45 m over a window: a straight cornice at the bottom, the tympanum
// under `rake` (its top edge, left to right, both ends on the cornice) and a raking cornice
// following it.
Asset pediment(std::string name, const std::vector<Vec2f> &rake) {
    constexpr float halfWidth = 0.7f, bottom = -0.225f, cornice = 0.08f, band = 0.08f;
    AssetBuilder b;
    b.box({-halfWidth, bottom, 0}, {halfWidth, bottom + cornice, 0.2f}, MaterialCategory::Material);
    b.prism(rake, PrismAxis::Z, 0, 0.08f, MaterialCategory::Material);
    std::vector<Vec2f> raking = rake;
    for (auto it = rake.rbegin(); it != rake.rend(); ++it) raking.push_back({it->x, it->y + band});
    b.prism(raking, PrismAxis::Z, 0, 0.2f, MaterialCategory::Material);
    return std::move(b).finish(std::move(name), ModelType::SmallRoof);
}

Asset segmentalPediment() {
    // The arc through the ends at the cornice and the crown 0.29 m above them.
    constexpr float halfChord = 0.7f, rise = 0.29f, base = -0.145f;
    float radius = (halfChord * halfChord + rise * rise) / (2 * rise);
    float halfAngle = std::asin(halfChord / radius) * 180 / kPi;
    std::vector<Vec2f> rake;
    appendArc(rake, {0, base + rise - radius}, radius, 90 + halfAngle, 90 - halfAngle, 2 * kArcSegments);
    return pediment("SmallRoofArc", rake);
}

Asset triangularPediment() { return pediment("SmallRoofTri", {{-0.7f, -0.145f}, {0, 0.145f}, {0.7f, -0.145f}}); }

// Half-round parts of the column stand against the wall: a half disc of `radius` in (z, x).
std::vector<Vec2f> halfDisc(float radius) {
    std::vector<Vec2f> outline;
    appendArc(outline, {0, 0}, radius, -90, 90, kArcSegments + 2);
    return outline;
}

// A Doric half column 0.3 × 3.0 m standing against the wall: square plinth, torus, a shaft
// of 16 flutes with sharp arrises (8 on the visible half), necking, echinus and abacus.
Asset doricColumn() {
    constexpr int flutes = 8;
    constexpr float shaftRadius = 0.12f, fluteDepth = 0.012f;
    AssetBuilder b;
    b.box({-0.15f, -1.5f, 0}, {0.15f, -1.42f, 0.15f}, MaterialCategory::Material);
    b.prism(halfDisc(0.14f), PrismAxis::Y, -1.42f, -1.36f, MaterialCategory::Material);
    std::vector<Vec2f> shaft;
    for (int i = 0; i <= 2 * flutes; ++i) {
        float angle = radians(-90 + 180 * float(i) / float(2 * flutes));
        float r = i % 2 == 0 ? shaftRadius : shaftRadius - fluteDepth;
        shaft.push_back({r * std::cos(angle), r * std::sin(angle)});
    }
    b.prism(shaft, PrismAxis::Y, -1.36f, 1.22f, MaterialCategory::Material);
    b.prism(halfDisc(0.125f), PrismAxis::Y, 1.22f, 1.26f, MaterialCategory::Material);
    b.prism(halfDisc(0.135f), PrismAxis::Y, 1.26f, 1.31f, MaterialCategory::Material);
    b.prism(halfDisc(0.145f), PrismAxis::Y, 1.31f, 1.36f, MaterialCategory::Material);
    b.box({-0.15f, 1.36f, 0}, {0.15f, 1.5f, 0.15f}, MaterialCategory::Material);
    return std::move(b).finish("ColumnDoric1", ModelType::Vertical);
}

}  // namespace

std::vector<Asset> mouldingAssets() {
    std::vector<Asset> assets;
    assets.push_back(cornice("Cornice1", plainBand(), 0.3f));
    assets.push_back(cornice("Cornice2Chamfer", chamferedBand(), 0.3f));
    assets.push_back(cornice("Cornice3Nasengesims", noseMoulding(), 0.3f));
    assets.push_back(cornice("Cornice4FallenderKarnies", cymaRecta(), 0.15f));
    assets.push_back(cornice("Cornice4FallenderKarniesOben", flipped(cymaRecta(), 0.15f), 0.15f));
    assets.push_back(cornice("Cornice5Basement", basementPlinth(), 1.0f));
    assets.push_back(cornice("Cornice6Kranzleiste", crownMoulding(), 0.4f));
    assets.push_back(straightHead());
    assets.push_back(segmentalPediment());
    assets.push_back(triangularPediment());
    assets.push_back(doricColumn());
    return assets;
}

}  // namespace veduta

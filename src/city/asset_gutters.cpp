// Rainwater goods (L2584-L2695): the half-round gutter under the eaves, repeated along the
// facade 1 m at a time (HORIZONTAL), its end pieces, and the cylinder the rules use for the
// downpipe and for the bars of basement windows. All metal.
#include <cmath>

#include "city/asset_builder.h"
#include "city/asset_shapes.h"

namespace veduta {

namespace {

// The gutter, in (y, z): a half round of radius 0.1 m hanging with its rim at y = 0, its back
// 1 cm off the wall.
constexpr float kRadius = 0.1f, kWall = 0.008f, kCentreZ = 0.11f;
constexpr int kSegments = 8;

// The trough's cross-section from the back rim round under to the front rim, at `radius`.
std::vector<Vec2f> halfRound(float radius) {
    std::vector<Vec2f> points;
    for (int i = 0; i <= kSegments; ++i) {
        float angle = kPi * float(i) / float(kSegments);
        points.push_back({-radius * std::sin(angle), kCentreZ - radius * std::cos(angle)});
    }
    return points;
}

// The flashing strip that leads the roof's water into the gutter, 0.1 m up the wall.
void addFlashing(AssetBuilder &b) { b.box({-0.5f, 0, 0}, {0.5f, kRadius, 0.004f}, MaterialCategory::Reflection); }

// One metre of gutter: the trough with a rolled bead on its front rim, and the flashing.
Asset gutterElement() {
    const MaterialCategory metal = MaterialCategory::Reflection;
    AssetBuilder b;
    std::vector<Vec2f> trough = halfRound(kRadius);
    std::vector<Vec2f> inner = halfRound(kRadius - kWall);
    trough.insert(trough.end(), inner.rbegin(), inner.rend());
    b.prism(trough, PrismAxis::X, -0.5f, 0.5f, metal);
    std::vector<Vec2f> bead;
    appendArc(bead, {0, kCentreZ + kRadius}, 0.012f, 0, 330, 11);
    b.prism(bead, PrismAxis::X, -0.5f, 0.5f, metal);
    addFlashing(b);
    return std::move(b).finish("gutterElement", ModelType::Horizontal);
}

// The end piece: the trough's section filled, squeezed by the rules into 1 cm at each end.
// It keeps the flashing so that its bounds, and so its fitting, are those of the gutter.
Asset gutterEnd() {
    AssetBuilder b;
    b.prism(halfRound(kRadius), PrismAxis::X, -0.5f, 0.5f, MaterialCategory::Reflection);
    addFlashing(b);
    return std::move(b).finish("gutterEnd", ModelType::Horizontal);
}

// A unit cylinder along y (1 m long, 1 m across) standing against the wall.
Asset cylinder() {
    std::vector<Vec2f> circle;  // in (z, x)
    appendArc(circle, {0.5f, 0}, 0.5f, 0, 360 - 360.0f / 16, 15);
    AssetBuilder b;
    b.prism(circle, PrismAxis::Y, -0.5f, 0.5f, MaterialCategory::Reflection);
    return std::move(b).finish("Cylinder", ModelType::Vertical);
}

}  // namespace

std::vector<Asset> gutterAssets() {
    std::vector<Asset> assets;
    assets.push_back(gutterElement());
    assets.push_back(gutterEnd());
    assets.push_back(cylinder());
    return assets;
}

}  // namespace veduta

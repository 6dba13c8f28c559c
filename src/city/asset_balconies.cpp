// The back facades' balconies (BackFacadeBalcony… rules, L2444-L2581): a balcony per storey
// with its railing, the terrace base under the lowest, the canopy over the highest, and the
// doors onto them. The balconies are NoType and fitted with z_scale="right", so their depth
// follows their width.
#include "city/asset_builder.h"
#include "city/asset_shapes.h"

namespace veduta {

namespace {

constexpr float kHalfWidth = 1.0f, kDepth = 1.2f;

// A steel railing round the front and sides of a slab whose top is at `floor`: bottom rail,
// handrail 1 m up, balusters 0.15 m apart.
void addRailing(AssetBuilder &b, float floor) {
    constexpr float bar = 0.02f, rail = 0.04f, spacing = 0.15f;
    const MaterialCategory metal = MaterialCategory::Reflection;
    for (float y : {floor + 0.1f, floor + 1.0f - rail}) {
        b.box({-kHalfWidth, y, kDepth - rail}, {kHalfWidth, y + rail, kDepth}, metal);
        b.box({-kHalfWidth, y, 0}, {-kHalfWidth + rail, y + rail, kDepth - rail}, metal);
        b.box({kHalfWidth - rail, y, 0}, {kHalfWidth, y + rail, kDepth - rail}, metal);
    }
    float from = floor + 0.1f + rail, to = floor + 1.0f - rail;
    auto count = [&](float length) { return int(length / spacing); };
    for (int i = 1; i < count(2 * kHalfWidth); ++i) {
        float x = -kHalfWidth + 2 * kHalfWidth * float(i) / float(count(2 * kHalfWidth));
        b.box({x - bar / 2, from, kDepth - rail / 2 - bar / 2}, {x + bar / 2, to, kDepth - rail / 2 + bar / 2}, metal);
    }
    for (int i = 1; i < count(kDepth); ++i) {
        float z = kDepth * float(i) / float(count(kDepth));
        for (float x : {-kHalfWidth + rail / 2, kHalfWidth - rail / 2}) {
            b.box({x - bar / 2, from, z - bar / 2}, {x + bar / 2, to, z + bar / 2}, metal);
        }
    }
}

// A balcony a storey high (2.0 × 3.0 m, 1.2 m deep): a slab at the floor, its railing, and
// steel posts at the front corners that carry the balcony above, as on the stacked iron
// balconies of Gründerzeit courtyards.
Asset balcony() {
    constexpr float bottom = -1.5f, slab = 0.15f, post = 0.05f;
    AssetBuilder b;
    b.box({-kHalfWidth, bottom, 0}, {kHalfWidth, bottom + slab, kDepth}, MaterialCategory::Material);
    addRailing(b, bottom + slab);
    for (float x : {-kHalfWidth, kHalfWidth - post}) {
        b.box({x, bottom + slab, kDepth - post}, {x + post, -bottom, kDepth}, MaterialCategory::Reflection);
    }
    return std::move(b).finish("Balcony1", ModelType::NoType);
}

// The terrace base under the lowest balcony, 2.0 × 0.45 m: a plinth under a coping slab.
Asset balconyGround() {
    AssetBuilder b;
    b.box({-kHalfWidth, 0.155f, 0}, {kHalfWidth, 0.225f, kDepth + 0.03f}, MaterialCategory::Material);
    b.box({-kHalfWidth + 0.03f, -0.225f, 0}, {kHalfWidth - 0.03f, 0.155f, kDepth}, MaterialCategory::Material);
    return std::move(b).finish("Balcony1Ground", ModelType::NoType);
}

// The canopy over the highest balcony, 2.0 × 0.5 m, 1.3 m deep: a slab falling from the
// wall to a fascia at the front. The roof's top runs from (y, z) = (0.25, 0) to (0, 1.3).
constexpr float kCanopyDepth = 1.3f, kCanopyTop = 0.25f, kCanopyFall = 0.25f;

float canopyTopAt(float z) { return kCanopyTop - kCanopyFall * z / kCanopyDepth; }

Asset balconyRoof(std::string name, bool solar) {
    constexpr float slab = 0.08f;
    AssetBuilder b;
    const Vec2f roof[] = {{canopyTopAt(0) - slab, 0},
                          {canopyTopAt(0), 0},
                          {canopyTopAt(kCanopyDepth), kCanopyDepth},
                          {canopyTopAt(kCanopyDepth) - slab, kCanopyDepth}};
    b.prism(roof, PrismAxis::X, -kHalfWidth, kHalfWidth, MaterialCategory::Material);
    b.box({-kHalfWidth, -kCanopyTop, kCanopyDepth - 0.04f}, {kHalfWidth, canopyTopAt(kCanopyDepth), kCanopyDepth},
          MaterialCategory::Material);
    if (solar) {
        // Two panels lying on the slope, a few centimetres above it.
        constexpr float nearZ = 0.1f, farZ = 1.2f, lift = 0.01f, thickness = 0.03f;
        const Vec2f panel[] = {{canopyTopAt(nearZ) + lift, nearZ},
                               {canopyTopAt(farZ) + lift, farZ},
                               {canopyTopAt(farZ) + lift + thickness, farZ},
                               {canopyTopAt(nearZ) + lift + thickness, nearZ}};
        b.prism(panel, PrismAxis::X, -kHalfWidth + 0.05f, -0.03f, MaterialCategory::Window);
        b.prism(panel, PrismAxis::X, 0.03f, kHalfWidth - 0.05f, MaterialCategory::Window);
    }
    return std::move(b).finish(std::move(name), ModelType::NoType);
}

// A door leaf between `left` and `right` standing on z = 0: stiles and rails, a raised panel
// in the lower part, glazing with a glazing bar above, a dark room behind the glass.
void addDoorLeaf(AssetBuilder &b, float left, float right, float bottom, float top) {
    constexpr float stile = 0.1f, leaf = 0.05f, glassZ = 0.025f;
    const MaterialCategory wood = MaterialCategory::Door;
    float lockRail = bottom + 0.38f * (top - bottom), lockRailTop = lockRail + 0.12f;
    b.box({left, bottom, 0}, {left + stile, top, leaf}, wood);
    b.box({right - stile, bottom, 0}, {right, top, leaf}, wood);
    b.box({left + stile, bottom, 0}, {right - stile, bottom + 0.15f, leaf}, wood);
    b.box({left + stile, lockRail, 0}, {right - stile, lockRailTop, leaf}, wood);
    b.box({left + stile, top - 0.1f, 0}, {right - stile, top, leaf}, wood);
    b.box({left + stile, bottom + 0.15f, 0}, {right - stile, lockRail, 0.02f}, wood);
    b.box({left + stile + 0.05f, bottom + 0.2f, 0.02f}, {right - stile - 0.05f, lockRail - 0.05f, 0.035f}, wood);
    float centre = (left + right) / 2, glassWidth = right - left - 2 * stile, glassHeight = top - 0.1f - lockRailTop;
    b.box({centre - 0.015f, lockRailTop, 0}, {centre + 0.015f, top - 0.1f, 0.04f}, wood);
    b.box({left + stile, lockRailTop + glassHeight * 0.55f, 0},
          {right - stile, lockRailTop + glassHeight * 0.55f + 0.03f, 0.04f}, wood);
    b.rectangle({left + stile, lockRailTop, glassZ}, {glassWidth, 0, 0}, {0, glassHeight, 0}, MaterialCategory::Window);
    b.rectangle({left + stile, lockRailTop, 0.005f}, {glassWidth, 0, 0}, {0, glassHeight, 0}, MaterialCategory::None);
}

// A balcony door in its frame: one leaf 1.0 × 2.3 m, or two in a frame 1.6 m wide.
Asset balconyDoor(std::string name, float halfWidth, int leaves) {
    constexpr float halfHeight = 1.15f, frame = 0.08f, depth = 0.08f;
    const MaterialCategory wood = MaterialCategory::Door;
    AssetBuilder b;
    b.box({-halfWidth, -halfHeight, 0}, {-halfWidth + frame, halfHeight, depth}, wood);
    b.box({halfWidth - frame, -halfHeight, 0}, {halfWidth, halfHeight, depth}, wood);
    b.box({-halfWidth + frame, halfHeight - frame, 0}, {halfWidth - frame, halfHeight, depth}, wood);
    b.box({-halfWidth + frame, -halfHeight, 0}, {halfWidth - frame, -halfHeight + 0.05f, depth}, wood);
    float leafWidth = (2 * (halfWidth - frame)) / float(leaves);
    for (int i = 0; i < leaves; ++i) {
        float left = -halfWidth + frame + leafWidth * float(i);
        addDoorLeaf(b, left, left + leafWidth, -halfHeight + 0.05f, halfHeight - frame);
    }
    return std::move(b).finish(std::move(name), ModelType::Door);
}

}  // namespace

std::vector<Asset> balconyAssets() {
    std::vector<Asset> assets;
    assets.push_back(balcony());
    assets.push_back(balconyGround());
    assets.push_back(balconyRoof("Balcony1Roof", false));
    assets.push_back(balconyRoof("Balcony1RoofSolar", true));
    assets.push_back(balconyDoor("BalconyDoor", 0.5f, 1));
    assets.push_back(balconyDoor("BalconyDoor2", 0.8f, 2));
    return assets;
}

}  // namespace veduta

// Windows and entrances: frames around a hole in the wall, with reveals going back to the
// implied wall thickness and a dark room behind, so that one never looks through a building.
#include "city/asset_builder.h"
#include "city/asset_shapes.h"

namespace veduta {

namespace {

constexpr float kRoomDepth = 0.6f;

struct Opening {
    float left, right, bottom, top;
    float revealDepth;  // how far back the reveals go: the wall's thickness at the frame
    bool sill;          // a sill or step covers the bottom reveal
};

// The four sides of a rectangular tunnel from z = `back` to z = `front`, facing inwards.
void addTunnel(AssetBuilder &b, const Opening &o, float back, float front, bool withBottom, MaterialCategory surface) {
    float width = o.right - o.left, height = o.top - o.bottom, depth = front - back;
    b.rectangle({o.left, o.bottom, back}, {0, height, 0}, {0, 0, depth}, surface);
    b.rectangle({o.right, o.bottom, back}, {0, 0, depth}, {0, height, 0}, surface);
    b.rectangle({o.left, o.top, back}, {width, 0, 0}, {0, 0, depth}, surface);
    if (withBottom) b.rectangle({o.left, o.bottom, back}, {0, 0, depth}, {width, 0, 0}, surface);
}

void addOpening(AssetBuilder &b, const Opening &o) {
    addTunnel(b, o, -o.revealDepth, 0, !o.sill, MaterialCategory::Material);
    addTunnel(b, o, -kRoomDepth, -o.revealDepth, true, MaterialCategory::None);
    b.rectangle({o.left, o.bottom, -kRoomDepth}, {o.right - o.left, 0, 0}, {0, o.top - o.bottom, 0},
                MaterialCategory::None);
}

// A casement frame around the glass at `glassZ`, with a mullion and, if `transomY` lies
// inside, a transom.
void addCasement(AssetBuilder &b, const Opening &o, float bar, float glassZ, float transomY) {
    float back = glassZ - bar / 2, front = glassZ + bar / 2;
    b.box({o.left, o.bottom, back}, {o.left + bar, o.top, front}, MaterialCategory::Material);
    b.box({o.right - bar, o.bottom, back}, {o.right, o.top, front}, MaterialCategory::Material);
    b.box({o.left + bar, o.bottom, back}, {o.right - bar, o.bottom + bar, front}, MaterialCategory::Material);
    b.box({o.left + bar, o.top - bar, back}, {o.right - bar, o.top, front}, MaterialCategory::Material);
    float centre = (o.left + o.right) / 2;
    b.box({centre - bar / 2, o.bottom + bar, back}, {centre + bar / 2, o.top - bar, front}, MaterialCategory::Material);
    if (transomY > o.bottom + bar && transomY < o.top - bar) {
        b.box({o.left + bar, transomY - bar / 2, back}, {o.right - bar, transomY + bar / 2, front},
              MaterialCategory::Material);
    }
}

// A surround of width `band` standing `proud` in front of the wall on the sides and top of
// the opening, from `bottom` up.
void addSurround(AssetBuilder &b, const Opening &o, float band, float bottom, float proud) {
    b.box({o.left - band, bottom, 0}, {o.left, o.top + band, proud}, MaterialCategory::Material);
    b.box({o.right, bottom, 0}, {o.right + band, o.top + band, proud}, MaterialCategory::Material);
    b.box({o.left, o.top, 0}, {o.right, o.top + band, proud}, MaterialCategory::Material);
}

// The window of the upper floors, 1.2 × 2.0 m: a stucco surround, a sill, reveals 0.25 m
// deep and a casement with mullion and transom around the glass plane the rule puts Glass0
// in (z -0.1, 0.8 × 0.85 of the scope).
Asset window1() {
    const Opening o{-0.48f, 0.48f, -0.86f, 0.88f, 0.25f, true};
    AssetBuilder b;
    addSurround(b, o, 0.12f, o.bottom, 0.03f);
    b.box({-0.6f, -1.0f, -o.revealDepth}, {0.6f, o.bottom, 0.08f}, MaterialCategory::Material);
    addOpening(b, o);
    addCasement(b, o, 0.05f, -0.1f, 0.42f);
    return std::move(b).finish("Window1", ModelType::Window);
}

// A basement window, 1.0 × 0.6 m, glazed at z -0.2 as BasementGlassChoice places it.
// With `surround`, a stone frame with a keystone; without, a bare opening with a ledge.
Asset basementWindow(std::string name, bool surround) {
    AssetBuilder b;
    if (surround) {
        const Opening o{-0.42f, 0.42f, -0.22f, 0.22f, 0.25f, true};
        addSurround(b, o, 0.08f, -0.3f, 0.04f);
        b.box({o.left, -0.3f, -o.revealDepth}, {o.right, o.bottom, 0.04f}, MaterialCategory::Material);
        b.box({-0.06f, 0.16f, 0}, {0.06f, 0.3f, 0.07f}, MaterialCategory::Material);
        addOpening(b, o);
        addCasement(b, o, 0.03f, -0.2f, o.top);
    } else {
        const Opening o{-0.5f, 0.5f, -0.26f, 0.3f, 0.25f, true};
        b.box({o.left, -0.3f, -o.revealDepth}, {o.right, o.bottom, 0.03f}, MaterialCategory::Material);
        addOpening(b, o);
        addCasement(b, o, 0.03f, -0.2f, o.top);
    }
    return std::move(b).finish(std::move(name), ModelType::Window);
}

// The plain entrance, 1.6 × 3.0 m: jambs, a lintel, a stone step and a reveal 0.3 m deep
// for the door.
Asset entrance1() {
    const Opening o{-0.6f, 0.6f, -1.42f, 1.3f, 0.3f, true};
    AssetBuilder b;
    addSurround(b, o, 0.2f, -1.5f, 0.06f);
    b.box({-0.6f, -1.5f, -o.revealDepth}, {0.6f, o.bottom, 0.15f}, MaterialCategory::Material);
    addOpening(b, o);
    return std::move(b).finish("Entrance1", ModelType::Door);
}

// The grand portal, 2.1 × 3.4 m: pilasters on plinths with capitals, a frieze under a
// moulded cornice, a keystone and a deeper step.
Asset entrance2() {
    const Opening o{-0.6f, 0.6f, -1.6f, 1.1f, 0.3f, true};
    constexpr float bottom = -1.7f, pilaster = 0.4f;
    AssetBuilder b;
    addSurround(b, o, pilaster, bottom, 0.08f);
    for (float left : {o.left - pilaster, o.right}) {
        b.box({left, bottom, 0}, {left + pilaster, -1.35f, 0.12f}, MaterialCategory::Material);
        b.box({left, 0.95f, 0}, {left + pilaster, o.top, 0.12f}, MaterialCategory::Material);
    }
    const Vec2f cornice[] = {{0, 0}, {0, 0.1f}, {0.06f, 0.1f}, {0.1f, 0.2f}, {0.2f, 0.2f}, {0.2f, 0}};
    b.prism(mouldingOutline(cornice, o.top + pilaster), PrismAxis::X, -1.05f, 1.05f, MaterialCategory::Material);
    b.box({-0.1f, 1.0f, 0}, {0.1f, 1.35f, 0.14f}, MaterialCategory::Material);
    b.box({-0.7f, bottom, -o.revealDepth}, {0.7f, o.bottom, 0.25f}, MaterialCategory::Material);
    addOpening(b, o);
    return std::move(b).finish("Entrance2", ModelType::Door);
}

}  // namespace

std::vector<Asset> openingAssets() {
    std::vector<Asset> assets;
    assets.push_back(window1());
    assets.push_back(basementWindow("WindowBasement", true));
    assets.push_back(basementWindow("WindowBasementSimple", false));
    assets.push_back(entrance1());
    assets.push_back(entrance2());
    return assets;
}

}  // namespace veduta

// Walls and panes: the plain pieces the rules lay over every scope.
#include "city/asset_builder.h"
#include "city/asset_shapes.h"

namespace veduta {

namespace {

// A unit square in the wall plane; walls get planar uvs from their scope when fitted.
Asset flatPiece(std::string name, ModelType type, MaterialCategory surface) {
    AssetBuilder b;
    b.rectangle({-0.5f, -0.5f, 0}, {1, 0, 0}, {0, 1, 0}, surface);
    return std::move(b).finish(std::move(name), type);
}

// The thesis' "+1" pieces stand 1 m proud of the wall (a unit cube), which is what its rules
// assume: OutpickingOrnamentWall scales their depth by 0.17 for a relief and by 0.0001 for a
// flat band (L2403, L2408), and a unit cube's faces take a texture exactly once each (L2421).
Asset unitCube(std::string name, ModelType type, MaterialCategory surface) {
    AssetBuilder b;
    b.box({-0.5f, -0.5f, 0}, {0.5f, 0.5f, 1}, surface);
    return std::move(b).finish(std::move(name), type);
}

// A loggia opening for a balcony door, 2.5 × 3 m: piers and a lintel of wall standing 1 m
// proud, the recessed wall at z = 0 between them, open to the floor. The thesis' rule
// (L2519-L2525) scales its depth to 0.5 and moves the door out by the same 0.5, into the
// opening's front plane.
Asset wallHole() {
    constexpr float halfWidth = 1.25f, halfHeight = 1.5f, halfOpening = 0.875f, lintel = 1.38f, depth = 1;
    AssetBuilder b;
    b.box({-halfWidth, -halfHeight, 0}, {-halfOpening, halfHeight, depth}, MaterialCategory::Wall);
    b.box({halfOpening, -halfHeight, 0}, {halfWidth, halfHeight, depth}, MaterialCategory::Wall);
    b.box({-halfOpening, lintel, 0}, {halfOpening, halfHeight, depth}, MaterialCategory::Wall);
    b.rectangle({-halfOpening, -halfHeight, 0}, {2 * halfOpening, 0, 0}, {0, lintel + halfHeight, 0},
                MaterialCategory::Wall);
    return std::move(b).finish("WallHole", ModelType::Wall);
}

}  // namespace

std::vector<Asset> wallAssets() {
    std::vector<Asset> assets;
    assets.push_back(flatPiece("Wall0", ModelType::Wall, MaterialCategory::Wall));
    assets.push_back(unitCube("Wall+1", ModelType::Wall, MaterialCategory::Wall));
    assets.push_back(wallHole());
    // The rules move panes back into their frames (Glass0 at z -0.1 in Window1).
    assets.push_back(flatPiece("Glass0", ModelType::Glass, MaterialCategory::Window));
    // TEXTURED in the thesis, but it takes the rule's texture like any glass piece.
    assets.push_back(unitCube("Glass+1", ModelType::Glass, MaterialCategory::Material));
    return assets;
}

}  // namespace veduta

// The buildings of a render scene, piece by piece in world space, for tests that compare what
// a generator made of each building (tests/city/building_identity_test.cpp, scene_seed_test.cpp).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "scene/render_scene.h"

namespace veduta::test {

// One baked mesh or instance of a building: positions (x y z …), triangles and the names of
// their materials (ids shift when another building adds a material first). Equal and ordered
// bit for bit.
struct Piece {
    std::vector<float> positions;
    std::vector<uint32_t> indices;
    std::vector<std::string> materials;
};
bool operator==(const Piece &a, const Piece &b);
bool operator<(const Piece &a, const Piece &b);

// Every building's pieces (building id 0, no building, left out), sorted: an instance is baked
// with the builder's own transform, so a prototype that one more building shares compares equal
// to its baked copy.
std::map<uint32_t, std::vector<Piece>> buildingsOf(const RenderScene &scene);

}  // namespace veduta::test

#include "solid_checks.h"

#include <cmath>
#include <map>
#include <tuple>

namespace veduta {

namespace {

using Key = std::tuple<long, long, long>;

Key keyOf(const Vec3f &p) { return {std::lround(p.x * 1e4), std::lround(p.y * 1e4), std::lround(p.z * 1e4)}; }

}  // namespace

bool isWatertight(const Mesh &mesh) {
    std::map<std::pair<Key, Key>, int> walked;  // +1 one way, −1 the other
    for (size_t t = 0; t < mesh.indices.size(); t += 3)
        for (int i = 0; i < 3; ++i) {
            Key a = keyOf(mesh.positions[mesh.indices[t + i]]),
                b = keyOf(mesh.positions[mesh.indices[t + (i + 1) % 3]]);
            if (a == b) return false;  // a degenerate triangle
            if (a < b) ++walked[{a, b}];
            else --walked[{b, a}];
        }
    for (const auto &[edge, balance] : walked)
        if (balance != 0) return false;
    return !walked.empty();
}

double enclosedVolume(const Mesh &mesh) {
    double volume = 0;
    for (size_t t = 0; t < mesh.indices.size(); t += 3) {
        const Vec3f &a = mesh.positions[mesh.indices[t]], &b = mesh.positions[mesh.indices[t + 1]],
                    &c = mesh.positions[mesh.indices[t + 2]];
        volume += double(dot(a, cross(b, c))) / 6;
    }
    return volume;
}

}  // namespace veduta

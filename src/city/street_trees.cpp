#include "city/street_trees.h"

#include <algorithm>
#include <cmath>

#include "core/hash.h"
#include "geo/tree_models.h"

namespace veduta {

namespace {

float distanceToSegment(Vec2f p, Vec2f a, Vec2f b) {
    Vec2f d = b - a;
    float span = dot(d, d);
    float t = span > 0 ? std::clamp(dot(p - a, d) / span, 0.0f, 1.0f) : 0.0f;
    return length(a + d * t - p);
}

// Whether p keeps clear of every street's carriageway and of the junctions (three or more
// streets at a node) by `clearance` metres beyond their reach.
bool clearOfStreets(const StreetNetwork &network, const std::vector<int> &degree, Vec2f p, float clearance) {
    for (const StreetNetwork::Street &s : network.streets) {
        if (distanceToSegment(p, network.nodes[s.from], network.nodes[s.to]) < 0.5f * s.width + clearance) return false;
    }
    for (size_t n = 0; n < network.nodes.size(); ++n) {
        if (degree[n] < 3) continue;
        float widest = 0;
        for (const StreetNetwork::Street &s : network.streets)
            if (s.from == n || s.to == n) widest = std::max(widest, s.width);
        if (length(p - network.nodes[n]) < kJunctionReach * 0.5f * widest + clearance + 3) return false;
    }
    return true;
}

}  // namespace

std::vector<PlacedTree> streetTrees(const StreetNetwork &network, const StreetStyle &style, uint32_t seed,
                                    const StreetTreeOptions &options) {
    std::vector<int> degree(network.nodes.size(), 0);
    for (const StreetNetwork::Street &s : network.streets) ++degree[s.from], ++degree[s.to];
    std::vector<PlacedTree> trees;
    for (size_t i = 0; i < network.streets.size(); ++i) {
        const StreetNetwork::Street &s = network.streets[i];
        if (s.width < options.minimumWidth) continue;
        Vec2f a = network.nodes[s.from], b = network.nodes[s.to];
        float span = length(b - a);
        if (span < options.spacing) continue;
        Vec2f along = (b - a) / span, left{-along.y, along.x};
        float offset = 0.5f * s.width + std::min(options.fromKerb, 0.5f * style.sidewalkWidth);
        int count = int(span / options.spacing);
        float start = 0.5f * (span - float(count - 1) * options.spacing);
        for (int k = 0; k < count; ++k) {
            for (float side : {1.0f, -1.0f}) {
                Vec2f p = a + along * (start + float(k) * options.spacing) + left * (side * offset);
                // Off the kerb by as much as the tree is from it: no other street's carriageway
                // reaches it, and no junction.
                if (!clearOfStreets(network, degree, p, options.fromKerb - 0.01f)) continue;
                uint32_t h = hashValues({seed, 0x74726565u, uint32_t(i), uint32_t(k), side > 0 ? 1u : 0u});
                PlacedTree tree;
                tree.position = p;
                tree.kind = TreeKind::Broadleaf;
                tree.variant = mix32(h) % kTreeVariants;
                tree.height = options.height * (0.9f + 0.2f * bitsToUnitFloat(h));
                tree.rotation = 2 * kPi * bitsToUnitFloat(mix32(h ^ 0x9e3779b9u));
                tree.widthScale = 0.7f;
                trees.push_back(tree);
            }
        }
    }
    return trees;
}

}  // namespace veduta

#include "city/party_walls.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <vector>

namespace veduta {

namespace {

constexpr float kLineTolerance = 0.1f;          // metres off the edge's line
constexpr float kParallelCosine = 0.99939083f;  // cos 2°
constexpr float kCoveredShare = 0.5f;           // of the edge's length
constexpr float kCell = 10;                     // metres: the grid edges are found through

struct EdgeRef {
    size_t footprint, edge;
};

int64_t cellKey(int x, int y) { return (int64_t(x) << 32) ^ int64_t(uint32_t(y)); }

// How much of edge (a, b) the edge (c, d) runs back along, as a share of its length.
float coveredShare(Vec2f a, Vec2f b, Vec2f c, Vec2f d) {
    Vec2f along = b - a;
    float len = length(along);
    if (len <= 0) return 0;
    Vec2f u = along / len, other = d - c;
    float otherLength = length(other);
    if (otherLength <= 0 || dot(u, other / otherLength) > -kParallelCosine) return 0;
    if (std::abs(cross(u, c - a)) > kLineTolerance || std::abs(cross(u, d - a)) > kLineTolerance) return 0;
    float s0 = std::clamp(dot(c - a, u), 0.0f, len), s1 = std::clamp(dot(d - a, u), 0.0f, len);
    return std::abs(s1 - s0) / len;
}

}  // namespace

std::vector<std::vector<bool>> partyWalls(std::span<const Footprint *const> footprints) {
    std::vector<std::vector<bool>> party(footprints.size());
    std::unordered_map<int64_t, std::vector<EdgeRef>> grid;
    for (size_t f = 0; f < footprints.size(); ++f) {
        const Footprint &fp = *footprints[f];
        party[f].assign(fp.edgeCount(), false);
        for (size_t e = 0; e < fp.edgeCount(); ++e) {
            Vec2f a = fp.edgeStart(e), b = fp.edgeEnd(e);
            int x0 = int(std::floor(std::min(a.x, b.x) / kCell)), x1 = int(std::floor(std::max(a.x, b.x) / kCell));
            int y0 = int(std::floor(std::min(a.y, b.y) / kCell)), y1 = int(std::floor(std::max(a.y, b.y) / kCell));
            for (int y = y0; y <= y1; ++y)
                for (int x = x0; x <= x1; ++x) grid[cellKey(x, y)].push_back({f, e});
        }
    }
    for (auto &[key, edges] : grid) {
        for (const EdgeRef &p : edges) {
            const Footprint &fp = *footprints[p.footprint];
            if (party[p.footprint][p.edge]) continue;
            for (const EdgeRef &q : edges) {
                if (q.footprint == p.footprint) continue;
                const Footprint &other = *footprints[q.footprint];
                if (coveredShare(fp.edgeStart(p.edge), fp.edgeEnd(p.edge), other.edgeStart(q.edge),
                                 other.edgeEnd(q.edge)) >= kCoveredShare) {
                    party[p.footprint][p.edge] = true;
                    break;
                }
            }
        }
    }
    return party;
}

}  // namespace veduta

#include "geo/shore_distance.h"

#include <algorithm>
#include <cmath>

namespace veduta {

namespace {

int64_t cellKey(int64_t x, int64_t y) { return (x << 32) ^ (y & 0xffffffff); }

double distanceToEdge(Vec2d p, Vec2d a, Vec2d b) {
    Vec2d d = b - a;
    double span = dot(d, d);
    double t = span > 0 ? std::clamp(dot(p - a, d) / span, 0.0, 1.0) : 0.0;
    return length(a + d * t - p);
}

}  // namespace

ShoreDistance::ShoreDistance(const std::vector<std::pair<Vec2d, Vec2d>> &edges) : edges_(edges) {
    for (uint32_t e = 0; e < edges_.size(); ++e) {
        auto [a, b] = edges_[e];
        int64_t x0 = int64_t(std::floor(std::min(a.x, b.x) / kCell)),
                x1 = int64_t(std::floor(std::max(a.x, b.x) / kCell));
        int64_t y0 = int64_t(std::floor(std::min(a.y, b.y) / kCell)),
                y1 = int64_t(std::floor(std::max(a.y, b.y) / kCell));
        for (int64_t y = y0; y <= y1; ++y)
            for (int64_t x = x0; x <= x1; ++x) cells_[cellKey(x, y)].push_back(e);
    }
}

double ShoreDistance::distance(Vec2d p, double reach) const {
    double best = reach;
    int64_t x0 = int64_t(std::floor((p.x - reach) / kCell)), x1 = int64_t(std::floor((p.x + reach) / kCell));
    int64_t y0 = int64_t(std::floor((p.y - reach) / kCell)), y1 = int64_t(std::floor((p.y + reach) / kCell));
    for (int64_t y = y0; y <= y1; ++y)
        for (int64_t x = x0; x <= x1; ++x) {
            auto found = cells_.find(cellKey(x, y));
            if (found == cells_.end()) continue;
            for (uint32_t e : found->second)
                best = std::min(best, distanceToEdge(p, edges_[e].first, edges_[e].second));
        }
    return best;
}

}  // namespace veduta

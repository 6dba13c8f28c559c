#include "slg/ear_clipping.h"

#include <numeric>

namespace veduta {

namespace {

// Whether p lies in the triangle abc (counter-clockwise) or on its boundary.
bool inTriangle(Vec2d p, Vec2d a, Vec2d b, Vec2d c) {
    return turnAt(a, b, p) != Turn::Right && turnAt(b, c, p) != Turn::Right && turnAt(c, a, p) != Turn::Right;
}

bool isEar(const Polygon2d &points, const std::vector<uint32_t> &ring, size_t i) {
    size_t n = ring.size();
    uint32_t a = ring[(i + n - 1) % n], b = ring[i], c = ring[(i + 1) % n];
    if (turnAt(points[a], points[b], points[c]) != Turn::Left) return false;
    for (uint32_t k : ring) {
        if (k == a || k == b || k == c) continue;
        if (points[k] == points[a] || points[k] == points[b] || points[k] == points[c]) continue;
        if (inTriangle(points[k], points[a], points[b], points[c])) return false;
    }
    return true;
}

}  // namespace

std::vector<std::array<uint32_t, 3>> clipEars(const Polygon2d &ccw) {
    std::vector<uint32_t> ring(ccw.size());
    std::iota(ring.begin(), ring.end(), 0u);
    std::vector<std::array<uint32_t, 3>> triangles;
    while (ring.size() > 3) {
        size_t n = ring.size(), ear = n;
        for (size_t i = 0; i < n && ear == n; ++i)
            if (isEar(ccw, ring, i)) ear = i;
        // No ear left: only corners on straight lines remain to cut (a triangle of no area).
        if (ear == n)
            for (size_t i = 0; i < n && ear == n; ++i)
                if (turnAt(ccw[ring[(i + n - 1) % n]], ccw[ring[i]], ccw[ring[(i + 1) % n]]) == Turn::Straight) ear = i;
        if (ear == n) ear = 0;  // not simple: cut on rather than loop
        triangles.push_back({ring[(ear + n - 1) % n], ring[ear], ring[(ear + 1) % n]});
        ring.erase(ring.begin() + long(ear));
    }
    if (ring.size() == 3) triangles.push_back({ring[0], ring[1], ring[2]});
    return triangles;
}

}  // namespace veduta

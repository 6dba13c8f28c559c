#include "city/street_pieces.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace veduta {

namespace {

// The corners are rounded to float before anything is decided about them: the exact union
// (street_regions.cpp) takes them as they are here, and the orientation test of a bevel must see
// the same points.
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

StreetRing ribbon(Vec2f a, Vec2f b, float halfWidth) {
    float dx = b.x - a.x, dy = b.y - a.y, length = std::hypot(dx, dy);
    float nx = -dy / length * halfWidth, ny = dx / length * halfWidth;
    return {{a.x - nx, a.y - ny}, {b.x - nx, b.y - ny}, {b.x + nx, b.y + ny}, {a.x + nx, a.y + ny}};
}

// A round joint at a node, so that streets meeting at any angle leave no notch.
StreetRing joint(Vec2f centre, float radius) {
    StreetRing p;
    // The polygon circumscribes the circle, so that it covers the ribbons' corners.
    float r = radius / std::cos(kPi / kStreetJointSides);
    for (int k = 0; k < kStreetJointSides; ++k) {
        float a = 2 * kPi * float(k) / kStreetJointSides;
        p.push_back({centre.x + r * std::cos(a), centre.y + r * std::sin(a)});
    }
    return p;
}

// The triangle that fills the notch on the outside of a bend at `node`, between the ends of
// the ribbons from `from` and to `to`; nothing when they run straight on.
std::optional<StreetRing> bevel(Vec2f from, Vec2f node, Vec2f to, float halfWidth) {
    Vec2f in = node - from, out = to - node;
    float turn = in.x * out.y - in.y * out.x;
    if (std::abs(turn) <= 1e-6f * std::hypot(in.x, in.y) * std::hypot(out.x, out.y)) return std::nullopt;
    // The outside of a left turn is on the right.
    float side = turn > 0 ? -1.0f : 1.0f;
    auto corner = [&](Vec2f d) {
        float length = std::hypot(d.x, d.y);
        return Vec2f{node.x + side * -d.y / length * halfWidth, node.y + side * d.x / length * halfWidth};
    };
    // In float the corners may fall onto the node or onto one line with it (a tiny width, far
    // coordinates): such a bevel covers nothing, and is no polygon CGAL takes.
    Vec2f apex = node, a = corner(in), b = corner(out);
    auto point = [](Vec2f p) { return Kernel::Point_2(p.x, p.y); };
    switch (CGAL::orientation(point(apex), point(a), point(b))) {
    case CGAL::COLLINEAR: return std::nullopt;
    case CGAL::CLOCKWISE: std::swap(a, b); break;
    default: break;
    }
    return StreetRing{apex, a, b};
}

// Streets meet at a node: its ribbons' ends, the widest half width among them, and for the
// node's bevel the other ends of its (at most two) streets.
struct NodeStreets {
    int count = 0;
    float widestHalf = 0;
    bool sameWidth = true;
    uint32_t others[2] = {0, 0};
};

bool zeroLength(const StreetNetwork &network, const StreetNetwork::Street &s) {
    Vec2f a = network.nodes[s.from], b = network.nodes[s.to];
    return a.x == b.x && a.y == b.y;
}

}  // namespace

std::vector<StreetRing> streetPieces(const StreetNetwork &network, float extra) {
    constexpr float kBevelTurnDegrees = 30;
    const float bevelCos = std::cos(kBevelTurnDegrees * kPi / 180);
    std::vector<StreetRing> pieces;
    std::vector<NodeStreets> at(network.nodes.size());
    auto meet = [&](uint32_t node, uint32_t other, float half) {
        NodeStreets &n = at[node];
        if (n.count > 0 && n.widestHalf != half) n.sameWidth = false;
        if (n.count < 2) n.others[n.count] = other;
        ++n.count;
        n.widestHalf = std::max(n.widestHalf, half);
    };
    for (const StreetNetwork::Street &s : network.streets) {
        if (zeroLength(network, s)) continue;
        pieces.push_back(ribbon(network.nodes[s.from], network.nodes[s.to], s.width / 2 + extra));
        // Widths compare without `extra`, so that the sidewalks' pieces are the carriageway's
        // widened, bevel for bevel, and contain them (the sidewalks are cut out of them).
        meet(s.from, s.to, s.width / 2);
        meet(s.to, s.from, s.width / 2);
    }
    for (size_t n = 0; n < network.nodes.size(); ++n) {
        const NodeStreets &node = at[n];
        if (node.count == 0) continue;
        Vec2f from = network.nodes[node.others[0]], centre = network.nodes[n], to = network.nodes[node.others[1]];
        Vec2f in = centre - from, out = to - centre;
        bool gentle = node.count == 2 && node.sameWidth &&
            in.x * out.x + in.y * out.y >= bevelCos * std::hypot(in.x, in.y) * std::hypot(out.x, out.y);
        if (!gentle) {
            pieces.push_back(joint(centre, node.widestHalf + extra));
        } else if (std::optional<StreetRing> b = bevel(from, centre, to, node.widestHalf + extra)) {
            pieces.push_back(std::move(*b));
        }
    }
    return pieces;
}

std::vector<StreetRing> junctionJoints(const StreetNetwork &network) {
    std::vector<int> streetsAt(network.nodes.size(), 0);
    std::vector<float> widestHalf(network.nodes.size(), 0.0f);
    for (const StreetNetwork::Street &s : network.streets) {
        if (zeroLength(network, s)) continue;
        for (uint32_t node : {s.from, s.to}) {
            ++streetsAt[node];
            widestHalf[node] = std::max(widestHalf[node], s.width / 2);
        }
    }
    std::vector<StreetRing> joints;
    for (size_t n = 0; n < network.nodes.size(); ++n)
        if (streetsAt[n] >= 3) joints.push_back(joint(network.nodes[n], kJunctionReach * widestHalf[n]));
    return joints;
}

}  // namespace veduta

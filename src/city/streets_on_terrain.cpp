#include "city/streets_on_terrain.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>

namespace veduta {

namespace {

constexpr double kUnset = -std::numeric_limits<double>::infinity();
// Metres a point may lie outside a street's strip or a node's joint and still count as in it:
// the plan's vertices are exact CGAL points rounded to float.
constexpr double kSlack = 1e-3;

Vec2d operator*(double k, Vec2d a) { return {k * a.x, k * a.y}; }

// Axis-aligned boxes bucketed on a square grid: the ids whose box may meet a query box.
class BoxIndex {
  public:
    void add(Vec2d lo, Vec2d hi, uint32_t id) {
        for (int64_t y = cell(lo.y); y <= cell(hi.y); ++y)
            for (int64_t x = cell(lo.x); x <= cell(hi.x); ++x) buckets_[{x, y}].push_back(id);
    }
    std::vector<uint32_t> near(Vec2d lo, Vec2d hi) const {
        std::vector<uint32_t> ids;
        for (int64_t y = cell(lo.y); y <= cell(hi.y); ++y)
            for (int64_t x = cell(lo.x); x <= cell(hi.x); ++x) {
                auto it = buckets_.find({x, y});
                if (it != buckets_.end()) ids.insert(ids.end(), it->second.begin(), it->second.end());
            }
        std::sort(ids.begin(), ids.end());
        ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
        return ids;
    }

  private:
    static constexpr double kCell = 20;  // metres
    static int64_t cell(double v) { return int64_t(std::floor(v / kCell)); }
    std::map<std::pair<int64_t, int64_t>, std::vector<uint32_t>> buckets_;
};

// A street's strip: its carriageway and sidewalks, from node `from` along d for `length`.
struct Strip {
    uint32_t from = 0, to = 0;
    Vec2d start, d, n;            // n = up × d
    double length = 0, half = 0;  // half: of carriageway and sidewalks
    double roadHalf = 0;          // of the carriageway
    std::vector<double> cuts;     // distances along where the height may change slope; empty: level throughout
    std::vector<uint32_t> vars;   // the height variable at each cut (the first and last: the end nodes' platforms)

    Vec2d at(double t, double s) const { return start + t * d + s * n; }
};

// The farthest distance along a street of half width `half` (direction d) at which it still
// overlaps another half strip from the same node (direction e, half width `other`).
double overlapReach(Vec2d d, double half, Vec2d e, double other) {
    double c = dot(d, e), s = std::abs(d.x * e.y - d.y * e.x);
    double reach = s > 1e-12 ? (other + half * std::abs(c)) / s : std::numeric_limits<double>::infinity();
    if (c < 0) reach = std::min(reach, half * s / -c);  // the other strip starts at the node
    return reach;
}

class StreetHeights {
  public:
    StreetHeights(const StreetNetwork &network, const TerrainSurface &terrain, const StreetStyle &style) :
        network_(network), terrain_(terrain), group_(network.nodes.size()) {
        makeStrips(style);
        platformRadii();
        mergePlatforms();
        cutStrips();
        startHeights();
        raisePieces();
    }

    // The street height at p (lift included), the highest of the strips and joints holding it.
    double at(Vec2d p) const {
        double z = kUnset;
        for (uint32_t k : strips_.near(p, p)) {
            const Strip &s = strip_[k];
            double t = dot(p - s.start, s.d), across = dot(p - s.start, s.n);
            if (t < -kSlack || t > s.length + kSlack || std::abs(across) > s.half + kSlack) continue;
            z = std::max(z, along(s, std::clamp(t, 0.0, s.length)));
        }
        if (z != kUnset) return z;
        for (uint32_t n : joints_.near(p, p)) {
            Vec2d off = p - node(n);
            if (std::hypot(off.x, off.y) <= jointRadius_[n] + kSlack) z = std::max(z, heights_[platform(n)]);
        }
        return z == kUnset ? fallback_ : z;
    }

    // The lines where the height changes slope, each across its street's strip.
    std::vector<std::array<Vec2d, 2>> cutLines() const {
        std::vector<std::array<Vec2d, 2>> lines;
        for (const Strip &s : strip_)
            for (double t : s.cuts) lines.push_back({s.at(t, -s.half - kSlack), s.at(t, s.half + kSlack)});
        return lines;
    }

  private:
    Vec2d node(uint32_t n) const { return {network_.nodes[n].x, network_.nodes[n].y}; }

    void makeStrips(const StreetStyle &style) {
        jointRadius_.assign(network_.nodes.size(), 0);
        for (const StreetNetwork::Street &street : network_.streets) {
            Vec2d a = node(street.from), b = node(street.to), ab = b - a;
            double length = std::hypot(ab.x, ab.y);
            if (length == 0) continue;
            Strip s;
            s.from = street.from, s.to = street.to, s.start = a, s.length = length;
            s.d = (1 / length) * ab, s.n = {-s.d.y, s.d.x};
            s.roadHalf = double(street.width / 2);
            s.half = s.roadHalf + double(style.sidewalkWidth);
            jointRadius_[s.from] = std::max(jointRadius_[s.from], s.half);
            jointRadius_[s.to] = std::max(jointRadius_[s.to], s.half);
            strip_.push_back(std::move(s));
        }
        for (double &r : jointRadius_) r /= std::cos(kPi / kStreetJointSides);  // the joint circumscribes its circle
        for (uint32_t k = 0; k < strip_.size(); ++k) {
            const Strip &s = strip_[k];
            std::array<Vec2d, 4> corners = quad(s, 0, s.length);
            Vec2d lo = corners[0], hi = corners[0];
            for (Vec2d c : corners) {
                lo = {std::min(lo.x, c.x), std::min(lo.y, c.y)};
                hi = {std::max(hi.x, c.x), std::max(hi.y, c.y)};
            }
            strips_.add(lo - Vec2d{kSlack, kSlack}, hi + Vec2d{kSlack, kSlack}, k);
        }
        for (uint32_t n = 0; n < network_.nodes.size(); ++n) {
            double r = jointRadius_[n] + kSlack;
            if (jointRadius_[n] > 0) joints_.add(node(n) - Vec2d{r, r}, node(n) + Vec2d{r, r}, n);
        }
    }

    // A node's platform reaches along each of its streets as far as the joint sticks out of the
    // street's strip, as far as any two of its strips overlap and, at a junction, as far as its
    // StreetJunction surface: there the height is the node's, and the junction is level.
    void platformRadii() {
        struct End {
            Vec2d d;
            double half, roadHalf;
        };
        std::vector<std::vector<End>> ends(network_.nodes.size());
        for (const Strip &s : strip_) {
            ends[s.from].push_back({s.d, s.half, s.roadHalf});
            ends[s.to].push_back({-1 * s.d, s.half, s.roadHalf});
        }
        radius_.assign(network_.nodes.size(), 0);
        for (size_t n = 0; n < ends.size(); ++n) {
            double r = 0, joint = jointRadius_[n];
            for (const End &a : ends[n]) {
                r = std::max(r, std::sqrt(std::max(0.0, joint * joint - a.half * a.half)));
                if (ends[n].size() >= 3)
                    r = std::max(r, kJunctionReach * a.roadHalf / std::cos(kPi / kStreetJointSides));
                for (const End &b : ends[n])
                    if (&a != &b) r = std::max(r, overlapReach(a.d, a.half, b.d, b.half));
            }
            radius_[n] = r + kSlack;
        }
    }

    uint32_t platform(uint32_t n) const {
        while (group_[n] != n) n = group_[n];
        return n;
    }

    // Nodes whose platforms meet along a street are one platform: the street between is level.
    void mergePlatforms() {
        std::iota(group_.begin(), group_.end(), 0u);
        for (const Strip &s : strip_) {
            if (radius_[s.from] + radius_[s.to] < s.length) continue;
            uint32_t a = platform(s.from), b = platform(s.to);
            if (a != b) group_[std::max(a, b)] = std::min(a, b);
        }
    }

    void cutStrips() {
        heights_.assign(network_.nodes.size(), kUnset);  // variable n: node n's platform (used at its root)
        for (Strip &s : strip_) {
            double first = radius_[s.from], last = s.length - radius_[s.to];
            if (first >= last) continue;
            // Where the centre line crosses the terrain's cell lines, so each piece can follow the ground.
            std::vector<Vec2d> centre = splitAtGridLines({s.at(first, 0), s.at(last, 0)}, terrain_.cellLines(), false);
            s.cuts.push_back(first);
            for (size_t i = 1; i + 1 < centre.size(); ++i) {
                double t = std::clamp(dot(centre[i] - s.start, s.d), first, last);
                if (t - s.cuts.back() > kSlack && last - t > kSlack) s.cuts.push_back(t);
            }
            s.cuts.push_back(last);
            s.vars.push_back(platform(s.from));
            for (size_t i = 1; i + 1 < s.cuts.size(); ++i) {
                s.vars.push_back(uint32_t(heights_.size()));
                heights_.push_back(kUnset);
            }
            s.vars.push_back(platform(s.to));
        }
    }

    std::array<Vec2d, 4> quad(const Strip &s, double t0, double t1) const {
        return {s.at(t0, -s.half), s.at(t1, -s.half), s.at(t1, s.half), s.at(t0, s.half)};
    }

    static void raiseTo(double &z, std::optional<double> ground) {
        if (ground) z = std::max(z, *ground + kStreetLiftOnTerrain);
    }

    // The highest ground across each cut and over each platform (its joints and the level ends
    // of its streets), plus the lift; parts off the terrain take the street's highest height.
    void startHeights() {
        for (uint32_t n = 0; n < network_.nodes.size(); ++n) {
            if (jointRadius_[n] == 0) continue;
            std::array<Vec2d, kStreetJointSides> joint;
            for (int k = 0; k < kStreetJointSides; ++k) {
                double a = 2 * kPi * k / kStreetJointSides;
                joint[size_t(k)] = node(n) + Vec2d{jointRadius_[n] * std::cos(a), jointRadius_[n] * std::sin(a)};
            }
            raiseTo(heights_[platform(n)], terrain_.maxOver(joint));
        }
        for (Strip &s : strip_) {
            if (s.cuts.empty()) {
                raiseTo(heights_[platform(s.from)], terrain_.maxOver(quad(s, 0, s.length)));
                continue;
            }
            raiseTo(heights_[s.vars.front()], terrain_.maxOver(quad(s, 0, s.cuts.front())));
            raiseTo(heights_[s.vars.back()], terrain_.maxOver(quad(s, s.cuts.back(), s.length)));
            for (size_t i = 1; i + 1 < s.cuts.size(); ++i) {
                std::array<Vec2d, 2> across{s.at(s.cuts[i], -s.half), s.at(s.cuts[i], s.half)};
                raiseTo(heights_[s.vars[i]], terrain_.maxOver(across));
            }
        }
        double highest = kUnset;
        for (double z : heights_) highest = std::max(highest, z);
        fallback_ = highest == kUnset ? double(network_.height) + kStreetLiftOnTerrain : highest;
        for (Strip &s : strip_) {
            double top = kUnset;
            for (uint32_t v : s.vars) top = std::max(top, heights_[v]);
            for (uint32_t v : s.vars)
                if (heights_[v] == kUnset) heights_[v] = top == kUnset ? fallback_ : top;
        }
        for (uint32_t n = 0; n < network_.nodes.size(); ++n)
            if (heights_[platform(n)] == kUnset) heights_[platform(n)] = fallback_;
    }

    // Each piece between two cuts (level across, linear along) is raised with both its ends
    // until it lies the lift above the surface everywhere. Raising only lifts the pieces and
    // platforms that share an end further, so one pass leaves every piece clear.
    void raisePieces() {
        for (const Strip &s : strip_) {
            for (size_t i = 0; i + 1 < s.cuts.size(); ++i) {
                double z0 = heights_[s.vars[i]], z1 = heights_[s.vars[i + 1]];
                double slope = (z1 - z0) / (s.cuts[i + 1] - s.cuts[i]);
                HeightPlane plane{z0 - slope * (dot(s.start, s.d) + s.cuts[i]), slope * s.d.x, slope * s.d.y};
                std::optional<double> above = terrain_.maxAbove(quad(s, s.cuts[i], s.cuts[i + 1]), plane);
                double rise = above ? *above + kStreetLiftOnTerrain : 0;
                if (rise <= 0) continue;
                heights_[s.vars[i]] += rise;
                if (s.vars[i + 1] != s.vars[i]) heights_[s.vars[i + 1]] += rise;
            }
        }
    }

    double along(const Strip &s, double t) const {
        if (s.cuts.empty()) return heights_[platform(s.from)];
        if (t <= s.cuts.front()) return heights_[s.vars.front()];
        if (t >= s.cuts.back()) return heights_[s.vars.back()];
        size_t i = size_t(std::upper_bound(s.cuts.begin(), s.cuts.end(), t) - s.cuts.begin()) - 1;
        double w = (t - s.cuts[i]) / (s.cuts[i + 1] - s.cuts[i]);
        return (1 - w) * heights_[s.vars[i]] + w * heights_[s.vars[i + 1]];
    }

    const StreetNetwork &network_;
    const TerrainSurface &terrain_;
    std::vector<Strip> strip_;
    BoxIndex strips_, joints_;
    std::vector<double> jointRadius_;  // circumscribed, 0 for a node no street uses
    std::vector<double> radius_;       // the platform's reach along each street from the node
    std::vector<uint32_t> group_;      // union–find of the platforms
    std::vector<double> heights_;      // per node (at its platform's root), then per inner cut
    double fallback_ = 0;
};

struct PlanVertex {
    double x = 0, y = 0, z = 0;  // z: 0 on the carriageway, kerbHeight on sidewalks and kerb tops
    Vec2f uv;
};
using PlanPolygon = std::vector<PlanVertex>;

// The point where edge a–b meets the line f = 0 (f(a), f(b) of opposite signs), computed from
// the lexicographically smaller end so that both triangles at a shared edge get the same point.
PlanVertex crossing(const PlanVertex &a, double fa, const PlanVertex &b, double fb) {
    bool swap = std::pair(b.x, b.y) < std::pair(a.x, a.y);
    const PlanVertex &p = swap ? b : a, &q = swap ? a : b;
    double fp = swap ? fb : fa, fq = swap ? fa : fb, w = fp / (fp - fq);
    return {p.x + (q.x - p.x) * w, p.y + (q.y - p.y) * w, p.z + (q.z - p.z) * w, p.uv + (q.uv - p.uv) * float(w)};
}

// A convex polygon split by the line through `line`: its part on either side (one, when the
// line misses it).
void splitBy(const PlanPolygon &polygon, const std::array<Vec2d, 2> &line, std::vector<PlanPolygon> &out) {
    Vec2d d = line[1] - line[0];
    auto side = [&](const PlanVertex &v) { return d.x * (v.y - line[0].y) - d.y * (v.x - line[0].x); };
    std::vector<double> f;
    bool below = false, above = false;
    for (const PlanVertex &v : polygon) {
        f.push_back(side(v));
        below = below || f.back() < 0, above = above || f.back() > 0;
    }
    if (!below || !above) {
        out.push_back(polygon);
        return;
    }
    for (double sign : {-1.0, 1.0}) {
        PlanPolygon part;
        for (size_t i = 0; i < polygon.size(); ++i) {
            size_t j = (i + 1) % polygon.size();
            if (sign * f[i] >= 0) part.push_back(polygon[i]);
            if ((f[i] < 0 && f[j] > 0) || (f[i] > 0 && f[j] < 0))
                part.push_back(crossing(polygon[i], f[i], polygon[j], f[j]));
        }
        out.push_back(std::move(part));
    }
}

}  // namespace

Mesh streetsOnTerrain(const StreetNetwork &network, const TerrainSurface &terrain, const StreetStyle &style) {
    StreetNetwork plan = network;
    plan.height = 0;
    StreetStyle flat = style;
    flat.lift = 0;
    Mesh planMesh = streetGeometry(plan, flat);
    StreetHeights heights(network, terrain, style);
    std::vector<std::array<Vec2d, 2>> lines = heights.cutLines();
    BoxIndex lineIndex;
    for (uint32_t k = 0; k < lines.size(); ++k)
        lineIndex.add({std::min(lines[k][0].x, lines[k][1].x), std::min(lines[k][0].y, lines[k][1].y)},
                      {std::max(lines[k][0].x, lines[k][1].x), std::max(lines[k][0].y, lines[k][1].y)}, k);

    Mesh mesh;
    for (size_t t = 0; t < planMesh.triangleCount(); ++t) {
        PlanPolygon triangle;
        Vec2d lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()}, hi = -1 * lo;
        for (int k = 0; k < 3; ++k) {
            uint32_t v = planMesh.indices[3 * t + size_t(k)];
            const Vec3f &p = planMesh.positions[v];
            triangle.push_back({p.x, p.y, p.z, planMesh.uvs[v]});
            lo = {std::min(lo.x, double(p.x)), std::min(lo.y, double(p.y))};
            hi = {std::max(hi.x, double(p.x)), std::max(hi.y, double(p.y))};
        }
        std::vector<PlanPolygon> pieces{std::move(triangle)}, next;
        for (uint32_t k : lineIndex.near(lo, hi)) {
            next.clear();
            for (const PlanPolygon &piece : pieces) splitBy(piece, lines[k], next);
            std::swap(pieces, next);
        }
        Vec3f planNormal = planMesh.normals[planMesh.indices[3 * t]];
        for (const PlanPolygon &piece : pieces) {
            std::vector<Vec3f> lifted;
            std::vector<Vec2f> uvs;
            for (const PlanVertex &v : piece) {
                Vec2f xy{float(v.x), float(v.y)};  // the height of the vertex as it is stored
                lifted.push_back({xy.x, xy.y, float(heights.at({xy.x, xy.y}) + v.z)});
                uvs.push_back(v.uv);
            }
            for (size_t k = 1; k + 1 < lifted.size(); ++k) {
                Vec3f normal = cross(lifted[k] - lifted[0], lifted[k + 1] - lifted[0]);
                if (length(normal) <= 0) continue;  // a sliver where a cut met a corner
                normal = dot(normal, planNormal) > 0 ? normalize(normal) : planNormal;
                auto base = uint32_t(mesh.positions.size());
                for (size_t c : {size_t(0), k, k + 1}) {
                    mesh.positions.push_back(lifted[c]);
                    mesh.normals.push_back(normal);
                    mesh.uvs.push_back(uvs[c]);
                }
                mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2});
                mesh.triangleMaterials.push_back(planMesh.triangleMaterials[t]);
            }
        }
    }
    return mesh;
}

}  // namespace veduta

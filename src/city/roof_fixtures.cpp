#include "city/roof_fixtures.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <tuple>
#include <vector>

#include <fmt/format.h>

#include "city/roofs.h"
#include "core/error.h"
#include "core/hash.h"
#include "geo/mesh_normals.h"

namespace veduta {

namespace {

constexpr float kRadian = float(M_PI / 180);

struct Triangle {
    Vec3f a, b, c;
};

// The roof's covering, one list of triangles per plane.
struct Slope {
    Vec3f normal;
    std::vector<Triangle> triangles;
};

std::vector<Triangle> coveringOf(const Mesh &roof) {
    std::vector<Triangle> out;
    for (size_t t = 0; t < roof.triangleCount(); ++t) {
        if (roof.triangleMaterials[t] != RoofCovering) continue;
        out.push_back({roof.positions[roof.indices[3 * t]], roof.positions[roof.indices[3 * t + 1]],
                       roof.positions[roof.indices[3 * t + 2]]});
    }
    return out;
}

Vec3f normalOf(const Triangle &t) {
    Vec3f n = cross(t.b - t.a, t.c - t.a);
    float l = length(n);
    return l > 0 ? n / l : Vec3f(0, 0, 1);
}

std::vector<Slope> slopesOf(const std::vector<Triangle> &covering) {
    std::map<std::tuple<int, int, int, int>, Slope> planes;
    for (const Triangle &t : covering) {
        Vec3f n = normalOf(t);
        if (n.z < 0) n = n * -1.0f;
        int offset = int(std::lround(dot(n, t.a) * 100));
        auto key = std::make_tuple(int(std::lround(n.x * 1000)), int(std::lround(n.y * 1000)),
                                   int(std::lround(n.z * 1000)), offset);
        Slope &s = planes[key];
        s.normal = n;
        s.triangles.push_back(t);
    }
    std::vector<Slope> out;
    for (auto &[key, slope] : planes) out.push_back(std::move(slope));
    return out;
}

// The highest covering over (x, y), if any covers it.
std::optional<float> roofHeightAt(const std::vector<Triangle> &covering, Vec2f p) {
    std::optional<float> top;
    for (const Triangle &t : covering) {
        Vec2f a{t.a.x, t.a.y}, b{t.b.x, t.b.y}, c{t.c.x, t.c.y};
        float area = cross(b - a, c - a);
        if (std::abs(area) < 1e-9f) continue;
        float wb = cross(p - a, c - a) / area, wc = cross(b - a, p - a) / area, wa = 1 - wb - wc;
        if (std::min({wa, wb, wc}) < -1e-4f) continue;
        float z = wa * t.a.z + wb * t.b.z + wc * t.c.z;
        if (!top || z > *top) top = z;
    }
    return top;
}

// A mesh being made, with a flat-shaded quad or triangle at a time.
struct Builder {
    Mesh mesh;

    void polygon(std::initializer_list<Vec3f> corners, FixtureSurface surface) {
        uint32_t first = uint32_t(mesh.positions.size());
        std::vector<Vec3f> points(corners);
        Vec3f n = normalize(cross(points[1] - points[0], points[2] - points[0]));
        // Texture coordinates in metres on the polygon's own plane.
        Vec3f u = normalize(points[1] - points[0]), v = cross(n, u);
        for (const Vec3f &p : points) {
            mesh.positions.push_back(p);
            mesh.normals.push_back(n);
            mesh.uvs.push_back({dot(p - points[0], u), dot(p - points[0], v)});
        }
        for (uint32_t k = 1; k + 1 < points.size(); ++k) {
            mesh.indices.insert(mesh.indices.end(), {first, first + k, first + k + 1});
            mesh.triangleMaterials.push_back(surface);
        }
    }
};

// A point of a dormer's frame: `across` metres along the eaves, `in` metres inwards from the
// front, at height z.
struct DormerFrame {
    Vec2f front;  // the front's middle, in plan
    Vec2f along, inward;

    Vec3f at(float across, float in, float z) const {
        Vec2f p = front + along * across + inward * in;
        return {p.x, p.y, z};
    }
};

bool facesAStreet(const Footprint &footprint, Vec2f outward) {
    for (size_t e = 0; e < footprint.edgeCount(); ++e) {
        if (e >= footprint.streetEdges.size() || !footprint.streetEdges[e]) continue;
        Vec3f n = footprint.outwardNormal(e);
        if (outward.x * n.x + outward.y * n.y > std::cos(20 * kRadian)) return true;
    }
    return false;
}

void addDormer(Builder &out, const DormerFrame &f, float frontZ, float tanSlope, const RoofFixtureOptions &o) {
    float half = 0.5f * o.dormerWidth, height = o.dormerHeight, tanDormer = std::tan(o.dormerPitch * kRadian);
    float top = frontZ + height;
    float back = height / (tanSlope - tanDormer);  // where the dormer's roof meets the slope
    // Front: a window in a frame of 0.15 m, a sill 0.1 m above the slope.
    constexpr float kFrame = 0.15f, kSill = 0.25f;
    float wl = -half + kFrame, wr = half - kFrame, wb = frontZ + kSill, wt = top - kFrame;
    out.polygon({f.at(-half, 0, frontZ), f.at(half, 0, frontZ), f.at(half, 0, wb), f.at(-half, 0, wb)}, FixtureWall);
    out.polygon({f.at(-half, 0, wt), f.at(half, 0, wt), f.at(half, 0, top), f.at(-half, 0, top)}, FixtureWall);
    out.polygon({f.at(-half, 0, wb), f.at(wl, 0, wb), f.at(wl, 0, wt), f.at(-half, 0, wt)}, FixtureWall);
    out.polygon({f.at(wr, 0, wb), f.at(half, 0, wb), f.at(half, 0, wt), f.at(wr, 0, wt)}, FixtureWall);
    out.polygon({f.at(wl, 0, wb), f.at(wr, 0, wb), f.at(wr, 0, wt), f.at(wl, 0, wt)}, FixtureWindow);
    // Cheeks: vertical triangles from the front down the slope's line to where the roofs meet.
    float meet = frontZ + back * tanSlope;
    out.polygon({f.at(half, 0, frontZ), f.at(half, back, meet), f.at(half, 0, top)}, FixtureWall);
    out.polygon({f.at(-half, 0, frontZ), f.at(-half, 0, top), f.at(-half, back, meet)}, FixtureWall);
    // The dormer's roof, reaching 0.2 m over the front and 0.1 m over the cheeks.
    constexpr float kEave = 0.2f, kVerge = 0.1f;
    float h = half + kVerge;
    out.polygon({f.at(-h, -kEave, top - kEave * tanDormer), f.at(h, -kEave, top - kEave * tanDormer),
                 f.at(h, back, meet), f.at(-h, back, meet)},
                FixtureRoof);
}

// Dormers on one slope: as many of the number asked as fit 1 m apart, evenly along its eaves,
// their fronts a third of the way up, each only where all of it lies on this slope.
void addDormers(Builder &out, const Slope &slope, const std::vector<Triangle> &covering, const RoofFixtureOptions &o) {
    Vec2f outward = normalize(Vec2f{slope.normal.x, slope.normal.y});
    Vec2f inward = outward * -1.0f, along{-outward.y, outward.x};
    float tanSlope = std::sqrt(1 - slope.normal.z * slope.normal.z) / slope.normal.z;
    float lowest = std::numeric_limits<float>::infinity(), highest = -lowest;
    float alongMin = lowest, alongMax = -lowest, inMin = lowest;
    for (const Triangle &t : slope.triangles) {
        for (const Vec3f &p : {t.a, t.b, t.c}) {
            Vec2f q{p.x, p.y};
            lowest = std::min(lowest, p.z), highest = std::max(highest, p.z);
            alongMin = std::min(alongMin, dot(q, along)), alongMax = std::max(alongMax, dot(q, along));
            inMin = std::min(inMin, dot(q, inward));
        }
    }
    float run = (highest - lowest) / tanSlope;
    float frontIn = inMin + run / 3;
    float back = o.dormerHeight / (tanSlope - std::tan(o.dormerPitch * kRadian));
    // At least 1 m between dormers: fewer than asked where the eaves are too short.
    float span = alongMax - alongMin;
    int count = std::min(o.dormers, int(span / (o.dormerWidth + 1)));
    float spacing = span / float(std::max(count, 1));
    for (int k = 0; k < count; ++k) {
        float middle = alongMin + spacing * (float(k) + 0.5f);
        Vec2f front = along * middle + inward * frontIn;
        DormerFrame f{front, along, inward};
        float half = 0.5f * o.dormerWidth + 0.1f;
        // The whole dormer on this very slope: its four corners' roof is this plane's.
        bool fits = true;
        std::optional<float> frontZ;
        for (Vec3f c : {f.at(-half, -0.2f, 0), f.at(half, -0.2f, 0), f.at(-half, back, 0), f.at(half, back, 0)}) {
            std::optional<float> z = roofHeightAt(slope.triangles, {c.x, c.y});
            std::optional<float> anyZ = roofHeightAt(covering, {c.x, c.y});
            if (!z || !anyZ || *anyZ > *z + 1e-3f) fits = false;
        }
        frontZ = roofHeightAt(slope.triangles, front);
        if (!fits || !frontZ || *frontZ + o.dormerHeight + 0.3f > highest) continue;
        addDormer(out, f, *frontZ, tanSlope, o);
    }
}

// A stack of chimneyWidth square from inside the roof to chimneyHeight above the highest roof
// point under it, with the top closed.
void addChimney(Builder &out, Vec2f centre, const std::vector<Triangle> &covering, const RoofFixtureOptions &o) {
    float h = 0.5f * o.chimneyWidth;
    Vec2f corners[4] = {{centre.x - h, centre.y - h},
                        {centre.x + h, centre.y - h},
                        {centre.x + h, centre.y + h},
                        {centre.x - h, centre.y + h}};
    float low = std::numeric_limits<float>::infinity(), high = -low;
    for (Vec2f c : corners) {
        std::optional<float> z = roofHeightAt(covering, c);
        if (!z) return;  // off the roof
        low = std::min(low, *z), high = std::max(high, *z);
    }
    float bottom = low - 0.2f, top = high + o.chimneyHeight;
    for (int k = 0; k < 4; ++k) {
        Vec2f a = corners[k], b = corners[(k + 1) % 4];
        out.polygon({{a.x, a.y, bottom}, {b.x, b.y, bottom}, {b.x, b.y, top}, {a.x, a.y, top}}, FixtureWall);
    }
    out.polygon({{corners[0].x, corners[0].y, top},
                 {corners[1].x, corners[1].y, top},
                 {corners[2].x, corners[2].y, top},
                 {corners[3].x, corners[3].y, top}},
                FixtureWall);
}

// Chimneys beside the ridge (the covering's highest points), evenly along it, each a little to
// one side as the building's seed says.
void addChimneys(Builder &out, const std::vector<Triangle> &covering, const RoofFixtureOptions &o, uint32_t seed,
                 uint32_t buildingId) {
    float top = -std::numeric_limits<float>::infinity();
    for (const Triangle &t : covering) top = std::max({top, t.a.z, t.b.z, t.c.z});
    std::vector<Vec2f> ridge;
    for (const Triangle &t : covering)
        for (const Vec3f &p : {t.a, t.b, t.c})
            if (p.z > top - 0.05f) ridge.push_back({p.x, p.y});
    if (ridge.empty()) return;
    // The ridge's two ends: the pair of its points farthest apart.
    Vec2f a = ridge[0], b = ridge[0];
    float farthest = 0;
    for (Vec2f p : ridge)
        for (Vec2f q : ridge)
            if (length(p - q) > farthest) farthest = length(p - q), a = p, b = q;
    Vec2f direction = farthest > 0 ? (b - a) / farthest : Vec2f{1, 0};
    Vec2f side{-direction.y, direction.x};
    for (int k = 0; k < o.chimneys; ++k) {
        uint32_t h = hashValues({seed, buildingId, 0x63686d6eu, uint32_t(k)});
        float t = (float(k) + 0.5f) / float(o.chimneys) + 0.1f * (bitsToUnitFloat(h) - 0.5f);
        float offset = (h & 0x100u ? 1.0f : -1.0f) * (0.5f * o.chimneyWidth + 0.4f);
        addChimney(out, a + (b - a) * t + side * offset, covering, o);
    }
}

int countSetting(const SettingsStack &settings, const char *name) {
    std::optional<float> value = settings.number(name);
    if (!value) return 0;
    if (!(*value >= 0 && *value <= 20) || *value != std::floor(*value))
        throw InputError(settings.find(name)->loc,
                         fmt::format("{} must be a whole number from 0 to 20, not {}", name, *value));
    return int(*value);
}

float sizeSetting(const SettingsStack &settings, const char *name, float otherwise, float most) {
    std::optional<float> value = settings.number(name);
    if (!value) return otherwise;
    if (!(*value > 0 && *value <= most))
        throw InputError(settings.find(name)->loc,
                         fmt::format("{} must be more than 0 and at most {} metres, not {}", name, most, *value));
    return *value;
}

}  // namespace

RoofFixtureOptions roofFixtureOptionsFor(const SettingsStack &settings) {
    RoofFixtureOptions o;
    o.dormers = countSetting(settings, "Dormers");
    o.dormerWidth = sizeSetting(settings, "DormerWidth", o.dormerWidth, 10);
    o.dormerHeight = sizeSetting(settings, "DormerHeight", o.dormerHeight, 5);
    o.chimneys = countSetting(settings, "Chimneys");
    o.chimneyHeight = sizeSetting(settings, "ChimneyHeight", o.chimneyHeight, 10);
    return o;
}

Mesh roofFixtures(const Mesh &roof, const Footprint &footprint, const RoofFixtureOptions &options, uint32_t seed,
                  uint32_t buildingId) {
    Builder out;
    std::vector<Triangle> covering = coveringOf(roof);
    if (covering.empty()) return out.mesh;
    if (options.dormers > 0) {
        for (const Slope &slope : slopesOf(covering)) {
            float pitch = std::acos(std::clamp(slope.normal.z, -1.0f, 1.0f)) / kRadian;
            if (pitch < 25 || pitch > 65) continue;
            if (!facesAStreet(footprint, normalize(Vec2f{slope.normal.x, slope.normal.y}))) continue;
            addDormers(out, slope, covering, options);
        }
    }
    if (options.chimneys > 0) addChimneys(out, covering, options, seed, buildingId);
    return out.mesh;
}

}  // namespace veduta

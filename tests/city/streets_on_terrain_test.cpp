// A city's street surfaces on terrain: never below the surface, level across, sidewalks a kerb
// above, no steps or gaps where the pieces meet; each check also run on what it would catch.
#include "city/streets_on_terrain.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "city/terrain_checks.h"
#include "geo/drape_areas.h"
#include "geo/geo_test_terrain.h"

namespace veduta {
namespace {

const MapPoint kSouthWest{530000, 5326000};
const LocalFrame kFrame{{530100, 5326100}};  // the grid's centre: local −100 … 100

struct Terrain : test::DrapedDgm {
    explicit Terrain(HeightGrid g) : DrapedDgm(std::move(g), kFrame) {}
};

// A hillside rising 12 % to the north and 5 % to the east, with ±0.4 m of noise at every node.
HeightGrid hillside() {
    HeightGrid grid = test::flatTerrain(41, 41, 5.0, kSouthWest, 0);
    for (int r = 0; r < grid.rows; ++r)
        for (int c = 0; c < grid.columns; ++c)
            grid.node(c, r) = float(300 + 0.25 * c + 0.6 * r + 0.8 * (test::unitRandom(5, uint32_t(r * 41 + c)) - 0.5));
    return grid;
}

// A small town: a main street with a T junction, a crossing, a bend, a dead end, an acute fork
// and a street shorter than its junctions' platforms.
StreetNetwork town() {
    StreetNetwork n;
    n.nodes = {{-80, -40}, {-20, -40}, {40, -40}, {85, -35},  // 0–3 the main street
               {-20, 30},  {40, 30},   {40, -80},             // 4–6 up from the T and through the crossing
               {-20, 70},  {10, 85},                          // 7–8 a bend, then on
               {60, 38},   {-75, 0},   {46, -40}};            // 9 a fork, 10 a dead end, 11 a stub
    n.streets = {{0, 1, 8}, {1, 2, 8}, {2, 3, 8}, {1, 4, 6}, {2, 5, 6},  {2, 6, 6},
                 {4, 7, 6}, {7, 8, 6}, {5, 9, 5}, {4, 5, 6}, {0, 10, 5}, {11, 3, 4}};
    n.height = 12;  // ignored on terrain
    return n;
}

TEST(StreetsOnTerrain, NoPointOfAStreetIsBelowTheTerrain) {
    for (uint32_t seed : {1u, 2u}) {
        Terrain rough(test::roughTerrain(41, 41, 5.0, kSouthWest, seed));  // a 0.8 slope, a 30 m ridge, noise
        Mesh streets = streetsOnTerrain(town(), rough.surface);
        ASSERT_GT(streets.triangleCount(), 500u);
        EXPECT_EQ(test::pointsBelow(streets, rough.surface), 0u) << seed;
        // The same plan flat at the terrain's mean height (today's streets) pierces it.
        StreetNetwork flat = town();
        flat.height = float(*rough.surface.heightAt({0, 0}));
        EXPECT_GT(test::pointsBelow(streetGeometry(flat), rough.surface), 1000u);
    }
}

// Two streets on the hillside that neither cross nor meet: one straight up it at x = −60, one
// along it at y = 0.
StreetNetwork upAndAlong() {
    StreetNetwork n;
    n.nodes = {{-60, -90}, {-60, 90}, {-30, 0}, {90, 0}};
    n.streets = {{0, 1, 6}, {2, 3, 6}};
    return n;
}

// The road height (a sidewalk's less the kerb) of the vertices of each street of upAndAlong by
// the place along it (y up the hill, x along it); how many vertices disagree with the first at
// their place, and how many agree.
struct Profiles {
    std::map<float, float> upHill, alongHill;
    size_t unlevel = 0, level = 0;
};

Profiles profiles(const Mesh &streets) {
    Profiles found;
    for (size_t t = 0; t < streets.triangleCount(); ++t) {
        MaterialId surface = streets.triangleMaterials[t];
        if (surface == StreetKerb) continue;
        for (int k = 0; k < 3; ++k) {
            const Vec3f &p = streets.positions[streets.indices[3 * t + size_t(k)]];
            float road = p.z - (surface == StreetSidewalk ? StreetStyle{}.kerbHeight : 0.0f);
            bool onClimb = std::abs(p.x + 60) <= 5.5f, onAlong = std::abs(p.y) <= 5.5f && p.x > -40;
            std::map<float, float> *line = onClimb ? &found.upHill : onAlong ? &found.alongHill : nullptr;
            if (!line) continue;
            auto [it, fresh] = line->try_emplace(onClimb ? p.y : p.x, road);
            // Two floats' rounding at 330 m apart at most.
            if (!fresh) ++(std::abs(it->second - road) <= 1e-4f ? found.level : found.unlevel);
        }
    }
    return found;
}

TEST(StreetsOnTerrain, AStreetIsLevelAcrossAndFollowsTheGroundAlong) {
    Terrain hill(hillside());
    Mesh streets = streetsOnTerrain(upAndAlong(), hill.surface);
    Profiles found = profiles(streets);
    EXPECT_EQ(found.unlevel, 0u);
    EXPECT_GT(found.level, 100u);
    // It follows the ground: 0.12 up per metre north, 0.05 per metre east (between places away
    // from its level ends, within the noise).
    auto rise = [](const std::map<float, float> &profile, float from, float to) {
        auto a = profile.lower_bound(from), b = profile.lower_bound(to);
        return std::pair(b->second - a->second, b->first - a->first);
    };
    auto [up, north] = rise(found.upHill, -70, 70);
    EXPECT_NEAR(up, 0.12 * north, 1.0);
    auto [along, east] = rise(found.alongHill, -10, 70);
    EXPECT_NEAR(along, 0.05 * east, 1.0);
    // Draped on the ground vertex by vertex instead, a street tilts with the cross slope.
    Mesh draped = streets;
    for (Vec3f &p : draped.positions)
        p.z += float(*hill.surface.heightAt({p.x, p.y}) - *hill.surface.heightAt({-60, 0}));
    EXPECT_GT(profiles(draped).unlevel, 100u);
}

// Where pieces of one surface meet (carriageway, junctions) or the kerb's foot and head meet
// the surfaces, the heights agree: at points a millimetre apart across every edge, the
// surfaces of one kind holding them differ by no more than the slope allows.
size_t steps(const Mesh &streets) {
    struct Sample {
        double z;
        MaterialId surface;
    };
    std::map<std::pair<long, long>, std::vector<Sample>> at;  // by 2 mm cells
    auto cell = [](double v) { return long(std::floor(v / 2e-3)); };
    for (size_t t = 0; t < streets.triangleCount(); ++t) {
        MaterialId surface = streets.triangleMaterials[t];
        if (surface == StreetKerb) continue;
        for (int e = 0; e < 3; ++e)
            for (double w : {0.25, 0.5, 0.75}) {
                double a = e == 0 ? w : e == 1 ? 1 - w : 0, b = e == 0 ? 0 : e == 1 ? w : 1 - w;
                Vec3d p = test::pointIn(streets, t, a, b);
                MaterialId kind = surface == StreetJunction ? StreetCarriageway : surface;
                at[{cell(p.x), cell(p.y)}].push_back({p.z, kind});
            }
    }
    size_t found = 0;
    for (auto &[where, samples] : at)
        for (const Sample &a : samples)
            for (const Sample &b : samples)
                if (a.surface == b.surface && std::abs(a.z - b.z) > 1e-3) ++found;
    return found;
}

TEST(StreetsOnTerrain, PiecesMeetWithoutStepsAndTheKerbClosesTheSidewalk) {
    Terrain hill(hillside());
    Mesh streets = streetsOnTerrain(town(), hill.surface);
    EXPECT_EQ(steps(streets), 0u);
    // Lifting each triangle on its own (no common height along the street) leaves steps.
    Mesh apart = streets;
    for (size_t t = 0; t < apart.triangleCount(); ++t)
        for (int k = 0; k < 3; ++k) apart.positions[apart.indices[3 * t + size_t(k)]].z += 0.01f * float(t % 7);
    EXPECT_GT(steps(apart), 100u);

    // Every kerb stands kerbHeight tall, its foot on the carriageway's edge.
    float kerb = StreetStyle{}.kerbHeight;
    std::map<std::pair<float, float>, std::vector<float>> kerbZ;
    for (size_t t = 0; t < streets.triangleCount(); ++t) {
        if (streets.triangleMaterials[t] != StreetKerb) continue;
        for (int k = 0; k < 3; ++k) {
            const Vec3f &p = streets.positions[streets.indices[3 * t + size_t(k)]];
            kerbZ[{p.x, p.y}].push_back(p.z);
        }
    }
    ASSERT_GT(kerbZ.size(), 50u);
    size_t tall = 0;
    for (auto &[xy, zs] : kerbZ) {
        auto [low, high] = std::minmax_element(zs.begin(), zs.end());
        if (*high - *low > kerb - 1e-4f && *high - *low < kerb + 1e-4f) ++tall;
    }
    EXPECT_GT(tall, kerbZ.size() * 9 / 10);  // the rest: cut points in the middle of a kerb face
}

// The largest height difference within one junction's surface (its triangles within 12 m of
// the node): none, a junction is a level platform.
float junctionTilt(const Mesh &streets, Vec2f node) {
    float low = 1e9f, high = -1e9f;
    for (size_t t = 0; t < streets.triangleCount(); ++t) {
        if (streets.triangleMaterials[t] != StreetJunction) continue;
        for (int k = 0; k < 3; ++k) {
            const Vec3f &p = streets.positions[streets.indices[3 * t + size_t(k)]];
            if (std::hypot(p.x - node.x, p.y - node.y) > 12) continue;
            low = std::min(low, p.z), high = std::max(high, p.z);
        }
    }
    return high - low;
}

TEST(StreetsOnTerrain, JunctionsAreLevel) {
    Terrain hill(hillside());
    StreetNetwork network = town();
    Mesh streets = streetsOnTerrain(network, hill.surface);
    for (uint32_t node : {1u, 2u, 4u}) {  // the T, the crossing and the corner of the fork street
        EXPECT_LT(junctionTilt(streets, network.nodes[node]), 1e-4f) << node;
    }
    // Where two 12 m streets cross, the junction surface reaches farther along them than their
    // sidewalks overlap.
    StreetNetwork wide;
    wide.nodes = {{0, 0}, {-80, 0}, {80, 0}, {0, -80}, {0, 80}};
    wide.streets = {{0, 1, 12}, {0, 2, 12}, {0, 3, 12}, {0, 4, 12}};
    EXPECT_LT(junctionTilt(streetsOnTerrain(wide, hill.surface), {0, 0}), 1e-4f);
    Mesh draped = streets;  // each vertex on the ground instead: the slope shows
    for (Vec3f &p : draped.positions) p.z = float(*hill.surface.heightAt({p.x, p.y}));
    EXPECT_GT(junctionTilt(draped, network.nodes[2]), 0.5f);
}

TEST(StreetsOnTerrain, EveryPartOfThePlanIsCovered) {
    // The lifted surfaces cover exactly the plan's area, kind by kind: no gaps, no overlaps.
    Terrain hill(hillside());
    StreetNetwork network = town();
    Mesh onTerrain = streetsOnTerrain(network, hill.surface), plan = streetGeometry(network);
    auto areas = [](const Mesh &m) {
        std::map<MaterialId, double> sum;
        for (size_t t = 0; t < m.triangleCount(); ++t)
            if (m.triangleMaterials[t] != StreetKerb) sum[m.triangleMaterials[t]] += test::planArea(m, t);
        return sum;
    };
    std::map<MaterialId, double> lifted = areas(onTerrain), flat = areas(plan);
    for (auto [surface, area] : flat) EXPECT_NEAR(lifted[surface], area, 1e-3 * area) << surface;
    for (size_t t = 0; t < onTerrain.triangleCount(); ++t) {
        if (onTerrain.triangleMaterials[t] != StreetKerb) {
            EXPECT_GT(test::planArea(onTerrain, t), 0) << t;
        }
    }
}

}  // namespace
}  // namespace veduta

// Streets traced through a tensor field (Chen et al. 2008; issue 20's outlook pattern): the
// field's directions, and networks traced from seeded fields as sound as the L-system's.
#include <gtest/gtest.h>

#include <cmath>

#include "grown_streets.h"
#include "streets/tensor_field.h"
#include "streets/tensor_streets.h"

namespace veduta {
namespace {

// The angle between two directions, a direction and its opposite being one: 0° … 90°.
float lineAngleDegrees(Vec2f a, Vec2f b) {
    float c = std::abs(dot(a, b)) / (std::hypot(a.x, a.y) * std::hypot(b.x, b.y));
    return std::acos(std::min(1.0f, c)) * 180 / 3.14159265f;
}

TEST(TensorField, AGridRunsAlongItsAngleAndRingsRoundTheirCentre) {
    TensorField grid({{TensorBasis::Kind::Grid, {0, 0}, 30, 1, 0}});
    for (Vec2f p : {Vec2f{0, 0}, Vec2f{500, -300}})
        EXPECT_LT(lineAngleDegrees(*grid.majorDirection(p), {std::cos(0.5236f), std::sin(0.5236f)}), 0.01f);
    TensorField rings({{TensorBasis::Kind::Radial, {100, 100}, 0, 1, 0}});
    EXPECT_LT(lineAngleDegrees(*rings.majorDirection({110, 100}), {0, 1}), 0.01f);  // tangent to the ring
    EXPECT_LT(lineAngleDegrees(*rings.majorDirection({100, 50}), {1, 0}), 0.01f);
}

TEST(TensorField, BasesBlendByDistanceAndCancelToADegeneratePoint) {
    // Two grids at right angles and of equal weight cancel everywhere.
    TensorField crossed({{TensorBasis::Kind::Grid, {0, 0}, 0, 1, 0}, {TensorBasis::Kind::Grid, {0, 0}, 90, 1, 0}});
    EXPECT_FALSE(crossed.majorDirection({10, 20}));
    // Each rules near its own centre, where the other's weight has fallen off.
    TensorField blended(
        {{TensorBasis::Kind::Grid, {0, 0}, 0, 1, 1e-5f}, {TensorBasis::Kind::Grid, {1000, 0}, 45, 1, 1e-5f}});
    EXPECT_LT(lineAngleDegrees(*blended.majorDirection({0, 0}), {1, 0}), 0.01f);
    EXPECT_LT(lineAngleDegrees(*blended.majorDirection({1000, 0}), {1, 1}), 0.01f);
    // Half way they weigh the same: 22.5°. Far from both, where their weights are all but gone, the
    // direction is still theirs.
    EXPECT_LT(lineAngleDegrees(*blended.majorDirection({500, 1500}), {std::cos(0.3927f), std::sin(0.3927f)}), 0.01f);
    EXPECT_LT(lineAngleDegrees(*blended.majorDirection({500, 0}), {std::cos(0.3927f), std::sin(0.3927f)}), 0.01f);
}

TEST(TensorField, NoiseTurnsTheDirectionsNoFurtherThanItsBoundByTheSeed) {
    std::vector<TensorBasis> east{{TensorBasis::Kind::Grid, {0, 0}, 0, 1, 0}};
    TensorField a(east, 1, 12, 100), again(east, 1, 12, 100), b(east, 2, 12, 100);
    float largest = 0;
    bool differ = false;
    for (float x = -500; x <= 500; x += 37)
        for (float y = -500; y <= 500; y += 41) {
            Vec2f d = *a.majorDirection({x, y});
            largest = std::max(largest, lineAngleDegrees(d, {1, 0}));
            EXPECT_EQ(d.x, again.majorDirection({x, y})->x);
            differ |= d.x != b.majorDirection({x, y})->x;
        }
    EXPECT_LE(largest, 12.01f);
    EXPECT_GT(largest, 6);
    EXPECT_TRUE(differ);
}

TEST(TensorStreets, SeededTownsAreSoundNetworks) {
    for (uint32_t seed = 1; seed <= 6; ++seed) {
        SCOPED_TRACE(seed);
        TracedStreets traced = traceStreets(townField(seed, 400), {{0, 0}, 400}, {});
        EXPECT_FALSE(traced.limitReached);
        EXPECT_GT(traced.streamlines.size(), 8u);
        EXPECT_GT(traced.graph.edges().size(), 150u);
        test::expectSoundNetwork(traced.graph);
        // Both families, every point inside the window.
        size_t major = 0;
        for (const Streamline &line : traced.streamlines) {
            major += line.major;
            for (Vec2f p : line.points) EXPECT_LE(std::hypot(p.x, p.y), 400.01f);
        }
        EXPECT_GT(major, 0u);
        EXPECT_LT(major, traced.streamlines.size());
    }
}

TEST(TensorStreets, TheSameSeedTracesTheSameGraph) {
    TracedStreets a = traceStreets(townField(4, 300), {{0, 0}, 300}, {});
    TracedStreets b = traceStreets(townField(4, 300), {{0, 0}, 300}, {});
    TracedStreets other = traceStreets(townField(5, 300), {{0, 0}, 300}, {});
    ASSERT_EQ(a.graph.vertices().size(), b.graph.vertices().size());
    ASSERT_EQ(a.graph.edges().size(), b.graph.edges().size());
    for (size_t v = 0; v < a.graph.vertices().size(); ++v)
        EXPECT_EQ(a.graph.vertex(v).position, b.graph.vertex(v).position);
    for (size_t e = 0; e < a.graph.edges().size(); ++e) {
        EXPECT_EQ(a.graph.edge(e).a, b.graph.edge(e).a);
        EXPECT_EQ(a.graph.edge(e).b, b.graph.edge(e).b);
    }
    bool same = a.graph.vertices().size() == other.graph.vertices().size() &&
        a.graph.vertex(5).position == other.graph.vertex(5).position;
    EXPECT_FALSE(same);
}

// An environment that forbids the half plane x > 100: no street crosses into it.
class WallAt100 final : public StreetEnvironment {
  public:
    float freeLength(const Vec3f &start, const Vec3f &direction, float length) const override {
        if (start.x > 100) return 0;
        if (direction.x <= 0) return length;
        return std::min(length, (100 - start.x) / direction.x);
    }
};

TEST(TensorStreets, GroundTheStreetsMayNotCrossStopsTheStreamlines) {
    WallAt100 wall;
    TracedStreets traced = traceStreets(townField(2, 300), {{0, 0}, 300}, {}, {}, &wall);
    for (const Streamline &line : traced.streamlines)
        for (Vec2f p : line.points) EXPECT_LE(p.x, 100.001f);
    EXPECT_GT(traced.graph.edges().size(), 40u);
}

}  // namespace
}  // namespace veduta

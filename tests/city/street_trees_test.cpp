// Street trees (issue 23): along both kerbs of streets wide enough, in the sidewalk, evenly
// spaced, out of the junctions and off every carriageway; the same on every run.
#include <gtest/gtest.h>

#include <cmath>

#include "city/street_trees.h"

namespace veduta {
namespace {

// A crossing of a 10 m avenue (west–east, 200 m) and a 6 m lane (south–north).
StreetNetwork crossing() {
    StreetNetwork n;
    n.nodes = {{-100, 0}, {0, 0}, {100, 0}, {0, -100}, {0, 100}};
    n.streets = {{0, 1, 10}, {1, 2, 10}, {3, 1, 6}, {1, 4, 6}};
    return n;
}

TEST(StreetTrees, LineTheWideStreetsInTheirSidewalks) {
    StreetNetwork n = crossing();
    StreetStyle style;
    std::vector<PlacedTree> trees = streetTrees(n, style, 5);
    ASSERT_FALSE(trees.empty());
    for (const PlacedTree &t : trees) {
        // Along the avenue only, 1 m into the sidewalk: 6 m from its axis.
        EXPECT_NEAR(std::abs(t.position.y), 6.0f, 1e-4f) << t.position.x;
        // Out of the junction: beyond √2 · 5 m + 1 m + 3 m of the crossing's middle.
        EXPECT_GT(std::hypot(t.position.x, t.position.y), 1.4142f * 5 + 1 + 3 - 1e-3f);
        // Off the lane's carriageway.
        EXPECT_GT(std::abs(t.position.x), 3.0f);
        EXPECT_GE(t.height, 9 * 0.9f);
        EXPECT_LE(t.height, 9 * 1.1f);
        EXPECT_EQ(t.kind, TreeKind::Broadleaf);
    }
    // Each 100 m half of the avenue: ten places 10 m apart a side, those near the crossing left out.
    size_t north = 0;
    for (const PlacedTree &t : trees) north += t.position.y > 0;
    EXPECT_EQ(north, trees.size() - north);
    EXPECT_EQ(north, 2u * 10 - 2);  // at ±5 m from the crossing's middle the junction keeps them out
    // The same seed, the same trees; another, other heights.
    std::vector<PlacedTree> again = streetTrees(n, style, 5), other = streetTrees(n, style, 6);
    ASSERT_EQ(again.size(), trees.size());
    bool differ = false;
    for (size_t i = 0; i < trees.size(); ++i) {
        EXPECT_EQ(again[i].position.x, trees[i].position.x);
        EXPECT_EQ(again[i].height, trees[i].height);
        differ |= other[i].height != trees[i].height;
    }
    EXPECT_TRUE(differ);
}

}  // namespace
}  // namespace veduta

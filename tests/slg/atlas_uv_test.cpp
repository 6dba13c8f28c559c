// Texture coordinates in an atlas (digest-003 §3.3): the thesis's examples at L2190–2233.
#include <gtest/gtest.h>

#include "slg/atlas_uv.h"

namespace veduta {
namespace {

void expectQuad(const QuadUv &actual, const QuadUv &expected) {
    const char *corners[] = {"bottom left", "bottom right", "top right", "top left"};
    for (size_t i = 0; i < 4; ++i) {
        EXPECT_DOUBLE_EQ(actual[i].u, expected[i].u) << corners[i];
        EXPECT_DOUBLE_EQ(actual[i].v, expected[i].v) << corners[i];
    }
}

TEST(AtlasUv, TheWholeImageOnAQuad) {
    expectQuad(simpleMapping(gridMotif(0, 0, 1, 1)), {Uv{0, 1}, Uv{1, 1}, Uv{1, 0}, Uv{0, 0}});
}

TEST(AtlasUv, TheSecondOfSixMotifsSideBySide) {
    expectQuad(simpleMapping(gridMotif(1, 0, 6, 1)), {Uv{1.0 / 6, 1}, Uv{2.0 / 6, 1}, Uv{2.0 / 6, 0}, Uv{1.0 / 6, 0}});
}

TEST(AtlasUv, ADoorMotifIsStretchedOverTheDoor) {
    AtlasRect door{{0.2, 0.2}, {0.4, 0.4}};
    expectQuad(simpleMapping(door), {Uv{0.2, 0.4}, Uv{0.4, 0.4}, Uv{0.4, 0.2}, Uv{0.2, 0.2}});
}

TEST(AtlasUv, TheBlockAtlasIsTwoStackedSquares) {
    expectQuad(simpleMapping(gridMotif(0, 1, 1, 2)), {Uv{0, 1}, Uv{1, 1}, Uv{1, 0.5}, Uv{0, 0.5}});
}

TEST(AtlasUv, AFiveMetreTextureRepeatsOneAndAHalfTimesOnSevenAndAHalfMetres) {
    AtlasRect wall{{0, 0.25}, {1, 0.5}};
    expectQuad(tiledMapping(wall, 5, 0, 7.5), {Uv{0, 0.5}, Uv{1.5, 0.5}, Uv{1.5, 0.25}, Uv{0, 0.25}});
}

TEST(AtlasUv, TheNextWallContinuesWhereThePreviousEnded) {
    AtlasRect wall{{0, 0.25}, {1, 0.5}};
    QuadUv first = tiledMapping(wall, 5, 0, 7.5);
    QuadUv second = tiledMapping(wall, 5, 7.5, 9.5);
    expectQuad(second, {Uv{1.5, 0.5}, Uv{1.9, 0.5}, Uv{1.9, 0.25}, Uv{1.5, 0.25}});
    EXPECT_EQ(second[0], first[1]);  // no seam at the shared corner
    EXPECT_EQ(second[3], first[2]);
}

TEST(AtlasUv, OnlyAMotifAsWideAsTheAtlasTiles) { EXPECT_ANY_THROW(tiledMapping(gridMotif(1, 0, 6, 1), 5, 0, 7.5)); }

}  // namespace
}  // namespace veduta

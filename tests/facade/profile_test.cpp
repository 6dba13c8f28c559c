#include "facade/profile.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "thesis_figures.h"

namespace veduta {
namespace {

using thesis::kFigure5_20;
using thesis::kFigure5_20Lines;
using thesis::kFigure5_28;

ProfileOutline outlineOf(const char *text, double arcStep = 5) {
    return traceProfile(parseCorniceDescription(text, "cornice.txt").profile, arcStep);
}

std::string errorOf(const std::string &text) {
    try {
        parseCorniceDescription(text, "cornice.txt");
    } catch (const InputError &error) {
        return error.what();
    }
    return "no error";
}

void expectNear(Vec2d actual, Vec2d expected, double tolerance) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
}

TEST(Profile, LinesOfFigure5_20StepOutwardFromAnUpwardStart) {
    ProfileOutline outline = outlineOf(kFigure5_20Lines);
    std::vector<Vec2d> expected{{0, 0},    {0.3, 0},    {0.3, 10},   {0.9, 10},   {0.9, 21},
                                {1.5, 21}, {1.5, 21.6}, {2.1, 21.6}, {2.1, 23.6}, {4.1, 23.6}};
    ASSERT_EQ(outline.points.size(), expected.size());
    for (size_t i = 0; i < expected.size(); ++i) expectNear(outline.points[i], expected[i], 1e-9);
    ASSERT_EQ(outline.commandEnds.size(), 9u);
    EXPECT_EQ(outline.commandEnds.back(), 9u);
}

TEST(Profile, ArcOfFigure5_20IsATangentCavettoThatEndsHeadingUp) {
    ProfileOutline outline = outlineOf(kFigure5_20, 10);
    // Centre (4.1, 27.6): the arc leaves (4.1, 23.6) heading out and ends at (8.1, 27.6) heading up.
    size_t arcStart = outline.commandEnds[8], arcEnd = outline.commandEnds[9];
    EXPECT_EQ(arcEnd - arcStart, 9u);  // 90° in steps of 10°
    expectNear(outline.points[arcEnd], {8.1, 27.6}, 1e-9);
    for (size_t i = arcStart; i <= arcEnd; ++i) {
        Vec2d fromCentre = outline.points[i] - Vec2d{4.1, 27.6};
        EXPECT_NEAR(length(fromCentre), 4.0, 1e-9);
    }
    // The next line (rel 90, 5) then steps outward: the heading was up.
    expectNear(outline.points[arcEnd + 1], {13.1, 27.6}, 1e-9);
}

TEST(Profile, Figure5_20ClimbsOutAndReturnsToTheWall) {
    ProfileOutline outline = outlineOf(kFigure5_20);
    for (size_t i = 1; i < outline.points.size(); ++i) EXPECT_GE(outline.points[i].y, outline.points[i - 1].y - 1e-12);
    double reach = 4.1 + 4 + 5 + 0.6 + 7 * std::sqrt(0.5) + 0.6;
    double top = 27.6 + 5 + 0.6 + 7 * std::sqrt(0.5) + 0.6 + 2;
    double turn = 84 * M_PI / 180;
    expectNear(outline.points.back(), {reach - 22 * std::sin(turn), top + 22 * std::cos(turn)}, 1e-9);
    double mostOut = 0;
    for (Vec2d point : outline.points) mostOut = std::max(mostOut, point.x);
    EXPECT_NEAR(mostOut, reach, 1e-9);
}

TEST(Profile, ArcOfFigure5_28StepsOutAsAQuarterRound) {
    ProfileOutline outline = outlineOf(kFigure5_28, 45);
    // Centre straight ahead at (0, 0.7); the arc starts outward and sweeps 45° counter-clockwise.
    ASSERT_EQ(outline.points.size(), 4u);
    double h = 0.5 * std::sqrt(0.5);
    expectNear(outline.points[1], {0, 0.2}, 1e-12);
    expectNear(outline.points[2], {h, 0.7 - h}, 1e-12);
    expectNear(outline.points[3], {h - 0.4 * std::sqrt(0.5), 0.7 - h + 0.4 * std::sqrt(0.5)}, 1e-12);
    for (size_t i = 1; i < outline.points.size(); ++i) {
        EXPECT_GE(outline.points[i].x, 0);
        EXPECT_GT(outline.points[i].y, outline.points[i - 1].y);
    }
}

TEST(Profile, ArcIsTessellatedByTheGivenStep) {
    ProfileOutline outline = outlineOf(kFigure5_28, 10);
    EXPECT_EQ(outline.commandEnds[1] - outline.commandEnds[0], 5u);  // 45° in steps of at most 10°
    for (size_t i = outline.commandEnds[0]; i <= outline.commandEnds[1]; ++i)
        EXPECT_NEAR(length(outline.points[i] - Vec2d{0, 0.7}), 0.5, 1e-12);
}

TEST(Profile, AbsoluteAnglesStartFromTheOriginalBasis) {
    ProfileOutline outline = outlineOf("Modifications { line, rel, 90, 1; line, abs, 90, 1; line, rel, 90, 1; }");
    expectNear(outline.points[2], {2, 0}, 1e-12);  // abs 90: outward again, not down
    expectNear(outline.points[3], {2, -1}, 1e-12);
}

TEST(Profile, ScalingFillsThePartitionHeightFromItsBottom) {
    Profile profile = parseCorniceDescription(kFigure5_20Lines, "c.txt").profile;
    ProfileOutline outline = traceProfile(profile, 5);
    double scale = heightScale(profile, outline, 0.59);
    EXPECT_NEAR(scale, 0.025, 1e-15);
    ProfileOutline scaled = scaledOutline(outline, scale);
    expectNear(scaled.points.back(), {4.1 * 0.025, 0.59}, 1e-12);
    ProfileOutline down = traceProfile(parseCorniceDescription("Modifications{line,rel,180,2;}", "c").profile, 5);
    expectNear(scaledOutline(down, 0.5).points[0], {0, 1}, 1e-12);
}

TEST(Profile, FlatProfileCannotFillAPartition) {
    Profile profile = parseCorniceDescription("Modifications {\n line, rel, 90, 1; }", "c.txt").profile;
    try {
        heightScale(profile, traceProfile(profile, 5), 1);
        FAIL() << "no error";
    } catch (const InputError &error) {
        EXPECT_STREQ(error.what(), "c.txt:1:1: the profile has no height to fill a partition with");
    }
}

TEST(CorniceDescription, Figure5_28ParsesWhole) {
    CorniceDescription description = parseCorniceDescription(kFigure5_28, "cornice.txt");
    ASSERT_EQ(description.profile.commands.size(), 3u);
    const ProfileCommand &arc = description.profile.commands[1];
    EXPECT_EQ(arc.kind, ProfileCommand::Kind::Arc);
    EXPECT_TRUE(arc.absolute);
    EXPECT_EQ(arc.angle, 90);
    EXPECT_EQ(arc.arcAngle, 45);
    EXPECT_EQ(arc.size, 0.5);
    EXPECT_EQ(arc.textures, (std::array<int, 3>{0, 1, 2}));
    EXPECT_EQ(description.profile.commands[0].textures, (std::array<int, 3>{-1, -1, -1}));
    ASSERT_EQ(description.consoles.size(), 1u);
    EXPECT_EQ(description.consoles[0].spacing, 1.5);
    EXPECT_EQ(description.consoles[0].objectFile, "objects/simple_console.obj");
    EXPECT_EQ(description.consoles[0].width, 0.35);
    EXPECT_EQ(description.consoles[0].height, 0.45);
    ASSERT_EQ(description.textures.size(), 3u);
    // v counted down from the image's top, as elsewhere in veduta.
    EXPECT_EQ(description.textures[0].file, "textures/frieze.bmp");
    EXPECT_EQ(description.textures[0].left, 0.0);
    EXPECT_EQ(description.textures[0].right, 0.04875);
    EXPECT_EQ(description.textures[0].top, 0.375);
    EXPECT_EQ(description.textures[0].bottom, 0.75);
    EXPECT_EQ(description.textures[1].top, 0.0);
    EXPECT_EQ(description.textures[1].bottom, 0.375);
    EXPECT_EQ(description.textures[2].left, 0.953125);
}

TEST(CorniceDescription, TexturePoolIsTheGrammarsNameForTextureDescs) {
    CorniceDescription description =
        parseCorniceDescription("Modifications { line, rel, 0, 1; } TexturePool { \"a.png\", 0, 1, 1, 0; }", "c");
    ASSERT_EQ(description.textures.size(), 1u);
    EXPECT_EQ(description.textures[0].top, 0.0);
    EXPECT_EQ(description.textures[0].bottom, 1.0);
}

TEST(CorniceDescription, ConsolesBlockHoldsSeveralPairs) {
    CorniceDescription description = parseCorniceDescription(
        "Modifications { line, rel, 0, 1; } Consoles { 1.5; \"a.obj\", 0.3, 0.4; 2; \"b.obj\", 0.5, 0.6; }", "c");
    ASSERT_EQ(description.consoles.size(), 2u);
    EXPECT_EQ(description.consoles[1].spacing, 2);
    EXPECT_EQ(description.consoles[1].objectFile, "b.obj");
}

TEST(CorniceDescription, ErrorsNameTheirPlace) {
    EXPECT_EQ(errorOf("Modifications {\n  line, rel, 0, 1;\n  curve, rel, 0, 1; }"),
              "cornice.txt:3:3: unknown command 'curve' (line or arc)");
    EXPECT_EQ(errorOf("Modifications { line, rel, 0; }"),
              "cornice.txt:1:17: line takes 4 fields, or 7 with three texture indices; found 3");
    EXPECT_EQ(errorOf("Modifications { arc, rel, 0, 90, 1, 2; }"),
              "cornice.txt:1:17: arc takes 5 fields, or 8 with three texture indices; found 6");
    EXPECT_EQ(errorOf("Modifications { line, rel, 0, -1; }"),
              "cornice.txt:1:31: the length must be positive, found -1");
    EXPECT_EQ(errorOf("Modifications { arc, abs, 0, 90, 0; }"),
              "cornice.txt:1:34: the radius must be positive, found 0");
    EXPECT_EQ(errorOf("Modifications { arc, abs, 0, 400, 1; }"),
              "cornice.txt:1:30: an arc's angle must be in [-360, 0) or (0, 360], found 400");
    EXPECT_EQ(errorOf("Modifications { line, sideways, 0, 1; }"),
              "cornice.txt:1:23: expected rel or abs, found 'sideways'");
    EXPECT_EQ(errorOf("Modifications { line, rel, 0, 1, 0, 1.5, 2; }"),
              "cornice.txt:1:37: a texture index must be a whole number, found 1.5");
    EXPECT_EQ(errorOf("Modifications { line, rel, 0, 1, 0, 1, 2; }"),
              "cornice.txt:1:17: texture index 0 names no texture (the pool has 0)");
    EXPECT_EQ(errorOf("Modifications { }"), "cornice.txt:1:1: a profile needs at least one line or arc");
    EXPECT_EQ(errorOf("Consoles { 1; \"a\", 1, 1; }"), "cornice.txt:1:1: the cornice has no Modifications block");
    EXPECT_EQ(errorOf("Modifications { line, rel, 0, 1; }\nGesims { 1; }"),
              "cornice.txt:2:1: unknown block 'Gesims' (Modifications, Consoles, TexturePool or TextureDescs)");
    EXPECT_EQ(errorOf("Modifications { line, rel, 0, 1; }\nModifications { line, rel, 0, 1; }"),
              "cornice.txt:2:1: a second Modifications block (the first is at cornice.txt:1:1)");
    EXPECT_EQ(errorOf("Modifications { line, rel, 0, 1; } Consoles { 1.5; \"a.obj\", 0.3, 0.4; 2; }"),
              "cornice.txt:1:71: a console is two items: abstand; \"obj\", breite, hoehe;");
    EXPECT_EQ(errorOf("Modifications { line, rel, 0, 1; } Consoles { 0; \"a.obj\", 0.3, 0.4; }"),
              "cornice.txt:1:47: the spacing must be positive, found 0");
    EXPECT_EQ(errorOf("Modifications { line, rel, 0, 1; } TexturePool { \"a\", 0, 1, 1.5, 0; }"),
              "cornice.txt:1:61: right must lie in [0, 1], found 1.5");
    EXPECT_EQ(errorOf("Modifications { line, rel, 0, 1; } TexturePool { \"a\", 0, 0.2, 1, 0.6; }"),
              "cornice.txt:1:58: a texture's top must lie above its bottom (v counts up)");
    EXPECT_EQ(errorOf("Modifications { line, rel, 0, 1; } TexturePool { \"a\", 0.5, 1, 0.5, 0; }"),
              "cornice.txt:1:63: a texture's right must lie right of its left");
}

// A profile that once reached +inf (the third line: 1e308 up, 1e308 on and 1 out) and one whose
// height overflowed (an infinite extent made the scale 0, and inf · 0 a NaN): sizes and angles
// are limited where they are read.
TEST(CorniceDescription, SizesAndAnglesAreLimited) {
    EXPECT_EQ(errorOf("Modifications { line, rel, 90, 1e308; line, rel, 0, 1e308; line, rel, -90, 1; }"),
              "cornice.txt:1:32: the length must be at most 10000, found 1e+308");
    EXPECT_EQ(errorOf("Modifications { arc, rel, 0, 90, 10000.5; }"),
              "cornice.txt:1:34: the radius must be at most 10000, found 10000.5");
    EXPECT_EQ(errorOf("Modifications { line, abs, 1e300, 1; }"),
              "cornice.txt:1:28: an angle must lie in [-3600, 3600], found 1e+300");
    EXPECT_EQ(errorOf("Modifications { line, rel, -3600.5, 1; }"),
              "cornice.txt:1:28: an angle must lie in [-3600, 3600], found -3600.5");
    EXPECT_EQ(errorOf("Modifications { line, rel, 0, 1; } Consoles { 1.5; \"a.obj\", 0.3, 1e5; }"),
              "cornice.txt:1:66: the height must be at most 10000, found 100000");
    EXPECT_EQ(errorOf("Modifications { line, rel, 3600, 10000; arc, rel, -3600, 360, 10000; }"), "no error");
}

// 1 - 1e-300 is 1: counted down from the top the rectangle was empty, and a frieze piece keeping
// its aspect was infinitely wide.
TEST(CorniceDescription, TextureRectangleMustStayNonEmptyCountedDown) {
    EXPECT_EQ(errorOf("Modifications { line, rel, 0, 1; } TexturePool { \"a\", 0, 1e-300, 1, 0; }"),
              "cornice.txt:1:58: a texture's top and bottom are too close to tell apart");
}

// Once 1 + 1e-300 == 1 drew a band of no length: NaN normals, and a frieze strip of height 0.
TEST(Profile, StepLostBesideTheProfilesSizeIsAnError) {
    Profile profile = parseCorniceDescription(
                          "Modifications { line, rel, 0, 1;\n line, rel, 90, 1e-300, 0, 0, 0; }\n"
                          "TexturePool { \"a\", 0, 1, 1, 0; }",
                          "c.txt")
                          .profile;
    try {
        traceProfile(profile, 5);
        FAIL() << "no error";
    } catch (const InputError &error) {
        EXPECT_STREQ(error.what(),
                     "c.txt:2:2: this command is too short to draw in a profile reaching 1 units from "
                     "its start");
    }
    // A tiny arc far from the start: its steps vanish too.
    Profile arc = parseCorniceDescription("Modifications { line, rel, 0, 10000; arc, rel, 0, 90, 1e-9; }", "c").profile;
    EXPECT_THROW(traceProfile(arc, 5), InputError);
    // Small beside the profile but not lost: drawn.
    Profile small = parseCorniceDescription("Modifications { line, rel, 0, 1; line, rel, 90, 1e-9; }", "c").profile;
    EXPECT_EQ(traceProfile(small, 5).points.size(), 3u);
}

TEST(Profile, ProfileMuchWiderThanHighCannotFillAPartition) {
    Profile profile =
        parseCorniceDescription("Modifications { line, rel, 90, 10000; line, rel, -90, 1e-3; }", "c.txt").profile;
    try {
        heightScale(profile, traceProfile(profile, 5), 1);
        FAIL() << "no error";
    } catch (const InputError &error) {
        EXPECT_STREQ(error.what(), "c.txt:1:1: the profile is more than 1000000 times as wide as it is high");
    }
    Profile wide =
        parseCorniceDescription("Modifications { line, rel, 90, 10000; line, rel, -90, 0.01; }", "c.txt").profile;
    EXPECT_NEAR(heightScale(wide, traceProfile(wide, 5), 1), 100, 1e-6);
}

TEST(Profile, OutlineBeyondFiniteCoordinatesHasNoScale) {
    Profile profile = parseCorniceDescription("Modifications { line, rel, 0, 1; }", "c.txt").profile;
    ProfileOutline outline{{{0, 0}, {HUGE_VAL, 1}}, {1}};
    EXPECT_THROW(heightScale(profile, outline, 1), InputError);
    outline.points = {{0, -1e308}, {0, 1e308}};  // the extent overflows
    EXPECT_THROW(heightScale(profile, outline, 1), InputError);
    outline.points = {{0, 0}, {std::nan(""), 1}};
    EXPECT_THROW(heightScale(profile, outline, 1), InputError);
}

TEST(CorniceDescription, CommandCountIsLimited) {
    std::string text = "Modifications {";
    for (size_t i = 0; i <= kProfileCommandLimit; ++i) text += " line, rel, 0, 1;";
    text += " }";
    EXPECT_EQ(errorOf(text),
              fmt::format("cornice.txt:1:{}: a profile may have at most {} commands", 17 + 17 * kProfileCommandLimit,
                          kProfileCommandLimit));
}

}  // namespace
}  // namespace veduta

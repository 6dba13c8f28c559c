#include <gtest/gtest.h>

#include <cmath>

#include "preview/thesis_shading.h"

namespace veduta {
namespace {

// Bilke's base material colours (L1190) and a light whose channels differ, so that a
// term taken from the wrong colour shows.
const ThesisLight kLight{{0.2f, 0.3f, 0.4f}, {0.9f, 0.8f, 0.7f}, {1.0f, 0.5f, 0.25f}};
const ThesisMaterial kMaterial{{0.4f, 0.4f, 0.4f}, {0.65f, 0.65f, 0.65f}, {1.0f, 1.0f, 0.85f}, 10.0f};
const Vec3f kFlatTexel{0.5f, 0.5f, 1.0f};  // the normal (0, 0, 1)

Vec3f lightAt(float degrees) { return {std::sin(radians(degrees)), 0, std::cos(radians(degrees))}; }

PpsunsInputs flatInputs(const Vec3f &lightVec, const Vec3f &eyeVec) {
    return {Vec3f(1.0f), kFlatTexel, 1.0f, lightVec, eyeVec, Vec3f(0.0f)};
}

// Colours are of order 1; the shininess exponent multiplies a cosine's float rounding
// tenfold, which stays far below any wrong term (Blinn's lobe would differ by 0.3 below).
void expectColor(const Vec3f &actual, const Vec3f &expected) {
    EXPECT_NEAR(actual.x, expected.x, 1e-5f);
    EXPECT_NEAR(actual.y, expected.y, 1e-5f);
    EXPECT_NEAR(actual.z, expected.z, 1e-5f);
}

// T13 (Bilke 2009 (digest §10)): flat normal map, base 1, environment 0, vAmbient = 0.4·La:
// 0.6·La + 0.325·Ld·max(l·n, 0) + spec. Seen from straight above, R·V = l·n, so the
// shader's specular is Ls·Ms·max(l·n, 0)^shininess.
TEST(ThesisShading, FlatPixelIsAmbientPlusHalfDiffusePlusSpecular) {
    for (float degrees : {0.0f, 30.0f, 60.0f, 89.0f, 120.0f, 180.0f}) {
        SCOPED_TRACE(degrees);
        float cosine = std::max(std::cos(radians(degrees)), 0.0f);
        Vec3f spec = kLight.specular * kMaterial.specular * std::pow(cosine, kMaterial.shininess);
        Vec3f expected = 0.6f * kLight.ambient + 0.325f * kLight.diffuse * cosine + spec;
        expectColor(ppsunsShade(kLight, kMaterial, flatInputs(lightAt(degrees), {0, 0, 1})), expected);
    }
}

// The shader normalises its light and eye vectors, which arrive interpolated.
TEST(ThesisShading, VectorLengthsDoNotMatter) {
    Vec3f unit = ppsunsShade(kLight, kMaterial, flatInputs(lightAt(40), normalize(Vec3f{0.3f, 0.1f, 1})));
    Vec3f scaled = ppsunsShade(kLight, kMaterial, flatInputs(7.0f * lightAt(40), Vec3f{0.9f, 0.3f, 3}));
    expectColor(scaled, unit);
}

// Phong's R·V (L1102), not the Blinn half-vector of the text (L847): 20° off the mirror
// direction the lobe is cos(20°)^n, where Blinn's would be cos(10°)^n.
TEST(ThesisShading, SpecularIsPhongAboutTheMirrorDirection) {
    ThesisLight specularOnly{Vec3f(0.0f), Vec3f(0.0f), Vec3f(1.0f)};
    ThesisMaterial material{Vec3f(0.0f), Vec3f(0.0f), Vec3f(1.0f), 10.0f};
    Vec3f mirror = lightAt(-40);
    expectColor(ppsunsShade(specularOnly, material, flatInputs(lightAt(40), mirror)), Vec3f(1.0f));
    float lobe = std::pow(std::cos(radians(20)), 10.0f);
    expectColor(ppsunsShade(specularOnly, material, flatInputs(lightAt(40), lightAt(-20))), Vec3f(lobe));
}

// The specular map's first channel scales the specular term and nothing else.
TEST(ThesisShading, SpecularMapScalesOnlyTheSpecular) {
    PpsunsInputs in = flatInputs(lightAt(30), {0, 0, 1});
    Vec3f full = ppsunsShade(kLight, kMaterial, in);
    in.specularTexel = 0;
    Vec3f none = ppsunsShade(kLight, kMaterial, in);
    in.specularTexel = 0.25f;
    Vec3f quarter = ppsunsShade(kLight, kMaterial, in);
    expectColor(none, 0.6f * kLight.ambient + 0.325f * kLight.diffuse * std::cos(radians(30)));
    expectColor(quarter, none + 0.25f * (full - none));
}

// The base colour multiplies ambient, environment and diffuse light; the specular is added
// after it, and the environment counts half.
TEST(ThesisShading, BaseColourTintsAllButTheSpecular) {
    PpsunsInputs in = flatInputs(lightAt(45), lightAt(-45));  // at the mirror direction: R·V = 1
    in.baseColor = {0.5f, 0.25f, 1.0f};
    in.environment = {0.2f, 0.4f, 0.6f};
    Vec3f lit = 0.6f * kLight.ambient + 0.5f * in.environment + 0.325f * kLight.diffuse * std::cos(radians(45));
    expectColor(ppsunsShade(kLight, kMaterial, in), lit * in.baseColor + kLight.specular * kMaterial.specular);
}

// The normal map's texel, mapped from [0, 1] to [−1, 1], replaces the geometric normal:
// a normal tilted 30° towards a light 30° off the surface normal faces it fully.
TEST(ThesisShading, NormalMapTiltsTheShadingNormal) {
    ThesisLight diffuseOnly{Vec3f(0.0f), Vec3f(1.0f), Vec3f(0.0f)};
    PpsunsInputs in = flatInputs(lightAt(30), {0, 0, 1});
    in.normalTexel = 0.5f * lightAt(30) + Vec3f(0.5f);
    expectColor(ppsunsShade(diffuseOnly, kMaterial, in), Vec3f(0.325f));
    in.normalTexel = 0.5f * lightAt(-60) + Vec3f(0.5f);  // tilted away: the light grazes it
    expectColor(ppsunsShade(diffuseOnly, kMaterial, in), Vec3f(0.0f));
}

}  // namespace
}  // namespace veduta

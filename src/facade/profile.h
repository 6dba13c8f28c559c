// Finkenzeller's cornice description (digest-001 §2.6, Defs 5.9–5.11, L1128–1216): the profile
// language `Modifications { (line|arc, rel|abs, …)+ }`, a turtle that draws a cornice's cross
// section, and the two blocks that extend it, `Consoles { (abstand; "obj", breite, hoehe;)+ }` and
// `TexturePool { ("file", left, top, right, bottom;)+ }` (Fig. 5.28 spells it `TextureDescs`; both
// names are read, digest §10). The blocks come from description_text.h; this checks their fields.
//
// The profile plane: x = the wall's normal (out of the wall), y = up, in the profile's own units.
// The turtle starts at the origin heading up (0, 1); its `normal` is always its heading turned a
// quarter clockwise, so it starts as (1, 0), out of the wall. Every angle is in degrees, and a
// positive angle turns toward the normal (clockwise here): `line, rel, 90, 0.3` steps outward
// (digest §8 row 10). `rel` angles start from the current heading, `abs` ones from (0, 1).
//   line, rel|abs, α, length      — a segment in the direction α; the turtle then heads along it.
//   arc, rel|abs, α, β, radius    — the centre M lies `radius` from the current point S, in the
//       basis's anti-normal turned by α toward the normal; the arc runs |β| degrees about M from S;
//       the turtle then heads along the end tangent.
// The thesis leaves the arc's centre and the sense of β open (L1141, digest §2.6 [UNCERTAIN]); no
// reading of it makes both the Fig. 5.20 arc (`arc, rel, 0, -90, 4.0`) and the Fig. 5.28 arc
// (`arc, abs, 90, 45, 0.5`) tangent-continuous. We chose:
//   * α = 0 puts M beside S on the side away from the normal, so the arc starts tangent to the
//     heading and bends away from the normal: Fig. 5.20's cavetto then ends heading up and the
//     rest of that main cornice climbs and ends at the wall, as a main cornice does. α = 90 puts M
//     straight ahead (Fig. 5.28: a quarter-round stepping out of the wall, with a kink at S).
//   * An arc never starts backwards: of its two senses it takes the one whose start tangent points
//     along the current heading; only where both are square to it (M straight ahead or behind)
//     does β's sign choose, positive starting toward the normal. |β| is the angle swept.
//   Both figures then give a profile that leaves the wall, climbs and returns to it (tests).
// Optional fields t0, t1, t2 after each command are the indices of its start, mid and end textures
// in the texture pool; negative means none (L1183).
// The profile is scaled uniformly so that its height fills the partition it is put on (L1128);
// its lowest point goes to the partition's bottom.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "core/vecmath.h"
#include "facade/description_text.h"

namespace veduta {

struct ProfileCommand {
    enum class Kind { Line, Arc };
    Kind kind = Kind::Line;
    bool absolute = false;                    // `abs`: angles start from the original basis
    double angle = 0;                         // α, degrees toward the normal
    double arcAngle = 0;                      // β, degrees (arc only)
    double size = 0;                          // the line's length or the arc's radius
    std::array<int, 3> textures{-1, -1, -1};  // start, mid, end; negative = none
    FileLoc loc;
};

struct Profile {
    std::vector<ProfileCommand> commands;
    FileLoc loc;  // of the Modifications block
};

// The traced cross section: points[0] is the start; command i draws points
// (i == 0 ? 0 : commandEnds[i-1]) … commandEnds[i].
struct ProfileOutline {
    std::vector<Vec2d> points;
    std::vector<size_t> commandEnds;
};

// One console of a Consoles block (Def 5.10): centres `spacing` metres apart, an external mesh on
// a rectangle `width` × `height` in the profile's units.
struct Console {
    double spacing = 0;
    std::string objectFile;
    double width = 0, height = 0;
    FileLoc loc;
};

// One texture of a TexturePool (Def 5.11): a sub-rectangle of an image. The thesis's numbers count
// v upward (Fig. 5.28 gives top 0.625 over bottom 0.25); they are stored here in veduta's
// convention, v = 0 at the image's top (as slg/atlas_uv.h), so top < bottom.
struct TextureRegion {
    std::string file;
    double left = 0, top = 0, right = 0, bottom = 0;
    FileLoc loc;
};

// A whole cornice description: one profile, and optionally consoles and textures.
struct CorniceDescription {
    Profile profile;
    std::vector<Console> consoles;
    std::vector<TextureRegion> textures;
};

// The most commands one profile may have.
inline constexpr size_t kProfileCommandLimit = 10000;
// The largest length, radius, breite or hoehe, in the profile's units, and the largest angle α
// either way, in degrees. Cornices measure a few units and turn by right angles; the limits keep
// every traced point finite (10000 commands of at most this size) and every angle precise enough
// to turn by (the cosine of 1e300° says nothing).
inline constexpr double kProfileSizeLimit = 1e4;
inline constexpr double kProfileAngleLimit = 3600;

// The most a profile may be wider (x) than high: filling a partition's height, a wider one would
// reach kilometres out of the wall, and the huge factor of a nearly flat one would carry its
// points past any finite coordinate.
inline constexpr double kProfileAspectLimit = 1e6;

// The checked contents of one block (its name is not looked at). InputError with the place of
// the offending field: an unknown command, a wrong field count, a length, radius or size that is
// not positive or over kProfileSizeLimit, an angle over kProfileAngleLimit, an arc over 360°, a
// texture index that is not a whole number, a texture rectangle outside [0, 1] or empty, a
// Consoles block whose items do not pair up.
Profile parseProfile(const DescriptionBlock &block);
std::vector<Console> parseConsoles(const DescriptionBlock &block);
std::vector<TextureRegion> parseTexturePool(const DescriptionBlock &block);

// Reads a whole cornice text: exactly one Modifications block, at most one Consoles and one
// TexturePool/TextureDescs block, nothing else; texture indices must name pool entries.
CorniceDescription parseCorniceDescription(std::string_view text, const std::string &file);

// Runs the turtle. Arcs become segments of at most `arcStepDegrees` (in (0, 90]). InputError at
// the command when one of its steps is too short to tell its ends apart beside the size of the
// whole profile (1e-12 of its largest coordinate): scaledOutline would make them one point.
ProfileOutline traceProfile(const Profile &profile, double arcStepDegrees);

// The factor that makes the outline's height (highest minus lowest y) `height`. InputError at the
// profile when it has no height, or when it is more than kProfileAspectLimit times as wide (x)
// as high.
double heightScale(const Profile &profile, const ProfileOutline &outline, double height);

// The outline scaled by `scale` and shifted up so that its lowest point has y = 0.
ProfileOutline scaledOutline(const ProfileOutline &outline, double scale);

}  // namespace veduta

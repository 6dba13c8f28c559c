// Roofs on any simple footprint, with or without courtyards (issue 7; Finkenzeller 2008, ch. 4.4,
// anchors-procedural §1.2, §6–7): flat with a parapet, hip (the straight skeleton lifted by the
// pitch), pyramid, shed, gable, half-hip and mansard, with eaves overhangs and a fallback to a
// simpler type, with the reason, when the footprint cannot take the one asked for.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "city/roofs.h"

namespace veduta {

// A roof's ground plan: `outer` counter-clockwise seen from above, `holes` (courtyards)
// clockwise, inside it and apart from each other, all simple; at ground height `base`. The
// building lies to the left of every edge.
struct RoofFootprint {
    std::vector<Vec2f> outer;
    std::vector<std::vector<Vec2f>> holes;
    float base = 0;
};

enum class RoofType { Flat, Hip, Pyramid, Shed, Gable, HalfHip, Mansard };
inline constexpr RoofType kRoofTypes[] = {RoofType::Flat,  RoofType::Hip,     RoofType::Pyramid, RoofType::Shed,
                                          RoofType::Gable, RoofType::HalfHip, RoofType::Mansard};

struct RoofOptions {
    RoofType type = RoofType::Hip;
    float pitchDegrees = 40;     // the slopes' angle; a flat roof ignores it
    float overhang = 0;          // metres the eaves reach beyond the walls (see buildRoof)
    float parapetHeight = 0.8f;  // a flat roof's parapet, 0 for none
    // Shed: the low edge; gable and half-hip: the one edge to carry the gable end. −1: the
    // longest edge for a shed, every end of a ridge for a gable or half-hip (roof_gables.h).
    // An index into `outer`'s edges.
    int gableEdge = -1;
    float halfHipFraction = 0.5f;  // in (0, 1): how far up the gable a half-hip's wall reaches
};

struct RoofResult {
    Mesh mesh;
    RoofType built;
    // Why the roof departs from the options (another type, no overhang, gable ends left
    // hipped), when it does.
    std::optional<std::string> fallback;
};

// The fallbacks, tried in this order until one can be built: Pyramid → Hip → Flat,
// Gable → Hip → Flat, HalfHip → Hip → Flat, Mansard → Flat, Hip → Flat, Shed → Flat; Flat
// always can.
inline constexpr float kParapetThickness = 0.3f;  // halved until it fits, at most kParapetHalvings times
inline constexpr int kParapetHalvings = 4;
inline constexpr float kMansardInset = 2;            // the mansard's slope reaches this far in (roofs.h)
inline constexpr float kMinShedWallHeight = 0.001f;  // lower shed walls are left out

std::string_view roofTypeName(RoofType type);
// The type a name stands for (flat, hip, pyramid, shed, gable, halfhip or half-hip, mansard; any
// case), or nullopt.
std::optional<RoofType> roofTypeFromName(std::string_view name);

// The roof over `footprint` with its eaves `eavesHeight` above the base: a mesh as roofs.h
// describes (RoofCovering slopes with UVs along the eaves and up the slant, RoofGableWall for
// gable, shed and parapet walls, whose UVs continue the facades'), whose open edges are exactly
// the footprint's (moved out by the overhang) at the eaves: with the footprint as a floor it
// closes. An overhang lowers the eaves by overhang · tan(pitch), so that the slopes pass over
// the wall tops at eavesHeight. Hip, mansard and flat roofs overhang on every edge; a shed on
// its low edge only; a gable or half-hip everywhere but its gable ends, whose walls stand
// flush with the house's (and run down past the wall tops to the lowered eaves); a pyramid's
// shallower faces reach out farther, so that all its eaves are lowered alike. Throws std::invalid_argument for a
// footprint that breaks the rules above, a pitch outside (0°, 90°) on a sloped type, a negative overhang or parapet, or
// a gableEdge that is no edge of `outer`, or a halfHipFraction outside (0, 1).
RoofResult buildRoof(const RoofFootprint &footprint, float eavesHeight, const RoofOptions &options);

}  // namespace veduta

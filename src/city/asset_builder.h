// Assembles a built-in asset (assets.h) in the model frame from parts, each on one of the
// asset's surfaces. Solids are closed and face out; faces meeting at a sharp edge get their
// own vertices, faces of a curve share smoothed normals; uvs are in metres.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "city/assets.h"

namespace veduta {

// The direction a prism is extruded in, and so the model axes of its outline's (a, b):
// along X the outline is in (y, z), along Y in (z, x), along Z in (x, y).
enum class PrismAxis { X, Y, Z };

class AssetBuilder {
  public:
    // A solid: `outline` (a simple polygon, either orientation) extruded along `axis` from
    // `from` to `to`. Side uvs: u runs along the outline, v along the axis.
    void prism(std::span<const Vec2f> outline, PrismAxis axis, float from, float to, MaterialCategory surface);
    void box(const Vec3f &min, const Vec3f &max, MaterialCategory surface);
    // A one-sided rectangle from `corner` along the edges `u` and `v`, facing along cross(u, v).
    void rectangle(const Vec3f &corner, const Vec3f &u, const Vec3f &v, MaterialCategory surface);

    // Surfaces are numbered in the order parts first use them: the first part added decides
    // surfaces[0], the one a rule's texture replaces.
    Asset finish(std::string name, ModelType type) &&;

  private:
    void add(Mesh part, const Transform &placement, MaterialCategory surface);

    Mesh mesh_;
    std::vector<MaterialCategory> surfaces_;
};

// Points on a circular arc from `fromDegrees` to `toDegrees` (counter-clockwise when `to` is
// the larger), both ends included, appended to `points`.
void appendArc(std::vector<Vec2f> &points, Vec2f centre, float radius, float fromDegrees, float toDegrees,
               int segments);

// A moulding's outline for a prism along X: `profile` gives (height above `bottom`,
// projection from the wall) from the bottom at the wall to the top at the wall.
std::vector<Vec2f> mouldingOutline(std::span<const Vec2f> profile, float bottom);

}  // namespace veduta

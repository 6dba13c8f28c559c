#include "geo/track_geometry.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "geo/mesh_normals.h"
#include "geo/ribbon_frame.h"

namespace veduta {

namespace {

constexpr double kSleeperHalfLength = 1.3, kSleeperDepth = 0.26, kSleeperPitch = 0.6, kSleeperHeight = 0.1;
constexpr double kRailOffset = 0.7175 + 0.035, kRailHalfWidth = 0.035, kRailHeight = 0.15;
constexpr double kTrackSpacing = 4.5;
constexpr double kRailStep = 1.0;  // metres between a rail's cross-sections, besides the ribbon's own
constexpr double kSunk = 0.02;     // how far solids reach into the ballast, so no gap shows

// A point on the ribbon: `s` metres along its centre line, `offset` metres left of it, at the
// ribbon's height there plus `rise`.
Vec3f onRibbon(const RibbonFrame &frame, double halfWidth, double s, double offset, double rise) {
    auto [i, t] = frame.pieceAt(s);
    Vec2d p = frame.at(i, t, offset / halfWidth);
    return {float(p.x), float(p.y), float(frame.heightAt(i, p) + rise)};
}

// Flat-shaded faces, each given counter-clockwise seen from outside.
void face(Mesh &out, std::initializer_list<Vec3f> corners, TrackSurface surface) {
    auto first = uint32_t(out.positions.size());
    for (const Vec3f &p : corners) {
        out.positions.push_back(p);
        out.uvs.push_back({p.x, p.y});
    }
    for (uint32_t k = 1; k + 1 < corners.size(); ++k) {
        out.indices.insert(out.indices.end(), {first, first + k, first + k + 1});
        out.triangleMaterials.push_back(surface);
    }
}

// A solid over the four plan corners a0 (start, right), a1 (start, left), b1 (end, left), b0
// (end, right), from `low` below the ribbon to `high` above it: its top and four sides.
void solid(Mesh &out, const RibbonFrame &frame, double halfWidth, double s0, double s1, double right, double left,
           double high, TrackSurface surface) {
    Vec3f a0 = onRibbon(frame, halfWidth, s0, right, -kSunk), a1 = onRibbon(frame, halfWidth, s0, left, -kSunk);
    Vec3f b0 = onRibbon(frame, halfWidth, s1, right, -kSunk), b1 = onRibbon(frame, halfWidth, s1, left, -kSunk);
    Vec3f up{0, 0, float(high + kSunk)};
    face(out, {a0 + up, b0 + up, b1 + up, a1 + up}, surface);
    face(out, {a0, b0, b0 + up, a0 + up}, surface);  // right
    face(out, {b1, a1, a1 + up, b1 + up}, surface);  // left
    face(out, {a1, a0, a0 + up, a1 + up}, surface);  // start
    face(out, {b0, b1, b1 + up, b0 + up}, surface);  // end
}

bool nearCamera(const RibbonFrame &frame, double halfWidth, double s, Vec3f camera, double reach) {
    return length(onRibbon(frame, halfWidth, s, 0, 0) - camera) <= reach;
}

}  // namespace

Mesh trackGeometry(const Mesh &ribbon, double width, int tracks, Vec3f camera, const TrackOptions &options) {
    Mesh out;
    RibbonFrame frame(ribbon);
    double halfWidth = 0.5 * width;
    if (frame.stations() < 2 || halfWidth <= 0 || !frame.near({camera.x, camera.y}, options.reach)) return out;
    for (int track = 0; track < tracks; ++track) {
        double centre = (track - 0.5 * (tracks - 1)) * kTrackSpacing;
        for (double s = 0; s + kSleeperDepth <= frame.length(); s += kSleeperPitch) {
            if (!nearCamera(frame, halfWidth, s, camera, options.reach)) continue;
            solid(out, frame, halfWidth, s, s + kSleeperDepth, centre - kSleeperHalfLength, centre + kSleeperHalfLength,
                  kSleeperHeight, TrackSleeper);
        }
        // Rails: one solid a step long after another, while the camera is near.
        for (double s = 0; s < frame.length(); s += kRailStep) {
            double end = std::min(s + kRailStep, frame.length());
            if (!nearCamera(frame, halfWidth, s, camera, options.reach)) continue;
            for (double side : {-1.0, 1.0}) {
                double middle = centre + side * kRailOffset;
                solid(out, frame, halfWidth, s, end, middle - kRailHalfWidth, middle + kRailHalfWidth, kRailHeight,
                      TrackRail);
            }
        }
    }
    out.normals = areaWeightedNormals(out);
    return out;
}

}  // namespace veduta

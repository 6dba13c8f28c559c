#include "facade/cornice_run.h"

#include <cmath>

#include "facade/consoles.h"

namespace veduta {
namespace {

// Arcs of a profile become segments of at most this many degrees.
constexpr double kArcStepDegrees = 10;
constexpr double kSamePoint = 1e-6;

void keepTurns(SweepPath &path) {
    std::vector<Vec2d> kept;
    size_t n = path.points.size();
    for (size_t i = 0; i < n; ++i) {
        bool end = !path.closed && (i == 0 || i + 1 == n);
        Vec2d prev = path.points[(i + n - 1) % n], next = path.points[(i + 1) % n], p = path.points[i];
        Vec2d a = p - prev, b = next - p;
        if (end || std::abs(cross(a, b)) > 1e-9 * length(a) * length(b) || dot(a, b) < 0) kept.push_back(p);
    }
    path.points = std::move(kept);
}

}  // namespace

SweepPath sweepPathThrough(const std::vector<Vec2d> &points, double baseHeight, bool closed, OutwardSide outward) {
    SweepPath path;
    path.baseHeight = baseHeight;
    path.closed = closed;
    path.outward = outward;
    for (Vec2d p : points)
        if (path.points.empty() || length(p - path.points.back()) > kSamePoint) path.points.push_back(p);
    if (closed && path.points.size() > 1 && length(path.points.front() - path.points.back()) <= kSamePoint)
        path.points.pop_back();
    if (path.points.size() > 2) keepTurns(path);
    return path;
}

CorniceRun buildCorniceRun(const CorniceDescription &cornice, const SweepPath &path, double bandHeight,
                           MaterialId material) {
    CorniceRun run;
    ProfileOutline traced = traceProfile(cornice.profile, kArcStepDegrees);
    double scale = heightScale(cornice.profile, traced, bandHeight);
    ProfileOutline outline = scaledOutline(traced, scale);
    SweptCornice swept = sweepCornice(cornice, outline, path, {!path.closed, 1});
    run.mesh = std::move(swept.mesh);
    run.mesh.setMaterial(material);
    for (const Console &console : cornice.consoles) {
        ConsoleSet set{console.objectFile, console.loc, material, placeConsoles(path, console, outline, scale)};
        if (!set.transforms.empty()) run.consoles.push_back(std::move(set));
    }
    return run;
}

}  // namespace veduta

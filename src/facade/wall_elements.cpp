#include "facade/wall_elements.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace veduta {

namespace {

constexpr double kSamePoint = 1e-9;      // metres: the joint of two features
constexpr double kSameHeight = 1e-9;     // metres: partitions that form one band
constexpr double kStraightTurn = 1e-12;  // |sin| of the turn below which a joint is straight
// A ZWE is a pier or pilaster: narrower than 1 cm it is no element one could build, and tiny
// widths would ask for billions of elements.
constexpr double kNarrowestInterWall = 0.01;       // metres
constexpr double kMostWallsPerBaseWall = 10000.0;  // a 100 m base wall of 1 cm walls and ZWE

bool isFinite(Vec2d p) { return std::isfinite(p.x) && std::isfinite(p.y); }

void checkSubdivision(const WallSubdivision &s) {
    if (!(std::isfinite(s.cornerWidth) && std::isfinite(s.interWallWidth) && std::isfinite(s.wallToInterWallRatio))) {
        throw std::invalid_argument("corner width, ZWE width and wall-to-ZWE ratio must be finite");
    }
    if (s.cornerWidth < 0 || s.interWallWidth < 0 || s.wallToInterWallRatio < 0) {
        throw std::invalid_argument("corner width, ZWE width and wall-to-ZWE ratio must not be negative");
    }
    if (s.interWallWidth > 0 && s.interWallWidth < kNarrowestInterWall) {
        throw std::invalid_argument(
            fmt::format("ZWE width {} m is below the narrowest, {} m", s.interWallWidth, kNarrowestInterWall));
    }
}

std::vector<BaseWall> baseWallsOf(const std::vector<std::vector<Vec2d>> &features, bool closed) {
    std::vector<BaseWall> walls;
    for (size_t f = 0; f < features.size(); ++f) {
        const std::vector<Vec2d> &points = features[f];
        if (points.size() < 2) throw std::invalid_argument(fmt::format("feature {} has fewer than two points", f));
        if (!std::all_of(points.begin(), points.end(), isFinite)) {
            throw std::invalid_argument(fmt::format("feature {} has a point that is not finite", f));
        }
        if (f > 0 && length(points.front() - features[f - 1].back()) > kSamePoint) {
            throw std::invalid_argument(fmt::format("feature {} does not start where feature {} ends", f, f - 1));
        }
        for (size_t i = 0; i + 1 < points.size(); ++i) walls.push_back({points[i], points[i + 1], f});
    }
    if (closed && !walls.empty() && length(walls.back().end - walls.front().start) > kSamePoint) {
        walls.push_back({walls.back().end, walls.front().start, features.size() - 1});
    }
    for (size_t w = 0; w < walls.size(); ++w) {
        if (walls[w].length() <= kSamePoint) throw std::invalid_argument(fmt::format("base wall {} has no length", w));
        // Finite points so far apart that the length overflows.
        if (!std::isfinite(walls[w].length())) {
            throw std::invalid_argument(fmt::format("base wall {} is too long to measure", w));
        }
    }
    return walls;
}

bool turnsLeft(const BaseWall &in, const BaseWall &out) {
    Vec2d a = in.end - in.start, b = out.end - out.start;
    return cross(a, b) > kStraightTurn * length(a) * length(b);
}

// The corners at the joints of consecutive base walls (Def 5.2): convex = a left turn on a
// counter-clockwise outline.
std::vector<HouseCorner> cornersOf(const std::vector<BaseWall> &walls, bool closed) {
    std::vector<HouseCorner> corners;
    size_t joints = closed ? walls.size() : walls.size() - 1;
    for (size_t j = 0; j < joints; ++j) {
        size_t after = (j + 1) % walls.size();
        if (turnsLeft(walls[j], walls[after])) corners.push_back({walls[j].end, j, after});
    }
    return corners;
}

// The width a corner face takes off a base wall (see the header on short walls).
double cornerFaceWidth(const BaseWall &wall, const WallSubdivision &subdivision) {
    return std::min(subdivision.cornerWidth, wall.length() / 3);
}

void appendWallsAndInterWalls(size_t wall, double from, double to, const WallSubdivision &subdivision,
                              std::vector<FacadeElement> &elements) {
    std::vector<double> widths = wallAndInterWallWidths(to - from, subdivision);
    double at = from;
    for (size_t i = 0; i < widths.size(); ++i) {
        ElementKind kind = i % 2 == 0 ? ElementKind::Wall : ElementKind::InterWall;
        double end = i + 1 == widths.size() ? to : at + widths[i];
        elements.push_back({kind, wall, at, end, 0});
        at = end;
    }
}

bool samePartition(const Partition &a, const Partition &b) {
    return std::abs(a.zFrom - b.zFrom) <= kSameHeight && std::abs(a.zTo - b.zTo) <= kSameHeight;
}

bool hasPartition(const std::vector<Partition> &list, const Partition &p) {
    return std::any_of(list.begin(), list.end(), [&](const Partition &q) { return samePartition(p, q); });
}

}  // namespace

std::vector<double> wallAndInterWallWidths(double length, const WallSubdivision &subdivision) {
    checkSubdivision(subdivision);
    if (!(length >= 0 && std::isfinite(length))) {
        throw std::invalid_argument(fmt::format("free length {} m must be finite and not negative", length));
    }
    double z = subdivision.interWallWidth;
    double w = subdivision.wallToInterWallRatio * z;
    if (z <= 0 || w <= 0) return {length};
    double count = std::round((length + z) / (w + z));
    if (!(count <= kMostWallsPerBaseWall)) {
        throw std::invalid_argument(fmt::format("ZWE width {} m and ratio {} ask {} walls on {} m, more than {}", z,
                                                subdivision.wallToInterWallRatio, count, length,
                                                kMostWallsPerBaseWall));
    }
    auto walls = static_cast<size_t>(std::max(1.0, count));
    // ZWE must leave the walls some width: fewer walls when they would not.
    while (walls > 1 && double(walls - 1) * z >= length) --walls;
    double wallWidth = (length - double(walls - 1) * z) / double(walls);
    std::vector<double> widths;
    for (size_t i = 0; i < walls; ++i) {
        if (i > 0) widths.push_back(z);
        widths.push_back(wallWidth);
    }
    return widths;
}

StoreyFacade subdivideStorey(const std::vector<std::vector<Vec2d>> &features, bool closed,
                             const WallSubdivision &subdivision) {
    return subdivideStorey(features, closed, std::vector<WallSubdivision>(features.size(), subdivision));
}

StoreyFacade subdivideStorey(const std::vector<std::vector<Vec2d>> &features, bool closed,
                             const std::vector<WallSubdivision> &subdivisions) {
    for (const WallSubdivision &subdivision : subdivisions) checkSubdivision(subdivision);
    if (features.empty()) throw std::invalid_argument("a storey outline needs at least one feature");
    if (subdivisions.size() != features.size())
        throw std::invalid_argument("a storey outline needs one subdivision per feature");
    StoreyFacade facade;
    facade.closed = closed;
    facade.baseWalls = baseWallsOf(features, closed);
    facade.corners = cornersOf(facade.baseWalls, closed);

    size_t wallCount = facade.baseWalls.size();
    std::vector<const HouseCorner *> cornerAtStart(wallCount, nullptr), cornerAtEnd(wallCount, nullptr);
    for (const HouseCorner &c : facade.corners) {
        cornerAtEnd[c.before] = &c;
        cornerAtStart[c.after] = &c;
    }
    for (size_t w = 0; w < wallCount; ++w) {
        const BaseWall &wall = facade.baseWalls[w];
        const WallSubdivision &subdivision = subdivisions[wall.feature];
        double face = cornerFaceWidth(wall, subdivision);
        double from = 0, to = wall.length();
        if (cornerAtStart[w] && face > 0) {
            facade.elements.push_back(
                {ElementKind::CornerFace, w, 0, face, size_t(cornerAtStart[w] - facade.corners.data())});
            from = face;
        }
        if (cornerAtEnd[w] && face > 0) to -= face;
        appendWallsAndInterWalls(w, from, to, subdivision, facade.elements);
        if (cornerAtEnd[w] && face > 0) {
            facade.elements.push_back(
                {ElementKind::CornerFace, w, to, wall.length(), size_t(cornerAtEnd[w] - facade.corners.data())});
        }
    }
    return facade;
}

std::vector<Partition> partitionHeights(double height, const std::vector<double> &cuts) {
    if (!(height > 0 && std::isfinite(height))) {
        throw std::invalid_argument(fmt::format("partition height {} m must be positive and finite", height));
    }
    if (cuts.size() < 2 || cuts.front() != 0 || cuts.back() != 1) {
        throw std::invalid_argument("partition cuts must run from 0 to 1");
    }
    std::vector<Partition> partitions;
    for (size_t i = 0; i + 1 < cuts.size(); ++i) {
        if (!(cuts[i] < cuts[i + 1])) throw std::invalid_argument(fmt::format("partition cut {} does not rise", i + 1));
        partitions.push_back({height * cuts[i], height * cuts[i + 1]});
    }
    return partitions;
}

std::vector<BandRun> findBands(const StoreyFacade &facade, const std::vector<std::vector<Partition>> &partitions) {
    size_t n = facade.elements.size();
    if (partitions.size() != n) throw std::invalid_argument("one partition list per facade element is needed");
    std::vector<BandRun> runs;
    for (size_t e = 0; e < n; ++e) {
        for (const Partition &p : partitions[e]) {
            size_t previous = (e + n - 1) % n;
            bool continuesOne = (e > 0 || facade.closed) && hasPartition(partitions[previous], p);
            size_t count = 1;
            while (count < n && (e + count < n || facade.closed) && hasPartition(partitions[(e + count) % n], p)) {
                ++count;
            }
            if (count == n && facade.closed) {
                // A ring: report it once, from element 0.
                if (e == 0) runs.push_back({0, n, p.zFrom, p.zTo, true});
            } else if (!continuesOne) {
                runs.push_back({e, count, p.zFrom, p.zTo, false});
            }
        }
    }
    return runs;
}

}  // namespace veduta

#include "facade/ornament_growth.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <fmt/format.h>

#include "core/check.h"
#include "core/polygon_area.h"

namespace veduta {
namespace {

constexpr double kPiD = 3.14159265358979323846;

// Motif sizes in cells (see the header: the raster's resolution sets the ornament's scale).
constexpr double kRootTube = 0.5;  // the root stem's tube radius
constexpr double kRootBoss = 1.5;  // the radius of the boss a point root springs from
constexpr double kRootBossHeight = 0.5;
constexpr double kStemTubeMin = 0.3;     // stems taper to this radius and no further
constexpr double kStemTubeShare = 0.12;  // a stem's radius at most this share of its circle's
constexpr double kStemTaper = 0.85;      // a stem at most this share of its parent's radius
constexpr double kLeafHeight = 0.3;
constexpr double kMidribTube = 0.35;  // above the leaf's plateau, so that the rib shows
constexpr double kTendrilTube = 0.3;
constexpr double kStemCircle = 6;  // free circles at least this large get a stem
constexpr double kLeafCircle = 3;  // ... this large a leaf; smaller ones a tendril

constexpr int kBezierSamples = 16;  // per segment
constexpr int kCircleSamples = 48;
constexpr double kArcStep = kPiD / 32;

Vec2d perp(Vec2d v) { return {-v.y, v.x}; }
Vec2d unit(Vec2d v) { return v * (1 / length(v)); }
double angleOf(Vec2d v) { return std::atan2(v.y, v.x); }

int64_t floorDiv(int64_t a, int64_t b) { return a / b - ((a % b != 0) && ((a < 0) != (b < 0))); }

Vec2d nearestOnSegment(Vec2d p, Vec2d a, Vec2d b) {
    Vec2d ab = b - a;
    double lengthSquared = dot(ab, ab);
    double t = lengthSquared > 0 ? std::clamp(dot(p - a, ab) / lengthSquared, 0.0, 1.0) : 0.0;
    return a + ab * t;
}

double pointSegmentDistance(Vec2d p, Vec2d a, Vec2d b) { return length(p - nearestOnSegment(p, a, b)); }

double squaredLength(Vec2d v) { return dot(v, v); }

double pointBoxSquaredDistance(Vec2d p, Vec2d low, Vec2d high) {
    double dx = std::max({low.x - p.x, 0.0, p.x - high.x});
    double dy = std::max({low.y - p.y, 0.0, p.y - high.y});
    return dx * dx + dy * dy;
}

// Whether segment a–b meets the closed box (Liang–Barsky clipping).
bool segmentMeetsBox(Vec2d a, Vec2d b, Vec2d low, Vec2d high) {
    double t0 = 0, t1 = 1;
    Vec2d d = b - a;
    const double p[4] = {-d.x, d.x, -d.y, d.y};
    const double q[4] = {a.x - low.x, high.x - a.x, a.y - low.y, high.y - a.y};
    for (int i = 0; i < 4; ++i) {
        if (p[i] == 0) {
            if (q[i] < 0) return false;
        } else {
            double t = q[i] / p[i];
            if (p[i] < 0) t0 = std::max(t0, t);
            else t1 = std::min(t1, t);
        }
    }
    return t0 <= t1;
}

// The squared distance between segment a–b and the closed box: between two disjoint convex sets
// it is reached at a vertex of one of them.
double segmentBoxSquaredDistance(Vec2d a, Vec2d b, Vec2d low, Vec2d high) {
    if (segmentMeetsBox(a, b, low, high)) return 0;
    double best = std::min(pointBoxSquaredDistance(a, low, high), pointBoxSquaredDistance(b, low, high));
    for (Vec2d corner : {low, Vec2d{high.x, low.y}, high, Vec2d{low.x, high.y}}) {
        best = std::min(best, squaredLength(corner - nearestOnSegment(corner, a, b)));
    }
    return best;
}

bool insideEvenOdd(Vec2d p, const std::vector<Vec2d> &ring) {
    bool inside = false;
    for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
        if ((ring[i].y > p.y) != (ring[j].y > p.y) &&
            p.x < ring[j].x + (p.y - ring[j].y) * (ring[i].x - ring[j].x) / (ring[i].y - ring[j].y)) {
            inside = !inside;
        }
    }
    return inside;
}

double distanceToRing(Vec2d p, const std::vector<Vec2d> &ring) {
    double best = std::numeric_limits<double>::infinity();
    for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
        best = std::min(best, pointSegmentDistance(p, ring[j], ring[i]));
    }
    return best;
}

Vec2d cubic(const Vec2d *p, double t) {
    double s = 1 - t;
    return p[0] * (s * s * s) + p[1] * (3 * s * s * t) + p[2] * (3 * s * t * t) + p[3] * (t * t * t);
}

// Adds the cells whose closed squares lie within `radius` of segment a–b (for radius 0: which it
// touches: the thesis's one-cell line); false when such a square lies off the raster.
bool addSegmentCells(const OrnamentRaster &raster, Vec2d a, Vec2d b, double radius, std::vector<int> &cells) {
    double cs = raster.cellSize();
    Vec2d origin = raster.origin();
    int column0 = int(std::floor((std::min(a.x, b.x) - radius - origin.x) / cs));
    int column1 = int(std::floor((std::max(a.x, b.x) + radius - origin.x) / cs));
    int row0 = int(std::floor((std::min(a.y, b.y) - radius - origin.y) / cs));
    int row1 = int(std::floor((std::max(a.y, b.y) + radius - origin.y) / cs));
    bool inside = true;
    for (int row = row0; row <= row1; ++row) {
        for (int column = column0; column <= column1; ++column) {
            Vec2d low{origin.x + column * cs, origin.y + row * cs};
            Vec2d high = low + Vec2d{cs, cs};
            bool reached = radius > 0 ? segmentBoxSquaredDistance(a, b, low, high) < radius * radius
                                      : segmentMeetsBox(a, b, low, high);
            if (!reached) continue;
            if (column < 0 || row < 0 || column >= raster.width() || row >= raster.height()) inside = false;
            else cells.push_back(row * raster.width() + column);
        }
    }
    return inside;
}

// Adds the cells a primitive's drawn footprint reaches: those its tube or outline reaches, and
// for a filled one those whose centres lie inside (a square wholly inside is reached by no edge);
// false when it reaches beyond the raster.
bool collectFootprint(const OrnamentRaster &raster, const OrnamentPrimitive &primitive, std::vector<int> &cells) {
    std::vector<Vec2d> path = primitive.path();
    bool filled = primitive.filled();
    double radius = filled ? 0 : primitive.relief;
    bool inside = true;
    if (path.size() == 1) return addSegmentCells(raster, path[0], path[0], radius, cells);
    for (size_t i = 0; i + 1 < path.size() + (filled ? 1 : 0); ++i) {
        inside = addSegmentCells(raster, path[i], path[(i + 1) % path.size()], radius, cells) && inside;
    }
    if (!filled || !inside) return inside;
    Vec2d low = path.front(), high = path.front();
    for (Vec2d p : path) {
        low = {std::min(low.x, p.x), std::min(low.y, p.y)};
        high = {std::max(high.x, p.x), std::max(high.y, p.y)};
    }
    int column0 = raster.cellAt(low) % raster.width(), row0 = raster.cellAt(low) / raster.width();
    int column1 = raster.cellAt(high) % raster.width(), row1 = raster.cellAt(high) / raster.width();
    for (int row = row0; row <= row1; ++row) {
        for (int column = column0; column <= column1; ++column) {
            int cell = row * raster.width() + column;
            if (insideEvenOdd(raster.centre(cell), path)) cells.push_back(cell);
        }
    }
    return true;
}

void sortUnique(std::vector<int> &cells) {
    std::sort(cells.begin(), cells.end());
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
}

OrnamentPrimitive makeLine(Vec2d a, Vec2d b, double relief) { return {PrimitiveType::Line, {a, b}, 0, 0, 0, relief}; }

OrnamentPrimitive makeArc(Vec2d centre, double radius, double startAngle, double sweep, double relief) {
    return {PrimitiveType::Arc, {centre}, radius, startAngle, startAngle + sweep, relief};
}

OrnamentPrimitive makeBezier(std::vector<Vec2d> points, double relief) {
    return {PrimitiveType::Bezier, std::move(points), 0, 0, 0, relief};
}

}  // namespace

// ---- the raster ------------------------------------------------------------------------------

OrnamentRaster::OrnamentRaster(int width, int height, double cellSize, Vec2d origin, std::vector<OrnamentCell> cells) :
    width_(width), height_(height), cellSize_(cellSize), origin_(origin), states_(std::move(cells)) {
    VEDUTA_CHECK(width > 0 && height > 0 && int64_t(width) * height <= kOrnamentCellLimit,
                 fmt::format("an ornament raster of {} × {} cells", width, height));
    VEDUTA_CHECK(std::isfinite(cellSize) && cellSize > 0, fmt::format("an ornament cell size of {}", cellSize));
    VEDUTA_CHECK(states_.size() == size_t(width) * size_t(height),
                 fmt::format("{} cells for a {} × {} ornament raster", states_.size(), width, height));
    VEDUTA_CHECK(
        std::none_of(states_.begin(), states_.end(), [](OrnamentCell c) { return c == OrnamentCell::Occupied; }),
        "a new ornament raster has occupied cells without elements");
    owners_.assign(states_.size(), -1);
    distances_ = squaredDistanceTransform(*this);
    listedRadius_.assign(states_.size(), -1);
    stamps_.assign(states_.size(), 0);
    for (int cell = 0; cell < cellCount(); ++cell) refreshMedialAxis(cell);
}

OrnamentRaster OrnamentRaster::fromRegion(const std::vector<Vec2d> &outline,
                                          const std::vector<std::vector<Vec2d>> &holes, double cellSize) {
    VEDUTA_CHECK(std::isfinite(cellSize) && cellSize > 0, fmt::format("an ornament cell size of {}", cellSize));
    VEDUTA_CHECK(outline.size() >= 3 && signedArea(outline) > 0,
                 "an ornament region's outline is not a counter-clockwise polygon");
    std::vector<const std::vector<Vec2d> *> rings{&outline};
    for (const std::vector<Vec2d> &hole : holes) {
        VEDUTA_CHECK(hole.size() >= 3, "an ornament region's hole has fewer than 3 points");
        rings.push_back(&hole);
    }
    Vec2d low = outline.front(), high = outline.front();
    for (const std::vector<Vec2d> *ring : rings) {
        for (Vec2d p : *ring) {
            VEDUTA_CHECK(std::isfinite(p.x) && std::isfinite(p.y), "an ornament region is not finite");
            low = {std::min(low.x, p.x), std::min(low.y, p.y)};
            high = {std::max(high.x, p.x), std::max(high.y, p.y)};
        }
    }
    // Less a hair, so that a side of exactly n cells gives n and not n + 1 by rounding.
    double columns = std::max(1.0, std::ceil((high.x - low.x) / cellSize - 1e-9));
    double rows = std::max(1.0, std::ceil((high.y - low.y) / cellSize - 1e-9));
    VEDUTA_CHECK(columns * rows <= kOrnamentCellLimit,
                 fmt::format("an ornament region of {} × {} cells exceeds the limit", columns, rows));
    int width = int(columns), height = int(rows);
    std::vector<OrnamentCell> cells(size_t(width) * size_t(height), OrnamentCell::Forbidden);
    std::vector<double> crossings;
    for (int row = 0; row < height; ++row) {
        // Even-odd scanline through the cell centres of this row, over all rings at once.
        double y = low.y + (row + 0.5) * cellSize;
        crossings.clear();
        for (const std::vector<Vec2d> *ring : rings) {
            for (size_t i = 0, j = ring->size() - 1; i < ring->size(); j = i++) {
                Vec2d a = (*ring)[j], b = (*ring)[i];
                if ((a.y > y) != (b.y > y)) crossings.push_back(a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y));
            }
        }
        std::sort(crossings.begin(), crossings.end());
        for (size_t k = 0; k + 1 < crossings.size(); k += 2) {
            for (int column = std::max(0, int(std::floor((crossings[k] - low.x) / cellSize - 0.5))); column < width;
                 ++column) {
                double x = low.x + (column + 0.5) * cellSize;
                if (x >= crossings[k + 1]) break;
                if (x > crossings[k]) cells[size_t(row) * size_t(width) + size_t(column)] = OrnamentCell::Free;
            }
        }
    }
    return OrnamentRaster(width, height, cellSize, low, std::move(cells));
}

int OrnamentRaster::cellAt(Vec2d p) const {
    double column = std::floor((p.x - origin_.x) / cellSize_), row = std::floor((p.y - origin_.y) / cellSize_);
    if (!(column >= 0 && row >= 0 && column < width_ && row < height_)) return -1;
    return int(row) * width_ + int(column);
}

Vec2d OrnamentRaster::centre(int cell) const {
    return origin_ + Vec2d{(cell % width_ + 0.5) * cellSize_, (cell / width_ + 0.5) * cellSize_};
}

std::vector<MedialAxisEntry> OrnamentRaster::medialAxis(int32_t minSquaredRadius) const {
    std::vector<MedialAxisEntry> entries;
    for (const MedialAxisEntry &entry : medialAxis_) {
        if (entry.squaredRadius < minSquaredRadius) break;
        entries.push_back(entry);
    }
    return entries;
}

void OrnamentRaster::occupy(const std::vector<int> &cells, int owner) {
    VEDUTA_CHECK(owner >= 0, "an ornament cell occupied by no element");
    for (int cell : cells) {
        VEDUTA_CHECK(cell >= 0 && cell < cellCount() && states_[cell] == OrnamentCell::Free,
                     fmt::format("ornament element {} claims cell {}, which is not free", owner, cell));
        states_[cell] = OrnamentCell::Occupied;
        owners_[cell] = owner;
    }
    std::vector<int> changed;
    for (int cell : cells) lowerDistancesAround(cell, changed);
    // A cell's medial-axis membership depends on its own and its neighbours' distances; each
    // affected cell once (marked with this update's stamp).
    ++stamp_;
    for (int cell : changed) {
        int column = cell % width_, row = cell / width_;
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                int x = column + dx, y = row + dy;
                if (x < 0 || y < 0 || x >= width_ || y >= height_ || stamps_[y * width_ + x] == stamp_) continue;
                stamps_[y * width_ + x] = stamp_;
                refreshMedialAxis(y * width_ + x);
            }
        }
    }
}

// L1258: lowers the distances that the new non-free cell `site` beats, ring by ring around it. A
// cell p beyond ring k can be nearer to the site than to its old obstacles only if the segment
// site–p crosses ring k at a point q with d(q) > |q − site|, so (d is 1-Lipschitz) only if a
// grid cell q' of ring k, at most ½ from q along the ring, has d(q') > |q' − site| − 1.
void OrnamentRaster::lowerDistancesAround(int site, std::vector<int> &changed) {
    distances_[site] = 0;
    changed.push_back(site);
    int siteColumn = site % width_, siteRow = site / width_;
    for (int k = 1;; ++k) {
        bool onRaster = false, goOn = false;
        auto visit = [&](int dx, int dy) {
            int x = siteColumn + dx, y = siteRow + dy;
            if (x < 0 || y < 0 || x >= width_ || y >= height_) return;
            onRaster = true;
            int cell = y * width_ + x;
            int32_t squared = dx * dx + dy * dy;
            int32_t old = distances_[cell];
            // (√old + 1)² ≤ 2 · old + 2, so only squares below that need the roots.
            if (!goOn && squared < 2 * old + 2) goOn = std::sqrt(double(old)) + 1 + 1e-9 > std::sqrt(double(squared));
            if (squared < old) {
                distances_[cell] = squared;
                changed.push_back(cell);
            }
        };
        for (int d = -k; d <= k; ++d) {
            visit(d, -k);
            visit(d, k);
        }
        for (int d = -k + 1; d <= k - 1; ++d) {
            visit(-k, d);
            visit(k, d);
        }
        if (!onRaster || !goOn) break;
    }
}

bool OrnamentRaster::isLocalMaximum(int cell) const {
    if (states_[cell] != OrnamentCell::Free) return false;
    int column = cell % width_, row = cell / width_;
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            int x = column + dx, y = row + dy;
            if (x >= 0 && y >= 0 && x < width_ && y < height_ && distances_[y * width_ + x] > distances_[cell]) {
                return false;
            }
        }
    }
    return true;
}

void OrnamentRaster::refreshMedialAxis(int cell) {
    if (listedRadius_[cell] >= 0) medialAxis_.erase({cell, listedRadius_[cell]});
    listedRadius_[cell] = -1;
    if (!isLocalMaximum(cell)) return;
    medialAxis_.insert({cell, distances_[cell]});
    listedRadius_[cell] = distances_[cell];
}

// Meijster, Roerdink and Hesselink (2000): columns first, then the lower envelope of parabolas
// along each row, in integers throughout. The raster is framed by non-free cells on all sides.
std::vector<int32_t> squaredDistanceTransform(const OrnamentRaster &raster) {
    int width = raster.width(), height = raster.height();
    std::vector<int64_t> columnDistance(size_t(width) * size_t(height));
    for (int x = 0; x < width; ++x) {
        int64_t run = 0;  // the frame row below
        for (int y = 0; y < height; ++y) {
            run = raster.state(y * width + x) == OrnamentCell::Free ? run + 1 : 0;
            columnDistance[size_t(y) * size_t(width) + size_t(x)] = run;
        }
        run = 0;  // the frame row above
        for (int y = height - 1; y >= 0; --y) {
            int64_t &g = columnDistance[size_t(y) * size_t(width) + size_t(x)];
            run = g == 0 ? 0 : run + 1;
            g = std::min(g, run);
        }
    }
    std::vector<int32_t> distances(size_t(width) * size_t(height));
    int m = width + 2;  // the row with the frame's cells at both ends
    std::vector<int64_t> g(m);
    std::vector<int> s(m), t(m);
    for (int y = 0; y < height; ++y) {
        g[0] = g[m - 1] = 0;
        for (int x = 0; x < width; ++x) g[x + 1] = columnDistance[size_t(y) * size_t(width) + size_t(x)];
        auto f = [&](int64_t x, int i) { return (x - i) * (x - i) + g[i] * g[i]; };
        auto sep = [&](int64_t i, int64_t u) {
            return floorDiv(u * u - i * i + g[u] * g[u] - g[i] * g[i], 2 * (u - i));
        };
        int q = 0;
        s[0] = t[0] = 0;
        for (int u = 1; u < m; ++u) {
            while (q >= 0 && f(t[q], s[q]) > f(t[q], u)) --q;
            if (q < 0) {
                q = 0;
                s[0] = u;
            } else {
                int64_t w = 1 + sep(s[q], u);
                if (w < m) {
                    ++q;
                    s[q] = u;
                    t[q] = int(w);
                }
            }
        }
        for (int u = m - 1; u >= 0; --u) {
            if (u >= 1 && u <= width) distances[size_t(y) * size_t(width) + size_t(u - 1)] = int32_t(f(u, s[q]));
            if (u == t[q]) --q;
        }
    }
    return distances;
}

// ---- primitives ------------------------------------------------------------------------------

bool OrnamentPrimitive::filled() const {
    return type == PrimitiveType::Circle || (type == PrimitiveType::Bezier && points.front() == points.back());
}

int OrnamentPrimitive::parameterCount() const {
    switch (type) {
    case PrimitiveType::Point: return 2;
    case PrimitiveType::Line: return 4;
    case PrimitiveType::Arc: return 5;
    case PrimitiveType::Circle: return 3;
    case PrimitiveType::Bezier: return 2 * int(points.size());
    }
    VEDUTA_UNREACHABLE("an ornament primitive of unknown type");
}

std::vector<Vec2d> OrnamentPrimitive::path() const {
    switch (type) {
    case PrimitiveType::Point:
    case PrimitiveType::Line: return points;
    case PrimitiveType::Arc: {
        int steps = std::max(2, int(std::ceil(std::abs(endAngle - startAngle) / kArcStep)));
        std::vector<Vec2d> samples;
        for (int i = 0; i <= steps; ++i) {
            double angle = startAngle + (endAngle - startAngle) * i / steps;
            samples.push_back(points.front() + Vec2d{std::cos(angle), std::sin(angle)} * radius);
        }
        return samples;
    }
    case PrimitiveType::Circle: {
        std::vector<Vec2d> samples;
        for (int i = 0; i < kCircleSamples; ++i) {
            double angle = 2 * kPiD * i / kCircleSamples;
            samples.push_back(points.front() + Vec2d{std::cos(angle), std::sin(angle)} * radius);
        }
        return samples;
    }
    case PrimitiveType::Bezier: {
        VEDUTA_CHECK(points.size() >= 4 && (points.size() - 1) % 3 == 0,
                     fmt::format("a Bézier chain of {} control points", points.size()));
        std::vector<Vec2d> samples{points.front()};
        for (size_t segment = 0; segment + 3 < points.size(); segment += 3) {
            for (int i = 1; i <= kBezierSamples; ++i)
                samples.push_back(cubic(&points[segment], double(i) / kBezierSamples));
        }
        if (filled()) samples.pop_back();  // the closing point repeats the first
        return samples;
    }
    }
    VEDUTA_UNREACHABLE("an ornament primitive of unknown type");
}

std::vector<int> footprintCells(const OrnamentRaster &raster, const OrnamentPrimitive &primitive) {
    std::vector<int> cells;
    collectFootprint(raster, primitive, cells);
    sortUnique(cells);
    return cells;
}

// ---- drawing ---------------------------------------------------------------------------------

HeightCanvas::HeightCanvas(Vec2d origin, double extentX, double extentY, double cellSize) :
    origin_(origin), cellSize_(cellSize) {
    VEDUTA_CHECK(std::isfinite(cellSize) && cellSize > 0, fmt::format("a height-map cell size of {}", cellSize));
    double columns = std::max(1.0, std::ceil(extentX / cellSize - 1e-9));
    double rows = std::max(1.0, std::ceil(extentY / cellSize - 1e-9));
    VEDUTA_CHECK(columns * rows <= 16.0 * kOrnamentCellLimit,
                 fmt::format("a height map of {} × {} pixels exceeds the limit", columns, rows));
    image_ = Image(int(columns), int(rows), 1);
}

// Pixel rows run top first; the bottom row's bottom edge lies on the origin.
Vec2d HeightCanvas::pixelCentre(int x, int y) const {
    return origin_ + Vec2d{(x + 0.5) * cellSize_, (image_.height - 1 - y + 0.5) * cellSize_};
}

void HeightCanvas::raisePrimitive(const OrnamentPrimitive &primitive) {
    if (primitive.filled()) raiseFilled(primitive.path(), primitive.relief);
    else raiseTube(primitive.path(), primitive.relief);
}

// A half-round tube: height √(r² − d²) at distance d from the path.
void HeightCanvas::raiseTube(const std::vector<Vec2d> &path, double radius) {
    size_t segments = path.size() == 1 ? 1 : path.size() - 1;
    for (size_t i = 0; i < segments; ++i) {
        Vec2d a = path[i], b = path[std::min(i + 1, path.size() - 1)];
        int x0 = std::max(0, int(std::floor((std::min(a.x, b.x) - radius - origin_.x) / cellSize_)));
        int x1 = std::min(image_.width - 1, int(std::floor((std::max(a.x, b.x) + radius - origin_.x) / cellSize_)));
        int bottom0 = std::max(0, int(std::floor((std::min(a.y, b.y) - radius - origin_.y) / cellSize_)));
        int bottom1 =
            std::min(image_.height - 1, int(std::floor((std::max(a.y, b.y) + radius - origin_.y) / cellSize_)));
        for (int bottom = bottom0; bottom <= bottom1; ++bottom) {
            int y = image_.height - 1 - bottom;
            for (int x = x0; x <= x1; ++x) {
                Vec2d q = pixelCentre(x, y);
                double squared = squaredLength(q - nearestOnSegment(q, a, b));
                if (squared >= radius * radius) continue;
                float &height = *image_.at(x, y);
                height = std::max(height, float(std::sqrt(radius * radius - squared)));
            }
        }
    }
}

// A plateau of `height` rising from the outline over a soft edge 2 · height wide.
void HeightCanvas::raiseFilled(const std::vector<Vec2d> &outline, double height) {
    Vec2d low = outline.front(), high = outline.front();
    for (Vec2d p : outline) {
        low = {std::min(low.x, p.x), std::min(low.y, p.y)};
        high = {std::max(high.x, p.x), std::max(high.y, p.y)};
    }
    double edge = 2 * height;
    int x0 = std::max(0, int(std::floor((low.x - origin_.x) / cellSize_)));
    int x1 = std::min(image_.width - 1, int(std::floor((high.x - origin_.x) / cellSize_)));
    int bottom0 = std::max(0, int(std::floor((low.y - origin_.y) / cellSize_)));
    int bottom1 = std::min(image_.height - 1, int(std::floor((high.y - origin_.y) / cellSize_)));
    for (int bottom = bottom0; bottom <= bottom1; ++bottom) {
        int y = image_.height - 1 - bottom;
        for (int x = x0; x <= x1; ++x) {
            Vec2d p = pixelCentre(x, y);
            if (!insideEvenOdd(p, outline)) continue;
            double t = std::min(1.0, distanceToRing(p, outline) / edge);
            float &value = *image_.at(x, y);
            value = std::max(value, float(height * t * t * (3 - 2 * t)));
        }
    }
}

// ---- elements --------------------------------------------------------------------------------

OrnamentElement::OrnamentElement(OrnamentKind kind, std::vector<OrnamentPrimitive> primitives, int parent, int side) :
    kind_(kind), primitives_(std::move(primitives)), parent_(parent), side_(side) {}

OrnamentElement OrnamentElement::rootAlong(const OrnamentRaster &raster, Vec2d a, Vec2d b) {
    OrnamentElement root(OrnamentKind::Root, {makeLine(a, b, kRootTube * raster.cellSize())}, -1, 1);
    VEDUTA_CHECK(root.claimCells(raster), "an ornament root along a baseline leaves the free cells");
    return root;
}

OrnamentElement OrnamentElement::rootAt(const OrnamentRaster &raster, Vec2d point) {
    double cs = raster.cellSize();
    OrnamentPrimitive boss{PrimitiveType::Circle, {point}, kRootBoss * cs, 0, 0, kRootBossHeight * cs};
    OrnamentElement root(OrnamentKind::Root, {boss}, -1, 1);
    VEDUTA_CHECK(root.claimCells(raster), "an ornament root at a point leaves the free cells");
    return root;
}

// The cells of all primitives except the parent's, which must all be free; at least one.
bool OrnamentElement::claimCells(const OrnamentRaster &raster) {
    cells_.clear();
    for (const OrnamentPrimitive &primitive : primitives_) {
        if (!collectFootprint(raster, primitive, cells_)) return false;
    }
    sortUnique(cells_);
    std::erase_if(cells_, [&](int cell) { return parent_ >= 0 && raster.owner(cell) == parent_; });
    return !cells_.empty() &&
        std::all_of(cells_.begin(), cells_.end(), [&](int cell) { return raster.state(cell) == OrnamentCell::Free; });
}

// Where a child grows from toward `target`: the nearest point of the spine, with the spine's
// direction there turned toward the target (a boss: halfway out toward it).
void OrnamentElement::attachment(Vec2d target, Vec2d &point, Vec2d &tangent) const {
    const OrnamentPrimitive &spine = primitives_.front();
    if (spine.type == PrimitiveType::Circle) {
        tangent = unit(target - spine.points.front());
        point = spine.points.front() + tangent * (0.5 * spine.radius);
        return;
    }
    std::vector<Vec2d> path = spine.path();
    point = path.front();
    tangent = target - point;
    double best = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i + 1 < path.size(); ++i) {
        Vec2d ab = path[i + 1] - path[i];
        double lengthSquared = dot(ab, ab);
        if (lengthSquared == 0) continue;
        Vec2d nearest = path[i] + ab * std::clamp(dot(target - path[i], ab) / lengthSquared, 0.0, 1.0);
        if (length(target - nearest) < best) {
            best = length(target - nearest);
            point = nearest;
            tangent = ab;
        }
    }
    if (dot(tangent, target - point) < 0) tangent = tangent * -1;
    tangent = unit(tangent);
}

GrowthResult OrnamentElement::grow(const OrnamentRaster &raster, const FreeCircle &circle, int self) const {
    double radius = circle.radius / raster.cellSize();
    if (kind_ == OrnamentKind::Leaf || kind_ == OrnamentKind::Tendril) return {};
    if (radius >= kStemCircle) return growStem(raster, circle, self);
    if (radius >= kLeafCircle) return growLeaf(raster, circle, self);
    if (kind_ == OrnamentKind::Stem) return growTendril(raster, circle, self);
    return {};
}

// A stem: a cubic Bézier from the spine to the circle's centre, arriving across its line of
// approach and curling into a hook there (a half turn of radius 0.3 R); alternately to one side
// and the other of its parent's, and as a plain arc where neither hook fits.
GrowthResult OrnamentElement::growStem(const OrnamentRaster &raster, const FreeCircle &circle, int self) const {
    Vec2d p, tangent, c = circle.centre;
    attachment(c, p, tangent);
    double distance = length(c - p);
    Vec2d u = (c - p) * (1 / distance), n = perp(u);
    double tube =
        std::max(kStemTubeMin * raster.cellSize(), std::min(kStemTaper * tubeRadius(), kStemTubeShare * circle.radius));
    double hook = 0.3 * circle.radius;
    for (int variant = 0; variant < 3; ++variant) {
        int side = variant == 1 ? side_ : -side_;
        Vec2d across = n * double(side);
        std::vector<Vec2d> points{p, p + tangent * (distance / 3)};
        if (variant < 2) {
            points.insert(points.end(),
                          {c - across * (distance / 3), c, c + across * (4 * hook / 3),
                           c + u * (2 * hook) + across * (4 * hook / 3), c + u * (2 * hook)});
        } else {
            points.insert(points.end(), {c - u * (distance / 3), c});
        }
        OrnamentElement stem(OrnamentKind::Stem, {makeBezier(std::move(points), tube)}, self, side);
        if (stem.claimCells(raster)) return {true, {std::move(stem)}};
    }
    return {};
}

// A leaf: a closed chain of two cubic Béziers from the spine through the circle to 0.7 R beyond
// its centre, widest (half-width w) about two thirds along, with a raised midrib; w = 0.5 R, or a
// slimmer 0.3 R where that does not fit.
GrowthResult OrnamentElement::growLeaf(const OrnamentRaster &raster, const FreeCircle &circle, int self) const {
    Vec2d p, tangent, c = circle.centre;
    attachment(c, p, tangent);
    double span = length(c - p) + 0.7 * circle.radius;
    Vec2d u = unit(c - p), n = perp(u);
    for (double width : {0.5 * circle.radius, 0.3 * circle.radius}) {
        Vec2d bulge = n * (4 * width / 3);  // a cubic's control offset k bulges 0.75 k
        std::vector<Vec2d> outline{p,
                                   p + u * (0.5 * span) + bulge,
                                   p + u * (0.9 * span) + bulge,
                                   p + u * span,
                                   p + u * (0.9 * span) - bulge,
                                   p + u * (0.5 * span) - bulge,
                                   p};
        double cs = raster.cellSize();
        OrnamentElement leaf(
            OrnamentKind::Leaf,
            {makeBezier(std::move(outline), kLeafHeight * cs), makeLine(p, p + u * (0.9 * span), kMidribTube * cs)},
            self, side_);
        if (leaf.claimCells(raster)) return {true, {std::move(leaf)}};
    }
    return {};
}

// A tendril: a stalk to 0.6 R before the circle's centre, then a spiral of three half turns of
// shrinking radius (ρ, 2ρ/3, ρ/3) about two centres ρ/3 apart; either way round.
GrowthResult OrnamentElement::growTendril(const OrnamentRaster &raster, const FreeCircle &circle, int self) const {
    Vec2d p, tangent, c = circle.centre;
    attachment(c, p, tangent);
    Vec2d u = unit(c - p);
    double rho = 0.6 * circle.radius, step = rho / 3, tube = kTendrilTube * raster.cellSize();
    double back = angleOf(u * -1), ahead = angleOf(u);
    for (int side : {side_, -side_}) {
        double sweep = side * kPiD;
        OrnamentElement tendril(
            OrnamentKind::Tendril,
            {makeLine(p, c - u * rho, tube), makeArc(c, rho, back, sweep, tube),
             makeArc(c + u * step, rho - step, ahead, sweep, tube), makeArc(c, rho - 2 * step, back, sweep, tube)},
            self, side);
        if (tendril.claimCells(raster)) return {true, {std::move(tendril)}};
    }
    return {};
}

void OrnamentElement::draw(HeightCanvas &canvas) const {
    for (const OrnamentPrimitive &primitive : primitives_) canvas.raisePrimitive(primitive);
}

// ---- the placement loop ----------------------------------------------------------------------

OrnamentGrower::OrnamentGrower(OrnamentRaster raster, std::vector<OrnamentElement> roots, OrnamentSettings settings) :
    ornament_{std::move(raster), {}, OrnamentStop::Running}, settings_(settings) {
    VEDUTA_CHECK(!roots.empty() && roots.size() <= size_t(kOrnamentElementLimit),
                 fmt::format("an ornament with {} roots", roots.size()));
    VEDUTA_CHECK(settings.minRadius >= 1 && settings.reach >= 0 && std::isfinite(settings.minRadius + settings.reach),
                 fmt::format("ornament settings: minimum radius {}, reach {}", settings.minRadius, settings.reach));
    for (OrnamentElement &root : roots) {
        VEDUTA_CHECK(root.kind() == OrnamentKind::Root, "an ornament grows from elements that are not roots");
        place(std::move(root));
    }
}

void OrnamentGrower::place(OrnamentElement element) {
    ornament_.raster.occupy(element.cells(), int(ornament_.elements.size()));
    ornament_.elements.push_back(std::move(element));
}

bool OrnamentGrower::step() {
    if (ornament_.stop != OrnamentStop::Running) return false;
    if (ornament_.elements.size() >= size_t(kOrnamentElementLimit)) {
        ornament_.stop = OrnamentStop::ElementLimit;
        return false;
    }
    auto minSquared = int32_t(std::ceil(settings_.minRadius * settings_.minRadius));
    std::vector<MedialAxisEntry> regions = ornament_.raster.medialAxis(minSquared);
    if (regions.empty()) {
        ornament_.stop = OrnamentStop::NoFreeRegion;
        return false;
    }
    for (const MedialAxisEntry &region : regions) {
        if (growInto(region)) return true;
        if (ornament_.stop != OrnamentStop::Running) return false;
    }
    ornament_.stop = OrnamentStop::NoGrowth;
    return false;
}

// The elements within the reach of the circle, nearest first (ties: the older), from the
// element numbered `firstUntried` on: by their cells' owners around the circle for a new circle,
// by the newer elements' own cells for one tried before.
std::vector<int> OrnamentGrower::nearbyElements(const MedialAxisEntry &entry, int firstUntried) const {
    const OrnamentRaster &raster = ornament_.raster;
    double within = std::sqrt(double(entry.squaredRadius)) + settings_.reach;
    auto withinSquared = int64_t(std::floor(within * within));
    int column = entry.cell % raster.width(), row = entry.cell / raster.width();
    std::vector<std::pair<int64_t, int>> found;  // (squared distance, element)
    auto consider = [&](int cell) {
        int64_t dx = cell % raster.width() - column, dy = cell / raster.width() - row;
        if (dx * dx + dy * dy <= withinSquared) found.emplace_back(dx * dx + dy * dy, raster.owner(cell));
    };
    if (firstUntried == 0) {
        int span = int(std::floor(within));
        for (int y = std::max(0, row - span); y <= std::min(raster.height() - 1, row + span); ++y) {
            for (int x = std::max(0, column - span); x <= std::min(raster.width() - 1, column + span); ++x) {
                if (raster.owner(y * raster.width() + x) >= 0) consider(y * raster.width() + x);
            }
        }
    } else {
        for (size_t e = size_t(firstUntried); e < ornament_.elements.size(); ++e) {
            for (int cell : ornament_.elements[e].cells()) consider(cell);
        }
    }
    std::sort(found.begin(), found.end(),
              [](auto a, auto b) { return std::pair(a.second, a.first) < std::pair(b.second, b.first); });
    found.erase(std::unique(found.begin(), found.end(), [](auto a, auto b) { return a.second == b.second; }),
                found.end());
    std::sort(found.begin(), found.end());
    std::vector<int> elements;
    for (auto [squared, element] : found) elements.push_back(element);
    return elements;
}

// L1268–1272: the nearby elements in turn grow into the circle until one succeeds.
bool OrnamentGrower::growInto(const MedialAxisEntry &entry) {
    int64_t key = (int64_t(entry.cell) << 32) | entry.squaredRadius;
    auto tried = tried_.find(key);
    int firstUntried = tried == tried_.end() ? 0 : tried->second;
    int count = int(ornament_.elements.size());
    if (firstUntried == count) return false;
    const OrnamentRaster &raster = ornament_.raster;
    FreeCircle circle{raster.centre(entry.cell), std::sqrt(double(entry.squaredRadius)) * raster.cellSize()};
    for (int e : nearbyElements(entry, firstUntried)) {
        GrowthResult result = ornament_.elements[size_t(e)].grow(raster, circle, e);
        if (!result.success) continue;
        if (ornament_.elements.size() + result.elements.size() > size_t(kOrnamentElementLimit)) {
            ornament_.stop = OrnamentStop::ElementLimit;
            return false;
        }
        for (OrnamentElement &element : result.elements) place(std::move(element));
        return true;
    }
    tried_[key] = count;
    return false;
}

Ornament OrnamentGrower::finish() {
    while (step()) {}
    return std::move(ornament_);
}

Ornament growOrnament(OrnamentRaster raster, std::vector<OrnamentElement> roots, OrnamentSettings settings) {
    return OrnamentGrower(std::move(raster), std::move(roots), settings).finish();
}

Image ornamentHeightMap(const Ornament &ornament, double cellSize) {
    const OrnamentRaster &raster = ornament.raster;
    HeightCanvas canvas(raster.origin(), raster.width() * raster.cellSize(), raster.height() * raster.cellSize(),
                        cellSize);
    for (const OrnamentElement &element : ornament.elements) element.draw(canvas);
    return canvas.image();
}

}  // namespace veduta

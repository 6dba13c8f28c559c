#include "geo/tree_placement.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "core/hash.h"
#include "core/random_streams.h"
#include "geo/tree_models.h"

namespace veduta {

namespace {

// The draws a tree is made of; each is hashed on its own.
enum class Draw : uint32_t { X, Y, Kind, Variant, Height, Rotation, Width, Along };
// Which placement a candidate belongs to, so that the three never share numbers.
enum class Source : uint32_t { Area, Line, Point };

// A candidate's identity within its object: area candidates are (grid row, grid column,
// attempt), line and point candidates (index, 0, 0).
struct Candidate {
    Source source = Source::Area;
    uint32_t a = 0, b = 0, c = 0;
};

float draw(uint32_t seed, uint32_t objectId, const Candidate &cand, Draw d) {
    return bitsToUnitFloat(hashValues({seed, objectId, streamTag(RandomStream::TreePlacement), uint32_t(cand.source),
                                       cand.a, cand.b, cand.c, uint32_t(d)}));
}

// False, and the set marked, once it holds its limit.
bool hasRoom(TreeSet &set) {
    if (set.trees.size() < set.limit) return true;
    set.limitReached = true;
    return false;
}

void addTree(TreeSet &set, Vec2f position, const TreeStand &stand, uint32_t seed, uint32_t objectId,
             const Candidate &cand) {
    auto u = [&](Draw d) { return draw(seed, objectId, cand, d); };
    TreeKind kind = stand.kind;
    if (kind == TreeKind::Mixed) kind = u(Draw::Kind) < stand.conifersInMixed ? TreeKind::Conifer : TreeKind::Broadleaf;
    set.trees.push_back({.position = position,
                         .kind = kind,
                         .variant = std::min(uint32_t(u(Draw::Variant) * kTreeVariants), kTreeVariants - 1),
                         .height = stand.minHeight + u(Draw::Height) * (stand.maxHeight - stand.minHeight),
                         .rotation = 2 * kPi * u(Draw::Rotation),
                         .widthScale = 1 + stand.widthJitter * (2 * u(Draw::Width) - 1)});
}

bool finite(Vec2f p) { return std::isfinite(p.x) && std::isfinite(p.y); }

// Local coordinates (metres from the scene origin) lie well within this; beyond it the grid
// indices and tree counts would overflow, and float resolves only decimetres anyway.
constexpr float kMaxLocal = 1e6f;

void checkLocal(const std::vector<Vec2f> &points) {
    for (Vec2f p : points) {
        if (std::abs(p.x) > kMaxLocal || std::abs(p.y) > kMaxLocal) {
            throw std::invalid_argument("tree placement: a point lies more than 1000 km from the scene origin");
        }
    }
}

void checkSpacing(const TreeStand &stand) {
    if (!(stand.spacing > 0) || !std::isfinite(stand.spacing)) {
        throw std::invalid_argument("tree placement: the spacing must be a positive number of metres");
    }
}

struct Edge {
    Vec2f a, b;
    float yMin() const { return std::min(a.y, b.y); }
    float yMax() const { return std::max(a.y, b.y); }
    // The x where the edge meets height y (within its y range).
    float xAt(float y) const { return a.y == b.y ? a.x : a.x + (y - a.y) / (b.y - a.y) * (b.x - a.x); }
};

// The crossing test against the edges that span p's height (pbrt's and Haines's half-open
// rule: a vertex on the ray counts for one of its two edges).
bool inside(Vec2f p, const std::vector<Edge> &edges) {
    bool in = false;
    for (const Edge &e : edges) {
        if ((e.a.y > p.y) != (e.b.y > p.y) && p.x < e.xAt(p.y)) in = !in;
    }
    return in;
}

// One accepted sample in a grid row, with its column.
struct RowSample {
    int64_t column = 0;
    Vec2f position;
};

// Grid-accelerated dart throwing in scan order: cells of spacing/√2 hold at most one sample,
// so a sample's neighbours within the spacing lie in the 5 × 5 cells around it, and of those
// only the ones already visited (two rows below and two cells to the left) can be taken. Each
// cell tries kAttempts hashed candidates and keeps the first that is inside and far enough
// from all. Rows keep only the band of the outline that crosses them (a sweep over the edges
// sorted by their lowest y), so memory grows with the trees and one row, not the bounding box.
class AreaSampler {
  public:
    static constexpr uint32_t kAttempts = 12;

    AreaSampler(const std::vector<Vec2f> &ring, float spacing) : spacing_(spacing), cell_(spacing / std::sqrt(2.0f)) {
        for (size_t i = 0; i < ring.size(); ++i) edges_.push_back({ring[i], ring[(i + 1) % ring.size()]});
        std::sort(edges_.begin(), edges_.end(), [](const Edge &p, const Edge &q) { return p.yMin() < q.yMin(); });
    }

    void run(TreeSet &set, const TreeStand &stand, uint32_t seed, uint32_t objectId) {
        float yLow = edges_.front().yMin(), yHigh = yLow;
        for (const Edge &e : edges_) yHigh = std::max(yHigh, e.yMax());
        int64_t firstRow = cellIndex(yLow), lastRow = cellIndex(yHigh);
        size_t next = 0;
        for (int64_t row = firstRow; row <= lastRow; ++row) {
            float y0 = float(row) * cell_, y1 = y0 + cell_;
            while (next < edges_.size() && edges_[next].yMin() <= y1) active_.push_back(edges_[next++]);
            std::erase_if(active_, [&](const Edge &e) { return e.yMax() < y0; });
            rows_[slot(row)].clear();
            float xLow = 0, xHigh = 0;
            if (!bandExtent(y0, y1, xLow, xHigh)) continue;
            for (int64_t column = cellIndex(xLow); column <= cellIndex(xHigh); ++column) {
                if (!hasRoom(set)) return;
                sampleCell(set, stand, seed, objectId, row, column);
            }
        }
    }

  private:
    int64_t cellIndex(float v) const { return int64_t(std::floor(v / cell_)); }
    static size_t slot(int64_t row) { return size_t(((row % 3) + 3) % 3); }

    // The x range of the outline within the band y0..y1, from the parts of its edges there.
    bool bandExtent(float y0, float y1, float &xLow, float &xHigh) const {
        bool any = false;
        for (const Edge &e : active_) {
            float ya = std::max(y0, e.yMin()), yb = std::min(y1, e.yMax());
            if (ya > yb) continue;
            for (float x : {e.xAt(ya), e.xAt(yb)}) {
                xLow = any ? std::min(xLow, x) : x;
                xHigh = any ? std::max(xHigh, x) : x;
                any = true;
            }
        }
        return any;
    }

    void sampleCell(TreeSet &set, const TreeStand &stand, uint32_t seed, uint32_t objectId, int64_t row,
                    int64_t column) {
        gatherNeighbours(row, column);
        for (uint32_t attempt = 0; attempt < kAttempts; ++attempt) {
            Candidate cand{Source::Area, uint32_t(row), uint32_t(column), attempt};
            Vec2f p{(float(column) + draw(seed, objectId, cand, Draw::X)) * cell_,
                    (float(row) + draw(seed, objectId, cand, Draw::Y)) * cell_};
            if (!farFromNeighbours(p) || !inside(p, active_)) continue;
            rows_[slot(row)].push_back({column, p});
            addTree(set, p, stand, seed, objectId, cand);
            return;
        }
    }

    // The samples in the cells within two columns of `column` in the two rows below and to
    // the left in this row: the only ones placed yet that can be nearer than the spacing.
    void gatherNeighbours(int64_t row, int64_t column) {
        neighbours_.clear();
        for (int64_t r = row - 2; r <= row; ++r) {
            const std::vector<RowSample> &samples = rows_[slot(r)];
            auto from = std::lower_bound(samples.begin(), samples.end(), column - 2,
                                         [](const RowSample &s, int64_t c) { return s.column < c; });
            for (auto it = from; it != samples.end() && it->column <= column + 2; ++it)
                neighbours_.push_back(it->position);
        }
    }

    bool farFromNeighbours(Vec2f p) const {
        for (Vec2f q : neighbours_) {
            Vec2f d = p - q;
            if (dot(d, d) < spacing_ * spacing_) return false;
        }
        return true;
    }

    float spacing_, cell_;
    std::vector<Edge> edges_;                     // sorted by lowest y
    std::vector<Edge> active_;                    // those crossing the current row's band
    std::array<std::vector<RowSample>, 3> rows_;  // the current row and the two below, by row mod 3
    std::vector<Vec2f> neighbours_;
};

}  // namespace

TreeStand treeStand(LandClass landClass, TreeKind kind) {
    switch (landClass) {
    case LandClass::Forest: return {.kind = kind, .spacing = 5.5f, .minHeight = 12, .maxHeight = 28};
    case LandClass::Shrubs: return {.kind = kind, .spacing = 3, .minHeight = 3, .maxHeight = 9};
    case LandClass::TreeRow: return {.kind = kind, .spacing = 9, .minHeight = 10, .maxHeight = 20};
    case LandClass::Hedge:
        return {
            .kind = TreeKind::Broadleaf, .spacing = 1.5f, .minHeight = 1.5f, .maxHeight = 3.5f, .widthJitter = 0.25f};
    default: return {.kind = kind, .spacing = 0};
    }
}

void plantArea(TreeSet &set, const std::vector<Vec2f> &ring, const TreeStand &stand, uint32_t seed, uint32_t objectId) {
    checkSpacing(stand);
    if (ring.size() < 3 || !std::all_of(ring.begin(), ring.end(), finite)) return;
    checkLocal(ring);
    AreaSampler(ring, stand.spacing).run(set, stand, seed, objectId);
}

void plantLine(TreeSet &set, const std::vector<Vec2f> &line, const TreeStand &stand, uint32_t seed, uint32_t objectId) {
    checkSpacing(stand);
    if (line.empty() || !std::all_of(line.begin(), line.end(), finite)) return;
    checkLocal(line);
    std::vector<float> along{0};  // arc length at each point
    for (size_t i = 1; i < line.size(); ++i) {
        Vec2f d = line[i] - line[i - 1];
        along.push_back(along.back() + std::sqrt(dot(d, d)));
    }
    float total = along.back();
    // Whole spacings that fill the line evenly; the jitter keeps neighbours at least
    // (1 − 2·rowJitter) spacings apart.
    auto count = std::max<size_t>(1, size_t(std::lround(total / stand.spacing)));
    float step = total / float(count);
    size_t segment = 0;
    for (size_t k = 0; k < count; ++k) {
        if (!hasRoom(set)) return;
        Candidate cand{Source::Line, uint32_t(k), 0, 0};
        float t = (float(k) + 0.5f + stand.rowJitter * (2 * draw(seed, objectId, cand, Draw::Along) - 1)) * step;
        t = std::clamp(t, 0.0f, total);
        while (segment + 2 < along.size() && along[segment + 1] < t) ++segment;
        Vec2f p = line[segment];
        if (segment + 1 < line.size() && along[segment + 1] > along[segment]) {
            float f = (t - along[segment]) / (along[segment + 1] - along[segment]);
            p = line[segment] + (line[segment + 1] - line[segment]) * f;
        }
        addTree(set, p, stand, seed, objectId, cand);
    }
}

void plantPoints(TreeSet &set, const std::vector<Vec2f> &points, const TreeStand &stand, uint32_t seed,
                 uint32_t objectId) {
    for (size_t k = 0; k < points.size(); ++k) {
        if (!finite(points[k])) continue;
        if (!hasRoom(set)) return;
        addTree(set, points[k], stand, seed, objectId, {Source::Point, uint32_t(k), 0, 0});
    }
}

Transform treeTransform(const PlacedTree &tree, float groundHeight) {
    float width = tree.height * tree.widthScale;
    return Transform::translate({tree.position.x, tree.position.y, groundHeight}) *
        Transform::rotate(2, degrees(tree.rotation)) * Transform::scale({width, width, tree.height});
}

}  // namespace veduta

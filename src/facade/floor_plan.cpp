#include "facade/floor_plan.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <tuple>
#include <utility>

#include "core/check.h"

namespace veduta {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_2;
using Segment = Kernel::Segment_2;

// Tolerance for "on the line" and "straight on", relative to the plan's size.
constexpr double kRelativeEpsilon = 1e-9;

Vec2d lerp(Vec2d p, Vec2d q, double t) { return p * (1 - t) + q * t; }
Point toPoint(Vec2d p) { return {p.x, p.y}; }

Vec2d complexMul(Vec2d a, Vec2d b) { return {a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x}; }
Vec2d complexDiv(Vec2d a, Vec2d b) {
    double n = dot(b, b);
    return {(a.x * b.x + a.y * b.y) / n, (a.y * b.x - a.x * b.y) / n};
}

std::vector<Point> toPoints(const std::vector<Vec2d> &outline) {
    std::vector<Point> points;
    for (Vec2d p : outline) points.push_back(toPoint(p));
    return points;
}

bool isFiniteUnit(double t) { return std::isfinite(t) && t >= 0 && t <= 1; }

// Whether two PP edges meet anywhere but at one shared endpoint (Def 4.2: they must not).
bool ppEdgesMeet(const Segment &s, const Segment &u) {
    if (!CGAL::do_intersect(s, u)) return false;
    for (const Point &shared : {s.source(), s.target()}) {
        if (shared != u.source() && shared != u.target()) continue;
        Point x = shared == s.source() ? s.target() : s.source();
        Point y = shared == u.source() ? u.target() : u.source();
        return CGAL::collinear(shared, x, y) && (x - shared) * (y - shared) > 0;
    }
    return true;
}

// The part of the open segment (p, q) that lies deeper than eps inside the convex CCW outline
// has positive length: the segment crosses the module.
bool segmentEntersModule(Vec2d p, Vec2d q, const std::vector<Vec2d> &outline, double eps) {
    double lo = 0, hi = 1;
    for (size_t i = 0; i < outline.size(); ++i) {
        Vec2d a = outline[i], e = outline[(i + 1) % outline.size()] - a;
        double s0 = cross(e, p - a) / length(e) - eps, s1 = cross(e, q - a) / length(e) - eps;
        if (s0 <= 0 && s1 <= 0) return false;
        if (s0 < 0) lo = std::max(lo, s0 / (s0 - s1));
        if (s1 < 0) hi = std::min(hi, s0 / (s0 - s1));
    }
    return (hi - lo) * length(q - p) > eps;
}

struct UnionFind {
    std::vector<int> parent;
    explicit UnionFind(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
    int find(int i) { return parent[i] == i ? i : parent[i] = find(parent[i]); }
    void join(int i, int j) { parent[find(i)] = find(j); }
};

}  // namespace

// Where a walk stands: on an element at parameter t, heading in direction dir (+1 along the
// element's parametrisation). skipKk / skipPp is the connection it just arrived by; fromChild
// the module it has just come round.
struct FloorPlan::Position {
    PlanElement element;
    double t = 0;
    int dir = 1;
    int skipKk = -1, skipPp = -1;
    int fromChild = -1;
};

// The next thing a walk meets on its element: a dock to go round, or a PP edge to take.
struct FloorPlan::Event {
    double t = 0;
    int kk = -1, pp = -1;
};

FloorPlan::FloorPlan(std::vector<FloorPlanModule> modules, std::vector<KkConnection> kkConnections,
                     std::vector<PpConnection> ppConnections) :
    modules_(std::move(modules)), kk_(std::move(kkConnections)), pp_(std::move(ppConnections)) {
    validateModules();
    validateConnections();
    checkIntervals();
    checkConnected();
    placeModules();
    checkPpEndpoints();
    checkPpCrossings();
    computeOutline();
}

Vec2d FloorPlan::edgePoint(int module, int edge, double t) const {
    const std::vector<Vec2d> &o = modules_[module].outline;
    return lerp(o[edge], o[(edge + 1) % o.size()], t);
}

Vec2d FloorPlan::ppStart(int pp) const { return edgePoint(pp_[pp].module1, pp_[pp].edge1, pp_[pp].a); }
Vec2d FloorPlan::ppEnd(int pp) const { return edgePoint(pp_[pp].module2, pp_[pp].edge2, pp_[pp].b); }

// Def 4.1: a convex polygon with distinct vertices; veduta's outlines run counter-clockwise.
void FloorPlan::validateModules() const {
    for (size_t m = 0; m < modules_.size(); ++m) {
        const FloorPlanModule &module = modules_[m];
        auto fail = [&](const std::string &what) {
            throw InputError(module.loc, fmt::format("floor-plan module {}: {}", m, what));
        };
        if (module.outline.size() < 3) fail("an outline needs at least 3 vertices");
        for (Vec2d p : module.outline)
            if (!std::isfinite(p.x) || !std::isfinite(p.y)) fail("a vertex is not a finite number");
        std::vector<Point> points = toPoints(module.outline);
        if (!CGAL::is_simple_2(points.begin(), points.end(), Kernel()))
            fail("the outline crosses itself or repeats a vertex");
        if (!CGAL::is_convex_2(points.begin(), points.end(), Kernel())) fail("the outline is not convex");
        if (CGAL::orientation_2(points.begin(), points.end(), Kernel()) != CGAL::COUNTERCLOCKWISE)
            fail("the outline runs clockwise; outlines run counter-clockwise");
    }
}

// Index ranges and parameters of every connection; each module is docked at most once.
void FloorPlan::validateConnections() {
    int moduleCount = static_cast<int>(modules_.size());
    auto edgeCount = [&](int m) { return static_cast<int>(modules_[m].outline.size()); };
    dockOf_.assign(modules_.size(), -1);
    for (size_t k = 0; k < kk_.size(); ++k) {
        const KkConnection &c = kk_[k];
        auto fail = [&](const std::string &what) {
            throw InputError(c.loc, fmt::format("KK connection {}: {}", k, what));
        };
        if (c.docked < 0 || c.docked >= moduleCount) fail(fmt::format("no module {}", c.docked));
        if (c.dockedEdge < 0 || c.dockedEdge >= edgeCount(c.docked))
            fail(fmt::format("module {} has no edge {}", c.docked, c.dockedEdge));
        if (c.onPpEdge) {
            if (c.dominant < 0 || c.dominant >= static_cast<int>(pp_.size()))
                fail(fmt::format("no PP connection {}", c.dominant));
        } else {
            if (c.dominant < 0 || c.dominant >= moduleCount) fail(fmt::format("no module {}", c.dominant));
            if (c.edge < 0 || c.edge >= edgeCount(c.dominant))
                fail(fmt::format("module {} has no edge {}", c.dominant, c.edge));
            if (c.dominant == c.docked) fail("a module cannot dock onto itself");
        }
        if (!isFiniteUnit(c.a) || !isFiniteUnit(c.b) || !(c.a < c.b))
            fail(fmt::format("the interval [{}, {}] is not 0 <= a < b <= 1", c.a, c.b));
        if (dockOf_[c.docked] >= 0)
            fail(fmt::format("module {} is docked a second time (KK connection {} docks it already)", c.docked,
                             dockOf_[c.docked]));
        dockOf_[c.docked] = static_cast<int>(k);
    }
    for (size_t p = 0; p < pp_.size(); ++p) {
        PpConnection &c = pp_[p];
        auto fail = [&](const std::string &what) {
            throw InputError(c.loc, fmt::format("PP connection {}: {}", p, what));
        };
        for (auto [m, e] : {std::pair{c.module1, c.edge1}, std::pair{c.module2, c.edge2}}) {
            if (m < 0 || m >= moduleCount) fail(fmt::format("no module {}", m));
            if (e < 0 || e >= edgeCount(m)) fail(fmt::format("module {} has no edge {}", m, e));
        }
        if (c.module1 == c.module2) fail("both ends lie on the same module");
        if (!isFiniteUnit(c.a) || !isFiniteUnit(c.b)) fail("a parameter is outside [0, 1]");
        // Stored with t < 1, so that each point of an outline has one (edge, t).
        if (c.a == 1) {
            c.edge1 = (c.edge1 + 1) % edgeCount(c.module1);
            c.a = 0;
        }
        if (c.b == 1) {
            c.edge2 = (c.edge2 + 1) % edgeCount(c.module2);
            c.b = 0;
        }
    }
}

PlanElement FloorPlan::hostOf(int kk) const {
    const KkConnection &c = kk_[kk];
    return c.onPpEdge ? PlanElement{true, c.dominant, 0} : PlanElement{false, c.dominant, c.edge};
}

// Def 4.3/4.4: the intervals docked onto one edge do not overlap, and no module docks onto the
// edge by which its dominant module is itself docked.
void FloorPlan::checkIntervals() const {
    for (size_t k = 0; k < kk_.size(); ++k) {
        const KkConnection &c = kk_[k];
        if (!c.onPpEdge && dockOf_[c.dominant] >= 0 && kk_[dockOf_[c.dominant]].dockedEdge == c.edge)
            throw InputError(c.loc,
                             fmt::format("KK connection {}: edge {} of module {} is covered by its own dock", k, c.edge,
                                         c.dominant));
        for (size_t j = 0; j < k; ++j) {
            if (!(hostOf(static_cast<int>(j)) == hostOf(static_cast<int>(k)))) continue;
            if (kk_[j].a < c.b && c.a < kk_[j].b)
                throw InputError(c.loc,
                                 fmt::format("KK connection {}: the interval [{}, {}] overlaps [{}, {}] of "
                                             "KK connection {} on the same edge",
                                             k, c.a, c.b, kk_[j].a, kk_[j].b, j));
        }
    }
}

void FloorPlan::checkConnected() const {
    UnionFind components(modules_.size());
    for (const KkConnection &c : kk_) {
        if (c.onPpEdge) {
            components.join(c.docked, pp_[c.dominant].module1);
        } else {
            components.join(c.docked, c.dominant);
        }
    }
    for (const PpConnection &c : pp_) components.join(c.module1, c.module2);
    for (size_t m = 1; m < modules_.size(); ++m) {
        if (components.find(static_cast<int>(m)) == components.find(0)) continue;
        throw InputError(modules_[m].loc,
                         fmt::format("floor-plan module {} is not connected to module 0: {} modules need {} KK "
                                     "docks (Def 4.5) or PP connections joining the rest, there are {} docks",
                                     m, modules_.size(), modules_.size() - 1, kk_.size()));
    }
}

// Places each docked module once its dominant module (or both ends of its PP edge) stands: a
// rotation, uniform scale and translation (a complex affine map) that puts q_j on c[b] and q_{j+1}
// on c[a] (Def 4.3; reversed, see floor_plan.h). The two docked vertices are then set to exactly
// those points, so that the shared edge matches bit for bit.
void FloorPlan::placeModules() {
    std::vector<bool> placed(modules_.size());
    for (size_t m = 0; m < modules_.size(); ++m) placed[m] = dockOf_[m] < 0;
    auto hostPlaced = [&](const KkConnection &c) {
        return c.onPpEdge ? placed[pp_[c.dominant].module1] && placed[pp_[c.dominant].module2] : placed[c.dominant];
    };
    auto hostPoint = [&](const KkConnection &c, double t) {
        return c.onPpEdge ? lerp(ppStart(c.dominant), ppEnd(c.dominant), t) : edgePoint(c.dominant, c.edge, t);
    };
    for (bool progress = true; progress;) {
        progress = false;
        for (const KkConnection &c : kk_) {
            if (placed[c.docked] || !hostPlaced(c)) continue;
            std::vector<Vec2d> &outline = modules_[c.docked].outline;
            size_t j = c.dockedEdge, j1 = (j + 1) % outline.size();
            Vec2d targetJ = hostPoint(c, c.b), targetJ1 = hostPoint(c, c.a);
            if (outline[j] != targetJ || outline[j1] != targetJ1) {
                Vec2d scaleRotate = complexDiv(targetJ1 - targetJ, outline[j1] - outline[j]);
                Vec2d shift = targetJ - complexMul(scaleRotate, outline[j]);
                for (Vec2d &p : outline) p = complexMul(scaleRotate, p) + shift;
                outline[j] = targetJ;
                outline[j1] = targetJ1;
            }
            placed[c.docked] = true;
            progress = true;
        }
    }
    for (size_t m = 0; m < modules_.size(); ++m) {
        if (placed[m]) continue;
        const KkConnection &c = kk_[dockOf_[m]];
        throw InputError(
            c.loc, fmt::format("KK connection {}: module {} cannot be placed, its docks form a cycle", dockOf_[m], m));
    }
}

// The covered parts of an edge (a dock interval on it, or the whole edge by which the module
// is docked) are inside the plan.
bool FloorPlan::isCovered(int module, int edge, double t) const {
    if (dockOf_[module] >= 0 && kk_[dockOf_[module]].dockedEdge == edge) return true;
    for (const KkConnection &c : kk_)
        if (!c.onPpEdge && c.dominant == module && c.edge == edge && c.a <= t && t <= c.b) return true;
    return false;
}

void FloorPlan::checkPpEndpoints() const {
    for (size_t p = 0; p < pp_.size(); ++p) {
        const PpConnection &c = pp_[p];
        for (auto [m, e, t] : {std::tuple{c.module1, c.edge1, c.a}, std::tuple{c.module2, c.edge2, c.b}}) {
            if (isCovered(m, e, t))
                throw InputError(c.loc,
                                 fmt::format("PP connection {}: its end on edge {} of module {} lies where "
                                             "a KK dock covers the edge",
                                             p, e, m));
        }
        if (ppStart(static_cast<int>(p)) == ppEnd(static_cast<int>(p)))
            throw InputError(c.loc, fmt::format("PP connection {}: both ends are the same point", p));
    }
}

double FloorPlan::planScale() const {
    double scale = 1;
    for (const FloorPlanModule &m : modules_)
        for (Vec2d p : m.outline) scale = std::max({scale, std::abs(p.x), std::abs(p.y)});
    return scale;
}

// Def 4.2: a PP edge crosses no module and no other PP edge.
void FloorPlan::checkPpCrossings() const {
    double eps = kRelativeEpsilon * planScale();
    for (size_t p = 0; p < pp_.size(); ++p) {
        Vec2d ra = ppStart(static_cast<int>(p)), rb = ppEnd(static_cast<int>(p));
        for (size_t m = 0; m < modules_.size(); ++m) {
            if (segmentEntersModule(ra, rb, modules_[m].outline, eps))
                throw InputError(pp_[p].loc, fmt::format("PP connection {}: its edge crosses module {}", p, m));
        }
        for (size_t q = 0; q < p; ++q) {
            Segment s(toPoint(ra), toPoint(rb));
            Segment u(toPoint(ppStart(static_cast<int>(q))), toPoint(ppEnd(static_cast<int>(q))));
            if (ppEdgesMeet(s, u))
                throw InputError(pp_[p].loc, fmt::format("PP connection {}: its edge crosses PP connection {}", p, q));
        }
    }
}

// The walk starts at the lowest of the leftmost vertices, which lies on the outline, on the
// module edge that leaves it turning furthest clockwise: the outline's next edge there.
FloorPlan::Position FloorPlan::startOfOutline() const {
    auto below = [](Vec2d a, Vec2d b) { return a.x < b.x || (a.x == b.x && a.y < b.y); };
    Vec2d corner = modules_[0].outline[0];
    for (const FloorPlanModule &m : modules_)
        for (Vec2d p : m.outline)
            if (below(p, corner)) corner = p;
    Position best;
    double bestAngle = 10;
    for (size_t m = 0; m < modules_.size(); ++m) {
        const std::vector<Vec2d> &o = modules_[m].outline;
        for (size_t i = 0; i < o.size(); ++i) {
            bool dockedByIt = dockOf_[m] >= 0 && kk_[dockOf_[m]].dockedEdge == static_cast<int>(i);
            if (o[i] != corner || dockedByIt) continue;
            Vec2d d = o[(i + 1) % o.size()] - o[i];
            double angle = std::atan2(d.y, d.x);
            if (angle < bestAngle) {
                bestAngle = angle;
                best.element = {false, static_cast<int>(m), static_cast<int>(i)};
            }
        }
    }
    VEDUTA_CHECK(bestAngle < 10, "no module edge leaves the outline's first vertex");
    return best;
}

FloorPlan::Event FloorPlan::nextEvent(const Position &pos, int sense, bool outlinePpOnly) const {
    Event best;
    bool found = false;
    auto consider = [&](double t, int kk, int pp) {
        bool ahead = pos.dir > 0 ? t >= pos.t : t <= pos.t;
        bool sooner = !found || (pos.dir > 0 ? t < best.t : t > best.t);
        if (!ahead || !sooner) return;
        best = {t, kk, pp};
        found = true;
    };
    // Docked modules lie right of their host element; the walk goes round them when that is
    // the side of the face it traces, which on module edges it always is.
    bool dockSide = !pos.element.isPp || pos.dir == sense;
    for (size_t k = 0; k < kk_.size(); ++k) {
        if (static_cast<int>(k) == pos.skipKk || !dockSide || !(hostOf(static_cast<int>(k)) == pos.element)) continue;
        consider(pos.dir > 0 ? kk_[k].a : kk_[k].b, static_cast<int>(k), -1);
    }
    if (pos.element.isPp) return best;
    for (size_t p = 0; p < pp_.size(); ++p) {
        if (static_cast<int>(p) == pos.skipPp || (outlinePpOnly && !ppOnOutline_[p])) continue;
        const PpConnection &c = pp_[p];
        if (c.module1 == pos.element.index && c.edge1 == pos.element.edge) consider(c.a, -1, static_cast<int>(p));
        if (c.module2 == pos.element.index && c.edge2 == pos.element.edge) consider(c.b, -1, static_cast<int>(p));
    }
    return best;
}

// Leaving a docked module by the edge next to its docked edge: back onto the host element,
// past the dock's interval.
FloorPlan::Position FloorPlan::returnToHost(int kk, int sense) const {
    const KkConnection &c = kk_[kk];
    Position pos;
    pos.element = hostOf(kk);
    pos.t = sense > 0 ? c.b : c.a;
    pos.dir = sense;
    pos.skipKk = kk;
    pos.fromChild = c.docked;
    return pos;
}

// One step of a walk: along the element to the next event or its end, then on. The walk traces
// one face of the plan: with sense +1 the outer face (module edges forward, the face on the
// right), with sense -1 a bounded face (module edges backward, the face on the left).
FloorPlan::Position FloorPlan::advance(const Position &pos, int sense, bool outlinePpOnly,
                                       std::vector<WalkPiece> &pieces) const {
    Event event = nextEvent(pos, sense, outlinePpOnly);
    bool atEvent = event.kk >= 0 || event.pp >= 0;
    double tEnd = atEvent ? event.t : (pos.dir > 0 ? 1.0 : 0.0);
    if (tEnd != pos.t) {
        WalkPiece piece{pos.element, pos.t, tEnd, {}, {}, pos.fromChild, -1};
        if (pos.element.isPp) {
            Vec2d ra = ppStart(pos.element.index), rb = ppEnd(pos.element.index);
            piece.from = lerp(ra, rb, pos.t);
            piece.to = lerp(ra, rb, tEnd);
            if (event.kk >= 0) piece.childAfter = kk_[event.kk].docked;
        } else {
            piece.from = edgePoint(pos.element.index, pos.element.edge, pos.t);
            piece.to = edgePoint(pos.element.index, pos.element.edge, tEnd);
        }
        pieces.push_back(piece);
    }
    Position next;
    next.dir = sense;
    if (event.kk >= 0) {  // round the docked module, starting next to its docked edge
        const KkConnection &c = kk_[event.kk];
        int n = static_cast<int>(modules_[c.docked].outline.size());
        next.element = {false, c.docked, (c.dockedEdge + (sense > 0 ? 1 : n - 1)) % n};
        next.t = sense > 0 ? 0 : 1;
        return next;
    }
    if (event.pp >= 0) {  // along the PP edge, away from this end
        bool fromStart = pp_[event.pp].module1 == pos.element.index && pp_[event.pp].edge1 == pos.element.edge &&
            pp_[event.pp].a == event.t;
        next.element = {true, event.pp, 0};
        next.t = fromStart ? 0 : 1;
        next.dir = fromStart ? 1 : -1;
        return next;
    }
    if (pos.element.isPp) {  // onto the module at the far end, the same way round
        const PpConnection &c = pp_[pos.element.index];
        next.element = pos.dir > 0 ? PlanElement{false, c.module2, c.edge2} : PlanElement{false, c.module1, c.edge1};
        next.t = pos.dir > 0 ? c.b : c.a;
        next.skipPp = pos.element.index;
        return next;
    }
    int m = pos.element.index, n = static_cast<int>(modules_[m].outline.size());
    int edge = (pos.element.edge + (sense > 0 ? 1 : n - 1)) % n;
    if (dockOf_[m] >= 0 && kk_[dockOf_[m]].dockedEdge == edge) return returnToHost(dockOf_[m], sense);
    next.element = {false, m, edge};
    next.t = sense > 0 ? 0 : 1;
    return next;
}

std::vector<WalkPiece> FloorPlan::walk(const Position &start, int sense, bool outlinePpOnly, bool &closed) const {
    size_t steps = 16 + 4 * (kk_.size() + pp_.size());
    for (const FloorPlanModule &m : modules_) steps += 2 * m.outline.size();
    std::vector<WalkPiece> pieces;
    Position pos = start;
    for (size_t step = 0; step < steps; ++step) {
        pos = advance(pos, sense, outlinePpOnly, pieces);
        if (pos.element == start.element && pos.t == start.t && pos.dir == start.dir) {
            closed = true;
            return pieces;
        }
    }
    closed = false;
    return pieces;
}

void FloorPlan::computeOutline() {
    bool closed = false;
    outline_ = walk(startOfOutline(), 1, false, closed);
    if (!closed) throw InputError({}, "the floor plan's outline does not close: do modules overlap?");
    ppOnOutline_.assign(pp_.size(), false);
    ppForwardOnOutline_.assign(pp_.size(), false);
    for (const WalkPiece &piece : outline_) {
        if (!piece.element.isPp) continue;
        ppOnOutline_[piece.element.index] = true;
        ppForwardOnOutline_[piece.element.index] = piece.t1 > piece.t0;
    }
    for (size_t k = 0; k < kk_.size(); ++k) {
        const KkConnection &c = kk_[k];
        if (c.onPpEdge && !(ppOnOutline_[c.dominant] && ppForwardOnOutline_[c.dominant]))
            throw InputError(c.loc,
                             fmt::format("KK connection {}: module {} docks on the inner side of PP "
                                         "connection {}; the outline must run from r_a to r_b there",
                                         k, c.docked, c.dominant));
    }
}

namespace {

// L677: the walk aborts at an interior angle above 180 degrees.
bool turnsLeftOnly(const std::vector<WalkPiece> &cycle, double eps) {
    for (size_t i = 0; i < cycle.size(); ++i) {
        const WalkPiece &a = cycle[i], &b = cycle[(i + 1) % cycle.size()];
        Vec2d da = a.to - a.from, db = b.to - b.from;
        if (cross(da, db) < -eps * length(da) * length(db)) return false;
    }
    return true;
}

}  // namespace

// L675-678: from each outline PP edge, walk the inner polyline, which runs against the
// modules' direction, until the start comes round again.
std::vector<PpModule> FloorPlan::ppModules() const {
    std::vector<PpModule> result;
    std::vector<bool> done(pp_.size());
    for (size_t p = 0; p < pp_.size(); ++p) {
        if (done[p] || !ppOnOutline_[p]) continue;
        Position start;
        start.element = {true, static_cast<int>(p), 0};
        start.dir = ppForwardOnOutline_[p] ? 1 : -1;
        start.t = start.dir > 0 ? 0 : 1;
        bool closed = false;
        std::vector<WalkPiece> cycle = walk(start, -1, true, closed);
        for (const WalkPiece &piece : cycle)
            if (piece.element.isPp) done[piece.element.index] = true;
        if (!closed || cycle.size() < 3 || !turnsLeftOnly(cycle, kRelativeEpsilon)) continue;
        PpModule module;
        for (const WalkPiece &piece : cycle) {
            module.outline.push_back(piece.from);
            module.edgeSources.push_back(piece.element);
        }
        result.push_back(std::move(module));
    }
    return result;
}

}  // namespace veduta

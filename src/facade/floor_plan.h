// The floor plan of one storey after Finkenzeller (digest-001 §2.1, Defs 4.1-4.5, L638-713):
// convex floor-plan modules joined by KK (edge-edge) docks and PP (point-point) edges, placed
// into plan coordinates and validated, plus the two walks along it: the outline walk that the
// features are cut from (plan_features.h) and the inner walk that finds PP modules (L675-678).
//
// Orientation: every outline here is counter-clockwise, as everywhere in veduta; edge i runs
// from p_i to p_{i+1} and is parametrised over [0,1], e_i[t] = (1-t) p_i + t p_{i+1}. The thesis
// walks clockwise (L676, L842). A thesis figure is read into this convention by mirroring it
// (x -> -x): that keeps every vertex label, edge index e_i and parameter t, so the thesis's
// "e5[b,1], e1..e4, e5[0,a]" reads unchanged; only "clockwise" becomes "counter-clockwise".
//
// Choices where the thesis is open:
// * KK dock orientation (digest §10, L695): the thesis writes d = (r_a, r_b), which with both
//   modules walked the same way would put them on the same side of c. We reverse it: the
//   docked edge d = (q_j, q_{j+1}) is placed with q_j on c[b] and q_{j+1} on c[a], so the docked
//   module lies outside the dominant one. The same holds on a PP edge (Def 4.4): the docked
//   module lies right of k = (r_a, r_b), which must be the outside of the plan there.
// * Def 4.5 says |M| = |C_ee| + 1, but the features section (L750, "m < l") and Figs 4.15/4.16
//   join modules by PP edges alone. We accept both: the KK docks form a forest, a module that no
//   dock places (a root) keeps its own coordinates, and the whole plan must be connected through
//   KK and PP connections. A plan without PP connections is then exactly Def 4.5's spanning tree.
// * Intervals on one edge may touch (b1 == a2; a row of modules docked side by side) but not
//   overlap; the thesis's closed-interval condition would forbid touching.
// * A PP endpoint must not lie on the covered part of an edge (a dock interval or the docked
//   edge of a module): the edge is not part of any outline there.
// * Inner PP edges (Fig. 4.15, not on the outline) are ignored for the outline and for PP
//   modules alike; the thesis says the algorithm "does not consider" them (L849).
// * The inner walk starts on the side of a PP edge away from the outline (the outline fixes it),
//   not on the side that the order fpm1, fpm2 of Def 4.2 would give.
#pragma once

#include <string>
#include <vector>

#include "core/error.h"
#include "core/vecmath.h"

namespace veduta {

// One floor-plan module (Def 4.1, Table 4.1).
struct FloorPlanModule {
    std::vector<Vec2d> outline;  // convex, counter-clockwise, distinct vertices
    std::string type;            // architectural type: "Risalit", "Balkon", ...
    double wallThickness = 0;
    double height = 0;  // wall height; balustrade height for a balcony
    std::string material;
    FileLoc loc;  // where the module was described, for error messages
};

// KK connection (Defs 4.3, 4.4): the whole edge `dockedEdge` of module `docked` is placed onto
// the interval [a, b] of the dominant edge, with reversed orientation (see the file comment).
struct KkConnection {
    bool onPpEdge = false;  // Def 4.4: the dominant edge is the edge of PP connection `dominant`
    int dominant = 0;       // module index, or PP connection index when onPpEdge
    int edge = 0;           // c: the dominant module's edge (unused on a PP edge)
    int docked = 0;
    int dockedEdge = 0;   // d
    double a = 0, b = 1;  // 0 <= a < b <= 1
    FileLoc loc;
};

// PP connection (Def 4.2): the new outline edge k = (r_a, r_b) from c[a] of module1 to d[b] of
// module2.
struct PpConnection {
    int module1 = 0, edge1 = 0;
    double a = 0;
    int module2 = 0, edge2 = 0;
    double b = 0;
    FileLoc loc;
};

// What a piece of a walk runs along: an edge of a module, or the edge of a PP connection.
struct PlanElement {
    bool isPp = false;
    int index = 0;  // module or PP connection
    int edge = 0;   // the module's edge; 0 for a PP edge
    bool operator==(const PlanElement &) const = default;
};

// One straight piece of a walk: element[t0, t1] (t1 < t0 when walked against the element's
// direction). childBefore / childAfter name the module docked on a PP edge that the walk has just
// come round / is about to go round, else -1; the features need them (case 7, L800).
struct WalkPiece {
    PlanElement element;
    double t0 = 0, t1 = 0;
    Vec2d from, to;
    int childBefore = -1, childAfter = -1;
};

// A PP module (L675-678): the convex cell that outline PP edges enclose with the modules. Edge i
// runs from outline[i] to outline[i+1]; edgeSources[i] says whether it is a PP edge or part of an
// edge of a neighbouring module (the adjacency that roofs use).
struct PpModule {
    std::vector<Vec2d> outline;  // counter-clockwise
    std::vector<PlanElement> edgeSources;
};

class FloorPlan {
  public:
    // Places the docked modules and validates the plan; throws InputError naming the module or
    // connection at fault.
    FloorPlan(std::vector<FloorPlanModule> modules, std::vector<KkConnection> kkConnections,
              std::vector<PpConnection> ppConnections);

    // The modules in plan coordinates.
    const std::vector<FloorPlanModule> &modules() const { return modules_; }
    const std::vector<KkConnection> &kkConnections() const { return kk_; }
    // As given, except that an end at t = 1 is stored as t = 0 of the next edge.
    const std::vector<PpConnection> &ppConnections() const { return pp_; }

    Vec2d edgePoint(int module, int edge, double t) const;
    Vec2d ppStart(int pp) const;  // r_a
    Vec2d ppEnd(int pp) const;    // r_b
    // The KK connection that places a module, or -1 for a root.
    int dockOf(int module) const { return dockOf_[module]; }

    // The outer outline, walked counter-clockwise (the thesis's feature algorithm, L842-847),
    // from the lowest of the leftmost vertices.
    const std::vector<WalkPiece> &outline() const { return outline_; }
    // PP connections whose edge is on the outline; the others are inner ones (Fig. 4.15).
    bool ppOnOutline(int pp) const { return ppOnOutline_[pp]; }
    // The PP modules, each once; none where the enclosed region is concave (Fig. 4.16).
    std::vector<PpModule> ppModules() const;

  private:
    struct Position;
    struct Event;
    void validateModules() const;
    void validateConnections();
    void placeModules();
    void checkIntervals() const;
    void checkPpEndpoints() const;
    void checkPpCrossings() const;
    void checkConnected() const;
    std::vector<WalkPiece> walk(const Position &start, int sense, bool outlinePpOnly, bool &closed) const;
    Position advance(const Position &pos, int sense, bool outlinePpOnly, std::vector<WalkPiece> &pieces) const;
    Event nextEvent(const Position &pos, int sense, bool outlinePpOnly) const;
    Position returnToHost(int kk, int sense) const;
    PlanElement hostOf(int kk) const;
    double planScale() const;
    Position startOfOutline() const;
    void computeOutline();

    bool isCovered(int module, int edge, double t) const;

    std::vector<FloorPlanModule> modules_;
    std::vector<KkConnection> kk_;
    std::vector<PpConnection> pp_;
    std::vector<int> dockOf_;
    std::vector<WalkPiece> outline_;
    std::vector<bool> ppOnOutline_;
    std::vector<bool> ppForwardOnOutline_;
};

}  // namespace veduta

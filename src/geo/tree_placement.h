// Where trees stand: Poisson-disk sampling inside forest and Gehölz outlines, trees at a
// spacing along tree rows and hedges, and single trees at points. Everything is in the scene's
// local frame (LocalFrame::toLocal); heights come later, from the terrain under each tree.
//
// Every random choice is a pure function of (seed, object id, candidate, dimension) through
// core/hash.h, so the same inputs give the same trees in any order and on any thread.
// docs/vegetation.md describes the method and the parameters.
#pragma once

#include <cstdint>
#include <vector>

#include "core/vecmath.h"
#include "geo/atkis.h"

namespace veduta {

// How trees grow in one object.
struct TreeStand {
    TreeKind kind = TreeKind::Mixed;       // Mixed: each tree is broadleaf or conifer by a hashed draw
    float conifersInMixed = 0.4f;          // the share of conifers where kind is Mixed
    float spacing = 5.5f;                  // areas: the minimum distance; lines: the mean distance (m)
    float rowJitter = 0.15f;               // lines: each tree moves along the line by ± this × spacing
    float minHeight = 12, maxHeight = 28;  // metres, drawn uniformly
    float widthJitter = 0.12f;             // the crown's width scales by 1 ± this
};

// The stand for a land class and its Laub/Nadel/Misch kind: Forest (5.5 m, 12–28 m),
// Shrubs (Gehölz: 3 m, 3–9 m), TreeRow (9 m, 10–20 m, also single trees), Hedge (1.5 m,
// 1.5–3.5 m, broadleaf). Other classes grow no trees: spacing 0.
TreeStand treeStand(LandClass landClass, TreeKind kind);

struct PlacedTree {
    Vec2f position;                       // local frame, metres
    TreeKind kind = TreeKind::Broadleaf;  // never Mixed
    uint32_t variant = 0;                 // < kTreeVariants
    float height = 0;                     // metres
    float rotation = 0;                   // about z, radians
    float widthScale = 1;                 // horizontal scale relative to the height
};

// The trees placed so far, up to a limit: placing stops once `limit` trees are there and
// `limitReached` says so, so that a huge or mistaken area costs a warning, not the memory.
struct TreeSet {
    std::vector<PlacedTree> trees;
    size_t limit = 2'000'000;
    bool limitReached = false;
};

// Poisson-disk samples inside the closed `ring` (concave allowed, either orientation, first
// point not repeated), at least stand.spacing apart. Rings with fewer than three points or
// non-finite coordinates plant nothing. Throws std::invalid_argument when stand.spacing is not
// positive or a point lies more than 1000 km from the origin (not local coordinates); callers
// turn that into an InputError naming the object.
void plantArea(TreeSet &set, const std::vector<Vec2f> &ring, const TreeStand &stand, uint32_t seed, uint32_t objectId);
// Trees along the polyline in equal steps of about stand.spacing metres, jittered along it,
// the first half a step from its start. A line shorter than one spacing gets one tree near its
// middle. The same errors as plantArea.
void plantLine(TreeSet &set, const std::vector<Vec2f> &line, const TreeStand &stand, uint32_t seed, uint32_t objectId);
// One tree at each point.
void plantPoints(TreeSet &set, const std::vector<Vec2f> &points, const TreeStand &stand, uint32_t seed,
                 uint32_t objectId);

// The instance transform of a prototype from treeModel (height 1, standing on the origin):
// scaled to the tree's height and width, turned, and stood at `groundHeight`.
Transform treeTransform(const PlacedTree &tree, float groundHeight);

}  // namespace veduta

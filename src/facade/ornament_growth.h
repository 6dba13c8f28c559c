// Bounded flat plant ornaments grown into a region (digest-001 §2.7, Ch. 5.4.2, L1220–1280), after
// Wong et al. [WZS98] as Finkenzeller does it: a grey raster of free, forbidden and occupied cells
// (L1245), the exact Euclidean distance transform of its free cells and the reduced medial axis
// as a list of free circles sorted by radius (L1254–1258), ornament elements that grow into the
// nearest free circle and mark their coarse proxy cells ("Vertreter") in the raster (Fig. 5.32),
// the placement loop of L1266–1276, and a rasteriser that turns the finished vector elements into
// a height map for a relief (L1276: "als Höhenmodell zur Erzeugung eines Reliefs").
//
// Units: the raster's cells are the unit of the motifs. Free-circle radii, the minimum radius and
// the reach are in cells, and stems, leaves and tendrils are sized in cells too, because the
// thesis lets the raster's resolution decide how fine an ornament gets (L1240: at most one element
// per cell). Geometry is in metres in the region's plane, y up; raster row 0 is the bottom.
//
// Choices where the thesis is open:
// * Outside the raster counts as forbidden, so that a directly given raster is bounded too.
// * A proxy cell is every cell whose closed square the drawn footprint reaches (a tube around a
//   stem's path, a filled leaf), not the thesis's one-cell-wide line: then the drawn relief never
//   spills onto a free or forbidden cell. An element's proxies leave out its parent's cells, where
//   it grows from, so that each cell holds at most one element.
// * After a placement each newly non-free cell updates the distances ring by ring around it and
//   stops at the first ring where no cell could still be nearer to it than to its old obstacle
//   (the distance is 1-Lipschitz, so a cell beyond can change only if some cell on the ring has
//   d ≥ |ring cell − new cell| − 1). This is the "only the pixels whose value exceeds their
//   distance to the new element" of L1258, and it equals a full recompute exactly (tested).
// * The loop (L1266–1276) tries the regions in order of decreasing radius; where no nearby
//   element grows into one it takes the next *smaller* one. The text's "nächstgrößere" (next
//   larger, [UNCERTAIN] in the digest) cannot be meant literally, since the loop starts at the
//   largest. For one region it tries all elements within the reach, nearest first (ties by age),
//   as "keines der nahe gelegenen Elemente" implies. A region's failed attempts are remembered:
//   cells only ever fill, so an element that could not grow into a circle never can later.
// * The vocabulary is deterministic: a root or a stem grows a stem into a circle of radius ≥ 6
//   cells, a leaf into one of ≥ 3, and (stems only) a tendril into a smaller one; leaves and
//   tendrils grow nothing. Each motif tries a few fixed variants and takes the first that fits.
// * The relief: stems, roots and tendrils are tubes of half-round profile (height √(r² − d²));
//   leaves and the root's boss are plateaus of height h rising over a soft edge 2h wide
//   (smoothstep), with a raised midrib on leaves. Overlaps take the higher value.
#pragma once

#include <cstdint>
#include <set>
#include <unordered_map>
#include <vector>

#include "core/image.h"
#include "core/vecmath.h"

namespace veduta {

// The grey values of the backbuffer (L1245): black, white, grey.
enum class OrnamentCell : uint8_t { Free, Forbidden, Occupied };

// The most cells a raster may have, and the most elements one ornament may hold: limits against
// inputs that would exhaust memory or grow without end.
inline constexpr int kOrnamentCellLimit = 1 << 22;
inline constexpr int kOrnamentElementLimit = 2000;

// A free circle of the reduced medial axis: a free cell at least as far from every non-free cell
// as its 8 neighbours are, with its squared distance in cells.
struct MedialAxisEntry {
    int cell = 0;
    int32_t squaredRadius = 0;
    bool operator==(const MedialAxisEntry &) const = default;
};

// The list order: largest radius first, ties by cell index, so that the order is total.
struct MedialAxisOrder {
    bool operator()(const MedialAxisEntry &a, const MedialAxisEntry &b) const {
        return a.squaredRadius != b.squaredRadius ? a.squaredRadius > b.squaredRadius : a.cell < b.cell;
    }
};

// The grey raster with its distance transform and medial axis, kept up to date as cells fill.
class OrnamentRaster {
  public:
    // `cells` (width · height, row 0 at the bottom, row-major) must be Free or Forbidden; cell
    // (column, row) covers [origin + (column, row) · cellSize, + cellSize].
    OrnamentRaster(int width, int height, double cellSize, Vec2d origin, std::vector<OrnamentCell> cells);
    // A polygon region: a cell is free when its centre lies inside `outline` (counter-clockwise)
    // and outside every hole (either orientation). The raster covers the outline's bounding box.
    static OrnamentRaster fromRegion(const std::vector<Vec2d> &outline, const std::vector<std::vector<Vec2d>> &holes,
                                     double cellSize);

    int width() const { return width_; }
    int height() const { return height_; }
    int cellCount() const { return width_ * height_; }
    double cellSize() const { return cellSize_; }
    Vec2d origin() const { return origin_; }
    OrnamentCell state(int cell) const { return states_[cell]; }
    // The element occupying a cell, or -1.
    int owner(int cell) const { return owners_[cell]; }
    // The cell holding `p`, or -1 outside the raster.
    int cellAt(Vec2d p) const;
    Vec2d centre(int cell) const;

    // Squared distance, in cells, of each cell to the nearest non-free cell (0 on non-free ones).
    const std::vector<int32_t> &squaredDistances() const { return distances_; }
    // The medial-axis entries with squared radius ≥ `minSquaredRadius`, in MedialAxisOrder.
    std::vector<MedialAxisEntry> medialAxis(int32_t minSquaredRadius = 1) const;

    // Marks free `cells` occupied by element `owner` and updates distances and medial axis.
    void occupy(const std::vector<int> &cells, int owner);

  private:
    void lowerDistancesAround(int site, std::vector<int> &changed);
    void refreshMedialAxis(int cell);
    bool isLocalMaximum(int cell) const;

    int width_ = 0, height_ = 0;
    double cellSize_ = 0;
    Vec2d origin_;
    std::vector<OrnamentCell> states_;
    std::vector<int> owners_;
    std::vector<int32_t> distances_;
    std::set<MedialAxisEntry, MedialAxisOrder> medialAxis_;
    std::vector<int32_t> listedRadius_;  // each cell's squared radius in medialAxis_, or -1
    std::vector<uint32_t> stamps_;       // the last update that refreshed each cell's listing
    uint32_t stamp_ = 0;
};

// The exact squared Euclidean distance transform of the free cells (Meijster et al. 2000), from
// scratch: what the incremental update must equal.
std::vector<int32_t> squaredDistanceTransform(const OrnamentRaster &raster);

// The five primitives of L1260–1263 (Grundformen). A cubic Bézier chain has 4 + 3k control points
// (8 parameters, then 6 per further segment); it is closed and filled when its last point is its
// first. Angles in radians; an arc runs from startAngle to endAngle, counter-clockwise when
// endAngle > startAngle. `relief`, metres: a tube's radius for the open ones (point, line, arc,
// open Bézier), the raised height for the filled ones (circle, closed Bézier).
enum class PrimitiveType { Point, Line, Arc, Circle, Bezier };

struct OrnamentPrimitive {
    PrimitiveType type = PrimitiveType::Point;
    std::vector<Vec2d> points;  // point 1, line 2, arc and circle the centre, Bézier 4 + 3k
    double radius = 0;          // arc, circle
    double startAngle = 0, endAngle = 0;
    double relief = 0;

    bool filled() const;
    // The parameter count of L1263: 2 per point, plus radius and angles.
    int parameterCount() const;
    // The outline or path the primitive is drawn and rasterised from: the filled shape's boundary
    // (closed, first point not repeated) or the open path (one point for a point).
    std::vector<Vec2d> path() const;
    bool operator==(const OrnamentPrimitive &) const = default;
};

// The proxy cells of a primitive: those whose closed squares its drawn footprint reaches (for an
// open one of relief 0, the squares its path touches: the thesis's one-cell-wide line), within the
// raster.
std::vector<int> footprintCells(const OrnamentRaster &raster, const OrnamentPrimitive &primitive);

enum class OrnamentKind { Root, Stem, Leaf, Tendril };

struct FreeCircle {
    Vec2d centre;       // metres
    double radius = 0;  // metres
};

class OrnamentElement;

struct GrowthResult {
    bool success = false;
    std::vector<OrnamentElement> elements;
};

// A height map being drawn: one channel, metres of relief, top row first, over the raster's
// rectangle. Raising takes the maximum with what is there.
class HeightCanvas {
  public:
    HeightCanvas(Vec2d origin, double extentX, double extentY, double cellSize);
    void raisePrimitive(const OrnamentPrimitive &primitive);
    const Image &image() const { return image_; }

  private:
    void raiseTube(const std::vector<Vec2d> &path, double radius);
    void raiseFilled(const std::vector<Vec2d> &outline, double height);
    Vec2d pixelCentre(int x, int y) const;

    Image image_;
    Vec2d origin_;
    double extentY_ = 0, cellSize_ = 0;
};

// An ornament element (Fig. 5.32): its primitives, its proxy cells, and its growth and drawing.
class OrnamentElement {
  public:
    // A root stem along the baseline a → b, or a root boss at a point; its cells must be free.
    static OrnamentElement rootAlong(const OrnamentRaster &raster, Vec2d a, Vec2d b);
    static OrnamentElement rootAt(const OrnamentRaster &raster, Vec2d point);

    OrnamentKind kind() const { return kind_; }
    const std::vector<OrnamentPrimitive> &primitives() const { return primitives_; }
    // The proxy cells this element occupies (not its parent's).
    const std::vector<int> &cells() const { return cells_; }
    int parent() const { return parent_; }

    // Growth (Wachstum) into `circle` for the element placed as number `self`: success and the new
    // elements, whose cells are free in `raster` now.
    GrowthResult grow(const OrnamentRaster &raster, const FreeCircle &circle, int self) const;
    // Drawing (Zeichnen), after placement has ended.
    void draw(HeightCanvas &canvas) const;

    bool operator==(const OrnamentElement &) const = default;

  private:
    OrnamentElement(OrnamentKind kind, std::vector<OrnamentPrimitive> primitives, int parent, int side);
    bool claimCells(const OrnamentRaster &raster);
    void attachment(Vec2d target, Vec2d &point, Vec2d &tangent) const;
    double tubeRadius() const { return primitives_.front().relief; }
    GrowthResult growStem(const OrnamentRaster &raster, const FreeCircle &circle, int self) const;
    GrowthResult growLeaf(const OrnamentRaster &raster, const FreeCircle &circle, int self) const;
    GrowthResult growTendril(const OrnamentRaster &raster, const FreeCircle &circle, int self) const;

    OrnamentKind kind_ = OrnamentKind::Root;
    std::vector<OrnamentPrimitive> primitives_;  // the first is the spine growth starts from
    std::vector<int> cells_;
    int parent_ = -1;
    int side_ = 1;  // which way the element curls: +1 counter-clockwise, -1 clockwise
};

// Why growth ended (L1274): no free circle of at least the minimum radius is left, none of the
// nearby elements grew into any of them, or the element limit was reached.
enum class OrnamentStop { Running, NoFreeRegion, NoGrowth, ElementLimit };

struct OrnamentSettings {
    double minRadius = 2;  // cells: smaller free circles are not filled
    double reach = 3;      // cells: how far beyond a circle an element may be and still grow into it
};

struct Ornament {
    OrnamentRaster raster;
    std::vector<OrnamentElement> elements;  // in order of placement, the roots first
    OrnamentStop stop = OrnamentStop::Running;
};

// The placement loop (L1266–1276), one growth per step, so that callers can watch it.
class OrnamentGrower {
  public:
    OrnamentGrower(OrnamentRaster raster, std::vector<OrnamentElement> roots, OrnamentSettings settings = {});
    // Places one growth; false (with stop() set) when growth has ended.
    bool step();
    OrnamentStop stop() const { return ornament_.stop; }
    const Ornament &ornament() const { return ornament_; }
    Ornament finish();

  private:
    bool growInto(const MedialAxisEntry &entry);
    std::vector<int> nearbyElements(const MedialAxisEntry &entry, int firstUntried) const;
    void place(OrnamentElement element);

    Ornament ornament_;
    OrnamentSettings settings_;
    std::unordered_map<int64_t, int> tried_;  // per circle (cell, squared radius): elements tried
};

// Grows the ornament to its end.
Ornament growOrnament(OrnamentRaster raster, std::vector<OrnamentElement> roots, OrnamentSettings settings = {});

// The ornament's relief over its raster's rectangle at `cellSize` metres per pixel.
Image ornamentHeightMap(const Ornament &ornament, double cellSize);

}  // namespace veduta

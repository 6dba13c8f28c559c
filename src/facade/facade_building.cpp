#include "facade/facade_building.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <numeric>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>

#include "core/check.h"
#include "core/hash.h"
#include "core/polygon_bounds.h"
#include "facade/apron_ornament.h"
#include "facade/casings.h"
#include "facade/convex_pieces.h"
#include "facade/cornice_run.h"
#include "facade/floor_plan.h"
#include "facade/plan_features.h"
#include "facade/profile_sweep.h"
#include "facade/roof_merge.h"
#include "facade/wall_elements.h"

namespace veduta {

namespace {

// How far outside a wall a neighbour's roof is sought over an opening's sill (row 19).
constexpr double kRoofProbe = 0.05;

Vec3f at(Vec2d xy, double z) { return {float(xy.x), float(xy.y), float(z)}; }

// A wall face: one module edge seen from outside, with its masonry style.
struct FaceKey {
    int module = 0, edge = 0;
    bool reversed = false;
    const MasonryStyle *masonry = nullptr;
    auto operator<=>(const FaceKey &) const = default;
};

struct FaceFrame {
    Vec2d origin, along;  // plan; along is a unit vector, outward is its right side
    double length = 0;
};

struct FaceBuild {
    FaceFrame frame;
    double xMin = INFINITY, xMax = -INFINITY, zMin = INFINITY, zMax = -INFINITY;
    std::vector<std::vector<Vec2d>> holes;
    MaterialId material = kNoMaterial;
    std::vector<uint32_t> triangles;
};

// The modules present at one storey that docks join, as one floor plan in global indices.
struct StoreyPlan {
    std::vector<int> modules;  // plan module i is structure module modules[i]
    FloorPlan plan;
};

// An apron keeps this far above its storey's floor, metres; lower, it is left out.
constexpr double kApronClearance = 0.05;

// The assembly of `window` at its size: refined opening, casing, frame and pane, and the reveal.
WindowAssembly assembleWindow(const WindowStyle &window, const PieceMaterials &materials, MaterialId interior) {
    Vec2d size{window.placement.width, window.placement.height};
    CoarseOpening coarse{{0, 0}, {size.x, 0}, size, {0, size.y}};
    RefinedOpening refined = refineOpening(coarse, window.refinement, window.dominance, window.kind);
    OpeningPieces pieces = buildOpeningPieces(refined, window.casing, window.frame);
    // The opening's frame: along x, up z, so out of the wall is -y.
    WallFrame3d frame{{0, 0, 0}, {1, 0, 0}, {0, 0, 1}};
    auto model = std::make_shared<Mesh>(extrudePieces(pieces.pieces, frame, materials));
    model->append(revealMesh(pieces.hole, frame, kRevealDepth, interior), Transform());
    std::shared_ptr<const Image> apron;
    if (window.apron) try {
            auto [low, high] = polygonBounds(pieces.hole);
            apron = std::make_shared<const Image>(apronRelief(high.x - low.x, window.apron->height));
        } catch (const std::invalid_argument &e) {
            throw InputError(window.apron->loc, fmt::format("the apron cannot be grown: {}", e.what()));
        }
    return {std::move(model), std::move(pieces.hole), std::move(apron)};
}

class BuildingAssembly {
  public:
    BuildingAssembly(const BuildingStructure &structure, const BuildingStyle &style, const MaterialByName &material,
                     uint32_t seed, uint32_t buildingId, WindowAssemblies &windows) :
        structure_(structure),
        style_(style),
        material_(material),
        seed_(seed),
        buildingId_(buildingId),
        windows_(windows) {}

    FacadeBuilding build() && {
        validateStructure(structure_);
        std::vector<std::string> names;
        for (const ModuleStructure &m : structure_.modules) names.push_back(m.name);
        checkBindings(style_, names, structure_.boundStoreyCount());
        placeModules();
        buildRoofs();
        for (size_t s = 0; s < structure_.storeyCount(); ++s)
            for (StoreyPlan &plan : storeyPlans(int(s))) buildStorey(plan, int(s));
        describeMasonry();
        appendRoofs();
        for (const auto &[reason, count] : dropped_)
            result_.notes.push_back(fmt::format("{} opening{} left out: {}", count, count == 1 ? "" : "s", reason));
        return std::move(result_);
    }

  private:
    // --- modules and plans ---------------------------------------------------------------

    std::vector<KkConnection> docksAmong(const std::vector<int> &present) const {
        std::vector<KkConnection> kk;
        auto local = [&](int m) {
            auto it = std::find(present.begin(), present.end(), m);
            return it == present.end() ? -1 : int(it - present.begin());
        };
        for (const ModuleDock &d : structure_.docks) {
            int docked = local(structure_.moduleIndex(d.docked, d.loc));
            int dominant = local(structure_.moduleIndex(d.dominant, d.loc));
            if (docked < 0 || dominant < 0) continue;
            KkConnection c;
            c.dominant = dominant;
            c.edge = d.edge;
            c.docked = docked;
            c.dockedEdge = d.dockedEdge;
            c.a = d.a;
            c.b = d.b;
            c.loc = d.loc;
            kk.push_back(c);
        }
        return kk;
    }

    // The ground storey's plan places every module (Def 4.3's docking transforms).
    void placeModules() {
        std::vector<int> all(structure_.modules.size());
        std::iota(all.begin(), all.end(), 0);
        std::vector<FloorPlanModule> modules;
        for (const ModuleStructure &m : structure_.modules) modules.push_back(m.module);
        FloorPlan ground(modules, docksAmong(all), {});
        for (const FloorPlanModule &m : ground.modules()) placed_.push_back(m.outline);
    }

    std::vector<StoreyPlan> storeyPlans(int storey) const {
        std::vector<int> present;
        for (size_t m = 0; m < structure_.modules.size(); ++m)
            if (int(structure_.modules[m].storeyHeights.size()) > storey) present.push_back(int(m));
        // Components of the docks among the present modules.
        std::vector<int> component(present.size());
        std::iota(component.begin(), component.end(), 0);
        auto find = [&](int i) {
            while (component[size_t(i)] != i) i = component[size_t(i)];
            return i;
        };
        for (const KkConnection &c : docksAmong(present)) component[size_t(find(c.docked))] = find(c.dominant);
        std::map<int, std::vector<int>> groups;
        for (size_t i = 0; i < present.size(); ++i) groups[find(int(i))].push_back(present[i]);
        std::vector<StoreyPlan> plans;
        for (auto &[root, members] : groups) {
            std::sort(members.begin(), members.end());
            std::vector<FloorPlanModule> modules;
            for (int m : members) {
                FloorPlanModule placed = structure_.modules[size_t(m)].module;
                placed.outline = placed_[size_t(m)];
                modules.push_back(placed);
            }
            plans.push_back({members, FloorPlan(modules, docksAmong(members), {})});
        }
        return plans;
    }

    double storeyBottom(int module, int storey) const {
        const std::vector<double> &h = structure_.modules[size_t(module)].storeyHeights;
        return std::accumulate(h.begin(), h.begin() + storey, 0.0);
    }

    const ResolvedStyle &resolved(int module, int storey) {
        auto [it, fresh] = resolved_.try_emplace({module, storey});
        if (fresh)
            it->second = resolveStyle(style_, structure_.modules[size_t(module)].name, structure_.storeyRole(storey));
        return it->second;
    }

    MaterialId material(const ResolvedStyle &style, StylePart part) {
        const std::string &name = style.material(part);
        auto [it, fresh] = materials_.try_emplace(name, kNoMaterial);
        if (fresh) it->second = material_(name, style_.bindings.loc);
        return it->second;
    }

    // --- one storey ----------------------------------------------------------------------

    // Where a walk piece lies: its module's edge and the face frame it is seen in. The structure
    // has no PP connections (Def 4.2), so every piece runs along a module's edge.
    struct PieceFace {
        int module = 0, edge = 0;  // the structure's module
        bool reversed = false;
        FaceFrame frame;
    };

    PieceFace pieceFace(const StoreyPlan &plan, const WalkPiece &piece) const {
        PieceFace f;
        f.module = plan.modules[size_t(piece.element.index)];
        f.edge = piece.element.edge;
        const std::vector<Vec2d> &o = placed_[size_t(f.module)];
        Vec2d start = o[size_t(f.edge)], end = o[(size_t(f.edge) + 1) % o.size()];
        f.reversed = piece.t1 < piece.t0;
        if (f.reversed) std::swap(start, end);
        f.frame.origin = start;
        f.frame.length = length(end - start);
        f.frame.along = (end - start) * (1 / f.frame.length);
        return f;
    }

    void buildStorey(const StoreyPlan &plan, int storey) {
        std::vector<Feature> features = planFeatures(plan.plan);
        std::vector<std::vector<Vec2d>> polylines;
        std::vector<PieceFace> faces;  // one per base wall
        std::vector<WallSubdivision> subdivisions;
        for (const Feature &f : features) {
            std::vector<Vec2d> line;
            for (const WalkPiece &piece : f.edges) {
                line.push_back(piece.from);
                faces.push_back(pieceFace(plan, piece));
            }
            line.push_back(f.edges.back().to);
            polylines.push_back(std::move(line));
            subdivisions.push_back(resolved(plan.modules[size_t(f.module)], storey).walls);
        }
        StoreyFacade facade = subdivideStorey(polylines, true, subdivisions);
        if (facade.baseWalls.size() != faces.size())
            throw std::logic_error("the storey's base walls do not follow its walk pieces");
        elementCount_ += facade.elements.size();
        if (elementCount_ > kFacadeElementLimit)
            throw InputError(structure_.modules.front().module.loc,
                             fmt::format("the building has more than {} wall elements", kFacadeElementLimit));

        std::vector<std::vector<Partition>> partitions(facade.elements.size());
        std::vector<std::vector<const BandStyle *>> bandsOf(facade.elements.size());
        for (size_t e = 0; e < facade.elements.size(); ++e) {
            const FacadeElement &element = facade.elements[e];
            const PieceFace &face = faces[element.baseWall];
            int module = face.module;
            double bottom = storeyBottom(module, storey);
            double height = structure_.modules[size_t(module)].storeyHeights[size_t(storey)];
            const ResolvedStyle &style = resolved(face.module, storey);
            buildElement(facade, element, face, style, bottom, height, storey);
            for (const BandStyle &band : style.bands) {
                partitions[e].push_back({bottom + band.vStart * height, bottom + band.vStop * height});
                bandsOf[e].push_back(&band);
            }
        }
        for (const BandRun &run : findBands(facade, partitions)) {
            const ResolvedStyle &style = resolved(faces[facade.elements[run.first].baseWall].module, storey);
            sweepBand(facade, run, bandAt(run, partitions[run.first], bandsOf[run.first]), style);
        }
    }

    FaceBuild &faceFor(const PieceFace &face, const ResolvedStyle &style) {
        FaceKey key{face.module, face.edge, face.reversed, style.masonry};
        auto [it, fresh] = faces_.try_emplace(key);
        if (fresh) {
            it->second.frame = face.frame;
            it->second.material = material(style, StylePart::Wall);
            faceOrder_.push_back(key);
        }
        return it->second;
    }

    void buildElement(const StoreyFacade &facade, const FacadeElement &element, const PieceFace &face,
                      const ResolvedStyle &style, double bottom, double height, int storey) {
        const BaseWall &wall = facade.baseWalls[element.baseWall];
        double offset = dot(wall.start - face.frame.origin, face.frame.along);
        double x0 = offset + element.from, x1 = offset + element.to;
        FaceBuild &build = faceFor(face, style);
        build.xMin = std::min(build.xMin, x0);
        build.xMax = std::max(build.xMax, x1);
        build.zMin = std::min(build.zMin, bottom);
        build.zMax = std::max(build.zMax, bottom + height);

        std::vector<std::vector<Vec2d>> holes;
        if (element.kind == ElementKind::Wall) {
            if (auto hole = buildOpening(face, style, {x0, bottom}, {x1, bottom + height}, storey)) {
                holes.push_back(*hole);
                build.holes.push_back(std::move(*hole));
            }
        }
        std::vector<Vec2d> rectangle = {{x0, bottom}, {x1, bottom}, {x1, bottom + height}, {x0, bottom + height}};
        appendWall(convexPieces(rectangle, holes), face.frame, build);
    }

    Vec3f worldOf(const FaceFrame &frame, Vec2d p) const { return at(frame.origin + frame.along * p.x, p.y); }

    // The element's pieces as triangles with wall coordinates for texture coordinates.
    void appendWall(const std::vector<std::vector<Vec2d>> &pieces, const FaceFrame &frame, FaceBuild &build) {
        Mesh wall;
        Vec3f outward(float(frame.along.y), float(-frame.along.x), 0.0f);
        for (const std::vector<Vec2d> &piece : pieces) {
            auto first = uint32_t(wall.positions.size());
            for (Vec2d p : piece) {
                wall.positions.push_back(worldOf(frame, p));
                wall.normals.push_back(outward);
                wall.uvs.push_back({float(p.x), float(p.y)});
            }
            for (uint32_t i = 1; i + 1 < piece.size(); ++i) {
                build.triangles.push_back(uint32_t(result_.mesh.triangleCount() + wall.triangleCount()));
                wall.indices.insert(wall.indices.end(), {first, first + i, first + i + 1});
            }
        }
        wall.setMaterial(build.material);
        result_.mesh.append(wall, Transform());
    }

    // The opening of the wall element from `low` to `high` (wall coordinates) and what fills
    // it, or nothing when its slot is blank, it does not fit or a roof covers it.
    std::optional<std::vector<Vec2d>> buildOpening(const PieceFace &face, const ResolvedStyle &style, Vec2d low,
                                                   Vec2d high, int storey) {
        const WindowStyle *window = style.window(slotAt(face, (low.x + high.x) / 2));
        if (!window) return std::nullopt;
        AbsolutePlacement placement = window->placement;
        if (window->kind == OpeningKind::Door) placement.sillHeight = 0;
        if (placement.width > high.x - low.x || placement.sillHeight + placement.height > high.y - low.y) {
            ++dropped_[fmt::format("the opening of {} does not fit its wall element", window->loc.toString())];
            return std::nullopt;
        }
        CoarseOpening coarse = placeOpening(WallQuad::rectangle(low, high), placement);
        if (std::optional<std::string> roof = coveringRoof(face, coarse)) {
            ++dropped_[fmt::format("storey {}: under the roof of module '{}'", storey, *roof)];
            return std::nullopt;
        }
        const OpeningModel &model = openingModel(*window, style);
        Vec2d along = face.frame.along;
        Vec2d corner = face.frame.origin + along * coarse.bl.x;
        result_.openingSets[model.set].transforms.push_back(
            {{float(along.x), float(-along.y), 0, float(corner.x), float(along.y), float(along.x), 0, float(corner.y),
              0, 0, 1, float(coarse.bl.y)}});
        ++result_.openings;
        std::vector<Vec2d> hole = model.hole;
        for (Vec2d &p : hole) p = p + coarse.bl;
        if (model.apron) addApron(face, hole, low.y, *window, model.apron, style);
        return hole;
    }

    // The window's apron right under its hole (ApronStyle), or a note where the storey leaves it
    // no room: a panel standing out of the wall, its sides in the casing's material, its face
    // in a masonry wall of the relief alone, which the building's atlas bakes.
    void addApron(const PieceFace &face, const std::vector<Vec2d> &hole, double floor, const WindowStyle &window,
                  const std::shared_ptr<const Image> &relief, const ResolvedStyle &style) {
        auto [low, high] = polygonBounds(hole);
        double width = relief->width * kApronCell, height = relief->height * kApronCell;
        Vec2d corner{(low.x + high.x - width) / 2, low.y - height};
        if (corner.y < floor + kApronClearance) {
            ++dropped_[fmt::format("the apron of {} does not fit below its window", window.loc.toString())];
            return;
        }
        MaterialId material = this->material(style, StylePart::Casing);
        uint32_t front = uint32_t(result_.mesh.triangleCount());
        result_.mesh.append(apronPanel(face.frame, corner, {width, height}, window.apron->depth, material),
                            Transform());
        MasonryWall wall;
        wall.face.outline = {corner, corner + Vec2d{width, 0}, corner + Vec2d{width, height},
                             corner + Vec2d{0, height}};
        wall.masonry.mortarColour = Vec3f(1.0f);  // the caller's to tint: the material's colour
        wall.masonry.relief = MasonryRelief{corner, kApronCell, relief};
        wall.material = material;
        wall.triangles = {front, front + 1};
        result_.masonry.push_back(std::move(wall));
    }

    // A box on the wall, `depth` out of it over [corner, corner + size] of its plane: the front first
    // (two triangles), then the four sides; wall metres as texture coordinates throughout.
    Mesh apronPanel(const FaceFrame &frame, Vec2d corner, Vec2d size, double depth, MaterialId material) const {
        Vec3f outward(float(frame.along.y), float(-frame.along.x), 0.0f),
            along(float(frame.along.x), float(frame.along.y), 0.0f);
        auto point = [&](Vec2d p, double out) { return worldOf(frame, corner + p) + outward * float(out); };
        Mesh panel;
        auto quad = [&](std::array<Vec3f, 4> corners, std::array<Vec2d, 4> uvs, Vec3f normal) {
            auto first = uint32_t(panel.positions.size());
            for (size_t k = 0; k < 4; ++k) {
                panel.positions.push_back(corners[k]);
                panel.normals.push_back(normal);
                panel.uvs.push_back({float(corner.x + uvs[k].x), float(corner.y + uvs[k].y)});
            }
            panel.indices.insert(panel.indices.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
        };
        const Vec2d bl{0, 0}, br{size.x, 0}, tr = size, tl{0, size.y};
        quad({point(bl, depth), point(br, depth), point(tr, depth), point(tl, depth)}, {bl, br, tr, tl}, outward);
        quad({point(tl, depth), point(tr, depth), point(tr, 0), point(tl, 0)}, {tl, tr, tr, tl}, {0, 0, 1});
        quad({point(br, depth), point(bl, depth), point(bl, 0), point(br, 0)}, {br, bl, bl, br}, {0, 0, -1});
        quad({point(bl, 0), point(bl, depth), point(tl, depth), point(tl, 0)}, {bl, bl, tl, tl}, -along);
        quad({point(br, depth), point(br, 0), point(tr, 0), point(tr, depth)}, {br, br, tr, tr}, along);
        panel.setMaterial(material);
        return panel;
    }

    struct OpeningModel {
        size_t set = 0;           // in result_.openingSets
        std::vector<Vec2d> hole;  // from the coarse opening's lower left corner
        std::shared_ptr<const Image> apron;
    };

    // The opening of `window` in `style`'s materials, built once: every window of a style has
    // its size, so its pieces differ only by where they stand.
    const OpeningModel &openingModel(const WindowStyle &window, const ResolvedStyle &style) {
        PieceMaterials materials{material(style, StylePart::Casing),  material(style, StylePart::Cornice),
                                 material(style, StylePart::Wall),    material(style, StylePart::Casing),
                                 material(style, StylePart::Cornice), material(style, StylePart::Frame),
                                 material(style, StylePart::Pane),    material(style, StylePart::Door)};
        MaterialId interior = material(style, StylePart::Interior);
        WindowAssemblies::Key key{&window,
                                  {materials.casing, materials.cornice, materials.wall, materials.frame, materials.pane,
                                   materials.door, interior}};
        auto [it, fresh] = openingModels_.try_emplace(key);
        if (!fresh) return it->second;
        const WindowAssembly &assembly =
            windows_.get(style_, key, [&] { return assembleWindow(window, materials, interior); });
        it->second = {result_.openingSets.size(), assembly.hole, assembly.apron};
        result_.openingSets.push_back({assembly.model, {}});
        return it->second;
    }

    int slotAt(const PieceFace &face, double x) const {
        double t = x / face.frame.length;
        if (face.reversed) t = 1 - t;
        for (const EdgeSubdivision &s : structure_.modules[size_t(face.module)].subdivisions)
            if (s.edge == face.edge && s.from <= t && t < s.to) return s.slot;
        return 0;
    }

    // Row 19: the module whose roof stands over the opening's sill just outside the wall.
    std::optional<std::string> coveringRoof(const PieceFace &face, const CoarseOpening &opening) const {
        Vec2d outward{face.frame.along.y, -face.frame.along.x};
        for (size_t m = 0; m < roofs_.size(); ++m) {
            if (int(m) == face.module) continue;
            for (double x : {opening.bl.x, (opening.bl.x + opening.br.x) / 2, opening.br.x}) {
                Vec2d p = face.frame.origin + face.frame.along * x + outward * kRoofProbe;
                std::optional<double> z = roofHeightAt(roofs_[m], p);
                if (z && *z > opening.bl.y) return structure_.modules[m].name;
            }
        }
        return std::nullopt;
    }

    // --- bands ---------------------------------------------------------------------------

    // The band of the run's first element that the run is made of.
    static const BandStyle *bandAt(const BandRun &run, const std::vector<Partition> &partitions,
                                   const std::vector<const BandStyle *> &bands) {
        for (size_t i = 0; i < partitions.size(); ++i)
            if (std::abs(partitions[i].zFrom - run.zFrom) <= 1e-9 && std::abs(partitions[i].zTo - run.zTo) <= 1e-9)
                return bands[i];
        return nullptr;
    }

    void sweepBand(const StoreyFacade &facade, const BandRun &run, const BandStyle *band, const ResolvedStyle &style) {
        if (!band || !band->cornice) return;
        SweepPath path = bandPath(facade, run);
        if (path.points.size() < (path.closed ? 3u : 2u)) return;
        CorniceRun swept =
            buildCorniceRun(*band->cornice, path, run.zTo - run.zFrom, material(style, StylePart::Cornice));
        result_.mesh.append(swept.mesh, Transform());
        for (ConsoleSet &set : swept.consoles) result_.consoles.push_back(std::move(set));
    }

    // The run's elements as a plan polyline, at the joints of their base walls.
    static SweepPath bandPath(const StoreyFacade &facade, const BandRun &run) {
        std::vector<Vec2d> points;
        size_t n = facade.elements.size();
        for (size_t k = 0; k < run.count; ++k) {
            const FacadeElement &e = facade.elements[(run.first + k) % n];
            const BaseWall &wall = facade.baseWalls[e.baseWall];
            Vec2d direction = (wall.end - wall.start) * (1 / wall.length());
            points.push_back(wall.start + direction * e.from);
            points.push_back(wall.start + direction * e.to);
        }
        return sweepPathThrough(points, run.zFrom, run.aroundTheOutline, OutwardSide::Right);
    }

    // --- roofs ---------------------------------------------------------------------------

    // Def 4.12's seams: the edges a neighbour at least as high covers whole.
    std::vector<bool> connectedEdges(int module) const {
        const ModuleStructure &m = structure_.modules[size_t(module)];
        std::vector<bool> connected(placed_[size_t(module)].size(), false);
        for (const ModuleDock &d : structure_.docks) {
            int docked = structure_.moduleIndex(d.docked, d.loc), dominant = structure_.moduleIndex(d.dominant, d.loc);
            if (docked == module && structure_.modules[size_t(dominant)].height() >= m.height())
                connected[size_t(d.dockedEdge)] = true;
            if (dominant == module && d.a <= 0 && d.b >= 1 && structure_.modules[size_t(docked)].height() >= m.height())
                connected[size_t(d.edge)] = true;
        }
        return connected;
    }

    void buildRoofs() {
        for (size_t m = 0; m < structure_.modules.size(); ++m) {
            const ModuleStructure &module = structure_.modules[m];
            std::vector<bool> connected = connectedEdges(int(m));
            try {
                roofs_.push_back(module.roof.kind == RoofStructure::Kind::Flat
                                     ? flatRoof(placed_[m], module.height(), connected, module.roof.parapet)
                                     : generalRoof(placed_[m], module.height(), connected, module.roof.general));
            } catch (const std::invalid_argument &e) {
                throw InputError(module.roof.loc, fmt::format("the roof of module '{}': {}", module.name, e.what()));
            }
        }
        for (const ModuleDock &d : structure_.docks) {
            int docked = structure_.moduleIndex(d.docked, d.loc), dominant = structure_.moduleIndex(d.dominant, d.loc);
            if (roofs_[size_t(docked)].ridge && roofs_[size_t(dominant)].ridge)
                mergeRoofs(roofs_[size_t(dominant)], size_t(d.edge), roofs_[size_t(docked)], size_t(d.dockedEdge));
        }
    }

    void appendRoofs() {
        for (size_t m = 0; m < roofs_.size(); ++m) {
            const ResolvedStyle &top = resolved(int(m), int(structure_.modules[m].storeyHeights.size()) - 1);
            RoofMaterials materials{material(top, StylePart::Roof), material(top, StylePart::RoofSide),
                                    material(top, StylePart::Parapet)};
            result_.mesh.append(roofMesh(roofs_[m], materials), Transform());
        }
    }

    // --- masonry -------------------------------------------------------------------------

    void describeMasonry() {
        for (const FaceKey &key : faceOrder_) {
            if (!key.masonry) continue;
            FaceBuild &build = faces_[key];
            MasonryWall wall;
            wall.face.outline = {
                {build.xMin, build.zMin}, {build.xMax, build.zMin}, {build.xMax, build.zMax}, {build.xMin, build.zMax}};
            wall.face.openings = build.holes;
            uint32_t wallId =
                hashValues({buildingId_, uint32_t(key.module), uint32_t(key.edge), uint32_t(key.reversed)});
            // resolveStyle gives plastered walls no masonry: these all lay stones.
            wall.recipe = styleMasonryRecipe(*key.masonry, wall.face, seed_, wallId);
            wall.material = build.material;
            wall.triangles = std::move(build.triangles);
            result_.masonry.push_back(std::move(wall));
        }
    }

    const BuildingStructure &structure_;
    const BuildingStyle &style_;
    const MaterialByName &material_;
    uint32_t seed_, buildingId_;
    FacadeBuilding result_;
    std::vector<std::vector<Vec2d>> placed_;  // module outlines in plan coordinates
    std::vector<ModuleRoof> roofs_;
    std::map<std::pair<int, int>, ResolvedStyle> resolved_;
    std::map<std::string, MaterialId> materials_;
    std::map<FaceKey, FaceBuild> faces_;
    std::vector<FaceKey> faceOrder_;
    std::map<std::string, size_t> dropped_;
    WindowAssemblies &windows_;
    std::map<WindowAssemblies::Key, OpeningModel> openingModels_;
    size_t elementCount_ = 0;
};

}  // namespace

const WindowAssembly &WindowAssemblies::get(const BuildingStyle &style, const Key &key,
                                            const std::function<WindowAssembly()> &make) {
    std::lock_guard lock(mutex_);
    if (!style_) style_ = &style;
    VEDUTA_CHECK(style_ == &style, "window assemblies given with a style not their own");
    auto it = built_.find(key);
    if (it == built_.end()) it = built_.emplace(key, make()).first;
    return it->second;
}

FacadeBuilding buildFacadeBuilding(const BuildingStructure &structure, const BuildingStyle &style,
                                   const MaterialByName &material, uint32_t seed, uint32_t buildingId,
                                   WindowAssemblies &windows) {
    return BuildingAssembly(structure, style, material, seed, buildingId, windows).build();
}

FacadeBuilding buildFacadeBuilding(const BuildingStructure &structure, const BuildingStyle &style,
                                   const MaterialByName &material, uint32_t seed, uint32_t buildingId) {
    WindowAssemblies windows;
    return buildFacadeBuilding(structure, style, material, seed, buildingId, windows);
}

}  // namespace veduta

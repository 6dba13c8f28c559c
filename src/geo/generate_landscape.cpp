#include "geo/generate_landscape.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <type_traits>

#include <fmt/format.h>

#include "core/hash.h"
#include "core/random_streams.h"
#include "geo/atkis.h"
#include "geo/dgm_file.h"
#include "geo/drape_areas.h"
#include "geo/edbs.h"
#include "geo/land_materials.h"
#include "geo/ribbons.h"
#include "geo/road_markings.h"
#include "geo/road_style.h"
#include "geo/terrain_mesh.h"
#include "geo/terrain_surface.h"
#include "geo/terrain_texture.h"
#include "geo/track_geometry.h"
#include "geo/tree_models.h"
#include "geo/tree_placement.h"
#include "geo/vector_file.h"
#include "geodesy/crs.h"
#include "geodesy/local_frame.h"
#include "geodesy/map_projection.h"

namespace veduta {

namespace {

// The CRS a data file's coordinates are in: the scene file's word, else the file's, else the
// scene's.
int dataEpsg(const DataFileDesc &d, int fileEpsg, int sceneEpsg) {
    if (d.epsg != 0) return d.epsg;
    return fileEpsg != 0 ? fileEpsg : sceneEpsg;
}

HeightGrid readTerrain(const LandscapeDesc &land, int sceneEpsg, std::vector<std::string> &warnings) {
    std::vector<std::filesystem::path> files;
    for (const DataFileDesc &d : land.dgm) files.push_back(d.file);
    // A geographic DGM (SRTM, global DEMs) can only be meant to be warped; a projected one in
    // another CRS than the scene's is more likely a mistake, and resampling would change the
    // surveyed heights, so it is refused below.
    Dgm dgm = readDgmTiles(files, NoDataPolicy{land.fillDistance}, warnings, sceneEpsg);
    const DataFileDesc &first = land.dgm.front();
    int epsg = dataEpsg(first, dgm.epsg, sceneEpsg);
    if (epsg != sceneEpsg) {
        throw InputError(first.loc,
                         fmt::format("the DGM is in EPSG:{} and the scene in EPSG:{}; a projected DGM is not "
                                     "reprojected: give it in the scene's CRS (gdalwarp does it)",
                                     epsg, sceneEpsg));
    }
    return std::move(dgm.grid);
}

bool isEdbs(const std::filesystem::path &file) {
    std::ifstream in(file, std::ios::binary);
    char head[4] = {};
    in.read(head, 4);
    return in && std::string_view(head, 4) == "EDBS";
}

// Every point into the scene's CRS; a point that cannot be one of the layer's CRS (GeoJSON
// without a crs member is WGS 84 longitude and latitude) is an error naming its object.
void convertPoints(AtkisData &data, const MapProjection &projection) {
    const AtkisObject *object = nullptr;
    auto convertPoint = [&](MapPoint &p) {
        try {
            p = projection.toScene(p);
        } catch (const std::out_of_range &e) {
            throw std::invalid_argument(fmt::format("{}: ({}, {}) is no point of EPSG:{}: {}", object->where, p.easting,
                                                    p.northing, projection.source().epsg, e.what()));
        }
    };
    for (AtkisObject &o : data.objects) {
        object = &o;
        for (MapRing &ring : o.areas)
            for (MapPoint &p : ring) convertPoint(p);
        for (MapLine &line : o.lines)
            for (MapPoint &p : line) convertPoint(p);
        for (MapPoint &p : o.points) convertPoint(p);
    }
}

// A layer's objects in the scene's CRS. EDBS areas must close (an open outline names its
// object); other sources are read through GDAL.
AtkisData readLayer(const DataFileDesc &d, const Georeference &georef, std::vector<std::string> &warnings) {
    if (!std::filesystem::is_regular_file(d.file))
        throw InputError(d.loc, fmt::format("cannot read the ATKIS file {}", d.file.string()));
    AtkisData data;
    if (isEdbs(d.file)) {
        EdbsConversion conversion = toAtkis(readEdbs(d.file), IncompleteObjects::Error);
        warnings.insert(warnings.end(), conversion.warnings.begin(), conversion.warnings.end());
        data = std::move(conversion.atkis);
    } else {
        data = readVectorFile(d.file, warnings);
    }
    int epsg = dataEpsg(d, data.epsg, georef.epsg);
    if (epsg != georef.epsg) {
        try {
            convertPoints(data, MapProjection(crsByEpsg(epsg), georef));
        } catch (const std::invalid_argument &e) {
            throw InputError(d.loc, e.what());
        }
    }
    data.epsg = georef.epsg;
    return data;
}

// The stable identity of an object for its random choices: its ATKIS id, or else its
// Objektart and geometry (coordinates bit for bit, each part's size), never its place in the
// layers: objects added before it leave its trees as they were. Two objects without ids of one
// kind and geometry share their trees' draws.
uint32_t objectKey(const AtkisObject &o) {
    if (!o.id.empty()) return hashString(o.id);
    std::vector<uint32_t> values{streamTag(RandomStream::AtkisGeometry), uint32_t(o.type)};
    auto add = [&](const std::vector<MapPoint> &part) {
        values.push_back(uint32_t(part.size()));
        for (const MapPoint &p : part) {
            for (double c : {p.easting, p.northing}) {
                auto bits = std::bit_cast<uint64_t>(c);
                values.insert(values.end(), {uint32_t(bits), uint32_t(bits >> 32)});
            }
        }
    };
    for (const MapRing &ring : o.areas) add(ring);
    for (const MapLine &line : o.lines) add(line);
    add(o.points);
    return hashSequence(values);
}

std::vector<Vec2f> toLocal(const std::vector<MapPoint> &points, const LocalFrame &frame) {
    std::vector<Vec2f> local;
    local.reserve(points.size());
    for (const MapPoint &p : points) local.push_back(frame.toLocal(p));
    return local;
}

// The most memory the simplification's error bounds may take.
constexpr double kSimplifyBytes = 8e9;

// Metres a tree keeps from a ribbon's or a city street's edge.
constexpr float kTreeClearance = 1.5f;

// The owner of terrain won by a city's street, in place of an object index.
constexpr uint32_t kCityStreetOwner = kNoArea - 1;

// Polylines with a clearance each, bucketed on a square grid: whether a point comes closer
// to any of them than its clearance.
class SegmentClearance {
  public:
    void add(const std::vector<Vec2f> &line, float clearance) {
        for (size_t i = 0; i + 1 < line.size(); ++i) {
            auto index = uint32_t(segments_.size());
            segments_.push_back({line[i], line[i + 1], clearance});
            Vec2f lo{std::min(line[i].x, line[i + 1].x) - clearance, std::min(line[i].y, line[i + 1].y) - clearance};
            Vec2f hi{std::max(line[i].x, line[i + 1].x) + clearance, std::max(line[i].y, line[i + 1].y) + clearance};
            for (int64_t y = cell(lo.y); y <= cell(hi.y); ++y)
                for (int64_t x = cell(lo.x); x <= cell(hi.x); ++x) buckets_[{x, y}].push_back(index);
        }
    }

    bool covers(Vec2f p) const {
        auto it = buckets_.find({cell(p.x), cell(p.y)});
        if (it == buckets_.end()) return false;
        for (uint32_t s : it->second) {
            const Segment &g = segments_[s];
            Vec2f d = g.b - g.a, ap = p - g.a;
            float length2 = d.x * d.x + d.y * d.y;
            float t = length2 > 0 ? std::clamp((ap.x * d.x + ap.y * d.y) / length2, 0.0f, 1.0f) : 0.0f;
            Vec2f off = ap - Vec2f{d.x * t, d.y * t};
            if (off.x * off.x + off.y * off.y < g.clearance * g.clearance) return true;
        }
        return false;
    }

  private:
    static constexpr float kCell = 25;  // metres
    static int64_t cell(float v) { return int64_t(std::floor(v / kCell)); }

    struct Segment {
        Vec2f a, b;
        float clearance;
    };
    std::vector<Segment> segments_;
    std::map<std::pair<int64_t, int64_t>, std::vector<uint32_t>> buckets_;
};

// What the landscape makes of an object: an area draped on the terrain, a ribbon, trees.
bool drapesAsArea(const AtkisObject &o) {
    LandClass c = landClass(o);
    return o.geometry == AtkisGeometry::Area && c != LandClass::Other && c != LandClass::Parcel;
}
bool drawsAsRibbon(const AtkisObject &o) {
    LandClass c = landClass(o);
    return o.geometry == AtkisGeometry::Line && (c == LandClass::Road || c == LandClass::Path || c == LandClass::Rail);
}
bool plantsTreesIn(const LandscapeDesc &land, const AtkisObject &o) {
    return land.trees && treeStand(landClass(o), treeKind(o)).spacing > 0;
}

// Nothing a layer holds goes unsaid: a layer with objects the landscape does not draw says
// how many, and of which Objektarten.
void reportUndrawn(const LandscapeDesc &land, const DataFileDesc &d, const AtkisData &layer,
                   std::vector<std::string> &warnings) {
    std::map<std::string, size_t> undrawn;
    for (const AtkisObject &o : layer.objects) {
        if (drapesAsArea(o) || drawsAsRibbon(o) || plantsTreesIn(land, o)) continue;
        std::string kind = o.type ? std::to_string(o.type) : "no Objektart";
        if (!o.typeName.empty()) kind += " " + o.typeName;
        if (landClass(o) == LandClass::Parcel) kind += " (parcels: cadastre, not land cover)";
        ++undrawn[kind];
    }
    if (layer.objects.empty()) {
        warnings.push_back(fmt::format("{}: {} holds no objects", d.loc.toString(), d.file.string()));
        return;
    }
    size_t count = 0;
    std::vector<std::pair<size_t, std::string>> kinds;
    for (const auto &[kind, n] : undrawn) {
        count += n;
        kinds.push_back({n, kind});
    }
    if (count == 0) return;
    std::sort(kinds.rbegin(), kinds.rend());
    std::string list;
    for (size_t k = 0; k < std::min<size_t>(kinds.size(), 5); ++k)
        list += fmt::format("{}{} × {}", k ? ", " : "", kinds[k].first, kinds[k].second);
    if (kinds.size() > 5) list += fmt::format(" and {} more kinds", kinds.size() - 5);
    warnings.push_back(
        fmt::format("{}: {}: {} of its {} objects are of kinds the landscape does not draw ({}); "
                    "docs/draping.md lists those it does",
                    d.loc.toString(), d.file.string(), count, layer.objects.size(), list));
}

// The outlines of the lakes' and rivers' areas, local: where the ground is wet (terrain_texture.h);
// null without water.
std::shared_ptr<const ShoreDistance> shoreOf(const std::vector<AtkisObject> &objects, const LocalFrame &frame) {
    std::vector<std::pair<Vec2d, Vec2d>> edges;
    for (const AtkisObject &o : objects) {
        LandClass c = landClass(o);
        if (!drapesAsArea(o) || (c != LandClass::Water && c != LandClass::River)) continue;
        for (const MapRing &ring : o.areas) {
            for (size_t k = 0; k < ring.size(); ++k)
                edges.push_back({toLocalDouble(ring[k], frame), toLocalDouble(ring[(k + 1) % ring.size()], frame)});
        }
    }
    return edges.empty() ? nullptr : std::make_shared<const ShoreDistance>(edges);
}

class LandscapeBuilder {
  public:
    LandscapeBuilder(const LandscapeDesc &land, LandscapeData data, uint32_t seed, const Georeference &georef,
                     const std::vector<LocalPolygon> &streetAreas, RenderSceneBuilder &builder,
                     const AddProcedural &addProcedural, const Camera *camera, std::vector<std::string> &warnings) :
        land_(land),
        seed_(seed),
        frame_(MapProjection(crsByEpsg(georef.epsg), georef).frame()),
        streetAreas_(streetAreas),
        builder_(builder),
        warnings_(warnings),
        grid_(std::make_shared<const HeightGrid>(std::move(data.grid))),
        objects_(std::move(data.objects)),
        materials_(builder, addProcedural, grid_, frame_, shoreOf(objects_, frame_), seed) {
        if (camera) camera_ = camera->position;
    }

    LandscapeGround build() {
        addTerrain();
        addRibbons();
        if (land_.trees) addTrees();
        std::shared_ptr<const TerrainSurface> surface = surface_;
        return {surface, [surface](const std::vector<Vec2f> &footprint) -> std::optional<float> {
                    std::optional<double> lowest = surface->minOver(footprint);
                    if (!lowest) return std::nullopt;
                    return float(*lowest);
                }};
    }

  private:
    bool plantsTrees(const AtkisObject &o) const { return plantsTreesIn(land_, o); }

    void addTerrain() {
        std::vector<DrapeArea> areas;
        for (size_t i = 0; i < objects_.size(); ++i) {
            const AtkisObject &o = objects_[i];
            if (!drapesAsArea(o)) continue;
            for (const MapRing &ring : o.areas) areas.push_back({ring, landClass(o), uint32_t(i), o.where});
        }
        for (size_t i = 0; i < streetAreas_.size(); ++i) {
            MapRing ring;
            for (Vec2d p : streetAreas_[i]) ring.push_back({frame_.origin.easting + p.x, frame_.origin.northing + p.y});
            areas.push_back(
                {std::move(ring), LandClass::CityStreet, kCityStreetOwner, fmt::format("city street area {}", i)});
            for (size_t k = 0; k < streetAreas_[i].size(); ++k) {
                Vec2d a = streetAreas_[i][k], b = streetAreas_[i][(k + 1) % streetAreas_[i].size()];
                streetClearance_.add({Vec2f{float(a.x), float(a.y)}, Vec2f{float(b.x), float(b.y)}}, kTreeClearance);
            }
        }
        Mesh mesh;
        if (areas.empty()) {
            checkSimplifiable();
            TerrainMeshOptions options;
            options.maxError = land_.simplify;
            options.material = materials_.land(LandClass::Other);
            mesh = terrainMesh(*grid_, frame_, options);
        } else {
            if (land_.simplify > 0)
                warnings_.push_back(
                    fmt::format("{}: the terrain keeps its full resolution under draped ATKIS areas; "
                                "simplify applies to bare terrain only",
                                land_.loc.toString()));
            DrapedTerrain draped = atLandscape([&] { return drapeAreas(*grid_, frame_, areas, {}); });
            MaterialId bare = materials_.land(LandClass::Other);
            triangleObject_.resize(draped.triangleArea.size(), kNoArea);
            for (size_t t = 0; t < draped.triangleArea.size(); ++t) {
                uint32_t a = draped.triangleArea[t];
                draped.mesh.triangleMaterials[t] = a == kNoArea ? bare : materials_.land(areas[a].landClass);
                if (a != kNoArea) triangleObject_[t] = areas[a].objectIndex;
            }
            mesh = std::move(draped.mesh);
        }
        surface_ = std::make_shared<TerrainSurface>(mesh, gridLines(*grid_, frame_));
        builder_.addWorldMesh(std::move(mesh), land_.objectId);
    }

    // The roads, paths and rails, all in one mesh, in their pavements' materials, and the
    // roads' markings in another.
    void addRibbons() {
        std::vector<Mesh> pieces;
        std::vector<RoadStyle> styles;
        for (const AtkisObject &o : objects_) {
            if (!drawsAsRibbon(o)) continue;
            RoadStyle style = roadStyle(o);
            RibbonOptions options;
            options.lift = ribbonLift(landClass(o));
            MaterialId material = materials_.pavement(style.pavement, style.tracks);
            for (const MapLine &line : o.lines) {
                Mesh ribbon =
                    atLandscape([&] { return drapeRibbon(line, style.width, *surface_, frame_, options); }, &o);
                ribbon.setMaterial(material);
                pieces.push_back(std::move(ribbon));
                styles.push_back(style);
                ribbonClearance_.add(toLocal(line, frame_), float(style.width / 2 + kTreeClearance));
            }
        }
        std::vector<MarkedRoad> roads;
        for (size_t i = 0; i < pieces.size(); ++i) roads.push_back({styles[i], &pieces[i]});
        Mesh markings = roadMarkings(roads, {});
        Mesh ribbons;
        for (const Mesh &piece : pieces) ribbons.append(piece, Transform());
        if (ribbons.triangleCount() > 0) builder_.addWorldMesh(std::move(ribbons), land_.objectId);
        if (markings.triangleCount() > 0) {
            markings.setMaterial(materials_.marking());
            builder_.addWorldMesh(std::move(markings), land_.objectId);
        }
        if (camera_) addTracks(pieces, styles);
    }

    // The sleepers and rails of the railways near the camera, in one mesh.
    void addTracks(const std::vector<Mesh> &pieces, const std::vector<RoadStyle> &styles) {
        Mesh tracks;
        for (size_t i = 0; i < pieces.size(); ++i) {
            if (styles[i].rank != RoadRank::Rail) continue;
            Mesh track = trackGeometry(pieces[i], styles[i].width, styles[i].tracks, *camera_);
            for (MaterialId &m : track.triangleMaterials) m = materials_.track(TrackSurface(m));
            tracks.append(track, Transform());
        }
        if (tracks.triangleCount() > 0) builder_.addWorldMesh(std::move(tracks), land_.objectId);
    }

    void addTrees() {
        TreeSet set;
        set.limit = land_.treeBudget;
        std::vector<uint32_t> planter;  // per tree: the object it was planted for
        for (size_t i = 0; i < objects_.size(); ++i) {
            const AtkisObject &o = objects_[i];
            if (!plantsTrees(o)) continue;
            TreeStand stand = treeStand(landClass(o), treeKind(o));
            uint32_t key = objectKey(o);
            try {
                for (const MapRing &ring : o.areas) plantArea(set, toLocal(ring, frame_), stand, seed_, key);
                for (const MapLine &line : o.lines) plantLine(set, toLocal(line, frame_), stand, seed_, key);
                if (!o.points.empty()) plantPoints(set, toLocal(o.points, frame_), stand, seed_, key);
            } catch (const std::invalid_argument &e) {
                throw InputError(land_.loc, fmt::format("{}: {}", o.where, e.what()));
            }
            planter.resize(set.trees.size(), uint32_t(i));
        }
        if (set.limitReached)
            throw InputError(land_.loc,
                             fmt::format("the landscape would have more than {} trees (tree_budget); "
                                         "raise tree_budget or set trees=\"false\"",
                                         land_.treeBudget));
        addTreeInstances(set, planter);
    }

    // Whether a tree planted for object `planter` may stand at `on`: a tree of an area only
    // where that area won the draping (not in a lake or on a road area drawn over the forest),
    // a tree of a row or a point not in water or on a traffic area; and none on a ribbon or on
    // a city's street, nor closer to their edges than kTreeClearance; none on rock or above the
    // tree line (treeMayGrow).
    bool treeMayStand(const PlacedTree &tree, uint32_t planter, const TerrainSurface::PointOnSurface &on) const {
        if (ribbonClearance_.covers(tree.position) || streetClearance_.covers(tree.position)) return false;
        if (!treeMayGrow(*grid_, frame_, {tree.position.x, tree.position.y})) return false;
        uint32_t owner = triangleObject_.empty() ? kNoArea : triangleObject_[on.triangle];
        if (owner == kCityStreetOwner) return false;
        if (objects_[planter].geometry == AtkisGeometry::Area) return owner == planter;
        if (owner == kNoArea) return true;
        LandClass c = landClass(objects_[owner]);
        return c != LandClass::Water && c != LandClass::River && c != LandClass::Road && c != LandClass::Path &&
            c != LandClass::Rail;
    }

    void addTreeInstances(const TreeSet &set, const std::vector<uint32_t> &planter) {
        TreeMaterials broadleaf = treeMaterials(builder_, TreeKind::Broadleaf);
        TreeMaterials conifer = treeMaterials(builder_, TreeKind::Conifer);
        PrototypeId prototypes[2][kTreeVariants] = {};
        bool made[2][kTreeVariants] = {};
        for (size_t i = 0; i < set.trees.size(); ++i) {
            const PlacedTree &tree = set.trees[i];
            std::optional<TerrainSurface::PointOnSurface> on = surface_->triangleAt({tree.position.x, tree.position.y});
            if (!on || !treeMayStand(tree, planter[i], *on)) continue;  // off the DGM, or not its place
            int k = tree.kind == TreeKind::Conifer ? 1 : 0;
            if (!made[k][tree.variant]) {
                const TreeMaterials &materials = k == 1 ? conifer : broadleaf;
                prototypes[k][tree.variant] =
                    builder_.addPrototype(treeModel(tree.kind, tree.variant, seed_, materials));
                made[k][tree.variant] = true;
            }
            builder_.addInstance({treeTransform(tree, float(on->height)), prototypes[k][tree.variant], kNoMaterial,
                                  land_.objectId, 0, 0});
        }
    }

    // The simplification pads the grid to a square of 2^k + 1 nodes with a 4-byte bound each:
    // a long thin DGM would ask for its longer side squared.
    void checkSimplifiable() const {
        if (land_.simplify <= 0) return;
        double side = 1;
        while (side < std::max(grid_->columns, grid_->rows)) side = 2 * side;
        double bytes = 4 * (side + 1) * (side + 1);
        if (bytes > kSimplifyBytes)
            throw InputError(land_.loc,
                             fmt::format("simplifying this {} × {} DGM needs {:.1f} GB (it is padded to a "
                                         "square); cut it into square tiles or leave simplify at 0",
                                         grid_->columns, grid_->rows, bytes / 1e9));
    }

    // An error of draping or a ribbon at the <landscape>, naming the object when known.
    template <typename Make>
    std::invoke_result_t<Make> atLandscape(Make make, const AtkisObject *object = nullptr) const {
        try {
            return make();
        } catch (const InputError &e) {
            throw InputError(land_.loc, object ? fmt::format("{}: {}", object->where, e.message()) : e.message());
        }
    }

    const LandscapeDesc &land_;
    uint32_t seed_;
    LocalFrame frame_;
    const std::vector<LocalPolygon> &streetAreas_;
    RenderSceneBuilder &builder_;
    std::vector<std::string> &warnings_;
    std::shared_ptr<const HeightGrid> grid_;
    std::vector<AtkisObject> objects_;
    LandMaterials materials_;
    std::optional<Vec3f> camera_;  // where railways get solid sleepers and rails near it
    std::shared_ptr<TerrainSurface> surface_;
    // Per terrain triangle: the object whose area won it, kCityStreetOwner or kNoArea.
    std::vector<uint32_t> triangleObject_;
    SegmentClearance ribbonClearance_;
    SegmentClearance streetClearance_;  // the city street areas' edges
};

}  // namespace

LandscapeData readLandscape(const LandscapeDesc &land, const std::optional<Georeference> &georeference,
                            std::vector<std::string> &warnings) {
    if (!georeference)
        throw InputError(land.loc, "a <landscape> needs the scene's <georeference crs=\"EPSG:…\" origin=\"E N\">");
    LandscapeData data;
    data.grid = readTerrain(land, georeference->epsg, warnings);
    for (const DataFileDesc &d : land.layers) {
        AtkisData layer = readLayer(d, *georeference, warnings);
        reportUndrawn(land, d, layer, warnings);
        for (AtkisObject &o : layer.objects) data.objects.push_back(std::move(o));
    }
    return data;
}

LandscapeGround generateLandscape(const LandscapeDesc &land, LandscapeData data, uint32_t seed,
                                  const std::optional<Georeference> &georeference,
                                  const std::vector<LocalPolygon> &streetAreas, RenderSceneBuilder &builder,
                                  std::vector<std::string> &warnings, const AddProcedural &addProcedural,
                                  const Camera *camera) {
    if (!georeference)
        throw InputError(land.loc, "a <landscape> needs the scene's <georeference crs=\"EPSG:…\" origin=\"E N\">");
    return LandscapeBuilder(land, std::move(data), seed, *georeference, streetAreas, builder, addProcedural, camera,
                            warnings)
        .build();
}

LandscapeGround generateLandscape(const LandscapeDesc &land, uint32_t seed,
                                  const std::optional<Georeference> &georeference,
                                  const std::vector<LocalPolygon> &streetAreas, RenderSceneBuilder &builder,
                                  std::vector<std::string> &warnings, const AddProcedural &addProcedural,
                                  const Camera *camera) {
    return generateLandscape(land, readLandscape(land, georeference, warnings), seed, georeference, streetAreas,
                             builder, warnings, addProcedural, camera);
}

}  // namespace veduta

#include "city/citygml_buildings.h"

#include <algorithm>
#include <limits>
#include <map>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "city/citygml_measures.h"
#include "city/citygml_twin.h"
#include "city/modular_buildings.h"
#include "core/check.h"
#include "core/error.h"
#include "core/hash.h"
#include "geodesy/map_projection.h"
#include "slg/ear_clipping.h"

namespace veduta {

namespace {

// The materials of a file's appearances: one per colour and one per texture image, each named
// by it. An image that cannot be read is said once; its polygons take their colour or kind.
class AppearanceMaterials {
  public:
    AppearanceMaterials(RenderSceneBuilder &builder, const AddTexture &addTexture) :
        builder_(builder), addTexture_(addTexture) {}

    // The polygon's material, and whether it is its texture's.
    std::pair<MaterialId, bool> of(const CityGmlPolygon &polygon) {
        if (!polygon.texture.empty())
            if (std::optional<MaterialId> textured = texture(polygon.texture)) return {*textured, true};
        if (polygon.diffuse) return {builder_.findOrAddMaterial(colour(*polygon.diffuse)), false};
        return {builder_.findOrAddMaterial(cityGmlMaterial(polygon.kind)), false};
    }

    void warnUnread(std::vector<std::string> &warnings) const {
        for (const auto &[file, image] : images_)
            if (!image.material)
                warnings.push_back(fmt::format("{}; {} polygon(s) are drawn without it", image.why, image.polygons));
    }

  private:
    struct Image {
        std::optional<MaterialId> material;
        std::string why;  // it has no material
        uint32_t polygons = 0;
    };

    std::optional<MaterialId> texture(const std::filesystem::path &file) {
        auto [it, fresh] = images_.try_emplace(file);
        Image &image = it->second;
        if (fresh) {
            try {
                Material m = Material::lambertian("citygml/texture/" + file.generic_string(), Vec3f(1.0f));
                m.diffuseMap = addTexture_(file);
                image.material = builder_.findOrAddMaterial(std::move(m));
            } catch (const InputError &e) {
                image.why = e.what();
            }
        }
        ++image.polygons;
        return image.material;
    }

    static Material colour(const Vec3f &diffuse) {
        return Material::lambertian(fmt::format("citygml/x3d/{:.3f},{:.3f},{:.3f}", diffuse.x, diffuse.y, diffuse.z),
                                    diffuse);
    }

    RenderSceneBuilder &builder_;
    const AddTexture &addTexture_;
    std::map<std::filesystem::path, Image> images_;
};

std::string envelopeCentre(const CityGmlModel &model) {
    if (!model.envelopeLow || !model.envelopeHigh) return "the file's centre";
    return fmt::format("{:.0f} {:.0f}", (model.envelopeLow->x + model.envelopeHigh->x) / 2,
                       (model.envelopeLow->y + model.envelopeHigh->y) / 2);
}

// Whether the centre of the building's bounding box lies in `box` (E0 N0 E1 N1 of the scene's CRS).
bool centreWithin(const CityGmlBuilding &building, const MapProjection &projection, const std::array<double, 4> &box,
                  const FileLoc &loc) {
    double low[2] = {1e300, 1e300}, high[2] = {-1e300, -1e300};
    for (const CityGmlPolygon &polygon : building.polygons)
        for (const CrsCoordinate &p : polygon.rings.front()) {
            low[0] = std::min(low[0], p.x), high[0] = std::max(high[0], p.x);
            low[1] = std::min(low[1], p.y), high[1] = std::max(high[1], p.y);
        }
    MapPoint centre;
    try {
        centre = projection.toScene({(low[0] + high[0]) / 2, (low[1] + high[1]) / 2});
    } catch (const std::out_of_range &e) {
        throw InputError(loc, fmt::format("building {}: {}", building.id, e.what()));
    }
    return centre.easting >= box[0] && centre.easting <= box[2] && centre.northing >= box[1] &&
        centre.northing <= box[3];
}

Mesh buildingMesh(const CityGmlBuilding &building, const MapProjection &projection, const FileLoc &loc,
                  AppearanceMaterials &materials) {
    Mesh mesh;
    for (const CityGmlPolygon &polygon : building.polygons) {
        auto first = uint32_t(mesh.positions.size());
        for (const auto &ring : polygon.rings)
            for (const CrsCoordinate &p : ring) {
                try {
                    mesh.positions.push_back(projection.toRender(p));
                } catch (const std::out_of_range &e) {
                    throw InputError(loc,
                                     fmt::format("building {}, polygon {}: {}", building.id, polygon.id, e.what()));
                }
            }
        auto [material, textured] = materials.of(polygon);
        if (textured) {
            mesh.uvs.resize(first, Vec2f{});  // the untextured polygons before this one
            mesh.uvs.insert(mesh.uvs.end(), polygon.uvs.begin(), polygon.uvs.end());
        }
        for (uint32_t index : polygon.triangles) mesh.indices.push_back(first + index);
        mesh.triangleMaterials.insert(mesh.triangleMaterials.end(), polygon.triangles.size() / 3, material);
    }
    if (!mesh.uvs.empty()) mesh.uvs.resize(mesh.positions.size(), Vec2f{});
    return mesh;
}

BuildingRecord recordOf(const CityGmlBuilding &building, const MapProjection &projection) {
    BuildingMeasures m = measureBuilding(building);
    BuildingRecord record{cityGmlBuildingId(building.id),
                          float(m.ground),
                          float(m.eaves),
                          float(m.ridge),
                          m.roofType ? std::string(roofTypeName(*m.roofType)) : std::string(),
                          {}};
    for (const auto &outline : m.footprint) {
        std::vector<Vec2f> &points = record.footprint.emplace_back();
        for (const CrsCoordinate &p : outline) {
            MapPoint local = projection.toLocal({p.x, p.y});
            points.push_back({float(local.easting), float(local.northing)});
        }
    }
    return record;
}

ModelEffort effortOf(const CityGmlBuilding &building) {
    ModelEffort effort;
    effort.surfaces = building.polygons.size();
    for (const CityGmlPolygon &polygon : building.polygons)
        for (const auto &ring : polygon.rings) effort.vertices += ring.size();
    return effort;
}

// The first untextured material of a polygon of this kind, else the kind's own: what a box
// takes for its walls and roof.
MaterialId boxMaterial(const CityGmlBuilding &building, SurfaceKind kind, AppearanceMaterials &materials,
                       RenderSceneBuilder &builder) {
    for (const CityGmlPolygon &polygon : building.polygons)
        if (polygon.kind == kind && polygon.texture.empty()) return materials.of(polygon).first;
    return builder.findOrAddMaterial(cityGmlMaterial(kind));
}

// The coarse level of a building: each outline of its footprint raised from its ground to half
// way between its eaves and its ridge (a gable roof's mean height), with a flat top; none for a
// building without a footprint (it is drawn as the file has it).
std::optional<Mesh> boxMesh(const CityGmlBuilding &building, const MapProjection &projection, MaterialId wall,
                            MaterialId roof) {
    BuildingMeasures m = measureBuilding(building);
    if (m.footprint.empty()) return std::nullopt;
    double top = (m.eaves + m.ridge) / 2;
    Mesh mesh;
    for (const std::vector<CrsCoordinate> &outline : m.footprint) {
        Polygon2d plan;
        auto first = uint32_t(mesh.positions.size());
        for (const CrsCoordinate &p : outline) {
            Vec3f low = projection.toRender({p.x, p.y, m.ground}), high = projection.toRender({p.x, p.y, top});
            mesh.positions.insert(mesh.positions.end(), {low, high});
            plan.push_back({low.x, low.y});
        }
        auto n = uint32_t(outline.size());
        for (uint32_t i = 0; i < n; ++i) {
            uint32_t a = first + 2 * i, b = first + 2 * ((i + 1) % n);
            mesh.indices.insert(mesh.indices.end(), {a, b, b + 1, a, b + 1, a + 1});
            mesh.triangleMaterials.insert(mesh.triangleMaterials.end(), 2, wall);
        }
        for (auto [i, j, k] : clipEars(plan)) {
            mesh.indices.insert(mesh.indices.end(), {first + 2 * i + 1, first + 2 * j + 1, first + 2 * k + 1});
            mesh.triangleMaterials.push_back(roof);
        }
    }
    return mesh;
}

// A building of the file as it will be drawn: how far from the camera and whether as a box.
struct PlacedBuilding {
    const CityGmlBuilding *building = nullptr;
    Mesh mesh;                // as the file has it; emptied when drawn as a box
    std::optional<Mesh> box;  // when drawn coarse
    float distance = 0;
};

uint64_t bytesOf(const PlacedBuilding &b) {
    return (b.box ? b.box->triangleCount() : b.mesh.triangleCount()) * kBytesPerTriangle;
}

// The buildings the element's coarse rule picks are boxes; past the builder's geometry budget,
// the farthest become boxes too (ties in file order), with a warning.
void chooseDetail(std::vector<PlacedBuilding> &placed, const CityGmlDesc &desc, const Camera &camera,
                  const MapProjection &projection, AppearanceMaterials &materials, RenderSceneBuilder &builder,
                  std::vector<std::string> &warnings) {
    auto coarsen = [&](PlacedBuilding &b) {
        MaterialId wall = boxMaterial(*b.building, SurfaceKind::Wall, materials, builder);
        MaterialId roof = boxMaterial(*b.building, SurfaceKind::Roof, materials, builder);
        b.box = boxMesh(*b.building, projection, wall, roof);
        if (b.box) b.mesh = Mesh();  // freed as soon as it is not wanted
        return b.box.has_value();
    };
    uint64_t expected = 0;
    for (PlacedBuilding &b : placed) {
        Vec3f low(std::numeric_limits<float>::max()), high(-std::numeric_limits<float>::max());
        for (const Vec3f &p : b.mesh.positions) {
            low = {std::min(low.x, p.x), std::min(low.y, p.y), std::min(low.z, p.z)};
            high = {std::max(high.x, p.x), std::max(high.y, p.y), std::max(high.z, p.z)};
        }
        if (b.mesh.positions.empty()) continue;  // no triangle to count or coarsen
        b.distance = length((low + high) * 0.5f - camera.position);
        if (desc.coarse.isCoarse(camera, low, high)) coarsen(b);
        expected += bytesOf(b);
    }
    uint64_t budget = builder.geometryBytesLeft();
    if (expected <= budget) return;
    std::vector<PlacedBuilding *> order;
    for (PlacedBuilding &b : placed) order.push_back(&b);
    std::stable_sort(order.begin(), order.end(),
                     [](const PlacedBuilding *a, const PlacedBuilding *b) { return a->distance > b->distance; });
    size_t coarsened = 0;
    for (PlacedBuilding *b : order) {
        if (expected <= budget) break;
        if (b->box) continue;
        expected -= bytesOf(*b);
        coarsened += coarsen(*b) ? 1 : 0;
        expected += bytesOf(*b);
    }
    warnings.push_back(fmt::format(
        "{}: the buildings would take more than the geometry budget of {:.1f} GB; {} of them drawn as boxes{}",
        desc.loc.toString(), double(budget) / double(1ull << 30), coarsened,
        expected > budget ? ", and even so they do not fit" : ""));
}

// Each building in full as a mesh of its own with its building id; the boxes in one mesh
// together, which keeps their records but not their ids.
void addBuildings(std::vector<PlacedBuilding> &placed, const CityGmlDesc &desc, const MapProjection &projection,
                  RenderSceneBuilder &builder) {
    LodCounts file, boxes;
    Mesh merged;
    for (PlacedBuilding &b : placed) {
        LodCounts &counts = b.box ? boxes : file;
        ++counts.buildings;
        counts.triangles += b.box ? b.box->triangleCount() : b.mesh.triangleCount();
        if (b.box) {
            ++counts.merged;
            merged.append(*b.box, Transform());
        } else {
            ++counts.meshes;
            builder.addWorldMesh(std::move(b.mesh), desc.objectId, cityGmlBuildingId(b.building->id));
        }
        builder.recordBuilding(recordOf(*b.building, projection));
        builder.addEffort(effortOf(*b.building));
    }
    if (merged.triangleCount() > 0) {
        ++boxes.meshes;
        builder.addWorldMesh(std::move(merged), desc.objectId);
    }
    if (file.buildings > 0) builder.countLod("citygml/file", file);
    if (boxes.buildings > 0) builder.countLod("citygml/box", boxes);
}

}  // namespace

Material cityGmlMaterial(SurfaceKind kind) {
    switch (kind) {
    case SurfaceKind::Wall: return Material::lambertian("citygml/wall", {0.72f, 0.69f, 0.63f});
    case SurfaceKind::Roof: return Material::lambertian("citygml/roof", {0.48f, 0.21f, 0.15f});
    case SurfaceKind::Ground: return Material::lambertian("citygml/ground", {0.35f, 0.34f, 0.32f});
    case SurfaceKind::Closure: return Material::lambertian("citygml/closure", {0.6f, 0.6f, 0.6f});
    case SurfaceKind::Other: break;
    }
    return Material::lambertian("citygml/other", {0.6f, 0.58f, 0.55f});
}

uint32_t cityGmlBuildingId(const std::string &gmlId) {
    constexpr uint32_t kIds = (1u << 24) - 1;  // what the float IndexBuilding pass holds exactly
    return 1 + hashString(gmlId) % kIds;
}

int cityGmlEpsg(const CityGmlDesc &desc, const CityGmlModel &model) {
    if (!model.srsName.empty() && model.epsg == 0)
        throw InputError(desc.fileLoc,
                         fmt::format("the file's srsName '{}' names no CRS veduta knows "
                                     "(docs/coordinates.md lists them)",
                                     model.srsName));
    if (model.epsg != 0) {
        try {
            crsByEpsg(model.epsg);
        } catch (const std::invalid_argument &e) {
            throw InputError(desc.fileLoc, fmt::format("the file's srsName '{}': {}", model.srsName, e.what()));
        }
        if (desc.epsg != 0 && desc.epsg != model.epsg)
            throw InputError(desc.crsLoc,
                             fmt::format("crs EPSG:{} disagrees with the file's srsName '{}' (EPSG:{}); "
                                         "leave crs out, or correct the file",
                                         desc.epsg, model.srsName, model.epsg));
        return model.epsg;
    }
    if (desc.epsg == 0)
        throw InputError(desc.fileLoc,
                         "the file names no CRS (no srsName on its model or envelope); give the "
                         "<citygml> a crs=\"EPSG:…\"");
    return desc.epsg;
}

namespace {

// The element's file, its warnings appended, and the CRS of its coordinates. Throws InputError
// when the scene has no georeference to place it.
CityGmlModel readElementFile(const CityGmlDesc &desc, const std::optional<Georeference> &georeference,
                             std::vector<std::string> &warnings, int &epsg) {
    CityGmlModel model;
    try {
        model = readCityGml(desc.file, {desc.minLod, desc.maxLod});
    } catch (const InputError &e) {  // it names the file; add where the scene names it
        throw InputError(desc.fileLoc, e.what());
    }
    warnings.insert(warnings.end(), model.warnings.begin(), model.warnings.end());
    epsg = cityGmlEpsg(desc, model);
    if (!georeference)
        throw InputError(desc.loc,
                         fmt::format("a <citygml> needs the scene's <georeference>, such as "
                                     "<georeference crs=\"EPSG:{}\" origin=\"{}\"/>",
                                     epsg, envelopeCentre(model)));
    return model;
}

// What the element keeps of the file's buildings, and what it draws nothing of, said.
void warnOfKept(const CityGmlDesc &desc, const CityGmlModel &model, size_t kept, std::vector<std::string> &warnings) {
    if (desc.bbox)
        warnings.push_back(fmt::format("{}: the bbox keeps {} of the file's {} buildings", desc.bboxLoc.toString(),
                                       kept, model.buildings.size()));
    if (model.buildings.empty())
        warnings.push_back(fmt::format(
            "{}: {} draws nothing: it holds {} building(s) with no polygon of LoD {} to {} and {} other city "
            "object(s), which veduta does not draw",
            desc.loc.toString(), desc.file.string(), model.buildingsWithoutGeometry, desc.minLod, desc.maxLod,
            model.otherObjects));
}

}  // namespace

uint32_t generateCityGml(const CityGmlDesc &desc, const std::optional<Georeference> &georeference, const Camera &camera,
                         RenderSceneBuilder &builder, const AddTexture &addTexture,
                         std::vector<std::string> &warnings) {
    int epsg = 0;
    CityGmlModel model = readElementFile(desc, georeference, warnings, epsg);
    MapProjection projection(crsByEpsg(epsg), *georeference);
    AppearanceMaterials materials(builder, addTexture);
    std::vector<PlacedBuilding> placed;
    for (const CityGmlBuilding &building : model.buildings) {
        if (desc.bbox && !centreWithin(building, projection, *desc.bbox, desc.loc)) continue;
        placed.push_back({&building, buildingMesh(building, projection, desc.loc, materials), std::nullopt, 0});
    }
    chooseDetail(placed, desc, camera, projection, materials, builder, warnings);
    addBuildings(placed, desc, projection, builder);
    materials.warnUnread(warnings);
    warnOfKept(desc, model, placed.size(), warnings);
    return uint32_t(placed.size());
}

std::vector<ModularBuildingDesc> cityGmlModularBuildings(const CityGmlDesc &desc,
                                                         const std::optional<Georeference> &georeference,
                                                         std::vector<std::string> &warnings) {
    VEDUTA_CHECK(desc.modular, "a <citygml> with a modular look");
    int epsg = 0;
    CityGmlModel model = readElementFile(desc, georeference, warnings, epsg);
    MapProjection projection(crsByEpsg(epsg), *georeference);
    std::vector<ModularBuildingDesc> descs;
    size_t kept = 0;
    for (const CityGmlBuilding &building : model.buildings) {
        if (desc.bbox && !centreWithin(building, projection, *desc.bbox, desc.loc)) continue;
        ++kept;
        std::optional<TwinBuilding> twin = deriveTwin(building, projection, warnings);
        if (!twin) continue;
        // Named as the OpenStreetMap import names a way: the file, then the building.
        FileLoc where{fmt::format("{}: building {}", desc.file.string(), twin->gmlId)};
        ModularBuildingDesc &b = descs.emplace_back(
            footprintBuilding(*desc.modular, where, std::move(twin->footprint), std::nullopt, float(twin->base)));
        b.objectId = desc.objectId;
        b.buildingId = twin->id;
        b.coarse = desc.coarse;
        if (building.storeysAboveGround) b.storeys = size_t(std::max(1, *building.storeysAboveGround));
        else b.eaves = twin->wallHeight;
    }
    warnOfKept(desc, model, kept, warnings);
    return descs;
}

}  // namespace veduta

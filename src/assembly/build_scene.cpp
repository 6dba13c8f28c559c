#include "assembly/build_scene.h"

#include <cmath>
#include <map>
#include <new>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include <fmt/format.h>

#include "assembly/build_environment.h"
#include "city/citygml_buildings.h"
#include "city/generate_buildings.h"
#include "city/generate_city.h"
#include "city/modular_buildings.h"
#include "city/slg_buildings.h"
#include "core/memory_limit.h"
#include "geo/generate_landscape.h"
#include "geodesy/local_frame.h"
#include "geodesy/map_projection.h"
#include "io/georeferenced_mesh.h"
#include "io/image_library.h"
#include "io/mesh_import.h"

namespace veduta {

namespace {

class SceneAssembler {
  public:
    SceneAssembler(const SceneDescription &d, std::vector<std::string> &warnings) : d_(d), warnings_(warnings) {}

    RenderScene assemble() && {
        Camera camera = placeCamera();
        builder_.setCamera(camera);
        Sun sun = placeSun(d_);
        builder_.setSun(sun);
        Environment environment = buildEnvironment(d_.environment, sun);
        builder_.setEnvironment(environment);
        builder_.setFog(placeFog(environment, sun));
        RenderSettings settings = d_.settings;
        settings.seed = seedOf(d_.renderSeed);
        builder_.setSettings(settings);
        // Geometry may take most of the process's memory budget; the rest is for the film,
        // textures and the libraries (docs/performance.md). No limit set (a library caller), no
        // budget.
        if (std::optional<uint64_t> limit = memoryLimit()) builder_.setGeometryBudget(uint64_t(double(*limit) * 0.6));
        // Material 0 is for geometry that names none; a scene may redefine "default".
        builder_.addMaterial(Material::lambertian("default", Vec3f(0.8f)));
        for (const MaterialDesc &m : d_.materials) builder_.addMaterial(withTextures(m));
        defaultMaterial_ = builder_.findMaterial("default");

        // Geometry repeated at the top level (the same mesh file or shape with the same
        // material) is shared like a prototype; the builder bakes what appears once.
        for (const GeometryDesc &g : d_.geometry) {
            auto [it, fresh] = repeatedGeometry_.try_emplace(sharingKey(g), 0);
            if (fresh) it->second = builder_.addPrototype(part(g));
            builder_.addInstance({g.transform, it->second, kNoMaterial, g.objectId, g.buildingId, 0});
        }
        for (const PrototypeDesc &p : d_.prototypes) {
            Mesh merged;
            for (const GeometryDesc &g : p.parts) merged.append(part(g), g.transform);
            prototypeIds_[p.name] = builder_.addPrototype(std::move(merged));
        }
        for (size_t i = 0; i < d_.instances.size(); ++i) {
            const InstanceDesc &inst = d_.instances[i];
            auto it = prototypeIds_.find(inst.prototype.name);
            if (it == prototypeIds_.end()) {
                throw InputError(inst.prototype.loc, fmt::format("unknown prototype '{}'", inst.prototype.name));
            }
            MaterialId override = inst.material.name.empty() ? kNoMaterial : material(inst.material);
            builder_.addInstance(
                {inst.transform, it->second, override, inst.objectId, inst.buildingId, uint32_t(i + 1)});
        }
        // The cities are read first: their streets are cut into the landscape's terrain, and
        // then they are built on it. The landscape's files are read before them, so that a grown
        // town's streets keep to its ground.
        std::optional<LandscapeData> land;
        if (d_.landscape)
            land = within(d_.landscape->loc, "<landscape>",
                          [&] { return readLandscape(*d_.landscape, d_.georeference, warnings_); });
        std::vector<SceneCity> cities;
        std::vector<LocalPolygon> streetAreas;
        for (const CityDesc &city : d_.cities) {
            cities.push_back(within(city.loc, elementName(city), [&] {
                return readCity(city, d_.georeference, seedOf(city.seed), land ? &*land : nullptr);
            }));
            if (!d_.landscape) continue;
            for (LocalPolygon &piece : streetAreaPieces(streetNetworkOf(cities.back().data)))
                streetAreas.push_back(std::move(piece));
        }
        // <slg level="atkis"> takes the landscape's settlement areas and footprints before the
        // landscape takes its data, and stands on its ground after.
        std::optional<SlgLand> slgLand;
        if (land)
            slgLand = SlgLand{
                slgLandInput(land->objects, MapProjection(crsByEpsg(d_.georeference->epsg), *d_.georeference).frame()),
                {}};
        std::optional<LandscapeGround> landscape;
        if (d_.landscape) {
            landscape = within(d_.landscape->loc, "<landscape>", [&] {
                return generateLandscape(
                    *d_.landscape, std::move(*land), seedOf(d_.landscape->seed), d_.georeference, streetAreas, builder_,
                    warnings_, [&](std::shared_ptr<const ProceduralTexture> t) { return textures().add(std::move(t)); },
                    &camera);
            });
        }
        GroundHeight ground = landscape ? landscape->ground : GroundHeight();
        if (slgLand) slgLand->ground = ground;
        // Where masonry's maps go (rule files' <Masonry>, <modular_building>): baked images, or the
        // shaders' procedural maps.
        MasonryOutput masonryMaps{
            d_.proceduralMasonry, [&](Image image) { return texture(std::move(image)); },
            [&](std::shared_ptr<const ProceduralTexture> t) { return textures().add(std::move(t)); }};
        for (const BuildingGroupDesc &group : d_.buildingGroups) {
            within(group.loc, "<buildings>", [&] {
                generateBuildings(group, seedOf(group.seed), ground, builder_, warnings_, &camera, masonryMaps);
            });
        }
        // Finkenzeller's buildings: the scene's own, and those that data's footprints stand as.
        std::optional<ModularBuildings> modular;
        if (needsModular()) modular.emplace(camera, builder_, masonryMaps, [&](MaterialId id) { return albedo(id); });
        for (const CityGmlDesc &gml : d_.cityGml)
            within(gml.loc, "<citygml>", [&] {
                if (gml.modular)
                    addFromData(*modular, cityGmlModularBuildings(gml, d_.georeference, warnings_), d_.seed);
                else
                    generateCityGml(
                        gml, d_.georeference, camera, builder_,
                        [&](const std::filesystem::path &image) {
                            return texture({image, "", gml.fileLoc});
                        },
                        warnings_);
            });
        if (slgLand && d_.landscape->modular)
            within(d_.landscape->loc, "<landscape>", [&] {
                for (const SlgDesc &slg : d_.slg)
                    if (slg.level == SlgDesc::Level::Atkis)
                        throw InputError(d_.landscape->modular->structureLoc,
                                         fmt::format("the ALK footprints stand either as modular buildings or as "
                                                     "the <slg level=\"atkis\"> at {}, not both",
                                                     slg.loc.toString()));
                addFromData(*modular, alkModularBuildings(*d_.landscape, slgLand->input.footprints, ground),
                            seedOf(d_.landscape->seed));
            });
        if (!d_.modularBuildings.empty()) {
            std::vector<uint32_t> seeds;
            for (const ModularBuildingDesc &b : d_.modularBuildings) seeds.push_back(seedOf(b.seed));
            modular->add(
                d_.modularBuildings, seeds,
                [&](const FileLoc &loc, const std::function<void()> &add) { within(loc, "<modular_building>", add); },
                warnings_);
        }
        if (!d_.slg.empty()) {
            std::vector<uint32_t> seeds;
            for (const SlgDesc &slg : d_.slg) seeds.push_back(seedOf(slg.seed));
            within(d_.slg.front().loc, "<slg>",
                   [&] { generateSlg(d_.slg, seeds, camera, slgLand ? &*slgLand : nullptr, builder_, warnings_); });
        }
        for (size_t i = 0; i < d_.cities.size(); ++i) {
            within(d_.cities[i].loc, elementName(d_.cities[i]), [&] {
                generateCity(d_.cities[i], cities[i], seedOf(d_.cities[i].seed), landscape ? &*landscape : nullptr,
                             builder_, warnings_, camera, masonryMaps, modular ? &*modular : nullptr);
            });
        }
        if (textures_) builder_.setTextures(textures_);
        return std::move(builder_).build();
    }

  private:
    bool needsModular() const {
        bool data = d_.landscape && d_.landscape->modular;
        for (const CityDesc &city : d_.cities) data = data || city.modular;
        for (const CityGmlDesc &gml : d_.cityGml) data = data || gml.modular;
        return data || !d_.modularBuildings.empty();
    }

    // Buildings on footprints from data, within the element that reads them.
    void addFromData(ModularBuildings &modular, const std::vector<ModularBuildingDesc> &descs, uint32_t seed) {
        modular.add(
            descs, std::vector<uint32_t>(descs.size(), seed),
            [](const FileLoc &, const std::function<void()> &add) { add(); }, warnings_);
    }

    // The landscape's ALK footprints (Folie 011) in its modular look, each on the lowest ground
    // under it (off the terrain at 0, with a warning) with the structure's storeys, edge 0 its
    // longest; a block where it spans fewer than 8 pixels.
    std::vector<ModularBuildingDesc> alkModularBuildings(const LandscapeDesc &land,
                                                         const std::vector<SlgFootprint> &footprints,
                                                         const GroundHeight &ground) {
        std::vector<ModularBuildingDesc> descs;
        for (const SlgFootprint &f : footprints) {
            std::vector<Vec2f> outline;
            for (Vec2d p : f.outline) outline.push_back({float(p.x), float(p.y)});
            std::optional<float> base = ground(outline);
            uint32_t id = cityBuildingId(land.objectId, f.identity);
            if (!base)
                warnings_.push_back(fmt::format("{}: ALK building {} stands off the terrain; it is placed at height 0",
                                                land.loc.toString(), id));
            ModularBuildingDesc &b =
                descs.emplace_back(footprintBuilding(*land.modular, land.loc, outline, std::nullopt, base.value_or(0)));
            b.objectId = land.objectId;
            b.buildingId = id;
            b.coarse = CoarseRule{};  // the landscape has no coarse attributes: the default, 8 pixels
        }
        return descs;
    }

    static const char *elementName(const CityDesc &city) { return city.growth ? "<generate>" : "<city>"; }

    // Runs `make` for the element at `loc`: memory running out there says which element ran
    // out, rather than a bare std::bad_alloc (exit 3, as every failure that is not the input's).
    template <typename Make>
    static std::invoke_result_t<Make> within(const FileLoc &loc, const char *element, Make make) {
        try {
            return make();
        } catch (const std::bad_alloc &) {
            throw std::runtime_error(
                fmt::format("{}: memory ran out while building this {}; give the scene less "
                            "to build, or the machine more memory",
                            loc.toString(), element));
        }
    }

    // Where every seed is resolved: a generator's (or the sampler's) own seed from the file,
    // else the scene's.
    uint32_t seedOf(const std::optional<uint32_t> &own) const { return own.value_or(d_.seed); }

    // The material with its maps registered as textures.
    Material withTextures(const MaterialDesc &d) {
        Material m = d.material;
        m.diffuseMap = texture(d.diffuseMap);
        m.specularMap = texture(d.specularMap);
        m.normalMap = texture(d.normalMap);
        m.reflectionMap = texture(d.reflectionMap);
        m.opacityMap = texture(d.opacityMap);
        return m;
    }

    TextureId texture(const ImageRef &ref) {
        if (!ref.given()) return kNoTexture;
        try {
            return textures().add(ref.file, ref.colorSpace);
        } catch (const InputError &error) {  // it names the file; add where the scene names it
            throw InputError(ref.loc, error.what());
        }
    }

    TextureId texture(Image image) { return textures().add(std::move(image)); }

    // A material's colour times its diffuse map's mean (a lookup over the whole period). Read-only:
    // the modular buildings ask it while they are made in parallel.
    Vec3f albedo(MaterialId id) const {
        const Material &m = builder_.materials().at(id);
        if (m.diffuseMap == kNoTexture) return m.diffuse;
        float mean[3] = {1, 1, 1};
        textures_->lookup(m.diffuseMap, {0.5f, 0.5f}, 1.0f, mean, 3);
        if (textures_->channels(m.diffuseMap) < 3) mean[1] = mean[2] = mean[0];
        return m.diffuse * Vec3f(mean[0], mean[1], mean[2]);
    }

    Textures &textures() {
        if (!textures_) textures_ = imageLibrary().makeTextures(defaultTextureCacheDirectory());
        return *textures_;
    }

    // The mesh of one geometry element in its own frame, with its material applied.
    Mesh part(const GeometryDesc &g) {
        Mesh mesh = g.shape ? makeShape(*g.shape) : meshFile(g);
        mesh.setMaterial(g.material.name.empty() ? defaultMaterial_ : material(g.material));
        return mesh;
    }

    // Equal keys mean equal meshes: the same file or shape parameters, and the same material.
    std::string sharingKey(const GeometryDesc &g) const {
        const std::string &material = g.material.name;
        if (!g.shape) return fmt::format("mesh {} {} {}", g.meshFile.string(), g.meshEpsg, material);
        const ShapeSpec &s = *g.shape;
        return fmt::format("shape {} {} {} {} {} {} {} {} {} {}", int(s.kind), s.size.x, s.size.y, s.size.z, s.radius,
                           s.height, s.segments, s.rings, s.smooth, material);
    }

    const Mesh &meshFile(const GeometryDesc &g) {
        auto key = std::make_pair(g.meshFile, g.meshEpsg);
        auto it = meshFiles_.find(key);
        if (it != meshFiles_.end()) return it->second;
        std::optional<MapProjection> projection;
        if (g.meshEpsg != 0) projection = meshProjection(g);
        try {
            Mesh mesh = projection ? importGeoreferencedMesh(g.meshFile, *projection) : importMesh(g.meshFile);
            return meshFiles_.emplace(key, std::move(mesh)).first->second;
        } catch (const InputError &e) {
            throw InputError(g.meshFileLoc, e.what());
        }
    }

    // The fog glows with the light it scatters: the sky's mean radiance and the sun's
    // irradiance spread over the sphere (isotropic scattering, albedo 1, nothing shadowed).
    Fog placeFog(const Environment &environment, const Sun &sun) const {
        Fog fog = d_.fog;
        fog.inscatter = environment.averageRadiance() + sun.irradiance / (4 * kPi);
        return fog;
    }

    // A camera given in map coordinates takes the route every map point takes into the frame.
    Camera placeCamera() const {
        Camera camera = d_.camera;
        if (!d_.mapCamera) return camera;
        const MapCameraDesc &m = *d_.mapCamera;
        if (!d_.georeference)
            throw InputError(m.loc,
                             "a camera in map coordinates (crs) needs the scene's <georeference "
                             "crs=\"EPSG:…\" origin=\"E N\"> to be placed");
        MapProjection projection(crsByEpsg(m.epsg), *d_.georeference);
        try {
            camera.position = projection.toRender(m.position);
            camera.lookAt = projection.toRender(m.lookAt);
        } catch (const std::out_of_range &e) {
            throw InputError(m.loc, fmt::format("camera: {}", e.what()));
        }
        for (const Vec3f &p : {camera.position, camera.lookAt}) {
            if (std::abs(p.x) > kFrameLimit || std::abs(p.y) > kFrameLimit || std::abs(p.z) > kFrameLimit)
                throw InputError(m.loc, "the camera lies more than 10,000 km from the scene origin");
        }
        if (const char *problem = camera.framingProblem())
            throw InputError(m.loc, fmt::format("{} in the render frame", problem));
        return camera;
    }

    // The one route of a mesh in map coordinates into the scene's frame.
    MapProjection meshProjection(const GeometryDesc &g) const {
        if (!d_.georeference)
            throw InputError(g.meshCrsLoc,
                             "a mesh in map coordinates (crs) needs the scene's <georeference "
                             "crs=\"EPSG:…\" origin=\"E N\"> to be placed");
        return MapProjection(crsByEpsg(g.meshEpsg), *d_.georeference);
    }

    MaterialId material(const NameRef &ref) const {
        MaterialId id = builder_.findMaterial(ref.name);
        if (id == kNoMaterial) throw InputError(ref.loc, fmt::format("unknown material '{}'", ref.name));
        return id;
    }

    const SceneDescription &d_;
    std::vector<std::string> &warnings_;
    RenderSceneBuilder builder_;
    std::map<std::string, PrototypeId> prototypeIds_;
    std::map<std::pair<std::filesystem::path, int>, Mesh> meshFiles_;  // by file and CRS
    std::map<std::string, PrototypeId> repeatedGeometry_;
    MaterialId defaultMaterial_ = 0;
    std::shared_ptr<Textures> textures_;
};

}  // namespace

// From a date and time, the azimuth is against true north; with a georeference the scene's
// +y is grid north, which differs by the meridian convergence.
Sun placeSun(const SceneDescription &d) {
    Sun sun = d.sun;
    if (!d.sunTime) return sun;
    const SunTimeDesc &t = *d.sunTime;
    if (!t.place && !d.georeference) {
        throw InputError(t.loc, "the sun needs 'latitude' and 'longitude', or a <georeference> for the scene");
    }
    GeographicPoint place = t.place
        ? *t.place
        : toGeographic(*d.georeference, d.georeference->originEasting, d.georeference->originNorthing);
    SolarAngles angles = solarPositionNoaa(t.time, place.latitude, place.longitude);
    double azimuth = angles.azimuthDegrees;
    if (d.georeference) {
        const Georeference &g = *d.georeference;
        azimuth = gridAzimuthDegrees(azimuth, meridianConvergenceDegrees(g, g.originEasting, g.originNorthing));
    }
    sun.direction = Sun::directionFromAzimuthElevation(float(azimuth), float(angles.elevationDegrees));
    // Once the whole disc has set, the sun of that date and time lights nothing (a sun given
    // by its direction still does: that is a lighting choice, not a time of day).
    if (angles.elevationDegrees < -0.5 * sun.angularDiameterDegrees) sun.irradiance = Vec3f(0.0f);
    return sun;
}

void replaceEverySeed(SceneDescription &d, uint32_t seed) {
    d.seed = seed;
    d.renderSeed.reset();
    for (BuildingGroupDesc &group : d.buildingGroups) group.seed.reset();
    for (CityDesc &city : d.cities) city.seed.reset();
    for (SlgDesc &slg : d.slg) slg.seed.reset();
    for (ModularBuildingDesc &b : d.modularBuildings) b.seed.reset();
    if (d.landscape) d.landscape->seed.reset();
}

RenderScene buildRenderScene(const SceneDescription &description, std::vector<std::string> *warnings) {
    std::vector<std::string> ignored;
    std::vector<std::string> &told = warnings ? *warnings : ignored;
    uint64_t fallbacksBefore = helmertFallbacks();
    RenderScene scene = SceneAssembler(description, told).assemble();
    if (std::optional<std::string> fallback = helmertFallbackWarning(fallbacksBefore)) told.push_back(*fallback);
    return scene;
}

}  // namespace veduta

// The scene-file reader: XML → SceneDescription. No geometry is made here.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string_view>

#include <fmt/format.h>

#include "description/material_file.h"
#include "description/scene_description.h"
#include "geodesy/crs.h"
#include "geodesy/local_frame.h"
#include "io/xml_reader.h"

namespace veduta {

namespace {

bool parsesAsCivilTime(std::string_view date, std::string_view time, std::string_view utcOffset) {
    try {
        parseCivilTime(date, time, utcOffset);
        return true;
    } catch (const std::invalid_argument &) {
        return false;
    }
}

class SceneFileReader {
  public:
    SceneFileReader(const XmlDocument &doc, std::filesystem::path baseDirectory) :
        doc_(doc), baseDirectory_(std::move(baseDirectory)) {}

    SceneDescription read() {
        XmlElement root(doc_, doc_.root());
        if (root.name() != "scene") root.fail(fmt::format("the root element is <{}>, expected <scene>", root.name()));
        root.integer("version", 1, 1, 1);  // the only version so far
        scene_.seed = root.unsignedInteger("seed", 0);
        root.checkAllRead();
        scene_.source = doc_.name();
        for (const XmlElement &e : root.children()) readTopLevel(e);
        assignObjectIds();
        assignBuildingIds();
        return std::move(scene_);
    }

  private:
    void readTopLevel(const XmlElement &e) {
        std::string_view n = e.name();
        if (n == "camera") {
            readCamera(e);
        } else if (n == "sun") {
            readSun(e);
        } else if (n == "environment") {
            readEnvironment(e);
        } else if (n == "fog") {
            readFog(e);
        } else if (n == "georeference") {
            readGeoreference(e);
        } else if (n == "render") {
            readSettings(e);
        } else if (n == "material") {
            addMaterial(readMaterialElement(e, baseDirectory_), e);
        } else if (n == "materials") {
            readMaterialsInclude(e);
        } else if (n == "prototype") {
            readPrototype(e);
        } else if (n == "instance") {
            readInstance(e);
        } else if (n == "buildings") {
            readBuildings(e);
        } else if (n == "city") {
            readCity(e);
        } else if (n == "generate") {
            readGenerate(e);
        } else if (n == "citygml") {
            readCityGml(e);
        } else if (n == "modular_building") {
            readModularBuilding(e);
        } else if (n == "slg") {
            readSlg(e);
        } else if (n == "landscape") {
            readLandscape(e);
        } else if (isGeometry(n)) {
            scene_.geometry.push_back(readGeometry(e, true));
        } else {
            e.fail(fmt::format("unknown element <{}>", n));
        }
    }

    static bool isGeometry(std::string_view n) {
        return n == "box" || n == "sphere" || n == "cylinder" || n == "cone" || n == "plane" || n == "mesh" ||
            n == "ground";
    }

    // A point of the render frame: metres from the scene origin, at most kFrameLimit.
    Vec3f framePoint(const XmlElement &e, const char *attribute, Vec3f fallback) const {
        Vec3f p = e.vec3(attribute, fallback);
        if (std::abs(p.x) > kFrameLimit || std::abs(p.y) > kFrameLimit || std::abs(p.z) > kFrameLimit)
            e.failAt(attribute,
                     fmt::format("{} {} {} lies more than 10,000 km from the scene origin (attribute '{}')", p.x, p.y,
                                 p.z, attribute));
        return p;
    }

    void readCamera(const XmlElement &e) {
        Camera &c = scene_.camera;
        if (e.has("crs")) {
            readMapCamera(e);
        } else {
            c.position = framePoint(e, "position", c.position);
            c.lookAt = framePoint(e, "look_at", c.lookAt);
            scene_.mapCamera.reset();
        }
        c.up = e.vec3("up", c.up);
        std::string projection =
            e.string("projection", c.projection == Projection::Orthographic ? "orthographic" : "perspective");
        if (projection != "perspective" && projection != "orthographic")
            e.failAt("projection",
                     fmt::format("projection '{}' is neither 'perspective' nor 'orthographic'", projection));
        c.projection = projection == "orthographic" ? Projection::Orthographic : Projection::Perspective;
        c.verticalFovDegrees = e.number("fov", c.verticalFovDegrees, 0.01f, 179.0f);
        c.orthoScale = e.number("ortho_scale", c.orthoScale, 1e-3f, 1e7f);
        if (e.has("shift")) {
            std::vector<float> shift = e.numbers("shift");
            if (shift.size() != 2 || std::abs(shift[0]) > 10 || std::abs(shift[1]) > 10)
                e.failAt("shift", "shift takes two numbers, horizontal and vertical, -10 to 10");
            c.shift = {shift[0], shift[1]};
        }
        c.fNumber = e.number("f_number", c.fNumber, 0, 1e4f);
        if (c.fNumber > 0 && c.fNumber < 0.1f) e.failAt("f_number", "f_number is 0 (a pinhole) or 0.1 to 10000");
        c.focusDistance = e.number("focus_distance", c.focusDistance, 0, 1e7f);
        c.sensorWidth = e.number("sensor_width", c.sensorWidth, 1, 1000);
        if (e.has("resolution")) {
            std::vector<float> r = e.numbers("resolution");
            if (r.size() != 2 || r[0] < 1 || r[1] < 1 || r[0] > 65536 || r[1] > 65536 || r[0] != std::floor(r[0]) ||
                r[1] != std::floor(r[1])) {
                e.failAt("resolution", "resolution takes two whole numbers, width and height, 1 to 65536");
            }
            c.width = int(r[0]);
            c.height = int(r[1]);
        }
        if (c.hasDepthOfField() && c.projection == Projection::Orthographic)
            e.fail("depth of field (f_number) needs a perspective camera");
        // A camera in map coordinates is checked once it is placed (assembly/build_scene.cpp).
        if (const char *problem = c.framingProblem(); problem && !scene_.mapCamera) e.fail(problem);
        e.checkLeaf();
    }

    // position and look_at as easting, northing and height in the camera's crs, in double:
    // the render frame is only known once the scene's georeference is.
    void readMapCamera(const XmlElement &e) {
        MapCameraDesc m;
        m.epsg = supportedCrsAttribute(e, "crs");
        m.loc = e.attributeLoc("crs");
        auto point = [&](const char *attribute) {
            std::vector<double> v = e.doubles(attribute);
            if (v.size() != 3)
                e.failAt(
                    attribute,
                    fmt::format("{} takes three numbers in map coordinates: easting, northing, height", attribute));
            return CrsCoordinate{v[0], v[1], v[2]};
        };
        m.position = point("position");
        m.lookAt = point("look_at");
        if (m.position.x == m.lookAt.x && m.position.y == m.lookAt.y && m.position.z == m.lookAt.z)
            e.fail("camera position and look_at are the same point");
        scene_.mapCamera = m;
    }

    // Extinction as a density (1/m) or as the meteorological visibility (m), by Koschmieder's
    // law: the distance at which contrast falls to 2 %, σ = −ln 0.02 / V = 3.912 / V.
    void readFog(const XmlElement &e) {
        Fog &fog = scene_.fog;
        if (e.has("density") == e.has("visibility")) e.fail("give the fog one of 'density' and 'visibility'");
        if (e.has("density")) {
            fog.density = e.number("density", 0, 0, 10);
        } else {
            fog.density = 3.912f / e.number("visibility", 1, 0.1f, 1e7f);
        }
        fog.baseHeight = e.number("height", fog.baseHeight, -1e4f, 1e5f);
        fog.scaleHeight = e.number("scale_height", fog.scaleHeight, 1, 1e6f);
        e.checkLeaf();
    }

    void readSun(const XmlElement &e) {
        Sun &sun = scene_.sun;
        int ways = int(e.has("direction")) + int(e.has("azimuth") || e.has("elevation")) + int(e.has("date"));
        if (ways > 1) e.fail("give the sun one of 'direction', 'azimuth' and 'elevation', or 'date' and 'time'");
        if (e.has("azimuth") != e.has("elevation")) e.fail("give the sun both 'azimuth' and 'elevation'");
        // A later <sun> that places the sun replaces how an earlier one did.
        if (e.has("date")) {
            readSunTime(e);
        } else if (e.has("direction")) {
            Vec3f d = e.vec3("direction", sun.direction);
            if (length(d) == 0) e.failAt("direction", "sun direction has zero length");
            sun.direction = normalize(d);
            scene_.sunTime.reset();
        } else if (e.has("azimuth")) {
            sun.direction = Sun::directionFromAzimuthElevation(e.number("azimuth", 0, -360, 360),
                                                               e.number("elevation", 0, -90, 90));
            scene_.sunTime.reset();
        }
        sun.irradiance = e.color("irradiance", sun.irradiance, 0, 1e9f);
        sun.angularDiameterDegrees = e.number("angular_diameter", sun.angularDiameterDegrees, 0, 30);
        e.checkLeaf();
    }

    // The sun's position from the date, the local time and its offset from UTC, and the
    // place (latitude and longitude, or else the georeference's origin).
    void readSunTime(const XmlElement &e) {
        SunTimeDesc t;
        t.loc = e.loc();
        std::string date = e.string("date"), time = e.string("time"), offset = e.string("utc_offset");
        try {
            t.time = parseCivilTime(date, time, offset);
        } catch (const std::invalid_argument &error) {
            // Point at the part that is wrong: each is tried with known-good others.
            const char *culprit = !parsesAsCivilTime(date, "00:00", "Z") ? "date"
                : !parsesAsCivilTime("2000-01-01", time, "Z")            ? "time"
                                                                         : "utc_offset";
            e.failAt(culprit, error.what());
        }
        if (e.has("latitude") != e.has("longitude")) e.fail("give the sun both 'latitude' and 'longitude'");
        if (e.has("latitude")) {
            t.place = GeographicPoint{e.number("latitude", 0, -90, 90), e.number("longitude", 0, -180, 180)};
        }
        scene_.sunTime = t;
    }

    void readGeoreference(const XmlElement &e) {
        if (scene_.georeference) e.fail("the scene has a georeference already");
        Georeference g;
        g.epsg = epsgAttribute(e, "crs");
        std::string crs = e.string("crs");
        std::vector<double> origin = e.doubles("origin");
        if (origin.size() != 2) e.failAt("origin", "origin takes two numbers, easting and northing");
        g.originEasting = origin[0];
        g.originNorthing = origin[1];
        GeographicPoint place{};
        try {
            place = toGeographic(g, g.originEasting, g.originNorthing);
        } catch (const std::invalid_argument &error) {
            e.failAt("crs", fmt::format("crs '{}': {}", crs, error.what()));
        }
        // Transverse Mercator holds within a few degrees of its central meridian; far outside
        // it the inverse gives nonsense or nothing.
        if (!std::isfinite(place.latitude) || !std::isfinite(place.longitude) || std::abs(place.latitude) > 84) {
            e.failAt("origin",
                     fmt::format("origin {} {} lies outside the area of {}", g.originEasting, g.originNorthing, crs));
        }
        e.checkLeaf();
        scene_.georeference = g;
    }

    // A crs attribute of the form EPSG:<code>; whether the code is supported is checked where
    // it is used.
    static int epsgAttribute(const XmlElement &e, const char *attribute) {
        std::string crs = e.string(attribute);
        int epsg = 0;
        bool epsgForm = crs.rfind("EPSG:", 0) == 0 && crs.size() >= 6 &&
            crs.find_first_not_of("0123456789", 5) == std::string::npos;
        if (!epsgForm) e.failAt(attribute, fmt::format("crs '{}' is not of the form EPSG:<code>", crs));
        auto [end, parseError] = std::from_chars(crs.data() + 5, crs.data() + crs.size(), epsg);
        if (parseError != std::errc() || end != crs.data() + crs.size())
            e.failAt(attribute, fmt::format("crs '{}': not a supported EPSG code", crs));
        return epsg;
    }

    // A crs attribute naming a CRS of geo/crs.h.
    static int supportedCrsAttribute(const XmlElement &e, const char *attribute) {
        int epsg = epsgAttribute(e, attribute);
        try {
            crsByEpsg(epsg);
        } catch (const std::invalid_argument &error) {
            e.failAt(attribute, error.what());
        }
        return epsg;
    }

    // An optional crs="EPSG:…" of a file element: its code (left 0 when absent) and place.
    static void readFileCrs(const XmlElement &e, int &epsg, FileLoc &loc) {
        if (!e.has("crs")) return;
        epsg = supportedCrsAttribute(e, "crs");
        loc = e.attributeLoc("crs");
    }

    void readEnvironment(const XmlElement &e) {
        EnvironmentDesc &env = scene_.environment;
        env.loc = e.loc();
        int sources = int(e.has("radiance")) + int(e.has("cubemap")) + int(e.has("sky"));
        if (sources > 1) e.fail("give the environment one of 'radiance', 'cubemap' and 'sky'");
        // A later <environment> that gives a source replaces an earlier one's.
        if (sources == 1) {
            env.radiance = Vec3f(0.0f);
            env.cubemap = {};
            env.sky = false;
        }
        env.radiance = e.color("radiance", env.radiance, 0, 1e9f);
        if (e.has("cubemap")) {
            env.cubemap.file = pathAttribute(e, "cubemap");
            env.cubemap.loc = e.attributeLoc("cubemap");
            env.cubemap.colorSpace = e.string("colorspace", "");
        }
        if (e.has("sky")) {
            std::string model = e.string("sky");
            if (model != "preetham") e.failAt("sky", fmt::format("unknown sky model '{}' (preetham)", model));
            env.sky = true;
            env.turbidity = e.number("turbidity", env.turbidity, 1.7f, 10);
            env.groundAlbedo = e.number("ground_albedo", env.groundAlbedo, 0, 1);
        }
        if (env.sky && e.has("rotation")) e.failAt("rotation", "the sky follows the sun; it cannot be rotated");
        env.faceSize = e.integer("face_size", env.faceSize, 0, 8192);
        env.rotationDegrees = e.number("rotation", env.rotationDegrees, -360, 360);
        env.intensity = e.number("intensity", env.intensity, 0, 1e9f);
        e.checkLeaf();
    }

    void addMaterial(MaterialDesc m, const XmlElement &e) {
        for (const MaterialDesc &other : scene_.materials) {
            if (other.material.name == m.material.name) {
                e.failAt("name",
                         fmt::format("material '{}' is already defined at {}", m.material.name, other.loc.toString()));
            }
        }
        scene_.materials.push_back(std::move(m));
    }

    // <materials file="..."/>: every material of a material file, as if written here.
    void readMaterialsInclude(const XmlElement &e) {
        std::filesystem::path file = pathAttribute(e, "file");
        e.checkLeaf();
        std::vector<MaterialDesc> materials;
        try {
            materials = readMaterialFile(file);
        } catch (const InputError &error) {
            // A file that cannot be opened has no line of its own: point at the include.
            if (error.loc().line == 0) e.failAt("file", error.what());
            throw;
        }
        for (MaterialDesc &m : materials) {
            for (const MaterialDesc &other : scene_.materials) {
                if (other.material.name == m.material.name) {
                    throw InputError(
                        m.loc,
                        fmt::format("material '{}' is already defined at {}", m.material.name, other.loc.toString()));
                }
            }
            scene_.materials.push_back(std::move(m));
        }
    }

    void readSettings(const XmlElement &e) {
        RenderSettings &s = scene_.settings;
        s.samplesPerPixel = uint32_t(e.integer("spp", int(s.samplesPerPixel), 1, 1 << 24));
        s.maxDepth = uint32_t(e.integer("max_depth", int(s.maxDepth), 1, 1024));
        if (std::optional<uint32_t> seed = seedOverride(e)) scene_.renderSeed = seed;
        s.tileSize = uint32_t(e.integer("tile_size", int(s.tileSize), 1, 4096));
        std::string filter = e.string("filter", "blackman-harris");
        if (filter == "box") {
            s.filter = {FilterKind::Box, 1.0f};
        } else if (filter != "blackman-harris") {
            e.failAt("filter", fmt::format("unknown filter '{}' (blackman-harris, box)", filter));
        }
        s.filter.width = e.number("filter_width", s.filter.width, 0.01f, 16);
        std::string sampling = e.string("light_sampling", "mis");
        if (sampling == "bsdf") {
            s.lightSampling = LightSampling::Bsdf;
        } else if (sampling == "light") {
            s.lightSampling = LightSampling::Light;
        } else if (sampling != "mis") {
            e.failAt("light_sampling", fmt::format("unknown light sampling '{}' (mis, bsdf, light)", sampling));
        }
        std::string masonry = e.string("masonry", "procedural");
        if (masonry != "baked" && masonry != "procedural")
            e.failAt("masonry", fmt::format("unknown masonry '{}' (baked, procedural)", masonry));
        scene_.proceduralMasonry = masonry == "procedural";
        e.checkLeaf();
    }

    void readPrototype(const XmlElement &e) {
        PrototypeDesc p{e.loc(), e.string("name"), {}};
        for (const PrototypeDesc &other : scene_.prototypes) {
            if (other.name == p.name) {
                e.failAt("name", fmt::format("prototype '{}' is already defined at {}", p.name, other.loc.toString()));
            }
        }
        e.checkAllRead();
        for (const XmlElement &child : e.children()) {
            if (!isGeometry(child.name()))
                child.fail(fmt::format("<{}> cannot stand inside <prototype>", child.name()));
            p.parts.push_back(readGeometry(child, false));
        }
        if (p.parts.empty()) e.fail(fmt::format("prototype '{}' has no geometry", p.name));
        scene_.prototypes.push_back(std::move(p));
    }

    void readInstance(const XmlElement &e) {
        InstanceDesc inst;
        inst.loc = e.loc();
        inst.prototype = {e.string("prototype"), e.attributeLoc("prototype")};
        inst.transform = readTransform(e);
        inst.material = readNameRef(e, "material");
        readObjectId(e, inst.loc);
        inst.buildingId = e.unsignedInteger("building", 0);
        e.checkLeaf();
        scene_.instances.push_back(std::move(inst));
    }

    // A generator's own seed, which overrides the scene's; unset when the element gives none.
    static std::optional<uint32_t> seedOverride(const XmlElement &e) {
        if (!e.has("seed")) return std::nullopt;
        return e.unsignedInteger("seed", 0);
    }

    static CoarseRule coarseRule(const XmlElement &e) {
        CoarseRule rule;
        if (e.has("coarse_beyond")) rule.beyond = e.number("coarse_beyond", 300, 0, 1e6f);
        rule.belowPixels = e.number("coarse_below_px", rule.belowPixels, 0, 1e6f);
        return rule;
    }

    // A required file attribute, resolved against the scene's folder when relative.
    std::filesystem::path pathAttribute(const XmlElement &e, const char *attribute) const {
        std::filesystem::path file = e.string(attribute);
        return file.is_absolute() ? file : baseDirectory_ / file;
    }

    // structure= and style=, both or neither.
    std::optional<ModularLookDesc> modularLook(const XmlElement &e) const {
        if (!e.has("structure") && !e.has("style")) return std::nullopt;
        for (const char *attribute : {"structure", "style"})
            if (!e.has(attribute))
                e.failAt(e.has("structure") ? "structure" : "style",
                         fmt::format("a modular look takes both structure and style; {} is missing", attribute));
        return ModularLookDesc{pathAttribute(e, "structure"), pathAttribute(e, "style"), e.attributeLoc("structure"),
                               e.attributeLoc("style")};
    }

    void readCity(const XmlElement &e) {
        CityDesc city;
        city.loc = e.loc();
        city.file = pathAttribute(e, "file");
        city.fileLoc = e.attributeLoc("file");
        if (e.has("rules")) {
            city.rules = pathAttribute(e, "rules");
            city.rulesLoc = e.attributeLoc("rules");
        }
        readFileCrs(e, city.epsg, city.crsLoc);
        city.seed = seedOverride(e);
        city.coarse = coarseRule(e);
        city.modular = modularLook(e);
        city.streetTrees = e.boolean("street_trees", true);
        readObjectId(e, city.loc);
        e.checkLeaf();
        scene_.cities.push_back(std::move(city));
    }

    void readGenerate(const XmlElement &e) {
        CityDesc city;
        city.loc = e.loc();
        city.fileLoc = city.loc;
        CityGrowthDesc &growth = city.growth.emplace();
        if (e.has("pattern")) {
            if (e.has("streets")) e.failAt("pattern", "give either streets (a rule file) or pattern, not both");
            if (e.string("pattern") != "tensor")
                e.failAt("pattern",
                         fmt::format("unknown pattern '{}'; the one pattern without a rule file is tensor",
                                     e.string("pattern")));
            growth.tensor = true;
        } else {
            growth.streets = pathAttribute(e, "streets");
            growth.streetsLoc = e.attributeLoc("streets");
        }
        city.rules = pathAttribute(e, "rules");
        city.rulesLoc = e.attributeLoc("rules");
        std::vector<double> centre = e.has("centre") ? e.doubles("centre") : std::vector<double>{0, 0};
        if (centre.size() != 2) e.failAt("centre", "centre takes two numbers, E N");
        growth.centreE = centre[0], growth.centreN = centre[1];
        growth.centreLoc = e.has("centre") ? e.attributeLoc("centre") : e.loc();
        growth.radius = e.number("radius", growth.radius, 1, 50000);
        growth.majorWidth = e.number("major_width", growth.majorWidth, 1, 100);
        growth.minorWidth = e.number("minor_width", growth.minorWidth, 1, 100);
        growth.majorShare = e.number("major_share", growth.majorShare, 0, 1);
        growth.maxGrade = e.number("max_grade", growth.maxGrade, 0.001f, 1);
        growth.levels = unsigned(e.integer("levels", int(growth.levels), 1, 16));
        growth.streetThickness = e.number("street_thickness", growth.streetThickness, 0.1f, 10);
        // A level's prisms stand up to 18 m high on its streets, under the next level's streets.
        growth.levelSpacing = e.number("level_spacing", growth.levelSpacing, 18 + growth.streetThickness, 1000);
        growth.liftReach = e.number("lift_reach", growth.liftReach, 0, 1000);
        if (e.has("lots")) {
            growth.lots = e.string("lots");
            growth.lotsLoc = e.attributeLoc("lots");
        }
        if (e.has("roads")) {
            growth.roads = pathAttribute(e, "roads");
            growth.roadsLoc = e.attributeLoc("roads");
        }
        city.seed = seedOverride(e);
        city.coarse = coarseRule(e);
        city.modular = modularLook(e);
        city.streetTrees = e.boolean("street_trees", true);
        readObjectId(e, city.loc);
        e.checkLeaf();
        scene_.cities.push_back(std::move(city));
    }

    void readCityGml(const XmlElement &e) {
        CityGmlDesc gml;
        gml.loc = e.loc();
        gml.file = pathAttribute(e, "file");
        gml.fileLoc = e.attributeLoc("file");
        readFileCrs(e, gml.epsg, gml.crsLoc);
        if (e.has("lod")) gml.minLod = gml.maxLod = unsigned(e.integer("lod", 2, 0, 4));
        if (e.has("bbox")) {
            std::vector<double> box = e.doubles("bbox");
            if (box.size() != 4 || !(box[0] < box[2]) || !(box[1] < box[3]))
                e.failAt("bbox", "bbox takes four numbers, E0 N0 E1 N1 with E0 < E1 and N0 < N1");
            gml.bbox = std::array<double, 4>{box[0], box[1], box[2], box[3]};
            gml.bboxLoc = e.attributeLoc("bbox");
        }
        gml.coarse = coarseRule(e);
        gml.modular = modularLook(e);
        readObjectId(e, gml.loc);
        e.checkLeaf();
        scene_.cityGml.push_back(std::move(gml));
    }

    void readModularBuilding(const XmlElement &e) {
        ModularBuildingDesc b;
        b.loc = e.loc();
        b.structure = pathAttribute(e, "structure");
        b.structureLoc = e.attributeLoc("structure");
        b.style = pathAttribute(e, "style");
        b.styleLoc = e.attributeLoc("style");
        if (e.has("footprint")) {
            std::vector<float> xy = e.numbers("footprint");
            b.footprintLoc = e.attributeLoc("footprint");
            if (xy.size() % 2 != 0 || xy.size() < 6)
                e.failAt("footprint",
                         fmt::format("a footprint is at least three x y pairs; {} numbers given", xy.size()));
            for (size_t i = 0; i < xy.size(); i += 2) b.footprint.push_back({xy[i], xy[i + 1]});
        }
        b.transform = readTransform(e);
        b.seed = seedOverride(e);
        b.buildingId = e.unsignedInteger("building", 0);
        if (e.has("building") && b.buildingId == 0)
            e.failAt("building", "building ids start at 1; 0 means no building");
        readObjectId(e, b.loc);
        e.checkLeaf();
        scene_.modularBuildings.push_back(std::move(b));
    }

    void readSlg(const XmlElement &e) {
        SlgDesc slg;
        slg.loc = e.loc();
        std::string level = e.string("level", "block");
        if (level != "block" && level != "district" && level != "atkis")
            e.failAt("level", fmt::format("level is 'block', 'district' or 'atkis', not '{}'", level));
        slg.level = level == "district" ? SlgDesc::Level::District
            : level == "atkis"          ? SlgDesc::Level::Atkis
                                        : SlgDesc::Level::Block;
        if (slg.level == SlgDesc::Level::Atkis) {
            // The outlines are the landscape's settlement areas and building footprints.
            for (const char *attribute : {"outline", "base"})
                if (e.has(attribute))
                    e.failAt(attribute,
                             fmt::format("level=\"atkis\" takes its outlines and heights from the "
                                         "<landscape>; leave out {}",
                                         attribute));
        } else {
            std::vector<float> points = e.numbers("outline");
            slg.outlineLoc = e.attributeLoc("outline");
            if (points.size() < 6 || points.size() % 2 != 0)
                e.failAt("outline", "outline takes x y pairs of at least three corners");
            for (size_t i = 0; i < points.size(); i += 2) slg.outline.push_back({points[i], points[i + 1]});
            slg.base = e.number("base", 0, -1e4f, 1e4f);
        }
        slg.tables = pathAttribute(e, "tables");
        slg.tablesLoc = e.attributeLoc("tables");
        slg.rooms = e.number("rooms_within", slg.rooms, 0, 1e6f);
        slg.storeys = e.number("storeys_within", slg.storeys, 0, 1e6f);
        if (slg.storeys < slg.rooms) e.failAt("storeys_within", "storeys_within is less than rooms_within");
        slg.roomsPixels = e.number("rooms_above_px", slg.roomsPixels, 0, 1e6f);
        slg.storeysPixels = e.number("storeys_above_px", slg.storeysPixels, 0, 1e6f);
        if (slg.roomsPixels < slg.storeysPixels)
            e.failAt("rooms_above_px", "rooms_above_px is less than storeys_above_px");
        slg.seed = seedOverride(e);
        readObjectId(e, slg.loc);
        e.checkLeaf();
        scene_.slg.push_back(std::move(slg));
    }

    void readLandscape(const XmlElement &e) {
        if (scene_.landscape) e.fail("the scene has a <landscape> already; give several <dgm> tiles inside one");
        LandscapeDesc land;
        land.loc = e.loc();
        std::string nodata = e.string("nodata", "fill");
        if (nodata != "fill" && nodata != "cut")
            e.failAt("nodata", fmt::format("nodata is 'fill' or 'cut', not '{}'", nodata));
        land.fillDistance = e.integer("fill_distance", kDefaultFillDistance, 1, 1 << 20);
        if (nodata == "cut") {
            if (e.has("fill_distance")) e.failAt("fill_distance", "fill_distance needs nodata=\"fill\"");
            land.fillDistance = 0;
        }
        land.simplify = e.number("simplify", 0, 0, 1000);
        land.trees = e.boolean("trees", true);
        land.treeBudget = e.unsignedInteger("tree_budget", land.treeBudget);
        land.seed = seedOverride(e);
        land.modular = modularLook(e);
        readObjectId(e, land.loc);
        e.checkAllRead();
        for (const XmlElement &child : e.children()) {
            if (child.name() != "dgm" && child.name() != "atkis")
                child.fail(
                    fmt::format("<{}> cannot stand inside <landscape>; expected <dgm> or <atkis>", child.name()));
            DataFileDesc data;
            data.loc = child.attributeLoc("file");
            data.file = pathAttribute(child, "file");
            if (child.has("crs")) data.epsg = epsgAttribute(child, "crs");
            child.checkLeaf();
            (child.name() == "dgm" ? land.dgm : land.layers).push_back(std::move(data));
        }
        if (land.dgm.empty()) e.fail("a <landscape> needs at least one <dgm file=\"...\"/>");
        scene_.landscape = std::move(land);
    }

    void readBuildings(const XmlElement &e) {
        BuildingGroupDesc group;
        group.loc = e.loc();
        group.rules = pathAttribute(e, "rules");
        group.rulesLoc = e.attributeLoc("rules");
        group.seed = seedOverride(e);
        e.checkAllRead();
        for (const XmlElement &child : e.children()) {
            if (child.name() == "BuildingSettings") {
                group.settings = readBuildingSettings(child);
            } else if (child.name() == "building") {
                group.buildings.push_back(readBuilding(child));
            } else if (child.name() == "facade") {
                group.facades.push_back(readFacade(child));
            } else {
                child.fail(fmt::format(
                    "<{}> cannot stand inside <buildings>; expected <building>, <facade> or <BuildingSettings>",
                    child.name()));
            }
        }
        scene_.buildingGroups.push_back(std::move(group));
    }

    BuildingDesc readBuilding(const XmlElement &e) {
        BuildingDesc b;
        b.loc = e.loc();
        b.buildingId = e.unsignedInteger("id", 0);
        if (e.has("id") && b.buildingId == 0) e.failAt("id", "building ids start at 1; 0 means no building");
        std::vector<float> xy = e.numbers("footprint");
        b.footprintLoc = e.attributeLoc("footprint");
        if (xy.size() % 2 != 0 || xy.size() < 6)
            e.failAt("footprint", fmt::format("a footprint is at least three x y pairs; {} numbers given", xy.size()));
        for (size_t i = 0; i < xy.size(); i += 2) b.footprint.push_back({xy[i], xy[i + 1]});
        b.streetLoc = e.attributeLoc("street");
        for (float edge : e.has("street") ? e.numbers("street") : std::vector<float>{}) {
            if (edge < 0 || edge != std::floor(edge) || edge >= float(b.footprint.size()))
                e.failAt("street",
                         fmt::format("street edges are numbers of footprint edges, 0 to {}; {} is not one",
                                     b.footprint.size() - 1, edge));
            b.streetEdges.push_back(uint32_t(edge));
        }
        if (e.has("base")) b.base = e.number("base", 0);
        b.settings = readSettingsChild(e);
        return b;
    }

    FacadeDesc readFacade(const XmlElement &e) {
        FacadeDesc f;
        f.loc = e.loc();
        f.buildingId = e.unsignedInteger("id", 0);
        if (e.has("id") && f.buildingId == 0) e.failAt("id", "building ids start at 1; 0 means no building");
        f.start = e.string("start");
        f.width = e.number("width", 0, 0.01f, 1e4f);
        f.height = e.number("height", 0, 0.01f, 1e4f);
        if (!e.has("width") || !e.has("height")) e.fail("<facade> needs 'width' and 'height' in metres");
        f.transform = readTransform(e);
        f.settings = readSettingsChild(e);
        return f;
    }

    // The optional <BuildingSettings> inside a <building> or <facade>, after its attributes.
    static SettingsMap readSettingsChild(const XmlElement &e) {
        e.checkAllRead();
        SettingsMap settings;
        for (const XmlElement &child : e.children()) {
            if (child.name() != "BuildingSettings")
                child.fail(
                    fmt::format("<{}> cannot stand inside <{}>; expected <BuildingSettings>", child.name(), e.name()));
            settings = readBuildingSettings(child);
        }
        return settings;
    }

    GeometryDesc readGeometry(const XmlElement &e, bool topLevel) {
        GeometryDesc g;
        g.loc = e.loc();
        if (e.name() == "mesh") {
            g.meshFile = pathAttribute(e, "file");
            g.meshFileLoc = e.attributeLoc("file");
            readFileCrs(e, g.meshEpsg, g.meshCrsLoc);
        } else {
            g.shape = readShape(e);
        }
        if (e.name() == "ground") {
            // Endless and level, it has a height instead of a transform.
            if (!topLevel) e.fail("<ground> stands at the top level of the scene, not in a <prototype>");
        } else {
            g.transform = readTransform(e);
        }
        g.material = readNameRef(e, "material");
        if (topLevel) {
            readObjectId(e, g.loc);
            g.buildingId = e.unsignedInteger("building", 0);
        } else {
            for (const char *attribute : {"id", "building"}) {
                if (e.has(attribute)) {
                    e.failAt(attribute,
                             fmt::format("parts of a prototype have no {} of their own; give it to the "
                                         "<instance>",
                                         attribute));
                }
            }
        }
        e.checkLeaf();
        return g;
    }

    static ShapeSpec readShape(const XmlElement &e) {
        ShapeSpec s;
        std::string_view n = e.name();
        if (n == "box") {
            s.kind = ShapeKind::Box;
            s.size = e.vec3("size", s.size);
        } else if (n == "ground") {
            s.kind = ShapeKind::Ground;
            s.height = e.number("height", 0, -1e4f, 1e5f);
        } else if (n == "plane") {
            s.kind = ShapeKind::Plane;
            if (e.has("size")) {
                std::vector<float> v = e.numbers("size");
                if (v.size() != 2) e.failAt("size", "plane size takes two numbers, x and y");
                s.size = {v[0], v[1], 0};
            }
        } else {
            s.kind = n == "sphere" ? ShapeKind::Sphere : (n == "cylinder" ? ShapeKind::Cylinder : ShapeKind::Cone);
            s.radius = e.number("radius", s.radius, 1e-6f, 1e7f);
            s.segments = e.integer("segments", s.segments, 3, 4096);
            if (s.kind == ShapeKind::Sphere) {
                s.rings = e.integer("rings", s.rings, 2, 4096);
            } else {
                s.height = e.number("height", s.height, 1e-6f, 1e7f);
                s.smooth = e.boolean("smooth", s.smooth);
            }
        }
        if (s.size.x < 0 || s.size.y < 0 || s.size.z < 0) e.failAt("size", "sizes must not be negative");
        return s;
    }

    // Scale, then rotate about x, y and z in that order, then translate; or a full matrix.
    static Transform readTransform(const XmlElement &e) {
        if (e.has("matrix")) {
            if (e.has("translate") || e.has("rotate") || e.has("scale")) {
                e.failAt("matrix", "give either 'matrix' or 'translate'/'rotate'/'scale', not both");
            }
            std::vector<float> m = e.numbers("matrix");
            if (m.size() != 12) e.failAt("matrix", "matrix takes 12 numbers: a 3x4 matrix, row by row");
            Transform t;
            std::copy(m.begin(), m.end(), t.m.begin());
            if (t.determinant() == 0) e.failAt("matrix", "matrix is singular");
            return t;
        }
        Vec3f scale = e.color("scale", Vec3f(1));
        if (scale.x == 0 || scale.y == 0 || scale.z == 0) e.failAt("scale", "scale must not be zero");
        Vec3f rotate = e.vec3("rotate", {0, 0, 0});
        Vec3f translate = e.vec3("translate", {0, 0, 0});
        return Transform::translate(translate) * Transform::rotate(2, rotate.z) * Transform::rotate(1, rotate.y) *
            Transform::rotate(0, rotate.x) * Transform::scale(scale);
    }

    static NameRef readNameRef(const XmlElement &e, const char *attribute) {
        if (!e.has(attribute)) return {};
        NameRef ref{e.string(attribute), e.attributeLoc(attribute)};
        if (ref.name.empty()) e.failAt(attribute, fmt::format("attribute '{}' is empty", attribute));
        return ref;
    }

    // Records an explicit id for the object at `loc`; assignObjectIds() fills in the rest.
    void readObjectId(const XmlElement &e, const FileLoc &loc) {
        if (!e.has("id")) return;
        uint32_t id = e.unsignedInteger("id", 0);
        if (id == 0) e.failAt("id", "object ids start at 1; 0 means no object");
        auto [it, fresh] = explicitIds_.emplace(id, e.attributeLoc("id"));
        if (!fresh) e.failAt("id", fmt::format("object id {} is already used at {}", id, it->second.toString()));
        idsByPlace_[{loc.line, loc.column}] = id;
    }

    // Objects without an id get the smallest unused numbers from 1 up, in file order, so
    // ids stay stable when objects are appended.
    void assignObjectIds() {
        std::map<std::pair<int, int>, uint32_t *> byPlace;
        for (GeometryDesc &g : scene_.geometry) byPlace[{g.loc.line, g.loc.column}] = &g.objectId;
        for (InstanceDesc &i : scene_.instances) byPlace[{i.loc.line, i.loc.column}] = &i.objectId;
        for (BuildingGroupDesc &group : scene_.buildingGroups) {
            for (BuildingDesc &b : group.buildings) byPlace[{b.loc.line, b.loc.column}] = &b.objectId;
            for (FacadeDesc &f : group.facades) byPlace[{f.loc.line, f.loc.column}] = &f.objectId;
        }
        for (CityDesc &c : scene_.cities) byPlace[{c.loc.line, c.loc.column}] = &c.objectId;
        for (CityGmlDesc &c : scene_.cityGml) byPlace[{c.loc.line, c.loc.column}] = &c.objectId;
        for (ModularBuildingDesc &b : scene_.modularBuildings) byPlace[{b.loc.line, b.loc.column}] = &b.objectId;
        for (SlgDesc &s : scene_.slg) byPlace[{s.loc.line, s.loc.column}] = &s.objectId;
        if (scene_.landscape)
            byPlace[{scene_.landscape->loc.line, scene_.landscape->loc.column}] = &scene_.landscape->objectId;
        uint32_t next = 1;
        for (auto &[place, id] : byPlace) {
            auto given = idsByPlace_.find(place);
            if (given != idsByPlace_.end()) {
                *id = given->second;
                continue;
            }
            while (explicitIds_.count(next)) ++next;
            *id = next++;
        }
    }

    // Buildings without an id get the smallest unused numbers from 1 up, in file order; an id
    // given twice is an error (it would give two buildings the same random choices).
    void assignBuildingIds() {
        std::vector<std::pair<uint32_t *, const FileLoc *>> all;
        for (BuildingGroupDesc &group : scene_.buildingGroups) {
            for (BuildingDesc &b : group.buildings) all.emplace_back(&b.buildingId, &b.loc);
            for (FacadeDesc &f : group.facades) all.emplace_back(&f.buildingId, &f.loc);
        }
        for (ModularBuildingDesc &b : scene_.modularBuildings) all.emplace_back(&b.buildingId, &b.loc);
        std::sort(all.begin(), all.end(), [](const auto &a, const auto &b) {
            return std::pair(a.second->line, a.second->column) < std::pair(b.second->line, b.second->column);
        });
        std::map<uint32_t, FileLoc> given;
        for (auto &[id, loc] : all) {
            if (*id == 0) continue;
            auto [it, fresh] = given.emplace(*id, *loc);
            if (!fresh)
                throw InputError(*loc, fmt::format("building id {} is already used at {}", *id, it->second.toString()));
        }
        uint32_t next = 1;
        for (auto &[id, loc] : all) {
            if (*id != 0) continue;
            while (given.count(next)) ++next;
            *id = next++;
        }
    }

    const XmlDocument &doc_;
    std::filesystem::path baseDirectory_;
    SceneDescription scene_;
    std::map<uint32_t, FileLoc> explicitIds_;
    std::map<std::pair<int, int>, uint32_t> idsByPlace_;
};

}  // namespace

SceneDescription readSceneFile(const std::filesystem::path &file) {
    XmlDocument doc = XmlDocument::fromFile(file);
    return SceneFileReader(doc, file.parent_path()).read();
}

SceneDescription readSceneText(std::string text, const std::string &name, const std::filesystem::path &baseDirectory) {
    XmlDocument doc = XmlDocument::fromString(std::move(text), name);
    return SceneFileReader(doc, baseDirectory).read();
}

}  // namespace veduta

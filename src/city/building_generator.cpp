#include "city/building_generator.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "city/asset_fitting.h"
#include "city/masonry_maps.h"
#include "city/roof_choice.h"
#include "city/roof_fixtures.h"
#include "city/start_shapes.h"
#include "core/check.h"
#include "core/hash.h"

namespace veduta {

namespace {

// A party wall: a fire wall's rough grey plaster, unless the scene defines `party_wall`.
Material partyWallMaterial() { return Material::lambertian("party_wall", {0.4f, 0.38f, 0.35f}); }

// The mesh a building's walls and roof are collected in, and its facades' terminals: each
// thread's, reused from building to building (welding copies the mesh out without spare room),
// so that they do not grow afresh each time.
struct BuildingBuffers {
    Mesh baked;
    std::vector<Terminal> terminals;
};

BuildingBuffers &threadBuffers() {
    thread_local BuildingBuffers buffers;
    return buffers;
}

Mesh &startBakedMesh() {
    Mesh &baked = threadBuffers().baked;
    for (auto *v : {&baked.positions, &baked.normals, &baked.tangents}) v->clear();
    baked.uvs.clear();
    baked.bitangentSigns.clear();
    baked.indices.clear();
    baked.triangleMaterials.clear();
    return baked;
}

// The material of a model's first surface in the key's materials: what a piece baked or swept
// in one material takes.
MaterialId firstMaterial(const Asset &model, const BuildingGenerator::PrototypeKey &key) {
    return key.materials[model.mesh.triangleMaterials.empty() ? 0 : model.mesh.triangleMaterials[0]];
}

// Where a terminal's scope lies on its facade: the box of its corners.
CornicePlace placeOf(const Terminal &terminal, const CorniceRule &rule, size_t facade, MaterialId material) {
    CornicePlace place{&rule, facade, INFINITY, -INFINITY, INFINITY, -INFINITY, material};
    for (float sx : {-0.5f, 0.5f})
        for (float sy : {-0.5f, 0.5f}) {
            Vec3f corner = terminal.shapeToFacade.applyPoint({sx * terminal.size.x, sy * terminal.size.y, 0.0f});
            place.left = std::min(place.left, double(corner.x));
            place.right = std::max(place.right, double(corner.x));
            place.bottom = std::min(place.bottom, double(corner.y));
            place.top = std::max(place.top, double(corner.y));
        }
    return place;
}

}  // namespace

size_t BuildingGenerator::PrototypeKeyHash::operator()(const PrototypeKey &key) const {
    uint32_t h = hashValues({key.model});
    for (MaterialId m : key.materials) h = mix32(h ^ m);
    return h;
}

BuildingGenerator::BuildingGenerator(const Grammar &grammar, const AssetLibrary &assets, RenderSceneBuilder &builder,
                                     uint32_t seed, const DerivationLimits &limits) :
    grammar_(grammar),
    assets_(assets),
    builder_(builder),
    palette_(builder),
    seed_(seed),
    limits_(limits),
    plainWall_(*assets.find("Wall0")),
    partyWall_(builder.findOrAddMaterial(partyWallMaterial())),
    consolePrototypes_(builder) {
    for (size_t a = 0; a < assets.size(); ++a)
        VEDUTA_CHECK(
            assets[uint32_t(a)].surfaces.size() <= kMaxSurfaces,
            fmt::format("the model {} has more surfaces than a prototype key holds", assets[uint32_t(a)].name));
    for (const MasonryRule &rule : grammar.rules().masonry) {
        std::optional<uint32_t> model = assets.find(rule.model);
        if (!model || assets[*model].type != ModelType::Wall)
            throw InputError(
                rule.loc,
                fmt::format("<Masonry model=\"{}\">: {}", rule.model,
                            model ? "not a wall model (masonry covers walls)" : "no such model in the library"));
        masonryModels_[*model].push_back(&rule);
    }
    for (const CorniceRule &rule : grammar.rules().cornices) {
        std::optional<uint32_t> model = assets.find(rule.model);
        if (!model || assets[*model].type == ModelType::Wall)
            throw InputError(
                rule.loc,
                fmt::format("<Cornice model=\"{}\">: {}", rule.model,
                            model ? "a wall model (walls are baked, not placed)" : "no such model in the library"));
        corniceModels_[*model].push_back(&rule);
    }
}

void BuildingGenerator::bakeMasonryWith(const Camera &camera, MasonryOutput masonry) {
    masonryBaking_.emplace(MasonryBaking{&camera, CameraRays(camera), std::move(masonry)});
}

PrototypeId BuildingGenerator::prototypeFor(const PrototypeKey &key) {
    auto it = prototypes_.find(key);
    if (it != prototypes_.end()) return it->second;
    Mesh mesh = assets_[key.model].mesh;
    for (MaterialId &m : mesh.triangleMaterials) m = key.materials[m];
    PrototypeId id = builder_.addPrototype(std::move(mesh));
    prototypes_.emplace(key, id);
    return id;
}

BuildingGenerator::PrototypeKey BuildingGenerator::keyFor(const Terminal &terminal,
                                                          const MaterialSet &materials) const {
    const Asset &model = assets_[terminal.model];
    PrototypeKey key;
    key.model = terminal.model;
    for (size_t s = 0; s < model.surfaces.size(); ++s) key.materials[s] = materials[model.surfaces[s]];
    if (terminal.texture) {
        std::lock_guard lock(textureMutex_);
        auto [it, added] = textureChoices_.try_emplace(terminal.texture);
        if (added) it->second = palette_.forTexture(*terminal.texture);
        key.materials[0] = it->second.in(materials);
    }
    return key;
}

// A wall piece is baked, not instanced: its texture coordinates are its position on the
// facade (metres along the perimeter, metres up; plus the depth for reveals) divided by the
// uv attribute, so neighbouring pieces continue one another (Bilke's planar wall mapping).
void BuildingGenerator::addWallPiece(const Asset &model, const Transform &modelToFacade, const Transform &facadeToWorld,
                                     float alongPerimeter, const Terminal &terminal, const PrototypeKey &key,
                                     Mesh &baked) const {
    auto first = uint32_t(baked.positions.size());
    auto firstTriangle = baked.triangleCount();
    baked.append(model.mesh, facadeToWorld * modelToFacade);
    for (size_t v = 0; v < model.mesh.positions.size(); ++v) {
        Vec3f onFacade = modelToFacade.applyPoint(model.mesh.positions[v]);
        baked.uvs[first + v] = {(alongPerimeter + onFacade.x + onFacade.z) / terminal.uv.x, onFacade.y / terminal.uv.y};
    }
    for (size_t t = firstTriangle; t < baked.triangleCount(); ++t)
        baked.triangleMaterials[t] = key.materials[model.mesh.triangleMaterials[t - firstTriangle]];
}

// The first <Cornice> that takes the model where the terminal's rule placed it, or none.
const CorniceRule *BuildingGenerator::corniceOf(const Terminal &terminal) const {
    auto rules = corniceModels_.find(terminal.model);
    if (rules == corniceModels_.end()) return nullptr;
    for (const CorniceRule *rule : rules->second) {
        if (rule->rules.empty()) return rule;
        const std::string &placedBy = grammar_.rules().rules.at(terminal.rule).predecessor;
        if (std::find(rule->rules.begin(), rule->rules.end(), placedBy) != rule->rules.end()) return rule;
    }
    return nullptr;
}

// The rules' <Cornice> places swept (rule_cornices.h) into the building's mesh, before it is
// welded; their consoles are set when the building is added.
void BuildingGenerator::addCornices(const std::vector<CornicePlace> &places, const std::vector<StartShape> &facades,
                                    Mesh &baked, MadeBuilding &made) const {
    if (places.empty()) return;
    CorniceRun swept = sweepRuleCornices(places, facades);
    baked.append(swept.mesh, Transform());
    for (ConsoleSet &set : swept.consoles) made.consoles.push_back(std::move(set));
}

// The first <Masonry> that covers the model on that facade, or none.
const MasonryRule *BuildingGenerator::masonryOf(uint32_t model, const std::string &facade) const {
    auto rules = masonryModels_.find(model);
    if (rules == masonryModels_.end()) return nullptr;
    for (const MasonryRule *rule : rules->second)
        if (rule->covers(facade)) return rule;
    return nullptr;
}

// A piece of a <Masonry> model: baked like any wall piece, but its texture coordinates are its
// facade metres (from the facade's lower left), which the masonry atlas maps later, and its
// triangles join the facade's masonry wall for that style.
void BuildingGenerator::addMasonryPiece(const Asset &model, const Transform &modelToFacade, const StartShape &start,
                                        const PrototypeKey &key, const MasonryRule &rule, Mesh &baked,
                                        MadeBuilding &made) const {
    auto first = uint32_t(baked.positions.size());
    auto firstTriangle = uint32_t(baked.triangleCount());
    baked.append(model.mesh, start.facadeToWorld * modelToFacade);
    for (size_t v = 0; v < model.mesh.positions.size(); ++v) {
        Vec3f onFacade = modelToFacade.applyPoint(model.mesh.positions[v]);
        baked.uvs[first + v] = {onFacade.x, onFacade.y};
    }
    MaterialId material = firstMaterial(model, key);
    for (uint32_t t = firstTriangle; t < baked.triangleCount(); ++t) baked.triangleMaterials[t] = material;
    // One masonry wall a facade and rule, its stones laid over the whole facade: pieces apart on
    // it continue one bond.
    auto facade = std::make_pair(start.edge, &rule);
    auto found = std::find(made.masonryFacades.begin(), made.masonryFacades.end(), facade);
    if (found == made.masonryFacades.end()) {
        MasonryWall wall;
        wall.face.outline = {{0, 0}, {start.width, 0}, {start.width, start.height}, {0, start.height}};
        wall.material = material;
        made.masonry.push_back(std::move(wall));
        made.masonryFacades.push_back(facade);
        found = made.masonryFacades.end() - 1;
    }
    MasonryWall &wall = made.masonry[size_t(found - made.masonryFacades.begin())];
    for (uint32_t t = firstTriangle; t < baked.triangleCount(); ++t) wall.triangles.push_back(t);
}

// Gives each masonry wall its recipe and bakes the building's atlas (laying the stones) or hands
// the recipes to a shader, before the mesh is welded (the atlas's coordinates keep the tiles'
// vertices apart); the stones are dropped once baked.
void BuildingGenerator::bakeMasonry(const BuildingContext &building, Mesh &baked, MadeBuilding &made,
                                    std::vector<std::string> &warnings) const {
    if (made.masonry.empty()) return;
    if (!masonryBaking_) {
        if (!masonryUnbakedSaid_.exchange(true))
            warnings.push_back(fmt::format("{}: no camera to bake masonry for; its walls keep their model's texture",
                                           grammar_.rules().masonry.front().loc.toString()));
        made.masonry.clear();
        made.masonryFacades.clear();
        return;
    }
    for (size_t w = 0; w < made.masonry.size(); ++w) {
        auto [edge, rule] = made.masonryFacades[w];
        MasonryWall &wall = made.masonry[w];
        // The rule's place in the file, stable where its address is not.
        auto place = uint32_t(rule - grammar_.rules().masonry.data());
        wall.recipe = styleMasonryRecipe(rule->style, wall.face, seed_, hashValues({building.id, edge, place}));
    }
    if (masonryBaking_->output.procedural) {
        made.masonryShader = shadeMasonry(baked, made.masonry);
        return;
    }
    made.masonryMaps = bakeMasonryMaps(baked, made.masonry, Transform(), masonryBaking_->rays, *masonryBaking_->camera);
    for (MasonryWall &wall : made.masonry) wall.masonry.stones = {};
}

// The roof closes the walls at the eaves: buildRoof's slopes pass over the wall tops there,
// overhang or not (roof_shapes.h).
void BuildingGenerator::addRoof(const BuildingSpec &building, const BuildingContext &context, Mesh &baked,
                                MadeBuilding &made, std::vector<std::string> &warnings) const {
    const Footprint &footprint = building.footprint;
    RoofOptions options = roofOptionsFor(footprint, building.settings, context.heights, seed_, building.id);
    RoofResult roof = buildRoof({footprint.points, {}, footprint.base}, context.heights.building, options);
    if (roof.fallback && roof.built != options.type) {
        warnings.push_back(fmt::format("building {}: a {} roof instead of {}: {}", building.id,
                                       roofTypeName(roof.built), roofTypeName(options.type), *roof.fallback));
    } else if (roof.fallback) {
        warnings.push_back(
            fmt::format("building {}: {} roof: {}", building.id, roofTypeName(roof.built), *roof.fallback));
    }
    float ridge = footprint.base + context.heights.building;
    for (const Vec3f &p : roof.mesh.positions) ridge = std::max(ridge, p.z);
    made.record = BuildingRecord{building.id,
                                 footprint.base,
                                 footprint.base + context.heights.building,
                                 ridge,
                                 std::string(roofTypeName(roof.built)),
                                 {footprint.points}};
    Mesh fixtures = roofFixtures(roof.mesh, footprint, roofFixtureOptionsFor(building.settings), seed_, building.id);
    for (MaterialId &m : roof.mesh.triangleMaterials)
        m = m == RoofGableWall ? context.materials[MaterialCategory::Wall] : context.materials[MaterialCategory::Roof];
    baked.append(roof.mesh, Transform{});
    for (MaterialId &m : fixtures.triangleMaterials) {
        MaterialCategory category = m == FixtureWindow ? MaterialCategory::Window
            : m == FixtureRoof                         ? MaterialCategory::Roof
                                                       : MaterialCategory::Wall;
        m = context.materials[category];
    }
    baked.append(fixtures, Transform{});
}

BuildingGenerator::BuildingContext BuildingGenerator::contextFor(uint32_t id, ObjectId objectId,
                                                                 const SettingsStack &settings) const {
    BuildingHeights heights = randomiseHeights(settings, seed_, id);
    return {id, objectId, heights, BuildingProperties(settings, heights), palette_.choose(seed_, id)};
}

// The whole wall of a start shape as the plain wall model.
Terminal BuildingGenerator::plainWallOf(const StartShape &start) const {
    Terminal wall;
    wall.model = plainWall_;
    wall.shapeToFacade = Transform::translate({start.width / 2, start.height / 2, 0});
    wall.size = {start.width, start.height};
    return wall;
}

void BuildingGenerator::addPlainWall(const BuildingContext &building, const StartShape &start, float alongPerimeter,
                                     Mesh &baked, std::optional<MaterialId> material) const {
    Terminal wall = plainWallOf(start);
    const Asset &model = assets_[plainWall_];
    PrototypeKey key = keyFor(wall, building.materials);
    if (material) key.materials.fill(*material);
    addWallPiece(model, modelToFacade(model, wall), start.facadeToWorld, alongPerimeter, wall, key, baked);
}

void BuildingGenerator::emitFacade(const BuildingContext &building, const StartShape &start, size_t facade,
                                   float alongPerimeter, Mesh &baked, MadeBuilding &made,
                                   std::vector<CornicePlace> &cornices, std::vector<std::string> &warnings) const {
    std::vector<Terminal> &terminals = threadBuffers().terminals;
    terminals.clear();
    if (grammar_.findRule(start.symbol)) {
        try {
            deriveFacade(grammar_, start.symbol, {start.width, start.height}, building.properties, {seed_, building.id},
                         terminals, warnings, limits_);
        } catch (const InputError &e) {
            // A limit is mostly hit by a facade's size, not by the rules.
            throw InputError(e.loc(),
                             fmt::format("{} (on a facade {:.0f} m wide and {:.0f} m high)", e.message(), start.width,
                                         start.height));
        }
    } else {
        // A rule set made for one kind of facade still builds whole buildings: the walls it has
        // no rule for are plain.
        const std::vector<Rule> &rules = grammar_.rules().rules;
        warnings.push_back(fmt::format("{}: the rule file has no rule for '{}'; those walls are plain",
                                       rules.empty() ? grammar_.rules().name : rules.front().loc.file, start.symbol));
        terminals.push_back(plainWallOf(start));
    }
    made.stats.terminals += terminals.size();
    for (const Terminal &terminal : terminals) {
        const Asset &model = assets_[terminal.model];
        Transform modelToFacadeFrame = modelToFacade(model, terminal);
        PrototypeKey key = keyFor(terminal, building.materials);
        if (model.type == ModelType::Wall) {
            if (const MasonryRule *masonry = masonryOf(terminal.model, start.symbol))
                addMasonryPiece(model, modelToFacadeFrame, start, key, *masonry, baked, made);
            else addWallPiece(model, modelToFacadeFrame, start.facadeToWorld, alongPerimeter, terminal, key, baked);
            continue;
        }
        if (const CorniceRule *cornice = corniceOf(terminal)) {
            cornices.push_back(placeOf(terminal, *cornice, facade, firstMaterial(model, key)));
            continue;
        }
        made.instances.push_back({start.facadeToWorld * modelToFacadeFrame, key});
        ++made.stats.instances;
    }
}

BuildingGenerator::MadeBuilding BuildingGenerator::make(const BuildingSpec &spec,
                                                        std::vector<std::string> &warnings) const {
    MadeBuilding made;
    made.objectId = spec.objectId;
    made.id = spec.id;
    BuildingContext building = contextFor(spec.id, spec.objectId, spec.settings);
    Mesh &baked = startBakedMesh();
    std::vector<StartShape> facades = makeStartShapes(spec.footprint, building.heights.building);
    std::vector<CornicePlace> cornices;
    for (size_t f = 0; f < facades.size(); ++f) {
        float along = spec.footprint.perimeterBefore(facades[f].edge);
        const std::vector<bool> &party = spec.partyEdges;
        if (facades[f].edge < party.size() && party[facades[f].edge])
            addPlainWall(building, facades[f], along, baked, partyWall_);
        else if (spec.coarse) addPlainWall(building, facades[f], along, baked);
        else emitFacade(building, facades[f], f, along, baked, made, cornices, warnings);
    }
    addCornices(cornices, facades, baked, made);
    addRoof(spec, building, baked, made, warnings);
    bakeMasonry(building, baked, made, warnings);
    made.stats.bakedTriangles = baked.triangleCount();
    made.mesh = weldVertices(baked);
    return made;
}

BuildingStats BuildingGenerator::add(MadeBuilding &&made, Mesh *merged) {
    for (const MadeBuilding::Placement &placement : made.instances) {
        Instance instance;
        instance.objectToWorld = placement.objectToWorld;
        instance.prototype = prototypeFor(placement.prototype);
        instance.objectId = made.objectId;
        instance.buildingId = made.id;
        builder_.addInstance(instance);
    }
    for (const ConsoleSet &set : made.consoles) {
        PrototypeId prototype = consolePrototypes_.get(set.objectFile, set);
        for (const Transform &t : set.transforms)
            builder_.addInstance({t, prototype, kNoMaterial, made.objectId, made.id, 0});
    }
    // A building has its mesh and record; a lone facade has no record, and a mesh only where
    // its rules baked walls.
    if (made.masonryMaps)
        addMasonryMaps(made.mesh, made.masonry, std::move(*made.masonryMaps), builder_, masonryBaking_->output.addImage,
                       made.id);
    if (made.masonryShader)
        addMasonryShader(made.mesh, made.masonry, std::move(made.masonryShader), builder_,
                         masonryBaking_->output.addProcedural, made.id);
    bool building = made.record.has_value();
    if (building) builder_.recordBuilding(std::move(*made.record));
    if (merged) merged->append(made.mesh, Transform());
    else if (building || made.mesh.triangleCount() > 0)
        builder_.addWorldMesh(std::move(made.mesh), made.objectId, made.id);
    return made.stats;
}

BuildingStats BuildingGenerator::generate(const BuildingSpec &spec, std::vector<std::string> &warnings) {
    return add(make(spec, warnings));
}

BuildingStats BuildingGenerator::generateFacade(const FacadeSpec &spec, std::vector<std::string> &warnings) {
    BuildingContext building = contextFor(spec.id, spec.objectId, spec.settings);
    StartShape start{spec.startSymbol, 0, spec.width, spec.height, spec.facadeToWorld};
    MadeBuilding made;
    made.objectId = spec.objectId;
    made.id = spec.id;
    Mesh &baked = startBakedMesh();
    std::vector<CornicePlace> cornices;
    emitFacade(building, start, 0, 0, baked, made, cornices, warnings);
    addCornices(cornices, {start}, baked, made);
    bakeMasonry(building, baked, made, warnings);
    made.stats.bakedTriangles = baked.triangleCount();
    made.mesh = weldVertices(baked);
    return add(std::move(made));
}

}  // namespace veduta

#include "facade/building_description.h"

#include <cmath>
#include <map>
#include <memory>
#include <vector>

#include <fmt/format.h>

#include "facade/description_text.h"

namespace veduta {
namespace {

// ---- Fields -------------------------------------------------------------------------------------

double boundedNumber(const DescriptionItem &item, size_t index, std::string_view what, double least, double most) {
    double value = item.number(index, what);
    if (!(value >= least && value <= most))
        throw InputError(item.fields[index].loc,
                         fmt::format("{} {} is outside [{}, {}]", what, item.fields[index].text, least, most));
    return value;
}

double positiveNumber(const DescriptionItem &item, size_t index, std::string_view what, double most) {
    double value = boundedNumber(item, index, what, 0, most);
    if (!(value > 0))
        throw InputError(item.fields[index].loc, fmt::format("{} {} is not positive", what, item.fields[index].text));
    return value;
}

double fraction(const DescriptionItem &item, size_t index, std::string_view what) {
    return boundedNumber(item, index, what, 0, 1);
}

int wholeNumber(const DescriptionItem &item, size_t index, std::string_view what, int least, int most) {
    double value = boundedNumber(item, index, what, least, most);
    if (std::floor(value) != value)
        throw InputError(item.fields[index].loc,
                         fmt::format("{} {} is not a whole number", what, item.fields[index].text));
    return int(value);
}

// An item that is only a quoted name.
const std::string &nameItem(const DescriptionItem &item, std::string_view what) {
    item.expectFieldCount(1, 1, what);
    return item.string(0, what);
}

void expectItems(const DescriptionBlock &block, size_t least, std::string_view what) {
    if (block.items.size() < least) throw InputError(block.loc, fmt::format("the {} block needs {}", block.name, what));
}

std::string secondOf(std::string_view what, const FileLoc &first) {
    return fmt::format("a second {} (the first is at {})", what, first.toString());
}

// ---- Structure ----------------------------------------------------------------------------------

ModuleStructure readModule(const DescriptionBlock &block) {
    expectItems(block, 4, "a name and at least 3 corners");
    const DescriptionItem &head = block.items[0];
    head.expectFieldCount(1, 2, "a module's name and type");
    ModuleStructure module;
    module.name = head.string(0, "the module's name");
    if (head.fields.size() == 2) module.module.type = head.string(1, "the module's type");
    module.module.loc = block.loc;
    if (block.items.size() - 1 > kModuleCornerLimit)
        throw InputError(block.loc, fmt::format("a module has at most {} corners", kModuleCornerLimit));
    for (size_t i = 1; i < block.items.size(); ++i) {
        const DescriptionItem &item = block.items[i];
        item.expectFieldCount(2, 2, "a corner (x, y)");
        module.module.outline.push_back({boundedNumber(item, 0, "x", -kBuildingSizeLimit, kBuildingSizeLimit),
                                         boundedNumber(item, 1, "y", -kBuildingSizeLimit, kBuildingSizeLimit)});
    }
    // Until a Roof block says otherwise (see the header).
    module.roof.kind = RoofStructure::Kind::Flat;
    module.roof.loc = block.loc;
    return module;
}

int edgeOf(const DescriptionItem &item, size_t index, std::string_view what, const ModuleStructure &module) {
    return wholeNumber(item, index, what, 0, int(module.module.outline.size()) - 1);
}

std::vector<double> readStoreys(const DescriptionBlock &block) {
    expectItems(block, 2, "a module and at least one storey");
    std::vector<double> heights;
    for (size_t i = 1; i < block.items.size(); ++i) {
        const DescriptionItem &item = block.items[i];
        item.expectFieldCount(1, 2, "a storey (height[, count])");
        double height = boundedNumber(item, 0, "a storey height", 0.5, kStoreyHeightLimit);
        int count = 1;
        if (item.fields.size() == 2) count = wholeNumber(item, 1, "a storey count", 1, int(kStructureStoreyLimit));
        if (heights.size() + size_t(count) > kStructureStoreyLimit)
            throw InputError(item.loc, fmt::format("a module has at most {} storeys", kStructureStoreyLimit));
        heights.insert(heights.end(), size_t(count), height);
    }
    return heights;
}

// The roofs a Roof block may give, with their fields (see the header).
struct RoofForm {
    const char *kind;
    size_t fields;
    const char *usage;
};
constexpr RoofForm kRoofForms[] = {{"general", 8, "general, e_i, e_j, c, d, a, b, h"},
                                   {"gable", 4, "gable, e_i, e_j, h"},
                                   {"hip", 5, "hip, e_i, e_j, h, inset"},
                                   {"pyramid", 4, "pyramid, e_i, e_j, h"},
                                   {"shed", 3, "shed, edge, h"},
                                   {"flat", 3, "flat, parapet height, parapet width"}};

// Def 4.13's parameters from a roof item of a general kind (its field count checked).
GeneralRoofParameters readGeneralRoof(const DescriptionItem &item, const std::string &kind,
                                      const ModuleStructure &module) {
    GeneralRoofParameters p;
    if (kind == "shed") {
        p.edgeI = p.edgeJ = size_t(edgeOf(item, 1, "the shed's high edge", module));
        p.c = 0, p.d = 1, p.a = 0, p.b = 1;
        p.height = positiveNumber(item, 2, "the roof height", kBuildingSizeLimit);
        return p;
    }
    p.edgeI = size_t(edgeOf(item, 1, "the roof's edge e_i", module));
    p.edgeJ = size_t(edgeOf(item, 2, "the roof's edge e_j", module));
    if (kind == "general") {
        p.c = fraction(item, 3, "c"), p.d = fraction(item, 4, "d");
        p.a = fraction(item, 5, "a"), p.b = fraction(item, 6, "b");
        if (p.a > p.b)
            throw InputError(item.fields[6].loc, fmt::format("the ridge's b {} is below its a {}", p.b, p.a));
        p.height = positiveNumber(item, 7, "the roof height", kBuildingSizeLimit);
    } else if (kind == "hip") {
        p.height = positiveNumber(item, 3, "the roof height", kBuildingSizeLimit);
        double inset = item.number(4, "the hip's inset");
        if (!(inset > 0 && inset < 0.5))
            throw InputError(item.fields[4].loc,
                             fmt::format("the hip's inset {} must lie between 0 (a gable) and 0.5 (a pyramid)",
                                         item.fields[4].text));
        p.a = inset, p.b = 1 - inset;
    } else {
        p.a = kind == "gable" ? 0 : 0.5, p.b = kind == "gable" ? 1 : 0.5;
        p.height = positiveNumber(item, 3, "the roof height", kBuildingSizeLimit);
    }
    const std::vector<Vec2d> &o = module.module.outline;
    auto at = [&](size_t edge, double t) { return o[edge] + (o[(edge + 1) % o.size()] - o[edge]) * t; };
    if (length(at(p.edgeJ, p.d) - at(p.edgeI, p.c)) <= 1e-9 * kBuildingSizeLimit)
        throw InputError(item.loc, "the ridge's chord from e_i[c] to e_j[d] has no length");
    return p;
}

RoofStructure readRoof(const DescriptionBlock &block, const ModuleStructure &module) {
    if (block.items.size() != 2) throw InputError(block.loc, "the Roof block takes a module and one roof");
    const DescriptionItem &item = block.items[1];
    const std::string &kind = item.word(0, "the roof's kind (general, gable, hip, pyramid, shed or flat)");
    const RoofForm *form = nullptr;
    for (const RoofForm &f : kRoofForms)
        if (kind == f.kind) form = &f;
    if (!form)
        throw InputError(item.fields[0].loc,
                         fmt::format("unknown roof '{}' (general, gable, hip, pyramid, shed or flat)", kind));
    item.expectFieldCount(form->fields, form->fields, fmt::format("a {} roof ({})", kind, form->usage));
    RoofStructure roof;
    roof.loc = item.loc;
    if (kind == "flat") {
        roof.kind = RoofStructure::Kind::Flat;
        roof.parapet = {positiveNumber(item, 1, "the parapet height", kBuildingSizeLimit),
                        positiveNumber(item, 2, "the parapet width", kBuildingSizeLimit)};
    } else {
        roof.kind = RoofStructure::Kind::General;
        roof.general = readGeneralRoof(item, kind, module);
    }
    return roof;
}

std::vector<EdgeSubdivision> readWindows(const DescriptionBlock &block, const ModuleStructure &module) {
    expectItems(block, 2, "a module and at least one edge part");
    std::vector<EdgeSubdivision> parts;
    for (size_t i = 1; i < block.items.size(); ++i) {
        const DescriptionItem &item = block.items[i];
        item.expectFieldCount(4, 4, "an edge part (edge, from, to, slot)");
        EdgeSubdivision part{edgeOf(item, 0, "the edge", module), fraction(item, 1, "from"), fraction(item, 2, "to"),
                             wholeNumber(item, 3, "the window slot", 0, kWindowSlotLimit - 1), item.loc};
        if (!(part.from < part.to))
            throw InputError(
                item.fields[2].loc,
                fmt::format("the part's end {} is not after its start {}", item.fields[2].text, item.fields[1].text));
        parts.push_back(part);
    }
    return parts;
}

class StructureReader {
  public:
    explicit StructureReader(const std::string &file) : file_(file) {}

    BuildingStructure read(const std::vector<DescriptionBlock> &blocks) {
        for (const DescriptionBlock &block : blocks) {
            if (block.name == "Module") addModule(block);
            else if (block.name != "Storeys" && block.name != "Roof" && block.name != "Dock" && block.name != "Windows")
                throw InputError(
                    block.loc, fmt::format("unknown block '{}' (Module, Storeys, Roof, Dock or Windows)", block.name));
        }
        if (structure_.modules.empty()) throw InputError({file_, 1, 1}, "the structure has no Module block");
        for (const DescriptionBlock &block : blocks) {
            if (block.name == "Storeys") moduleOf(block, storeysSeen_).storeyHeights = readStoreys(block);
            else if (block.name == "Roof") {
                ModuleStructure &module = moduleOf(block, roofSeen_);
                module.roof = readRoof(block, module);
            } else if (block.name == "Windows") {
                ModuleStructure &module = moduleOf(block, windowsSeen_);
                module.subdivisions = readWindows(block, module);
            } else if (block.name == "Dock") addDocks(block);
        }
        for (size_t m = 0; m < structure_.modules.size(); ++m) {
            ModuleStructure &module = structure_.modules[m];
            if (!storeysSeen_.contains(m))
                throw InputError(module.module.loc, fmt::format("the module '{}' has no Storeys block", module.name));
            module.module.height = module.height();
        }
        validateStructure(structure_);
        return std::move(structure_);
    }

  private:
    void addModule(const DescriptionBlock &block) {
        if (structure_.modules.size() == kStructureModuleLimit)
            throw InputError(block.loc, fmt::format("a structure has at most {} modules", kStructureModuleLimit));
        ModuleStructure module = readModule(block);
        auto [at, added] = names_.emplace(module.name, structure_.modules.size());
        if (!added)
            throw InputError(
                block.items[0].loc,
                secondOf(fmt::format("module named '{}'", module.name), structure_.modules[at->second].module.loc));
        structure_.modules.push_back(std::move(module));
    }

    size_t moduleIndex(const DescriptionItem &item, size_t index) const {
        const std::string &name = item.string(index, "a module's name");
        auto at = names_.find(name);
        if (at == names_.end()) throw InputError(item.fields[index].loc, fmt::format("no module named '{}'", name));
        return at->second;
    }

    // The module a Storeys, Roof or Windows block is about; each such block once per module.
    ModuleStructure &moduleOf(const DescriptionBlock &block, std::map<size_t, FileLoc> &seen) {
        expectItems(block, 1, "a module's name");
        nameItem(block.items[0], "the module's name");
        size_t m = moduleIndex(block.items[0], 0);
        auto [at, added] = seen.emplace(m, block.loc);
        if (!added)
            throw InputError(
                block.loc,
                secondOf(fmt::format("{} block for '{}'", block.name, structure_.modules[m].name), at->second));
        return structure_.modules[m];
    }

    void addDocks(const DescriptionBlock &block) {
        expectItems(block, 1, "at least one dock");
        for (const DescriptionItem &item : block.items) {
            item.expectFieldCount(6, 6, "a dock (docked module, its edge, dominant module, its edge, a, b)");
            const ModuleStructure &docked = structure_.modules[moduleIndex(item, 0)];
            const ModuleStructure &dominant = structure_.modules[moduleIndex(item, 2)];
            if (&docked == &dominant)
                throw InputError(item.fields[2].loc, fmt::format("the module '{}' is docked onto itself", docked.name));
            ModuleDock dock{docked.name,
                            edgeOf(item, 1, "the docked module's edge", docked),
                            dominant.name,
                            edgeOf(item, 3, "the dominant module's edge", dominant),
                            fraction(item, 4, "a"),
                            fraction(item, 5, "b"),
                            item.loc};
            if (!(dock.a < dock.b))
                throw InputError(
                    item.fields[5].loc,
                    fmt::format("the dock's b {} is not above its a {}", item.fields[5].text, item.fields[4].text));
            structure_.docks.push_back(dock);
        }
    }

    const std::string &file_;
    BuildingStructure structure_;
    std::map<std::string, size_t> names_;
    std::map<size_t, FileLoc> storeysSeen_, roofSeen_, windowsSeen_;
};

// ---- Style --------------------------------------------------------------------------------------

// The files a style names: each read once, each parsed once per language (see the header).
class NamedFiles {
  public:
    explicit NamedFiles(const DescribedFileReader &readFile) : readFile_(readFile) {}

    std::shared_ptr<const BrickBond> bond(const DescriptionField &name) { return parsed(bonds_, name, parseBrickBond); }
    std::shared_ptr<const AshlarMasonry> ashlar(const DescriptionField &name) {
        return parsed(ashlars_, name, parseAshlarMasonry);
    }
    std::shared_ptr<const CyclopeanMasonry> cyclopean(const DescriptionField &name) {
        return parsed(cyclopeans_, name, parseCyclopeanMasonry);
    }
    std::shared_ptr<const CorniceDescription> cornice(const DescriptionField &name) {
        return parsed(cornices_, name, parseCorniceDescription);
    }
    uint64_t hash(const DescriptionField &name) { return descriptionHash(text(name)); }

  private:
    template <typename T>
    using Parsed = std::map<std::string, std::shared_ptr<const T>>;

    template <typename T, typename Parse>
    std::shared_ptr<const T> parsed(Parsed<T> &done, const DescriptionField &name, Parse parse) {
        if (auto at = done.find(name.text); at != done.end()) return at->second;
        auto value = std::make_shared<const T>(parse(text(name), name.text));
        done.emplace(name.text, value);
        return value;
    }

    const std::string &text(const DescriptionField &name) {
        if (name.text.empty()) throw InputError(name.loc, "a file name is empty");
        auto at = texts_.find(name.text);
        if (at == texts_.end()) at = texts_.emplace(name.text, readFile_(name.text, name.loc)).first;
        return at->second;
    }

    const DescribedFileReader &readFile_;
    std::map<std::string, std::string> texts_;
    Parsed<BrickBond> bonds_;
    Parsed<AshlarMasonry> ashlars_;
    Parsed<CyclopeanMasonry> cyclopeans_;
    Parsed<CorniceDescription> cornices_;
};

WallSubdivision readWalls(const DescriptionItem &item) {
    item.expectFieldCount(4, 4, "walls (walls, corner width, ZWE width, wall:ZWE ratio)");
    return {boundedNumber(item, 1, "the corner width", 0, kBuildingSizeLimit),
            boundedNumber(item, 2, "the ZWE width", 0, kBuildingSizeLimit),
            positiveNumber(item, 3, "the wall:ZWE ratio", kBuildingSizeLimit)};
}

MasonryStyle readMasonry(const DescriptionItem &item, NamedFiles &files) {
    const std::string &kind = item.word(1, "the masonry (plain, bricks, ashlar or cyclopean)");
    MasonryStyle masonry;
    masonry.loc = item.loc;
    if (kind == "plain") {
        item.expectFieldCount(2, 2, "plain masonry (masonry, plain)");
    } else if (kind == "bricks" || kind == "ashlar") {
        item.expectFieldCount(4, 4, fmt::format("{} masonry (masonry, {}, \"file\", metres per unit)", kind, kind));
        item.string(2, "the description's file");
        masonry.source = files.hash(item.fields[2]);
        masonry.metresPerUnit = positiveNumber(item, 3, "metres per unit", kBuildingSizeLimit);
        if (kind == "bricks") masonry.kind = MasonryStyle::Kind::Bricks, masonry.bricks = files.bond(item.fields[2]);
        else masonry.kind = MasonryStyle::Kind::Ashlar, masonry.ashlar = files.ashlar(item.fields[2]);
    } else if (kind == "cyclopean") {
        item.expectFieldCount(3, 3, "cyclopean masonry (masonry, cyclopean, \"file\")");
        item.string(2, "the description's file");
        masonry.source = files.hash(item.fields[2]);
        masonry.kind = MasonryStyle::Kind::Cyclopean;
        masonry.cyclopean = files.cyclopean(item.fields[2]);
    } else {
        throw InputError(item.fields[1].loc,
                         fmt::format("unknown masonry '{}' (plain, bricks, ashlar or cyclopean)", kind));
    }
    return masonry;
}

// `window, slot, width, height, sill, left, right` or `door, slot, width, height, left, right`.
WindowStyle readOpening(const DescriptionItem &item, OpeningKind kind) {
    bool door = kind == OpeningKind::Door;
    item.expectFieldCount(door ? 6 : 7, door ? 6 : 7,
                          door ? "a door (door, slot, width, height, dist left, dist right)"
                               : "a window (window, slot, width, height, sill, dist left, dist right)");
    WindowStyle window;
    window.kind = kind;
    window.loc = item.loc;
    AbsolutePlacement &p = window.placement;
    p.width = positiveNumber(item, 2, "the width", kBuildingSizeLimit);
    p.height = positiveNumber(item, 3, "the height", kBuildingSizeLimit);
    size_t next = 4;
    if (!door) p.sillHeight = boundedNumber(item, next++, "the sill height", 0, kBuildingSizeLimit);
    p.distLeft = boundedNumber(item, next, "the distance left", 0, kBuildingSizeLimit);
    p.distRight = boundedNumber(item, next + 1, "the distance right", 0, kBuildingSizeLimit);
    if (!(p.distLeft + p.distRight > 0))
        throw InputError(item.fields[next + 1].loc, "the distances left and right are both 0 (their ratio places it)");
    return window;
}

CasingStyle casingStyle(const DescriptionItem &item) {
    const std::string &name = item.word(2, "the casing's style (einfach, gesims, doppelgesims or klinker)");
    if (name == "einfach") return CasingStyle::Einfach;
    if (name == "gesims") return CasingStyle::Gesims;
    if (name == "doppelgesims") return CasingStyle::Doppelgesims;
    if (name == "klinker") return CasingStyle::Klinker;
    throw InputError(item.fields[2].loc,
                     fmt::format("unknown casing style '{}' (einfach, gesims, doppelgesims or klinker)", name));
}

// `casing, slot, style, size, thickness, overhang` onto its window (see the header).
void applyCasing(const DescriptionItem &item, WindowStyle &window) {
    item.expectFieldCount(6, 6, "a casing (casing, slot, style, size, thickness, overhang)");
    CasingStyle style = casingStyle(item);
    double size = boundedNumber(item, 3, "the top band's size", 0, 1);
    double thickness = boundedNumber(item, 4, "the casing thickness", 0, 1);
    double overhang = boundedNumber(item, 5, "the casing overhang", -kBuildingSizeLimit, kBuildingSizeLimit);
    const FileLoc &sizeLoc = item.fields[3].loc;
    if ((style == CasingStyle::Einfach || style == CasingStyle::Klinker) && size > 0)
        throw InputError(sizeLoc, fmt::format("a casing '{}' has no band: its size must be 0", item.fields[2].text));
    if (style == CasingStyle::Gesims && size > 0 && size < thickness)
        throw InputError(sizeLoc, fmt::format("the band {} is thinner than the casing {}", size, thickness));
    if (style == CasingStyle::Doppelgesims && !(size > 0 && size >= 2 * thickness))
        throw InputError(
            sizeLoc,
            fmt::format("a doppelgesims needs a band at least twice its thickness {} for its gable, not {}", thickness,
                        size));
    double bottom = window.kind == OpeningKind::Door ? 0 : thickness;
    if (bottom + (size > 0 ? size : thickness) >= 1 || 2 * thickness >= 1)
        throw InputError(item.fields[4].loc, "the casing's opposite sides meet inside the opening");
    Casing &casing = window.casing;
    casing.style = style;
    for (EdgeCasing &edge : casing.edges) edge = {thickness, overhang};
    casing.edges[kBottom].thickness = bottom;
    window.refinement[kTop].size = size;
    if (style == CasingStyle::Doppelgesims) window.refinement[kTop].profile = {{0.5, 1}};
}

// `frame, slot, thickness, overhang, pane depth`.
void applyFrame(const DescriptionItem &item, WindowStyle &window) {
    item.expectFieldCount(5, 5, "a frame (frame, slot, thickness, overhang, pane depth)");
    WindowFrame &frame = window.frame;
    frame.thickness = boundedNumber(item, 2, "the frame thickness", 0, 1);
    if (!(frame.thickness < 1)) throw InputError(item.fields[2].loc, "the frame thickness must be below 1");
    frame.overhang = boundedNumber(item, 3, "the frame overhang", -kBuildingSizeLimit, kBuildingSizeLimit);
    frame.paneDepth = boundedNumber(item, 4, "the pane depth", -kBuildingSizeLimit, kBuildingSizeLimit);
    if (frame.paneDepth > frame.overhang)
        throw InputError(
            item.fields[4].loc,
            fmt::format("the pane depth {} lies in front of the frame's overhang {}", frame.paneDepth, frame.overhang));
}

// `apron, slot, height, depth`: at least 10 cm high, up to 1 m proud.
void applyApron(const DescriptionItem &item, WindowStyle &window) {
    item.expectFieldCount(4, 4, "an apron (apron, slot, height, depth)");
    if (window.kind == OpeningKind::Door) throw InputError(item.fields[1].loc, "a door has no apron below it");
    window.apron = ApronStyle{boundedNumber(item, 2, "the apron's height", 0.1, 10),
                              boundedNumber(item, 3, "the apron's depth", 0, 1), item.loc};
}

BandStyle readBand(const DescriptionItem &item, NamedFiles &files) {
    item.expectFieldCount(4, 4, "a band (band, vStart, vStop, \"cornice file\")");
    BandStyle band{fraction(item, 1, "the band's vStart"), fraction(item, 2, "the band's vStop"), nullptr, item.loc};
    if (!(band.vStart < band.vStop))
        throw InputError(
            item.fields[2].loc,
            fmt::format("the band's vStop {} is not above its vStart {}", item.fields[2].text, item.fields[1].text));
    item.string(3, "the cornice's file");
    band.cornice = files.cornice(item.fields[3]);
    return band;
}

// The part as a word, or quoted where its name is none ("roof-side").
StylePart stylePart(const DescriptionItem &item) {
    bool quoted = item.fields.size() > 1 && item.fields[1].kind == DescriptionField::Kind::String;
    const std::string &name = quoted ? item.string(1, "the part") : item.word(1, "the part a material is for");
    std::string names;
    for (size_t p = 0; p < kStylePartCount; ++p) {
        if (name == stylePartName(StylePart(p))) return StylePart(p);
        names += (p ? ", " : "") + std::string(stylePartName(StylePart(p)));
    }
    throw InputError(item.fields[1].loc, fmt::format("unknown part '{}' ({})", name, names));
}

class StyleReader {
  public:
    StyleReader(const DescriptionBlock &block, NamedFiles &files) : block_(block), files_(files) {}

    Style read() {
        expectItems(block_, 1, "a name");
        style_.name = nameItem(block_.items[0], "the style's name");
        style_.loc = block_.loc;
        std::vector<const DescriptionItem *> casings, frames, aprons;
        for (size_t i = 1; i < block_.items.size(); ++i) {
            const DescriptionItem &item = block_.items[i];
            const std::string &kind = item.word(0,
                                                "the kind of a style item (walls, masonry, window, door, casing, "
                                                "frame, apron, band, bands or material)");
            if (kind == "walls") setWalls(item);
            else if (kind == "masonry") setMasonry(item);
            else if (kind == "window" || kind == "door") addWindow(item, kind);
            else if (kind == "casing") casings.push_back(&item);
            else if (kind == "frame") frames.push_back(&item);
            else if (kind == "apron") aprons.push_back(&item);
            else if (kind == "band") addBand(item);
            else if (kind == "bands") noBands(item);
            else if (kind == "material") addMaterial(item);
            else
                throw InputError(item.fields[0].loc,
                                 fmt::format("unknown style item '{}' (walls, masonry, window, door, casing, frame, "
                                             "apron, band, bands or material)",
                                             kind));
        }
        for (const DescriptionItem *item : casings) applyCasing(*item, windowOf(*item, "casing"));
        for (const DescriptionItem *item : frames) applyFrame(*item, windowOf(*item, "frame"));
        for (const DescriptionItem *item : aprons) applyApron(*item, windowOf(*item, "apron"));
        return std::move(style_);
    }

  private:
    // A single-valued item, keyed by what it says.
    void once(const DescriptionItem &item, const std::string &key) {
        auto [at, added] = seen_.emplace(key, item.loc);
        if (!added) throw InputError(item.loc, secondOf(key, at->second));
    }

    void setWalls(const DescriptionItem &item) {
        once(item, "walls item");
        style_.walls = readWalls(item);
    }

    void setMasonry(const DescriptionItem &item) {
        once(item, "masonry item");
        style_.masonry = readMasonry(item, files_);
    }

    int slotOf(const DescriptionItem &item) const { return wholeNumber(item, 1, "the slot", 0, kWindowSlotLimit - 1); }

    void addWindow(const DescriptionItem &item, const std::string &kind) {
        int slot = slotOf(item);
        once(item, fmt::format("window or door for slot {}", slot));
        style_.windows[slot] = readOpening(item, kind == "door" ? OpeningKind::Door : OpeningKind::Window);
    }

    WindowStyle &windowOf(const DescriptionItem &item, const std::string &what) {
        int slot = slotOf(item);
        once(item, fmt::format("{} for slot {}", what, slot));
        auto at = style_.windows.find(slot);
        if (at == style_.windows.end())
            throw InputError(item.fields[1].loc,
                             fmt::format("a {} for slot {}, which has no window or door in the style '{}'", what, slot,
                                         style_.name));
        return at->second;
    }

    void addBand(const DescriptionItem &item) {
        if (auto none = seen_.find("bands none"); none != seen_.end())
            throw InputError(item.loc, fmt::format("a band beside 'bands, none' at {}", none->second.toString()));
        seen_.emplace("band", item.loc);
        if (!style_.bands) style_.bands.emplace();
        style_.bands->push_back(readBand(item, files_));
    }

    void noBands(const DescriptionItem &item) {
        item.expectFieldCount(2, 2, "bands, none");
        if (item.word(1, "'none'") != "none")
            throw InputError(item.fields[1].loc, fmt::format("expected 'none', found '{}'", item.fields[1].text));
        if (auto band = seen_.find("band"); band != seen_.end())
            throw InputError(item.loc, fmt::format("'bands, none' beside the band at {}", band->second.toString()));
        once(item, "bands none");
        style_.bands.emplace();
    }

    void addMaterial(const DescriptionItem &item) {
        item.expectFieldCount(3, 3, "a material (material, part, \"scene material\")");
        StylePart part = stylePart(item);
        once(item, fmt::format("material for '{}'", stylePartName(part)));
        style_.materials[size_t(part)] = item.string(2, "the scene material's name");
    }

    const DescriptionBlock &block_;
    NamedFiles &files_;
    Style style_;
    std::map<std::string, FileLoc> seen_;
};

StyleBindings readBindings(const DescriptionBlock &block, const std::map<std::string, FileLoc> &styleNames) {
    StyleBindings bindings;
    bindings.loc = block.loc;
    std::map<std::string, FileLoc> seen;
    auto once = [&](const DescriptionItem &item, const std::string &key) {
        auto [at, added] = seen.emplace(key, item.loc);
        if (!added) throw InputError(item.loc, secondOf(key, at->second));
    };
    auto styleName = [&](const DescriptionItem &item, size_t index) {
        const std::string &name = item.string(index, "a style's name");
        if (!styleNames.contains(name))
            throw InputError(item.fields[index].loc, fmt::format("no style named '{}'", name));
        return name;
    };
    for (const DescriptionItem &item : block.items) {
        const std::string &level = item.word(0, "the level (building, storey or module)");
        if (level == "building") {
            item.expectFieldCount(2, 2, "building, \"style\"");
            once(item, "building binding");
            bindings.building = styleName(item, 1);
        } else if (level == "storey") {
            item.expectFieldCount(3, 3, "storey, number, \"style\"");
            int storey = wholeNumber(item, 1, "the storey", 0, int(kStructureStoreyLimit) - 1);
            once(item, fmt::format("binding of storey {}", storey));
            bindings.storeys[storey] = styleName(item, 2);
        } else if (level == "module") {
            item.expectFieldCount(3, 3, "module, \"module\", \"style\"");
            const std::string &module = item.string(1, "a module's name");
            once(item, fmt::format("binding of module '{}'", module));
            bindings.modules[module] = styleName(item, 2);
        } else {
            throw InputError(item.fields[0].loc, fmt::format("unknown level '{}' (building, storey or module)", level));
        }
    }
    if (!seen.contains("building binding"))
        throw InputError(block.loc, "the Bind block binds no building style (building, \"style\")");
    return bindings;
}

}  // namespace

BuildingStructure parseBuildingStructure(std::string_view text, const std::string &file) {
    return StructureReader(file).read(readDescriptionBlocks(text, file));
}

BuildingStyle parseBuildingStyle(std::string_view text, const std::string &file, const DescribedFileReader &readFile) {
    std::vector<DescriptionBlock> blocks = readDescriptionBlocks(text, file);
    BuildingStyle style;
    NamedFiles files(readFile);
    std::map<std::string, FileLoc> names;
    const DescriptionBlock *bind = nullptr;
    for (const DescriptionBlock &block : blocks) {
        if (block.name == "Bind") {
            if (bind) throw InputError(block.loc, secondOf("Bind block", bind->loc));
            bind = &block;
        } else if (block.name == "Style") {
            if (style.styles.size() == kStyleLimit)
                throw InputError(block.loc, fmt::format("at most {} styles", kStyleLimit));
            style.styles.push_back(StyleReader(block, files).read());
            auto [at, added] = names.emplace(style.styles.back().name, block.loc);
            if (!added)
                throw InputError(block.items[0].loc, secondOf(fmt::format("style named '{}'", at->first), at->second));
        } else {
            throw InputError(block.loc, fmt::format("unknown block '{}' (Style or Bind)", block.name));
        }
    }
    if (!bind) throw InputError({file, 1, 1}, "the style has no Bind block");
    style.bindings = readBindings(*bind, names);
    return style;
}

}  // namespace veduta

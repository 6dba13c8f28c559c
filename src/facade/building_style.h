// The style of a Finkenzeller building (digest-001 §3, "Style concepts" and "Style binding";
// L1551–1556): named styles, each saying some of how walls are divided (Unterteilung), what
// masonry they show, their windows by slot (FensterTuer, FTStock, Fensterrahmen), their bands and
// cornices (Wandpartition, Gesims) and the materials of their parts; and the bindings that hang
// styles on the structure at three levels: the building and its storeys (hat_Stockwerksstil),
// modules (hat_Modulstil), and edge subdivisions, whose window slots the styles fill.
//
// σ inheritance: what a style leaves unsaid comes from the next style of the chain. A wall of
// module m at storey s asks, in order, the module's style, the storey's style and the building's
// style, then the defaults below; a window slot is looked up the same way (L1744: edge
// subdivision → the module's Stil → the Grundstein's). Swapping a style is re-pointing a binding
// (L1551); the structure does not change.
//
// Choices where the thesis is open:
// * Materials are scene material names (the scene's <materials> file), like the grammar's rules;
//   the thesis's Material/Farbe/Glanzlicht tuples are what such a file says.
// * A slot that no style of the chain fills is a blank wall: no opening.
// * Masonry and cornice descriptions are the small languages' own texts (brick_bond.h, ashlar.h,
//   cyclopean.h, profile.h), read from files beside the style.
#pragma once

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/error.h"
#include "facade/ashlar.h"
#include "facade/brick_bond.h"
#include "facade/casings.h"
#include "facade/cyclopean.h"
#include "facade/openings.h"
#include "facade/profile.h"
#include "facade/wall_elements.h"

namespace veduta {

// Mauerziegelverband / Zyklopenmauerwerk, or a plain rendered wall.
struct MasonryStyle {
    enum class Kind { Plain, Bricks, Ashlar, Cyclopean };
    Kind kind = Kind::Plain;
    std::shared_ptr<const BrickBond> bricks;
    std::shared_ptr<const AshlarMasonry> ashlar;
    std::shared_ptr<const CyclopeanMasonry> cyclopean;
    double metresPerUnit = 1;  // bricks and ashlar: the description's unit in metres
    uint64_t source = 0;       // descriptionHash of the description's text
    FileLoc loc;
};

// A hash of a masonry description's text: with the kind and scale it says which stones are laid.
uint64_t descriptionHash(std::string_view text);

// The stones `style` lays on `wall` (bricks, ashlar or cyclopean; none for plain), each wall's own
// by `wallId`, every random choice from `seed` and that id.
Masonry layStyleMasonry(const MasonryStyle &style, const WallFace &wall, uint32_t seed, uint32_t wallId);

// Checks now what layStyleMasonry would report on `wall` (an InputError at the description) and
// returns the recipe that lays the same stones on it later.
MasonryRecipe styleMasonryRecipe(const MasonryStyle &style, const WallFace &wall, uint32_t seed, uint32_t wallId);

// Brüstungsfeld: a panel under a window's casing, standing `depth` proud of the wall, `height` high
// (metres), its face an ornament grown into it (ornament_growth.h, §2.7) and baked as relief into
// the building's atlas (facade_building.h).
struct ApronStyle {
    double height = 0, depth = 0;
    FileLoc loc;
};

// FensterTuer with its refinement, casing and frame (Defs 5.12–5.15), and an apron below it.
struct WindowStyle {
    OpeningKind kind = OpeningKind::Window;
    AbsolutePlacement placement;
    std::array<EdgeRefinement, 4> refinement{};  // kBottom, kRight, kTop, kLeft
    Dominance dominance = Dominance::BottomAndTop;
    Casing casing;
    WindowFrame frame;
    std::optional<ApronStyle> apron;
    FileLoc loc;
};

// Wandpartition with its Gesims: a cornice swept in [vStart, vStop] of the storey's height.
struct BandStyle {
    double vStart = 0, vStop = 1;
    std::shared_ptr<const CorniceDescription> cornice;
    FileLoc loc;
};

// Interior: the reveals and the dim room behind a pane (casings.h, revealMesh).
enum class StylePart { Wall, Casing, Cornice, Frame, Pane, Door, Roof, RoofSide, Parapet, Interior };
inline constexpr size_t kStylePartCount = 10;
const char *stylePartName(StylePart part);

struct Style {
    std::string name;
    std::optional<WallSubdivision> walls;
    std::optional<MasonryStyle> masonry;
    std::map<int, WindowStyle> windows;           // by slot
    std::optional<std::vector<BandStyle>> bands;  // an empty list: this style wants none
    std::array<std::optional<std::string>, kStylePartCount> materials;
    FileLoc loc;
};

// The three binding levels: the building's style, storeys' and modules' (by the structure's
// module names). Edge subdivisions bind through their slots.
struct StyleBindings {
    std::string building;
    std::map<int, std::string> storeys;
    std::map<std::string, std::string> modules;
    FileLoc loc;
};

inline constexpr size_t kStyleLimit = 1000;
inline constexpr int kWindowSlotLimit = 1000;

struct BuildingStyle {
    std::vector<Style> styles;
    StyleBindings bindings;

    const Style &style(const std::string &name, const FileLoc &loc) const;  // InputError if unknown
};

// What a wall of one module at one storey is, every field resolved through the chain.
struct ResolvedStyle {
    std::vector<const Style *> chain;  // the module's, the storey's, the building's: each once
    WallSubdivision walls;
    const MasonryStyle *masonry = nullptr;  // the chain's, where its styles keep it; null: plain
    std::vector<BandStyle> bands;
    std::array<std::string, kStylePartCount> materials;  // "" for the scene's default material

    const WindowStyle *window(int slot) const;  // null: a blank wall
    const std::string &material(StylePart part) const { return materials[size_t(part)]; }
};

// Throws InputError when a binding names an unknown style or module (`moduleNames`) or a storey
// the structure does not have (`storeys`).
void checkBindings(const BuildingStyle &style, const std::vector<std::string> &moduleNames, size_t storeys);

ResolvedStyle resolveStyle(const BuildingStyle &style, const std::string &module, int storey);

}  // namespace veduta

#include "facade/building_style.h"

#include <algorithm>

#include <fmt/format.h>

#include "core/word_hasher.h"

namespace veduta {

Masonry layStyleMasonry(const MasonryStyle &style, const WallFace &wall, uint32_t seed, uint32_t wallId) {
    MasonryPlacement placement{style.metresPerUnit, seed, wallId};
    switch (style.kind) {
    case MasonryStyle::Kind::Bricks: return layBrickBond(*style.bricks, wall, placement);
    case MasonryStyle::Kind::Ashlar: return layAshlar(*style.ashlar, wall, placement);
    case MasonryStyle::Kind::Cyclopean: return cyclopeanMasonry(wall, *style.cyclopean, seed, wallId);
    case MasonryStyle::Kind::Plain: break;
    }
    return {};
}

uint64_t descriptionHash(std::string_view text) {
    WordHasher hash;
    hash.add(std::string(text));
    return hash.value();
}

MasonryRecipe styleMasonryRecipe(const MasonryStyle &style, const WallFace &wall, uint32_t seed, uint32_t wallId) {
    switch (style.kind) {
    case MasonryStyle::Kind::Bricks: checkBrickBond(*style.bricks, wall, style.metresPerUnit); break;
    case MasonryStyle::Kind::Ashlar: checkAshlar(*style.ashlar, wall, style.metresPerUnit); break;
    case MasonryStyle::Kind::Cyclopean: checkCyclopean(wall, *style.cyclopean); break;
    case MasonryStyle::Kind::Plain: break;
    }
    WordHasher hash;
    hash.add(int(style.kind)), hash.add(style.source), hash.add(style.metresPerUnit);
    hash.add(uint64_t(seed)), hash.add(uint64_t(wallId));
    return {[style, seed, wallId](const WallFace &face) { return layStyleMasonry(style, face, seed, wallId); },
            hash.value()};
}

const char *stylePartName(StylePart part) {
    static constexpr std::array<const char *, kStylePartCount> kNames = {
        "wall", "casing", "cornice", "frame", "pane", "door", "roof", "roof-side", "parapet", "interior"};
    return kNames[size_t(part)];
}

const Style &BuildingStyle::style(const std::string &name, const FileLoc &loc) const {
    for (const Style &s : styles)
        if (s.name == name) return s;
    throw InputError(loc, fmt::format("no style is called '{}'", name));
}

void checkBindings(const BuildingStyle &style, const std::vector<std::string> &moduleNames, size_t storeys) {
    const StyleBindings &b = style.bindings;
    style.style(b.building, b.loc);
    for (const auto &[storey, name] : b.storeys) {
        if (storey < 0 || size_t(storey) >= storeys)
            throw InputError(b.loc,
                             fmt::format("a style is bound to storey {}, but the building has storeys 0 to {}", storey,
                                         storeys - 1));
        style.style(name, b.loc);
    }
    for (const auto &[module, name] : b.modules) {
        if (std::find(moduleNames.begin(), moduleNames.end(), module) == moduleNames.end())
            throw InputError(b.loc,
                             fmt::format("a style is bound to module '{}', which the structure does not have", module));
        style.style(name, b.loc);
    }
}

namespace {

// The chain of §3's fallback: the module's style, the storey's, the building's; each style once.
std::vector<const Style *> styleChain(const BuildingStyle &style, const std::string &module, int storey) {
    std::vector<const Style *> chain;
    auto add = [&](const std::string &name) {
        const Style *s = &style.style(name, style.bindings.loc);
        if (std::find(chain.begin(), chain.end(), s) == chain.end()) chain.push_back(s);
    };
    if (auto m = style.bindings.modules.find(module); m != style.bindings.modules.end()) add(m->second);
    if (auto s = style.bindings.storeys.find(storey); s != style.bindings.storeys.end()) add(s->second);
    add(style.bindings.building);
    return chain;
}

// The first value the chain sets, else `fallback`.
template <typename T, typename Field>
T firstSet(const std::vector<const Style *> &chain, Field field, T fallback) {
    for (const Style *s : chain)
        if (const auto &value = s->*field) return *value;
    return fallback;
}

}  // namespace

ResolvedStyle resolveStyle(const BuildingStyle &style, const std::string &module, int storey) {
    ResolvedStyle r;
    r.chain = styleChain(style, module, storey);
    r.walls = firstSet(r.chain, &Style::walls, WallSubdivision{});
    for (const Style *s : r.chain) {
        if (!s->masonry) continue;
        if (s->masonry->kind != MasonryStyle::Kind::Plain) r.masonry = &*s->masonry;
        break;
    }
    r.bands = firstSet(r.chain, &Style::bands, std::vector<BandStyle>{});
    for (size_t p = 0; p < kStylePartCount; ++p) {
        for (const Style *s : r.chain) {
            if (!s->materials[p]) continue;
            r.materials[p] = *s->materials[p];
            break;
        }
    }
    return r;
}

const WindowStyle *ResolvedStyle::window(int slot) const {
    for (const Style *s : chain)
        if (auto w = s->windows.find(slot); w != s->windows.end()) return &w->second;
    return nullptr;
}

}  // namespace veduta

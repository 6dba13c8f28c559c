#include "city/assets.h"

#include <iterator>

#include "city/asset_shapes.h"

namespace veduta {

AssetLibrary::AssetLibrary() {
    auto add = [this](std::vector<Asset> family) {
        assets_.insert(assets_.end(), std::make_move_iterator(family.begin()), std::make_move_iterator(family.end()));
    };
    add(wallAssets());
    add(openingAssets());
    add(mouldingAssets());
    add(balconyAssets());
    add(gutterAssets());
    for (uint32_t i = 0; i < assets_.size(); ++i) index_.emplace(assets_[i].name, i);
}

const AssetLibrary &AssetLibrary::builtIn() {
    static const AssetLibrary library;
    return library;
}

std::optional<uint32_t> AssetLibrary::find(std::string_view name) const {
    constexpr std::string_view kModelSuffix = ".wrl";
    if (name.ends_with(kModelSuffix)) name.remove_suffix(kModelSuffix.size());
    auto it = index_.find(name);
    if (it == index_.end()) return std::nullopt;
    return it->second;
}

}  // namespace veduta

#include "city/console_prototypes.h"

#include "io/mesh_import.h"

namespace veduta {

PrototypeId ConsolePrototypes::get(const std::filesystem::path &file, const ConsoleSet &set) {
    auto [it, fresh] = prototypes_.try_emplace({file.lexically_normal().string(), set.material}, 0);
    if (fresh) {
        Mesh model;
        try {
            model = importMesh(file);
        } catch (const InputError &e) {
            prototypes_.erase(it);
            throw InputError(set.loc, e.what());
        }
        model.setMaterial(set.material);
        it->second = builder_.addPrototype(std::move(model));
    }
    return it->second;
}

}  // namespace veduta

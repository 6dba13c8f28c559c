// The stable name of an object, as exports and Cryptomatte mattes call it: built from the ids the
// scene gives it, so that the same object keeps its name from render to render and file to file.
#pragma once

#include <cstdint>
#include <string>

#include <fmt/format.h>

#include "scene/render_scene.h"

namespace veduta {

// "object_<id>", or "building_<building>/object_<id>" for a part of a building.
inline std::string objectName(ObjectId objectId, uint32_t buildingId) {
    if (buildingId == 0) return fmt::format("object_{}", objectId);
    return fmt::format("building_{}/object_{}", buildingId, objectId);
}

}  // namespace veduta

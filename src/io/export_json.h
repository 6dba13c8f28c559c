// JSON text for the exporters' files (glTF, the .geo.json sidecar), written straight into a
// buffer: a glTF of a landscape has hundreds of thousands of nodes, and a document object
// model of them would cost more than the geometry.
#pragma once

#include <string>
#include <string_view>

#include "core/json_text.h"
#include "core/vecmath.h"

namespace veduta {

// The shortest decimal that reads back as `value`; throws std::invalid_argument for NaN and
// infinities, which JSON cannot hold.
std::string jsonNumber(double value);
// [x, y, z]
std::string jsonArray(const Vec3f &v);

}  // namespace veduta

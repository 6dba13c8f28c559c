// Primitive shapes, tessellated into meshes. Each stands on the origin: boxes, cylinders and
// cones rest on z = 0 centred on the z axis, spheres are centred on the origin, planes lie
// in z = 0 facing +z. Transforms place them. The endless ground (ground.h) lies at its height.
#pragma once

#include "scene/mesh.h"

namespace veduta {

enum class ShapeKind { Box, Sphere, Cylinder, Cone, Plane, Ground };

struct ShapeSpec {
    ShapeKind kind = ShapeKind::Box;
    Vec3f size{1.0f};     // box: x y z extent; plane: x y extent
    float radius = 0.5f;  // sphere, cylinder, cone
    float height = 1.0f;  // cylinder, cone; ground: the plane's z
    int segments = 32;    // around the z axis
    int rings = 16;       // sphere, from pole to pole
    bool smooth = true;   // vertex normals on curved sides; false gives facets (roofs, prisms)
};

Mesh makeShape(const ShapeSpec &spec);

}  // namespace veduta

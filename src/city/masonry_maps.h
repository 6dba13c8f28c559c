// A building's masonry (facade/facade_building.h's MasonryWall: stones laid on a wall face, and the
// face's triangles in the building's mesh with their wall metres as texture coordinates) baked
// into one texture atlas at the texels the camera asks for, and given to the walls as maps.
//
// * Each wall is cut into tiles of about 4 × 4 m (whole pieces of its mesh, so no vertex is shared
//   by two tiles), each sampled at 9 × 9 points.
// * A tile none of whose points falls in the image (with a margin of a tenth of its size), or
//   whose wall the camera sees from behind, is baked at the coarsest texel (kCoarsestAtlasTexel):
//   it shows only in reflections and bounced light, and casts its shadow whatever its texture.
// * The seen tiles of a wall share the texel that shows its finest seen point at about one texel
//   a pixel (kFinestMasonryTexel at the finest). One texel a wall rather than a tile: a bake takes
//   what lies under each texel's centre, so joints about a texel wide alias, and tiles at texels
//   of their own show as patches of different stripes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "facade/facade_building.h"
#include "facade/masonry_atlas.h"
#include "facade/masonry_shader.h"
#include "scene/camera.h"
#include "scene/mesh.h"
#include "scene/render_scene.h"
#include "scene/textures.h"

namespace veduta {

// The most texels one building's masonry atlas may have; finer asks are coarsened
// (facade/masonry_atlas.h), so that a building costs at most 32 bytes a texel while it is baked
// (64 MB). The texture registry holds the atlases whole, with their mip levels, while they fit its
// memory budget (images/oiio_textures.h), and streams the rest from its cache.
inline constexpr size_t kBuildingMasonryTexels = size_t(1) << 21;
// The finest texel asked for, metres: finer than a brick's chamfer shows nothing more.
inline constexpr double kFinestMasonryTexel = 0.002;

// Where a generator's masonry goes (docs/facades.md, "Baked or shaded procedurally"): baked into an
// atlas whose maps go through `addImage`, or, `procedural`, kept as stones for a MasonryShader
// whose maps go through `addProcedural`.
struct MasonryOutput {
    bool procedural = false;
    AddImage addImage;
    AddProcedural addProcedural;

    explicit operator bool() const { return procedural ? bool(addProcedural) : bool(addImage); }
};

// The atlas of `walls` (triangles of `mesh`, whose object-to-world transform is `toWorld`), with
// the walls' texture coordinates moved from wall metres onto it; nothing when there are no walls.
// Lays the walls from their recipes first. Touches no scene: buildings may be baked in parallel.
std::optional<MasonryAtlas> bakeMasonryMaps(Mesh &mesh, std::vector<MasonryWall> &walls, const Transform &toWorld,
                                            const CameraRays &rays, const Camera &camera);

// Registers the atlas's maps and gives each wall's triangles a copy of its material (named
// "… (building N masonry)") that reads them.
void addMasonryMaps(Mesh &mesh, const std::vector<MasonryWall> &walls, MasonryAtlas atlas, RenderSceneBuilder &builder,
                    const AddImage &addImage, uint32_t buildingId);

// The walls' masonry as one shader, their recipes (or stones) moved into it and their triangles'
// texture coordinates into its space; nothing when there are no walls. Touches no scene.
std::shared_ptr<const MasonryShader> shadeMasonry(Mesh &mesh, std::vector<MasonryWall> &walls);

// Registers the shader's maps and gives the walls' triangles their material copies, as
// addMasonryMaps does.
void addMasonryShader(Mesh &mesh, const std::vector<MasonryWall> &walls, std::shared_ptr<const MasonryShader> shader,
                      RenderSceneBuilder &builder, const AddProcedural &addProcedural, uint32_t buildingId);

}  // namespace veduta

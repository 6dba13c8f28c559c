#include "city/masonry_maps.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <utility>

#include <fmt/format.h>

#include "core/polygon_bounds.h"

namespace veduta {

namespace {

// The vertices of the triangles, each once, in increasing order.
std::vector<uint32_t> verticesOf(const Mesh &mesh, const std::vector<uint32_t> &triangles) {
    std::vector<uint32_t> vertices;
    vertices.reserve(3 * triangles.size());
    for (uint32_t t : triangles)
        vertices.insert(vertices.end(), &mesh.indices[3 * size_t(t)], &mesh.indices[3 * size_t(t) + 3]);
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    return vertices;
}

// A part of a masonry wall baked as a region of its own: some of the wall's triangles (whole
// pieces: no vertex is shared with another tile), the face the bake covers (the rectangle of
// wall metres they span, with the wall's openings) and its texel.
struct MasonryTile {
    size_t wall = 0;
    Masonry masonry;  // the wall's stones that reach into the face
    WallFace face;
    std::vector<uint32_t> triangles;
    double texel = 0;
};

// The side of a tile, metres: the parts of a wall out of the camera's view cost few texels; a tile
// adds only its gutter.
constexpr double kMasonryTileSize = 4.0;

// The connected pieces of a set of triangles (sharing vertices), as a piece number per triangle:
// union-find over the vertices, numbered densely.
std::vector<uint32_t> piecesOf(const Mesh &mesh, const std::vector<uint32_t> &triangles) {
    std::vector<uint32_t> vertices;
    for (uint32_t t : triangles)
        vertices.insert(vertices.end(), &mesh.indices[3 * size_t(t)], &mesh.indices[3 * size_t(t) + 3]);
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    auto dense = [&](uint32_t v) {
        return uint32_t(std::lower_bound(vertices.begin(), vertices.end(), v) - vertices.begin());
    };
    std::vector<uint32_t> parent(vertices.size());
    std::iota(parent.begin(), parent.end(), 0u);
    auto root = [&](uint32_t v) {
        while (parent[v] != v) v = parent[v] = parent[parent[v]];
        return v;
    };
    for (uint32_t t : triangles) {
        uint32_t r = root(dense(mesh.indices[3 * size_t(t)]));
        for (int k = 1; k < 3; ++k) parent[root(dense(mesh.indices[3 * size_t(t) + size_t(k)]))] = r;
    }
    std::vector<uint32_t> piece;
    for (uint32_t t : triangles) piece.push_back(root(dense(mesh.indices[3 * size_t(t)])));
    return piece;
}

using Box = std::pair<Vec2d, Vec2d>;

bool meet(const Box &a, const Box &b) {
    return a.first.x <= b.second.x && a.second.x >= b.first.x && a.first.y <= b.second.y && a.second.y >= b.first.y;
}

// The wall's triangles in tiles of about kMasonryTileSize: each connected piece goes to the cell
// of its centre, and a tile spans its pieces and bakes only the stones and openings that reach
// into it.
void tileWall(const Mesh &mesh, const MasonryWall &wall, size_t index, std::vector<MasonryTile> &tiles) {
    struct Cell {
        std::vector<uint32_t> triangles;
        Box box{{INFINITY, INFINITY}, {-INFINITY, -INFINITY}};
    };
    auto grow = [](Box &box, const Box &by) {
        box.first = {std::min(box.first.x, by.first.x), std::min(box.first.y, by.first.y)};
        box.second = {std::max(box.second.x, by.second.x), std::max(box.second.y, by.second.y)};
    };
    std::vector<uint32_t> piece = piecesOf(mesh, wall.triangles);
    std::map<uint32_t, Cell> pieces;
    for (size_t i = 0; i < wall.triangles.size(); ++i) {
        Cell &p = pieces[piece[i]];
        uint32_t t = wall.triangles[i];
        p.triangles.push_back(t);
        for (int k = 0; k < 3; ++k) {
            Vec2f uv = mesh.uvs[mesh.indices[3 * size_t(t) + size_t(k)]];
            grow(p.box, {{uv.x, uv.y}, {uv.x, uv.y}});
        }
    }
    std::map<std::pair<int64_t, int64_t>, Cell> cells;
    for (const auto &[root, p] : pieces) {
        Vec2d centre = (p.box.first + p.box.second) * 0.5;
        Cell &cell =
            cells[{int64_t(std::floor(centre.x / kMasonryTileSize)), int64_t(std::floor(centre.y / kMasonryTileSize))}];
        cell.triangles.insert(cell.triangles.end(), p.triangles.begin(), p.triangles.end());
        grow(cell.box, p.box);
    }
    std::vector<Box> stoneBoxes, openingBoxes;
    for (const Stone &stone : wall.masonry.stones) stoneBoxes.push_back(polygonBounds(stone.outline));
    for (const auto &opening : wall.face.openings) openingBoxes.push_back(polygonBounds(opening));
    for (auto &[key, cell] : cells) {
        MasonryTile tile;
        tile.wall = index;
        tile.masonry.mortarColour = wall.masonry.mortarColour;
        tile.masonry.mortarThickness = wall.masonry.mortarThickness;
        tile.masonry.relief = wall.masonry.relief;
        const Box &box = cell.box;
        for (size_t s = 0; s < stoneBoxes.size(); ++s)
            if (meet(stoneBoxes[s], box)) tile.masonry.stones.push_back(wall.masonry.stones[s]);
        tile.face.outline = {box.first, {box.second.x, box.first.y}, box.second, {box.first.x, box.second.y}};
        for (size_t o = 0; o < openingBoxes.size(); ++o)
            if (meet(openingBoxes[o], box)) tile.face.openings.push_back(wall.face.openings[o]);
        tile.triangles = std::move(cell.triangles);
        tiles.push_back(std::move(tile));
    }
}

// How far past the image's edges a wall point still counts as seen, in image sizes: a pixel at the
// border filters texels beyond it, and depth of field and the lens shift move little.
constexpr float kViewMargin = 0.1f;
// Points per side of the grid a tile is sampled at for its finest texel.
constexpr int kTileSamples = 9;

// The texel that shows the finest seen part of a tile at about one texel a pixel, from a grid of
// its points; nothing for a tile the camera sees from behind or not at all.
std::optional<double> seenTexel(const Mesh &mesh, const MasonryTile &tile, const Transform &toWorld,
                                const CameraRays &rays, const Camera &camera) {
    // The affine map from wall metres to the world, from the tile's largest triangle in wall
    // metres (a sliver would give it no precision).
    auto uvArea = [&](uint32_t t) {
        const uint32_t *c = &mesh.indices[3 * size_t(t)];
        Vec2f e1 = mesh.uvs[c[1]] - mesh.uvs[c[0]], e2 = mesh.uvs[c[2]] - mesh.uvs[c[0]];
        return std::abs(e1.x * e2.y - e1.y * e2.x);
    };
    uint32_t largest = *std::max_element(tile.triangles.begin(), tile.triangles.end(),
                                         [&](uint32_t a, uint32_t b) { return uvArea(a) < uvArea(b); });
    const uint32_t *corner = &mesh.indices[3 * size_t(largest)];
    Vec3f p0 = toWorld.applyPoint(mesh.positions[corner[0]]), p1 = toWorld.applyPoint(mesh.positions[corner[1]]),
          p2 = toWorld.applyPoint(mesh.positions[corner[2]]);
    if (dot(cross(p1 - p0, p2 - p0), camera.position - p0) <= 0) return std::nullopt;
    Vec2f t0 = mesh.uvs[corner[0]], e1 = mesh.uvs[corner[1]] - t0, e2 = mesh.uvs[corner[2]] - t0;
    float det = e1.x * e2.y - e1.y * e2.x;
    if (det == 0) return std::nullopt;
    Vec3f alongU = ((p1 - p0) * e2.y - (p2 - p0) * e1.y) / det;
    Vec3f alongV = ((p2 - p0) * e1.x - (p1 - p0) * e2.x) / det;
    auto world = [&](Vec2d wall) { return p0 + alongU * (float(wall.x) - t0.x) + alongV * (float(wall.y) - t0.y); };
    const Vec2d low = tile.face.outline[0], high = tile.face.outline[2];
    const float width = float(camera.width), height = float(camera.height);
    // pixelsSpanned measures from the box's centre: a metre-long box about the point.
    const Vec3f half(0.5f / std::sqrt(3.0f));
    double finest = 0;
    for (int i = 0; i < kTileSamples; ++i)
        for (int j = 0; j < kTileSamples; ++j) {
            Vec2d at{low.x + (high.x - low.x) * i / (kTileSamples - 1),
                     low.y + (high.y - low.y) * j / (kTileSamples - 1)};
            Vec3f point = world(at);
            float x, y;
            if (!rays.project(point, x, y) || x < -kViewMargin * width || x > (1 + kViewMargin) * width ||
                y < -kViewMargin * height || y > (1 + kViewMargin) * height)
                continue;
            finest = std::max(finest, double(camera.pixelsSpanned(point - half, point + half)));
        }
    if (finest == 0) return std::nullopt;
    return std::clamp(1 / finest, kFinestMasonryTexel, kCoarsestAtlasTexel);
}

}  // namespace

std::optional<MasonryAtlas> bakeMasonryMaps(Mesh &mesh, std::vector<MasonryWall> &walls, const Transform &toWorld,
                                            const CameraRays &rays, const Camera &camera) {
    for (MasonryWall &wall : walls) {
        if (wall.recipe.lay) wall.masonry = std::exchange(wall.recipe, {}).lay(wall.face);
    }
    std::vector<MasonryTile> tiles;
    for (size_t w = 0; w < walls.size(); ++w) tileWall(mesh, walls[w], w, tiles);
    if (tiles.empty()) return std::nullopt;
    std::vector<std::optional<double>> seen;
    std::vector<double> wallTexel(walls.size(), kCoarsestAtlasTexel);
    for (const MasonryTile &tile : tiles) {
        seen.push_back(seenTexel(mesh, tile, toWorld, rays, camera));
        if (seen.back()) wallTexel[tile.wall] = std::min(wallTexel[tile.wall], *seen.back());
    }
    double finest = INFINITY;
    for (size_t t = 0; t < tiles.size(); ++t)
        finest = std::min(finest, tiles[t].texel = seen[t] ? wallTexel[tiles[t].wall] : kCoarsestAtlasTexel);
    std::vector<AtlasWall> regions;
    for (const MasonryTile &tile : tiles) regions.push_back({&tile.masonry, &tile.face, tile.texel / finest});
    MasonryAtlas atlas = bakeMasonryAtlas(regions, finest, {}, kBuildingMasonryTexels);
    for (size_t r = 0; r < tiles.size(); ++r) {
        // Tiles share no vertex, and a tile's triangles share theirs: each vertex is mapped once.
        for (uint32_t v : verticesOf(mesh, tiles[r].triangles))
            mesh.uvs[v] = atlas.uvOf(r, {mesh.uvs[v].x, mesh.uvs[v].y});
    }
    return atlas;
}

namespace {

// Gives each wall's triangles a copy of its material (named "… (building N masonry)") that reads
// the maps; texture coordinates are the maps' own (textureSize 1).
void giveWallsMaps(Mesh &mesh, const std::vector<MasonryWall> &walls, TextureId diffuse, TextureId normal,
                   TextureId specular, RenderSceneBuilder &builder, uint32_t buildingId) {
    std::map<MaterialId, MaterialId> mapped;
    for (const MasonryWall &wall : walls) {
        auto [it, fresh] = mapped.try_emplace(wall.material, kNoMaterial);
        if (fresh) {
            Material m = builder.materials().at(wall.material == kNoMaterial ? 0 : wall.material);
            m.name = fmt::format("{} (building {} masonry)", m.name, buildingId);
            m.diffuse = Vec3f(1.0f);  // the maps hold the colours
            m.diffuseMap = diffuse;
            m.normalMap = normal;
            m.specularMap = specular;
            if (m.specular == Vec3f(0.0f)) m.specular = Vec3f(1.0f);
            m.textureSize = {1.0f, 1.0f};
            it->second = builder.addMaterial(std::move(m));
        }
        for (uint32_t t : wall.triangles) mesh.triangleMaterials[t] = it->second;
    }
}

}  // namespace

void addMasonryMaps(Mesh &mesh, const std::vector<MasonryWall> &walls, MasonryAtlas atlas, RenderSceneBuilder &builder,
                    const AddImage &addImage, uint32_t buildingId) {
    TextureId diffuse = addImage(std::move(atlas.diffuse));
    TextureId normal = addImage(std::move(atlas.normal));
    TextureId specular = addImage(std::move(atlas.specular));
    giveWallsMaps(mesh, walls, diffuse, normal, specular, builder, buildingId);
}

std::shared_ptr<const MasonryShader> shadeMasonry(Mesh &mesh, std::vector<MasonryWall> &walls) {
    if (walls.empty()) return nullptr;
    std::vector<ShadedWall> shaded;
    for (MasonryWall &wall : walls) shaded.push_back({std::move(wall.masonry), wall.face, std::move(wall.recipe)});
    auto shader = std::make_shared<const MasonryShader>(std::move(shaded));
    for (size_t w = 0; w < walls.size(); ++w) {
        // Walls share no vertex (as the atlas's tiles): each vertex is moved once.
        for (uint32_t v : verticesOf(mesh, walls[w].triangles))
            mesh.uvs[v] = shader->uvOf(w, {mesh.uvs[v].x, mesh.uvs[v].y});
        walls[w].masonry = {};
        walls[w].recipe = {};
    }
    return shader;
}

void addMasonryShader(Mesh &mesh, const std::vector<MasonryWall> &walls, std::shared_ptr<const MasonryShader> shader,
                      RenderSceneBuilder &builder, const AddProcedural &addProcedural, uint32_t buildingId) {
    TextureId diffuse = addProcedural(std::make_shared<MasonryTexture>(shader, MasonryMap::Diffuse));
    TextureId normal = addProcedural(std::make_shared<MasonryTexture>(shader, MasonryMap::Normal));
    TextureId specular = addProcedural(std::make_shared<MasonryTexture>(shader, MasonryMap::Specular));
    giveWallsMaps(mesh, walls, diffuse, normal, specular, builder, buildingId);
}

}  // namespace veduta

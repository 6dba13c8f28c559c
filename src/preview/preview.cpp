#include "preview/preview.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/hash.h"
#include "preview/preview_shader.h"
#include "preview/shadow_map.h"
#include "scene/texture_frame.h"

namespace veduta {

namespace {

constexpr float kNear = 0.05f;  // metres in front of the eye; nearer geometry is clipped
constexpr float kInfinity = std::numeric_limits<float>::infinity();
constexpr uint32_t kNoItem = ~0u;
constexpr uint32_t kBackFacing = 1u << 31;
// Items whose screen box spans more tiles than this share one transformed copy of their
// vertices; smaller ones are transformed per tile, which costs less than the shared copy's memory.
constexpr int kSharedVerticesTileCount = 4;

struct Box3 {
    Vec3f lo{kInfinity}, hi{-kInfinity};
    void extend(const Vec3f &p) {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
};

Box3 boundsOf(const Mesh &mesh) {
    Box3 box;
    for (const Vec3f &p : mesh.positions) box.extend(p);
    return box;
}

// The camera as the rasterizer sees it: world → camera space (x right, y up, z forward) and
// camera space → raster, with the frame CameraRays uses (lens shift, orthographic scale). A
// thin lens is drawn as the pinhole at its centre.
struct RasterProjection {
    Transform cameraFromWorld;
    Vec3f eye;
    bool orthographic;
    float scaleX, scaleY, offsetX, offsetY;

    explicit RasterProjection(const Camera &c) :
        eye(c.position), orthographic(c.projection == Projection::Orthographic) {
        const auto [forward, right, up] = c.axes();
        cameraFromWorld = {{right.x, right.y, right.z, -dot(right, eye), up.x, up.y, up.z, -dot(up, eye), forward.x,
                            forward.y, forward.z, -dot(forward, eye)}};
        // CameraRays' frame: the same extent, and Blender's shift in lengths of the longer side.
        Vec2f half = c.halfExtent();
        float longer = 2 * std::max(half.x, half.y);
        scaleX = float(c.width) / (2 * half.x);
        scaleY = float(c.height) / (2 * half.y);
        offsetX = float(c.width) * 0.5f - c.shift.x * longer * scaleX;
        offsetY = float(c.height) * 0.5f + c.shift.y * longer * scaleY;
    }
    float rasterX(const Vec3f &p) const { return (orthographic ? p.x : p.x / p.z) * scaleX + offsetX; }
    float rasterY(const Vec3f &p) const { return offsetY - (orthographic ? p.y : p.y / p.z) * scaleY; }
};

// A mesh as drawn: a baked mesh or one instance of a prototype.
struct DrawItem {
    const Mesh *mesh;
    Transform objectToWorld;
    Transform cameraFromObject;
    Transform normalToWorld;
    MaterialId materialOverride;
    ObjectId objectId;
    int x0, y0, x1, y1;  // tiles it may touch, inclusive
    bool mirrored;       // the transform turns windings around
    bool instanced;      // an instance of a prototype, not a mesh in world space
    bool mayCutOut;      // some of its triangles have a cut-out material
};

// A vertex in camera space and, when it lies beyond the near plane, on the raster.
struct CameraVertex {
    Vec3f p;
    float x = 0, y = 0, invZ = 0;
};

// What each pixel of one tile shows after rasterization: which triangle, where on it, how
// near. Kept per tile, so that it stays in cache and costs no full-image memory.
struct TileFragments {
    std::vector<float> invDepth;  // 1 / view-axis distance; 0 where nothing was drawn
    std::vector<uint32_t> item;
    std::vector<uint32_t> triangle;  // with kBackFacing set when its back is towards the camera
    std::vector<float> b1, b2;       // barycentrics of the triangle's vertices 1 and 2
    std::vector<float> edgePixels;   // distance to the nearest edge of that triangle, for wireframes

    void reset(size_t n) {
        invDepth.assign(n, 0.0f);
        item.resize(n);
        triangle.resize(n);
        b1.resize(n);
        b2.resize(n);
        edgePixels.resize(n);
    }
};

// Per-thread working memory of the tile loop.
struct TileScratch {
    std::vector<CameraVertex> vertices;
    TileFragments fragments;
};

// A corner of a triangle during near-plane clipping: camera-space position and its
// barycentric coordinates on the original triangle.
struct ClipVertex {
    Vec3f p;
    Vec3f bary;
};

// A triangle corner as the rasterizer takes it.
struct RasterVertex {
    float x, y, invZ;
    Vec3f bary;  // on the original triangle, which clipping may have cut
};

struct Tile {
    int x0, y0, x1, y1;  // pixels, exclusive upper bounds
};

class Rasterizer {
  public:
    Rasterizer(const RenderScene &scene, const PreviewOptions &options) :
        scene_(scene),
        options_(options),
        projection_(scene.camera),
        width_(scene.camera.width),
        height_(scene.camera.height),
        tilesX_((width_ + options.tileSize - 1) / options.tileSize),
        tilesY_((height_ + options.tileSize - 1) / options.tileSize),
        shader_(scene, options.mode),
        rays_(scene.camera),
        forward_(scene.camera.axes().forward),
        pixelSpread_(rays_.pixelSpread()) {
        collectItems();
        binItems();
        if (options.shadows && options.mode == PreviewMode::Shaded && scene.sun.enabled()) {
            shadowMap_.emplace(scene, options.shadowMapSize);
        }
    }

    void run(PreviewImage &image) {
        tbb::parallel_for(
            tbb::blocked_range<size_t>(0, bins_.size(), 1),
            [&](const tbb::blocked_range<size_t> &r) {
                TileScratch scratch;
                for (size_t t = r.begin(); t != r.end(); ++t) {
                    Tile tile = tileRect(t);
                    scratch.fragments.reset(size_t(tile.x1 - tile.x0) * size_t(tile.y1 - tile.y0));
                    rasterizeTile(t, tile, scratch);
                    shadeTile(tile, scratch.fragments, image);
                }
            },
            tbb::simple_partitioner());
    }

  private:
    void collectItems() {
        std::vector<Box3> prototypeBounds;
        std::vector<char> prototypeCutsOut;
        for (const Mesh &p : scene_.prototypes) {
            prototypeBounds.push_back(boundsOf(p));
            prototypeCutsOut.push_back(cutsOut(p));
        }
        for (const BakedMesh &m : scene_.meshes)
            addItem(m.mesh, Transform{}, boundsOf(m.mesh), kNoMaterial, m.objectId, false, cutsOut(m.mesh));
        for (const Instance &inst : scene_.instances) {
            bool mayCutOut = inst.materialOverride != kNoMaterial ? shader_.cutsOut(inst.materialOverride)
                                                                  : prototypeCutsOut[inst.prototype] != 0;
            addItem(scene_.prototypes[inst.prototype], inst.objectToWorld, prototypeBounds[inst.prototype],
                    inst.materialOverride, inst.objectId, true, mayCutOut);
        }
        sharedVertices_.resize(items_.size());
        sharedOnce_ = std::make_unique<std::once_flag[]>(items_.size());
    }

    // Whether some triangle of the mesh has a cut-out material.
    bool cutsOut(const Mesh &mesh) const {
        return std::any_of(mesh.triangleMaterials.begin(), mesh.triangleMaterials.end(),
                           [&](MaterialId m) { return shader_.cutsOut(m); });
    }

    // Keeps an item if its bounding box may be visible, with the tiles it may touch.
    void addItem(const Mesh &mesh, const Transform &objectToWorld, const Box3 &box, MaterialId override, ObjectId id,
                 bool instanced, bool mayCutOut) {
        if (mesh.triangleCount() == 0) return;
        Transform cameraFromObject = projection_.cameraFromWorld * objectToWorld;
        float minX = kInfinity, minY = kInfinity, maxX = -kInfinity, maxY = -kInfinity;
        float nearest = kInfinity, farthest = kNear;
        bool anyInFront = false, anyBehind = false;
        for (int c = 0; c < 8; ++c) {
            Vec3f corner{c & 1 ? box.hi.x : box.lo.x, c & 2 ? box.hi.y : box.lo.y, c & 4 ? box.hi.z : box.lo.z};
            Vec3f p = cameraFromObject.applyPoint(corner);
            if (p.z < kNear) {
                anyBehind = true;
                continue;
            }
            anyInFront = true;
            nearest = std::min(nearest, p.z);
            farthest = std::max(farthest, p.z);
            float x = projection_.rasterX(p), y = projection_.rasterY(p);
            minX = std::min(minX, x), maxX = std::max(maxX, x), minY = std::min(minY, y), maxY = std::max(maxY, y);
        }
        if (!anyInFront) return;
        if (anyBehind) {  // the box crosses the near plane: its projection is unbounded
            minX = minY = -kInfinity;
            maxX = maxY = kInfinity;
        }
        if (maxX < 0 || maxY < 0 || minX > float(width_) || minY > float(height_)) return;
        depthNear_ = std::min(depthNear_, std::max(nearest, kNear));
        depthFar_ = std::max(depthFar_, farthest);
        int ts = options_.tileSize;
        DrawItem item{&mesh,
                      objectToWorld,
                      cameraFromObject,
                      objectToWorld.normalTransform(),
                      override,
                      id,
                      std::clamp(int(std::floor(std::max(minX, 0.0f))) / ts, 0, tilesX_ - 1),
                      std::clamp(int(std::floor(std::max(minY, 0.0f))) / ts, 0, tilesY_ - 1),
                      std::clamp(int(std::min(maxX, float(width_))) / ts, 0, tilesX_ - 1),
                      std::clamp(int(std::min(maxY, float(height_))) / ts, 0, tilesY_ - 1),
                      objectToWorld.determinant() < 0,
                      instanced,
                      mayCutOut};
        items_.push_back(item);
    }

    void binItems() {
        bins_.resize(size_t(tilesX_) * size_t(tilesY_));
        for (uint32_t i = 0; i < items_.size(); ++i) {
            const DrawItem &item = items_[i];
            for (int ty = item.y0; ty <= item.y1; ++ty) {
                for (int tx = item.x0; tx <= item.x1; ++tx)
                    bins_[size_t(ty) * size_t(tilesX_) + size_t(tx)].push_back(i);
            }
        }
    }

    Tile tileRect(size_t t) const {
        int ts = options_.tileSize;
        int tx = int(t % size_t(tilesX_)), ty = int(t / size_t(tilesX_));
        return {tx * ts, ty * ts, std::min((tx + 1) * ts, width_), std::min((ty + 1) * ts, height_)};
    }

    RasterVertex project(const Vec3f &p, const Vec3f &bary) const {
        return {projection_.rasterX(p), projection_.rasterY(p), 1.0f / p.z, bary};
    }

    void transformVertices(const DrawItem &item, std::vector<CameraVertex> &out) const {
        out.resize(item.mesh->vertexCount());
        for (size_t v = 0; v < out.size(); ++v) {
            CameraVertex &c = out[v];
            c.p = item.cameraFromObject.applyPoint(item.mesh->positions[v]);
            if (c.p.z < kNear) continue;
            RasterVertex r = project(c.p, {});
            c.x = r.x, c.y = r.y, c.invZ = r.invZ;
        }
    }

    const std::vector<CameraVertex> &cameraVertices(uint32_t i, std::vector<CameraVertex> &scratch) {
        const DrawItem &item = items_[i];
        if ((item.x1 - item.x0 + 1) * (item.y1 - item.y0 + 1) <= kSharedVerticesTileCount) {
            transformVertices(item, scratch);
            return scratch;
        }
        std::call_once(sharedOnce_[i], [&] { transformVertices(item, sharedVertices_[i]); });
        return sharedVertices_[i];
    }

    void rasterizeTile(size_t t, const Tile &tile, TileScratch &scratch) {
        // Pixel centres lie at +0.5: a triangle reaches into the tile only past these bounds.
        float left = float(tile.x0) + 0.5f, right = float(tile.x1) - 0.5f;
        float top = float(tile.y0) + 0.5f, bottom = float(tile.y1) - 0.5f;
        for (uint32_t i : bins_[t]) {
            const std::vector<CameraVertex> &v = cameraVertices(i, scratch.vertices);
            const Mesh &mesh = *items_[i].mesh;
            for (uint32_t tri = 0; tri < mesh.triangleCount(); ++tri) {
                const uint32_t *idx = &mesh.indices[3 * size_t(tri)];
                const CameraVertex &a = v[idx[0]], &b = v[idx[1]], &c = v[idx[2]];
                if (a.p.z < kNear || b.p.z < kNear || c.p.z < kNear) {
                    ClipVertex clip[3] = {{a.p, {1, 0, 0}}, {b.p, {0, 1, 0}}, {c.p, {0, 0, 1}}};
                    drawClipped(clip, tile, scratch.fragments, i, tri);
                    continue;
                }
                // Most triangles of a detailed mesh miss a given tile: reject them before setup.
                if (std::max({a.x, b.x, c.x}) < left || std::min({a.x, b.x, c.x}) > right ||
                    std::max({a.y, b.y, c.y}) < top || std::min({a.y, b.y, c.y}) > bottom) {
                    continue;
                }
                RasterVertex r[3] = {
                    {a.x, a.y, a.invZ, {1, 0, 0}}, {b.x, b.y, b.invZ, {0, 1, 0}}, {c.x, c.y, c.invZ, {0, 0, 1}}};
                rasterize(r, tile, scratch.fragments, i, tri);
            }
        }
    }

    // Clips a triangle against the near plane (into at most two) and rasterizes the rest.
    void drawClipped(const ClipVertex (&c)[3], const Tile &tile, TileFragments &f, uint32_t item, uint32_t tri) {
        int behind = (c[0].p.z < kNear) + (c[1].p.z < kNear) + (c[2].p.z < kNear);
        if (behind == 3) return;
        ClipVertex poly[4];
        int n = 0;
        for (int k = 0; k < 3; ++k) {
            const ClipVertex &a = c[k], &b = c[(k + 1) % 3];
            if (a.p.z >= kNear) poly[n++] = a;
            if ((a.p.z < kNear) != (b.p.z < kNear)) {
                float s = (kNear - a.p.z) / (b.p.z - a.p.z);
                poly[n++] = {a.p + (b.p - a.p) * s, a.bary + (b.bary - a.bary) * s};
                poly[n - 1].p.z = kNear;
            }
        }
        for (int k = 1; k + 1 < n; ++k) {
            RasterVertex fan[3] = {project(poly[0].p, poly[0].bary), project(poly[k].p, poly[k].bary),
                                   project(poly[k + 1].p, poly[k + 1].bary)};
            rasterize(fan, tile, f, item, tri);
        }
    }

    // Edge functions at pixel centres over the triangle's box within the tile. Depth and
    // barycentrics are interpolated perspective-correctly through 1/z (orthographic: affinely).
    void rasterize(const RasterVertex (&c)[3], const Tile &tile, TileFragments &f, uint32_t item, uint32_t tri) {
        const float x[3] = {c[0].x, c[1].x, c[2].x}, y[3] = {c[0].y, c[1].y, c[2].y};
        const float invZ[3] = {c[0].invZ, c[1].invZ, c[2].invZ};
        const float depth[3] = {1 / invZ[0], 1 / invZ[1], 1 / invZ[2]};
        if (!std::isfinite(x[0] + x[1] + x[2] + y[0] + y[1] + y[2])) return;
        // Pixels whose centres the triangle's box holds, clamped to the tile in float first:
        // a vertex just beyond the near plane can project far outside int's range.
        int px0 = int(std::ceil(std::clamp(std::min({x[0], x[1], x[2]}) - 0.5f, float(tile.x0), float(tile.x1))));
        int px1 =
            int(std::floor(std::clamp(std::max({x[0], x[1], x[2]}) - 0.5f, float(tile.x0 - 1), float(tile.x1 - 1))));
        int py0 = int(std::ceil(std::clamp(std::min({y[0], y[1], y[2]}) - 0.5f, float(tile.y0), float(tile.y1))));
        int py1 =
            int(std::floor(std::clamp(std::max({y[0], y[1], y[2]}) - 0.5f, float(tile.y0 - 1), float(tile.y1 - 1))));
        if (px0 > px1 || py0 > py1) return;
        float area = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
        if (area == 0 || !std::isfinite(area)) return;
        // Raster y points down, so counter-clockwise seen from the front has negative area; a
        // mirroring transform turns that around.
        bool backFacing = (area > 0) != items_[item].mirrored;
        if (options_.backfaceCulling && backFacing) return;
        uint32_t triangleWord = tri | (backFacing ? kBackFacing : 0u);
        // A cut-out removes the surface where its map says so, before the depth test keeps it.
        const bool cutOut = items_[item].mayCutOut && shader_.cutsOut(materialOf(items_[item], tri));

        float sign = area > 0 ? 1.0f : -1.0f, invArea = 1.0f / std::abs(area);
        // Edge k joins the two corners other than k. It is measured from the endpoint first in
        // (y, x) order, whichever triangle it belongs to, so that two triangles sharing an edge
        // compute exactly opposite values and no pixel centre falls between them. Values come
        // from absolute pixel coordinates, never stepped from the tile's corner, so that they do
        // not depend on where tiles begin.
        float originX[3], originY[3], dxEdge[3], dyEdge[3], edgeSign[3], invLength[3];
        for (int k = 0; k < 3; ++k) {
            int a = (k + 1) % 3, b = (k + 2) % 3;
            bool swap = y[b] < y[a] || (y[b] == y[a] && x[b] < x[a]);
            int from = swap ? b : a, to = swap ? a : b;
            originX[k] = x[from];
            originY[k] = y[from];
            dxEdge[k] = x[to] - x[from];
            dyEdge[k] = y[to] - y[from];
            edgeSign[k] = swap ? -sign : sign;
            invLength[k] = options_.wireframe ? 1.0f / std::sqrt(dxEdge[k] * dxEdge[k] + dyEdge[k] * dyEdge[k]) : 0.0f;
        }
        for (int py = py0; py <= py1; ++py) {
            float cy = float(py) + 0.5f;
            float row[3] = {dxEdge[0] * (cy - originY[0]), dxEdge[1] * (cy - originY[1]),
                            dxEdge[2] * (cy - originY[2])};
            for (int px = px0; px <= px1; ++px) {
                float cx = float(px) + 0.5f;
                float e[3] = {edgeSign[0] * (row[0] - dyEdge[0] * (cx - originX[0])),
                              edgeSign[1] * (row[1] - dyEdge[1] * (cx - originX[1])),
                              edgeSign[2] * (row[2] - dyEdge[2] * (cx - originX[2]))};
                if (std::min(std::min(e[0], e[1]), e[2]) < 0) continue;  // one branch, not three
                // In perspective 1/z is affine on the raster: test it before paying for a
                // division. An orthographic view has z itself affine, and affine weights.
                float w0 = e[0] * invZ[0], w1 = e[1] * invZ[1], w2 = e[2] * invZ[2];
                float invDepth = (w0 + w1 + w2) * invArea;
                if (projection_.orthographic) {
                    w0 = e[0], w1 = e[1], w2 = e[2];
                    invDepth = 1.0f / ((w0 * depth[0] + w1 * depth[1] + w2 * depth[2]) * invArea);
                }
                size_t p = size_t(py - tile.y0) * size_t(tile.x1 - tile.x0) + size_t(px - tile.x0);
                if (!(invDepth > f.invDepth[p])) continue;
                // Perspective-correct weights of the three corners.
                float norm = 1.0f / (w0 + w1 + w2);
                float s0 = w0 * norm, s1 = w1 * norm, s2 = w2 * norm;
                float b1 = s0 * c[0].bary.y + s1 * c[1].bary.y + s2 * c[2].bary.y;
                float b2 = s0 * c[0].bary.z + s1 * c[1].bary.z + s2 * c[2].bary.z;
                if (cutOut && cutAway(items_[item], triangleWord, b1, b2, invDepth)) continue;
                f.invDepth[p] = invDepth;
                f.item[p] = item;
                f.triangle[p] = triangleWord;
                f.b1[p] = b1;
                f.b2[p] = b2;
                if (options_.wireframe) {
                    f.edgePixels[p] = std::min({e[0] * invLength[0], e[1] * invLength[1], e[2] * invLength[2]});
                }
            }
        }
    }

    void shadeTile(const Tile &tile, const TileFragments &f, PreviewImage &image) const;
    Vec3f surfaceColor(const DrawItem &item, uint32_t triangleWord, float b1, float b2, float invDepth) const;
    Vec3f normalAt(const DrawItem &item, uint32_t triangleWord, float b1, float b2) const;
    PreviewSurface surfaceAt(const DrawItem &item, uint32_t triangleWord, float b1, float b2, float invDepth) const;
    bool cutAway(const DrawItem &item, uint32_t triangleWord, float b1, float b2, float invDepth) const {
        return shader_.cutAway(surfaceAt(item, triangleWord, b1, b2, invDepth));
    }
    static MaterialId materialOf(const DrawItem &item, uint32_t tri) {
        return item.materialOverride != kNoMaterial ? item.materialOverride : item.mesh->triangleMaterials[tri];
    }

    const RenderScene &scene_;
    const PreviewOptions &options_;
    RasterProjection projection_;
    int width_, height_, tilesX_, tilesY_;
    std::vector<DrawItem> items_;
    std::vector<std::vector<uint32_t>> bins_;
    std::vector<std::vector<CameraVertex>> sharedVertices_;
    std::unique_ptr<std::once_flag[]> sharedOnce_;
    // The depth mode's grey ramp spans the depths of the drawn objects' boxes.
    float depthNear_ = kInfinity, depthFar_ = kNear;
    std::optional<ShadowMap> shadowMap_;
    PreviewShader shader_;
    CameraRays rays_;    // the path tracer's camera rays: background directions
    Vec3f forward_;      // the view axis, towards the eye an orthographic camera's surfaces face
    float pixelSpread_;  // texture footprints grow with distance by this, as the path tracer's ray cones
};

// The interpolated shading normal, on the side the camera sees. Surfaces are two-sided: as in
// the path tracer, the side seen is decided by the triangle's winding, and a smooth normal
// follows it.
Vec3f Rasterizer::normalAt(const DrawItem &item, uint32_t triangleWord, float b1, float b2) const {
    const Mesh &mesh = *item.mesh;
    const uint32_t *idx = &mesh.indices[3 * size_t(triangleWord & ~kBackFacing)];
    const Vec3f &p0 = mesh.positions[idx[0]];
    Vec3f n = mesh.normals.empty()
        ? cross(mesh.positions[idx[1]] - p0, mesh.positions[idx[2]] - p0)
        : mesh.normals[idx[0]] * (1 - b1 - b2) + mesh.normals[idx[1]] * b1 + mesh.normals[idx[2]] * b2;
    n = normalize(item.normalToWorld.applyVector(n));
    return (triangleWord & kBackFacing) != 0 ? -n : n;
}

// The point the pixel shows, with what shading and texture lookups need, worked out as the path
// tracer's SurfaceLookup does, so that both read the same texels.
PreviewSurface Rasterizer::surfaceAt(const DrawItem &item, uint32_t triangleWord, float b1, float b2,
                                     float invDepth) const {
    const Mesh &mesh = *item.mesh;
    uint32_t tri = triangleWord & ~kBackFacing;
    const uint32_t *idx = &mesh.indices[3 * size_t(tri)];
    float b0 = 1 - b1 - b2;
    PreviewSurface s;
    s.material = materialOf(item, tri);
    s.backFacing = (triangleWord & kBackFacing) != 0;
    s.normal = normalAt(item, triangleWord, b1, b2);
    const Vec3f &p0 = mesh.positions[idx[0]], &p1 = mesh.positions[idx[1]], &p2 = mesh.positions[idx[2]];
    const Transform *placement = item.instanced ? &item.objectToWorld : nullptr;
    Vec3f local = p0 * b0 + p1 * b1 + p2 * b2;
    s.position = placement ? placement->applyPoint(local) : local;
    WorldTriangle world{p1 - p0, p2 - p0, {}};
    if (placement) world = {placement->applyVector(world.e1), placement->applyVector(world.e2), {}};
    world.ng = cross(world.e1, world.e2);
    if (item.mirrored) world.ng = -world.ng;  // back to the side the mesh faces
    Vec3f ng = normalize(world.ng);
    s.geometricNormal = s.backFacing ? -ng : ng;
    s.toEye = projection_.orthographic ? -forward_ : normalize(projection_.eye - s.position);
    if (!shader_.hasMaps(s.material)) return s;
    // The path tracer's footprint: its ray cone's width where the camera ray meets the surface.
    float distance = projection_.orthographic ? 1.0f / invDepth : length(s.position - projection_.eye);
    s.map.footprint = pixelSpread_ * distance;
    if (mesh.uvs.size() == mesh.positions.size()) {
        TextureFrame frame = textureFrame(mesh, idx, b0, b1, b2, world, placement, item.mirrored);
        s.map.uv = frame.uv;
        s.map.uvPerMetre = frame.uvPerMetre;
        s.tangent = frame.tangent;
        s.bitangentSign = frame.bitangentSign;
    }
    return s;
}

Vec3f Rasterizer::surfaceColor(const DrawItem &item, uint32_t triangleWord, float b1, float b2, float invDepth) const {
    switch (options_.mode) {
    case PreviewMode::Depth:
        if (!(depthFar_ > depthNear_)) return Vec3f(1.0f);  // everything at one depth
        return Vec3f(std::clamp((depthFar_ - 1.0f / invDepth) / (depthFar_ - depthNear_), 0.0f, 1.0f));
    case PreviewMode::Id: return objectIdColor(item.objectId);
    default: break;
    }
    MaterialId m = materialOf(item, triangleWord & ~kBackFacing);
    if (!shadowMap_ && shader_.fromNormalAlone(m, !item.mesh->normals.empty()))
        return shader_.colorFromNormal(m, normalAt(item, triangleWord, b1, b2));
    PreviewSurface s = surfaceAt(item, triangleWord, b1, b2, invDepth);
    // The shadow map is looked up with the normal of the side the mesh faces.
    bool sunVisible =
        !shadowMap_ || !shadowMap_->shadowed(s.position, s.backFacing ? -s.geometricNormal : s.geometricNormal);
    return shader_.color(s, sunVisible);
}

void Rasterizer::shadeTile(const Tile &tile, const TileFragments &f, PreviewImage &image) const {
    const bool constantBackground = shader_.constantBackground();
    const Vec3f background = shader_.background(forward_);
    // A flat triangle whose colour follows from its normal has one colour all over (except with
    // shadows): neighbouring pixels of the same one reuse it.
    bool reuseFlat = options_.mode != PreviewMode::Depth && !shadowMap_;
    uint32_t lastItem = kNoItem, lastTriangle = 0;
    Vec3f lastColor;
    size_t p = 0;
    for (int y = tile.y0; y < tile.y1; ++y) {
        for (int x = tile.x0; x < tile.x1; ++x, ++p) {
            size_t out = size_t(y) * size_t(width_) + size_t(x);
            if (f.invDepth[p] == 0) {
                image.film.set(x, y,
                               constantBackground
                                   ? background
                                   : shader_.background(rays_.generate(float(x) + 0.5f, float(y) + 0.5f).direction));
                image.depth[out] = kInfinity;
                image.objectId[out] = 0;
                continue;
            }
            const DrawItem &item = items_[f.item[p]];
            Vec3f color;
            if (reuseFlat && f.item[p] == lastItem && f.triangle[p] == lastTriangle) {
                color = lastColor;
            } else {
                color = surfaceColor(item, f.triangle[p], f.b1[p], f.b2[p], f.invDepth[p]);
                bool flat = item.mesh->normals.empty() &&
                    (options_.mode == PreviewMode::Id ||
                     shader_.fromNormalAlone(materialOf(item, f.triangle[p] & ~kBackFacing), false));
                lastItem = flat ? f.item[p] : kNoItem;
                lastTriangle = f.triangle[p];
                lastColor = color;
            }
            if (options_.wireframe && f.edgePixels[p] < 0.75f) color = Vec3f(0.02f);
            image.film.set(x, y, color);
            image.depth[out] = 1.0f / f.invDepth[p];
            image.objectId[out] = item.objectId;
        }
    }
}

}  // namespace

Vec3f objectIdColor(uint32_t id) {
    if (id == 0) return Vec3f(0.0f);
    uint32_t h = mix32(id * 0x9e3779b9u + 1);
    // Each channel in [0.1, 1]: distinct from the black background and from each other.
    return {0.1f + 0.9f * float(h & 0xffu) / 255.0f, 0.1f + 0.9f * float((h >> 8) & 0xffu) / 255.0f,
            0.1f + 0.9f * float((h >> 16) & 0xffu) / 255.0f};
}

void renderPreview(const RenderScene &scene, const PreviewOptions &options, PreviewImage &image) {
    int w = scene.camera.width, h = scene.camera.height;
    if (image.film.width() != w || image.film.height() != h) image.film = RgbaImage(w, h);
    image.depth.resize(size_t(w) * size_t(h));
    image.objectId.resize(size_t(w) * size_t(h));
    Rasterizer(scene, options).run(image);
}

PreviewImage renderPreview(const RenderScene &scene, const PreviewOptions &options) {
    PreviewImage image{RgbaImage(0, 0), {}, {}};
    renderPreview(scene, options, image);
    return image;
}

}  // namespace veduta

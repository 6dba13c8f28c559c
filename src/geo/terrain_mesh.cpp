#include "geo/terrain_mesh.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace veduta {

namespace {

constexpr uint32_t kNoVertex = ~0u;

bool hasHeight(const HeightGrid &grid, int column, int row) {
    return column >= 0 && row >= 0 && column < grid.columns && row < grid.rows && !std::isnan(grid.node(column, row));
}

// The slope along one axis from the nodes before and after (central difference), or from the
// one that has a height.
double slope(const HeightGrid &grid, int column, int row, int dc, int dr) {
    bool before = hasHeight(grid, column - dc, row - dr), after = hasHeight(grid, column + dc, row + dr);
    double h = grid.node(column, row);
    if (before && after)
        return (double(grid.node(column + dc, row + dr)) - grid.node(column - dc, row - dr)) / (2 * grid.spacing);
    if (after) return (grid.node(column + dc, row + dr) - h) / grid.spacing;
    if (before) return (h - grid.node(column - dc, row - dr)) / grid.spacing;
    return 0;
}

// Writes the vertex of node (column, row) at `index` of the mesh's arrays.
void writeVertex(const HeightGrid &grid, const LocalFrame &frame, float uvTile, int column, int row, size_t index,
                 Mesh &mesh) {
    Vec3f p = frame.toLocal(grid.nodePoint(column, row), grid.node(column, row));
    mesh.positions[index] = p;
    // 0 − s rather than −s: a level plane gets +0, not −0.
    double nx = 0 - slope(grid, column, row, 1, 0), ny = 0 - slope(grid, column, row, 0, 1);
    double length = std::sqrt(nx * nx + ny * ny + 1);
    mesh.normals[index] = {float(nx / length), float(ny / length), float(1 / length)};
    mesh.uvs[index] = {p.x / uvTile, p.y / uvTile};
}

void resizeVertices(Mesh &mesh, size_t vertices, size_t triangles, MaterialId material) {
    mesh.positions.reserve(vertices + 1);  // the padding that lets Embree share the vertices (render/bvh.cpp)
    mesh.positions.resize(vertices);
    mesh.normals.resize(vertices);
    mesh.uvs.resize(vertices);
    mesh.indices.resize(3 * triangles);
    mesh.triangleMaterials.assign(triangles, material);
}

// ---- full resolution ----

Mesh fullResolution(const HeightGrid &grid, const LocalFrame &frame, const TerrainMeshOptions &options) {
    int columns = grid.columns, rows = grid.rows;
    // Per row: the nodes with a height, and the cells (to the row above) with four.
    std::vector<size_t> vertexStart(size_t(rows) + 1), triangleStart(size_t(rows), 0);
    tbb::parallel_for(0, rows, [&](int r) {
        size_t nodes = 0, cells = 0;
        for (int c = 0; c < columns; ++c) {
            nodes += !std::isnan(grid.node(c, r));
            if (r + 1 < rows && c + 1 < columns)
                cells += hasHeight(grid, c, r) && hasHeight(grid, c + 1, r) && hasHeight(grid, c, r + 1) &&
                    hasHeight(grid, c + 1, r + 1);
        }
        vertexStart[size_t(r) + 1] = nodes;
        triangleStart[size_t(r)] = 2 * cells;
    });
    size_t triangles = 0;
    for (int r = 0; r < rows; ++r) {
        vertexStart[size_t(r) + 1] += vertexStart[size_t(r)];
        size_t count = triangleStart[size_t(r)];
        triangleStart[size_t(r)] = triangles;
        triangles += count;
    }
    size_t vertices = vertexStart.back();
    bool holes = vertices != grid.heights.size();

    Mesh mesh;
    resizeVertices(mesh, vertices, triangles, options.material);
    // Without holes vertex = node index; with them a map, filled row by row.
    std::vector<uint32_t> vertexOf(holes ? grid.heights.size() : 0, kNoVertex);
    tbb::parallel_for(0, rows, [&](int r) {
        size_t index = vertexStart[size_t(r)];
        for (int c = 0; c < columns; ++c) {
            if (std::isnan(grid.node(c, r))) continue;
            if (holes) vertexOf[size_t(r) * size_t(columns) + size_t(c)] = uint32_t(index);
            writeVertex(grid, frame, options.uvTile, c, r, index++, mesh);
        }
    });
    auto vertex = [&](int c, int r) {
        size_t node = size_t(r) * size_t(columns) + size_t(c);
        return holes ? vertexOf[node] : uint32_t(node);
    };
    tbb::parallel_for(0, rows - 1, [&](int r) {
        uint32_t *out = mesh.indices.data() + 3 * triangleStart[size_t(r)];
        for (int c = 0; c + 1 < columns; ++c) {
            uint32_t v00 = vertex(c, r), v10 = vertex(c + 1, r), v01 = vertex(c, r + 1), v11 = vertex(c + 1, r + 1);
            if (holes && (v00 == kNoVertex || v10 == kNoVertex || v01 == kNoVertex || v11 == kNoVertex)) continue;
            // The SW–NE diagonal v00–v11: south-east triangle, then north-west, counter-clockwise.
            *out++ = v00, *out++ = v10, *out++ = v11;
            *out++ = v00, *out++ = v11, *out++ = v01;
        }
    });
    return mesh;
}

// ---- simplified: right-triangulated irregular network ----

// The RTIN over the grid padded to (size + 1)² nodes, size a power of two. Each triangle is
// named by its hypotenuse a–b and its right-angle corner c; it splits at the hypotenuse's
// midpoint m into (c, a, m) and (b, c, m). errors_ holds at each midpoint a bound on the
// vertical error of both triangles that share that hypotenuse, so both split or neither
// (no cracks), and a parent's bound is never below its children's.
class Rtin {
  public:
    explicit Rtin(const HeightGrid &grid) : grid_(grid) {
        while (size_ < std::max(grid.columns - 1, grid.rows - 1)) size_ *= 2;
        errors_.assign(size_t(size_ + 1) * size_t(size_ + 1), 0.0f);
        for (int s = 1; s <= size_ / 2; s *= 2) {
            axisLevel(s);
            squareLevel(s);
        }
    }

    // Calls emit(a, b, c) (node coordinates, counter-clockwise) for every triangle of the
    // network split down to maxError.
    template <class Emit>
    void triangles(double maxError, Emit &&emit) const {
        split({0, 0}, {size_, size_}, {size_, 0}, maxError, emit);
        split({size_, size_}, {0, 0}, {0, size_}, maxError, emit);
    }

  private:
    struct Node {
        int x = 0, y = 0;
    };
    static Node mid(Node a, Node b) { return {(a.x + b.x) / 2, (a.y + b.y) / 2}; }

    bool valid(Node n) const { return hasHeight(grid_, n.x, n.y); }
    double height(Node n) const { return grid_.node(n.x, n.y); }
    float &error(Node n) { return errors_[size_t(n.y) * size_t(size_ + 1) + size_t(n.x)]; }
    float error(Node n) const { return errors_[size_t(n.y) * size_t(size_ + 1) + size_t(n.x)]; }
    bool inside(Node n) const { return n.x >= 0 && n.y >= 0 && n.x <= size_ && n.y <= size_; }

    // The bound at midpoint m of hypotenuse a–b, over the triangles with corner c1 or c2 that
    // lie inside the square. Triangles with legs of √2 (s = 1) have half cells as children,
    // which contain no other node: their error is the midpoint's own.
    void diamond(Node m, Node a, Node b, Node c1, Node c2, bool halfCellChildren) {
        constexpr double infinity = std::numeric_limits<double>::infinity();
        double own = valid(a) && valid(b) && valid(m) ? std::abs(height(m) - (height(a) + height(b)) / 2) : infinity;
        double bound = 0;
        for (Node c : {c1, c2}) {
            if (!inside(c)) continue;
            double children = halfCellChildren ? (valid(c) ? 0.0 : infinity)
                                               : std::max(double(error(mid(c, a))), double(error(mid(b, c))));
            bound = std::max(bound, own + children);
        }
        float rounded = float(bound);
        error(m) = double(rounded) < bound ? std::nextafter(rounded, std::numeric_limits<float>::infinity()) : rounded;
    }

    // Hypotenuses of length 2s along the grid lines, midpoints at odd multiples of s.
    void axisLevel(int s) {
        int count = size_ / (2 * s);
        tbb::parallel_for(0, count + 1, [&](int j) {
            for (int i = 0; i < count; ++i) {
                int odd = s * (2 * i + 1), even = 2 * s * j;
                diamond({odd, even}, {odd - s, even}, {odd + s, even}, {odd, even - s}, {odd, even + s}, s == 1);
                diamond({even, odd}, {even, odd - s}, {even, odd + s}, {even - s, odd}, {even + s, odd}, s == 1);
            }
        });
    }

    // Diagonals of squares of side 2s; each runs through the centre of the square of side 4s
    // it is a quarter of (so the whole square's diagonal runs south-west to north-east).
    void squareLevel(int s) {
        int count = size_ / (2 * s);
        tbb::parallel_for(0, count, [&](int j) {
            for (int i = 0; i < count; ++i) {
                Node m{s * (2 * i + 1), s * (2 * j + 1)};
                Node a{i % 2 ? m.x - s : m.x + s, j % 2 ? m.y - s : m.y + s};
                Node b{2 * m.x - a.x, 2 * m.y - a.y};
                diamond(m, a, b, {a.x, b.y}, {b.x, a.y}, false);
            }
        });
    }

    template <class Emit>
    void split(Node a, Node b, Node c, double maxError, Emit &emit) const {
        if (std::min({a.x, b.x, c.x}) >= grid_.columns || std::min({a.y, b.y, c.y}) >= grid_.rows) return;  // padding
        Node m = mid(a, b);
        if (std::abs(a.x - c.x) + std::abs(a.y - c.y) > 1 && double(error(m)) > maxError) {
            split(c, a, m, maxError, emit);
            split(b, c, m, maxError, emit);
        } else if (valid(a) && valid(b) && valid(c)) {
            emit(a, c, b);  // the network's triangles run clockwise
        }
    }

    const HeightGrid &grid_;
    int size_ = 1;
    std::vector<float> errors_;
};

Mesh simplified(const HeightGrid &grid, const LocalFrame &frame, const TerrainMeshOptions &options) {
    Rtin rtin(grid);
    size_t triangles = 0;
    rtin.triangles(options.maxError, [&](auto, auto, auto) { ++triangles; });

    std::vector<uint32_t> vertexOf(grid.heights.size(), kNoVertex);
    std::vector<uint32_t> nodes;  // node index of each vertex
    std::vector<uint32_t> indices;
    indices.reserve(3 * triangles);
    rtin.triangles(options.maxError, [&](auto a, auto b, auto c) {
        for (auto n : {a, b, c}) {
            size_t node = size_t(n.y) * size_t(grid.columns) + size_t(n.x);
            if (vertexOf[node] == kNoVertex) {
                vertexOf[node] = uint32_t(nodes.size());
                nodes.push_back(uint32_t(node));
            }
            indices.push_back(vertexOf[node]);
        }
    });
    Mesh mesh;
    resizeVertices(mesh, nodes.size(), 0, options.material);
    mesh.indices = std::move(indices);
    mesh.triangleMaterials.assign(triangles, options.material);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, nodes.size()), [&](const tbb::blocked_range<size_t> &range) {
        for (size_t i = range.begin(); i < range.end(); ++i)
            writeVertex(grid, frame, options.uvTile, int(nodes[i] % uint32_t(grid.columns)),
                        int(nodes[i] / uint32_t(grid.columns)), i, mesh);
    });
    return mesh;
}

}  // namespace

Mesh terrainMesh(const HeightGrid &grid, const LocalFrame &frame, const TerrainMeshOptions &options) {
    if (grid.columns < 2 || grid.rows < 2) return {};
    return options.maxError > 0 ? simplified(grid, frame, options) : fullResolution(grid, frame, options);
}

}  // namespace veduta

#include "io/georeferenced_mesh.h"

#include <cmath>
#include <map>
#include <stdexcept>
#include <tuple>

#include <fmt/format.h>
// The reader's implementation, compiled here once, with double coordinates.
#define TINYOBJLOADER_IMPLEMENTATION
#define TINYOBJLOADER_USE_DOUBLE
#include <tiny_obj_loader.h>

#include "core/error.h"
#include "core/file_extension.h"
#include "io/map_mesh.h"
#include "io/ply_file.h"

namespace veduta {

namespace {

// How the source grid's east and north map onto the scene's near a point, as the columns of
// the conversion's Jacobian (metres per metre): a normal transforms by its inverse transpose.
struct GridTurn {
    double a = 1, b = 0, c = 0, d = 1;  // [[a, c], [b, d]]: columns (a, b) east, (c, d) north

    Vec3f normal(const Vec3f &n) const {
        double det = a * d - b * c;
        double x = (d * n.x - b * n.y) / det, y = (-c * n.x + a * n.y) / det;
        double length = std::sqrt(x * x + y * y + double(n.z) * n.z);
        return {float(x / length), float(y / length), float(n.z / length)};
    }
};

GridTurn gridTurn(const MapProjection &projection, const MapPoint &p) {
    if (projection.source().epsg == projection.sceneCrs().epsg) return {};
    MapPoint o = projection.toScene(p), e = projection.toScene({p.easting + 1, p.northing}),
             n = projection.toScene({p.easting, p.northing + 1});
    return {e.easting - o.easting, e.northing - o.northing, n.easting - o.easting, n.northing - o.northing};
}

// OBJ indexes positions, normals and texture coordinates apart; a mesh vertex is one triple.
class ObjMeshBuilder {
  public:
    ObjMeshBuilder(const tinyobj::attrib_t &attrib, const std::filesystem::path &file) : attrib_(attrib), file_(file) {}

    void addFaces(const tinyobj::shape_t &shape) {
        size_t next = 0;
        for (unsigned vertices : shape.mesh.num_face_vertices) {
            if (vertices == 3) {
                for (size_t k = 0; k < 3; ++k) mesh_.indices.push_back(vertex(shape.mesh.indices[next + k]));
            }
            next += vertices;  // points and lines are not surfaces
            ++face_;
        }
    }

    MapMesh take() {
        if (!allNormals_) mesh_.normals.clear();
        if (!allUvs_) mesh_.uvs.clear();
        return std::move(mesh_);
    }

  private:
    uint32_t vertex(const tinyobj::index_t &i) {
        auto key = std::make_tuple(i.vertex_index, i.normal_index, i.texcoord_index);
        auto [it, fresh] = vertices_.try_emplace(key, uint32_t(mesh_.positions.size()));
        if (!fresh) return it->second;
        check(i.vertex_index, attrib_.vertices.size() / 3, "vertex");
        const double *v = &attrib_.vertices[3 * size_t(i.vertex_index)];
        mesh_.positions.push_back({v[0], v[1], v[2]});
        allNormals_ = allNormals_ && i.normal_index >= 0;
        if (i.normal_index >= 0) {
            check(i.normal_index, attrib_.normals.size() / 3, "normal");
            const double *n = &attrib_.normals[3 * size_t(i.normal_index)];
            mesh_.normals.push_back({float(n[0]), float(n[1]), float(n[2])});
        }
        allUvs_ = allUvs_ && i.texcoord_index >= 0;
        if (i.texcoord_index >= 0) {
            check(i.texcoord_index, attrib_.texcoords.size() / 2, "texture coordinate");
            const double *t = &attrib_.texcoords[2 * size_t(i.texcoord_index)];
            mesh_.uvs.push_back({float(t[0]), float(t[1])});
        }
        return it->second;
    }

    // tinyobjloader only warns of an index beyond the file's lists.
    void check(int index, size_t count, const char *what) const {
        if (index < 0 || size_t(index) >= count)
            throw InputError(
                {file_.string()},
                fmt::format("face {} refers to {} {}, beyond the {} the file has", face_ + 1, what, index + 1, count));
    }

    const tinyobj::attrib_t &attrib_;
    const std::filesystem::path &file_;
    MapMesh mesh_;
    std::map<std::tuple<int, int, int>, uint32_t> vertices_;
    size_t face_ = 0;
    bool allNormals_ = true, allUvs_ = true;
};

MapMesh readObj(const std::filesystem::path &file) {
    tinyobj::ObjReaderConfig config;
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    if (!reader.ParseFromFile(file.string(), config)) {
        std::string error = reader.Error();
        while (!error.empty() && error.back() == '\n') error.pop_back();
        throw InputError({file.string()}, fmt::format("cannot read the OBJ file: {}", error));
    }
    ObjMeshBuilder builder(reader.GetAttrib(), file);
    for (const tinyobj::shape_t &shape : reader.GetShapes()) builder.addFaces(shape);
    return builder.take();
}

// The map mesh in the scene's render frame.
Mesh place(const MapMesh &in, const MapProjection &projection, const std::filesystem::path &file) {
    if (in.indices.empty()) throw InputError({file.string()}, "mesh file holds no triangles");
    Mesh mesh;
    for (size_t i = 0; i < in.positions.size(); ++i) {
        const CrsCoordinate &p = in.positions[i];
        try {
            mesh.positions.push_back(projection.toRender(p));
            if (!in.normals.empty()) mesh.normals.push_back(gridTurn(projection, {p.x, p.y}).normal(in.normals[i]));
        } catch (const std::out_of_range &e) {
            throw InputError({file.string()},
                             fmt::format("vertex {} ({}, {}) is no point of EPSG:{}: {}", i + 1, p.x, p.y,
                                         projection.source().epsg, e.what()));
        }
    }
    mesh.uvs = in.uvs;
    mesh.indices = in.indices;
    mesh.setMaterial(0);
    return mesh;
}

}  // namespace

Mesh importGeoreferencedMesh(const std::filesystem::path &file, const MapProjection &projection) {
    if (!std::filesystem::is_regular_file(file)) throw InputError({file.string()}, "no such mesh file");
    std::string extension = lowercaseExtension(file);
    if (extension == ".obj") return place(readObj(file), projection, file);
    if (extension == ".ply") return place(readPlyFile(file), projection, file);
    throw InputError({file.string()},
                     fmt::format("georeferenced meshes are read from OBJ and PLY, whose coordinates "
                                 "keep double precision; convert this {} file to one of them",
                                 extension.empty() ? "extensionless" : extension));
}

}  // namespace veduta

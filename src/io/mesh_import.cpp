#include "io/mesh_import.h"

#include <assimp/BaseImporter.h>
#include <assimp/DefaultIOSystem.h>
#include <assimp/MemoryIOWrapper.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <fmt/format.h>
#include <assimp/Importer.hpp>
#include <cmath>
#include <memory>
#include <set>

#include "core/error.h"
#include "core/file_extension.h"
#include "io/ply_file.h"

namespace veduta {

namespace {

Transform toTransform(const aiMatrix4x4 &m) {
    return {{m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4}};
}

Mesh convert(const aiMesh &in, const std::filesystem::path &file) {
    Mesh m;
    m.positions.reserve(in.mNumVertices);
    for (unsigned i = 0; i < in.mNumVertices; ++i) {
        const aiVector3D &v = in.mVertices[i];
        // Embree's BVH build asserts on a bound that is not finite.
        if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
            throw InputError({file.string()},
                             fmt::format("vertex {} is not a finite point ({} {} {})", i, v.x, v.y, v.z));
        m.positions.push_back({v.x, v.y, v.z});
    }
    if (in.HasNormals()) {
        for (unsigned i = 0; i < in.mNumVertices; ++i)
            m.normals.push_back({in.mNormals[i].x, in.mNormals[i].y, in.mNormals[i].z});
    }
    if (in.HasTextureCoords(0)) {
        for (unsigned i = 0; i < in.mNumVertices; ++i)
            m.uvs.push_back({in.mTextureCoords[0][i].x, in.mTextureCoords[0][i].y});
    }
    for (unsigned f = 0; f < in.mNumFaces; ++f) {
        const aiFace &face = in.mFaces[f];
        if (face.mNumIndices != 3) continue;  // points and lines left after triangulation
        for (unsigned k = 0; k < 3; ++k) {
            if (face.mIndices[k] >= in.mNumVertices) {
                throw InputError({file.string()},
                                 fmt::format("face {} refers to vertex {}, beyond the {} vertices", f, face.mIndices[k],
                                             in.mNumVertices));
            }
        }
        m.indices.insert(m.indices.end(), {face.mIndices[0], face.mIndices[1], face.mIndices[2]});
    }
    m.setMaterial(0);
    return m;
}

void collect(const aiScene &scene, const aiNode &node, const Transform &parent, const std::filesystem::path &file,
             Mesh &out) {
    Transform toWorld = parent * toTransform(node.mTransformation);
    for (unsigned i = 0; i < node.mNumMeshes; ++i) out.append(convert(*scene.mMeshes[node.mMeshes[i]], file), toWorld);
    for (unsigned i = 0; i < node.mNumChildren; ++i) collect(scene, *node.mChildren[i], toWorld, file, out);
}

// A PLY file as read by veduta's own reader, in the file's coordinates.
Mesh toMesh(const MapMesh &in, const std::filesystem::path &file) {
    if (in.indices.empty()) throw InputError({file.string()}, "mesh file holds no triangles");
    Mesh mesh;
    mesh.positions.reserve(in.positions.size());
    for (size_t i = 0; i < in.positions.size(); ++i) {
        Vec3f p{float(in.positions[i].x), float(in.positions[i].y), float(in.positions[i].z)};
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw InputError({file.string()},
                             fmt::format("vertex {} is not a finite point in single precision ({} {} {})", i,
                                         in.positions[i].x, in.positions[i].y, in.positions[i].z));
        mesh.positions.push_back(p);
    }
    mesh.normals = in.normals;
    mesh.uvs = in.uvs;
    mesh.indices = in.indices;
    mesh.setMaterial(0);
    return mesh;
}

// Leaves the importer only the readers that claim `extension` (lower case, without the dot).
// Where they all turn a file down, Assimp would offer it to every other reader it has, and some
// of those read past the end of a short file (5.2.5's MD5 token search, found by
// fuzz/mesh_fuzzer.cpp): the extension decides the format. Assimp forgets the readers it is
// told to unregister, so they are deleted here.
// Assimp 5's OBJ reader cuts a file into lines in a buffer as large as the file and hands the
// last token to strtol without a terminator when the last line fills it (AddressSanitizer's
// strict string checks caught the read; digits at the end would run on past the buffer). Text
// files read through this end in a newline and a NUL, so every line the reader cuts has one.
class TerminatedTextFiles : public Assimp::DefaultIOSystem {
  public:
    Assimp::IOStream *Open(const char *file, const char *mode) override {
        std::unique_ptr<Assimp::IOStream> stream(DefaultIOSystem::Open(file, mode));
        if (!stream) return nullptr;
        size_t size = stream->FileSize();
        auto bytes = std::make_unique<uint8_t[]>(size + 2);
        size_t read = stream->Read(bytes.get(), 1, size);
        bytes[read] = '\n';
        bytes[read + 1] = '\0';
        return new Assimp::MemoryIOStream(bytes.release(), read + 2, true);
    }
};

void keepReadersOf(Assimp::Importer &importer, const std::string &extension) {
    for (size_t i = importer.GetImporterCount(); i-- > 0;) {
        Assimp::BaseImporter *reader = importer.GetImporter(i);
        std::set<std::string> extensions;
        reader->GetExtensionList(extensions);
        if (extensions.count(extension)) continue;
        importer.UnregisterLoader(reader);
        delete reader;
    }
}

}  // namespace

Mesh importMesh(const std::filesystem::path &file) {
    if (!std::filesystem::is_regular_file(file)) throw InputError({file.string()}, "no such mesh file");
    // Assimp's PLY reader loops for ever on a malformed header line ("elemen 0") or a cut
    // body; veduta's own reader (io/ply_file.h) names the line instead.
    std::string extension = lowercaseExtension(file);
    if (extension == ".ply") return toMesh(readPlyFile(file), file);
    if (extension == ".gml")
        throw InputError({file.string()},
                         "a .gml file is no mesh; CityGML buildings come into a scene with "
                         "<citygml file=\"…\"/> (docs/citygml.md)");
    Assimp::Importer importer;
    if (extension.empty())
        throw InputError({file.string()},
                         "a mesh file needs an extension that names its format (.obj, .gltf, .glb, …)");
    keepReadersOf(importer, extension.substr(1));
    if (extension == ".obj") importer.SetIOHandler(new TerminatedTextFiles);  // the importer owns it
    // Normals are the file's own; we do not invent smooth normals for faceted models. Assimp
    // checks what its reader built (face indices, counts) before the other steps use it.
    const aiScene *scene = importer.ReadFile(file.string(),
                                             aiProcess_ValidateDataStructure | aiProcess_Triangulate |
                                                 aiProcess_JoinIdenticalVertices | aiProcess_SortByPType);
    if (!scene || !scene->mRootNode || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE)) {
        throw InputError({file.string()}, std::string("cannot read mesh: ") + importer.GetErrorString());
    }
    Mesh mesh;
    collect(*scene, *scene->mRootNode, Transform{}, file, mesh);
    if (mesh.triangleCount() == 0) throw InputError({file.string()}, "mesh file holds no triangles");
    return mesh;
}

}  // namespace veduta

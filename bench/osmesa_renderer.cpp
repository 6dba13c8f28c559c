#include "osmesa_renderer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

// The prototypes only give decltype() the functions' types; every call goes through pointers
// from OSMesaGetProcAddress (see GlFunctions).
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>

namespace veduta {

namespace {

constexpr float kNear = 0.05f;  // metres, as the preview clips

// GL entry points, looked up through OSMesa rather than linked by name: libOSMesa exports
// them too, but so does glvnd's libGL/libOpenGL, which a dependency can bring into the process
// (OpenCV already brings libGLX); whichever came first would win, and glvnd without a current
// GLX context silently does nothing.
// clang-format off
#define VEDUTA_GL_FUNCTIONS(X)                                                                                         \
    X(ActiveTexture) X(AttachShader) X(BindBuffer) X(BindTexture) X(BindVertexArray) X(BufferData) X(Clear)            \
    X(ClearColor) X(CompileShader) X(CreateProgram) X(CreateShader) X(DeleteBuffers) X(DeleteProgram)    \
    X(DeleteShader) X(DeleteTextures) X(DeleteVertexArrays) X(DepthFunc) X(DrawElementsInstanced) X(Enable)            \
    X(EnableVertexAttribArray) X(Finish) X(GenBuffers) X(GenTextures) X(GenVertexArrays) X(GetError)                   \
    X(GetProgramInfoLog) X(GetProgramiv) X(GetShaderInfoLog) X(GetShaderiv) X(GetString) X(GetUniformLocation)         \
    X(LinkProgram) X(ShaderSource) X(TexBuffer) X(Uniform1i) X(Uniform3f) X(UniformMatrix4fv) X(UseProgram)           \
    X(VertexAttribDivisor) X(VertexAttribIPointer) X(VertexAttribPointer) X(Viewport)
// clang-format on

struct GlFunctions {
#define VEDUTA_GL_DECLARE(name) decltype(&::gl##name) name = nullptr;
    VEDUTA_GL_FUNCTIONS(VEDUTA_GL_DECLARE)
#undef VEDUTA_GL_DECLARE

    // Needs a current context.
    void load() {
#define VEDUTA_GL_LOAD(name)                                                   \
    name = reinterpret_cast<decltype(name)>(OSMesaGetProcAddress("gl" #name)); \
    if (!name) throw std::runtime_error("OSMesa has no gl" #name);
        VEDUTA_GL_FUNCTIONS(VEDUTA_GL_LOAD)
#undef VEDUTA_GL_LOAD
    }
};

// The vertex shader places each vertex with its instance's rows (baked meshes use an identity
// entry) and looks its albedo up once per vertex; vertices are split by material on upload, so
// every corner of a triangle carries the same one. The faceted variant has no vertex normals
// and takes the face normal from screen-space derivatives of the world position, which are
// in the triangle's plane.
constexpr const char *kVertexShader = R"(
layout(location = 0) in vec3 position;
#ifdef SMOOTH
layout(location = 1) in vec3 normal;
#endif
layout(location = 2) in uint material;
layout(location = 3) in vec4 worldRow0;  // objectToWorld, row-major 3x4, per instance
layout(location = 4) in vec4 worldRow1;
layout(location = 5) in vec4 worldRow2;
layout(location = 6) in vec3 normalRow0;  // its normal transform, per instance
layout(location = 7) in vec3 normalRow1;
layout(location = 8) in vec3 normalRow2;
layout(location = 9) in uint materialOverride;

uniform mat4 clipFromWorld;
uniform samplerBuffer materials;  // diffuse albedo per MaterialId

out vec3 worldPosition;
#ifdef SMOOTH
out vec3 worldNormal;
#endif
flat out vec3 albedo;

void main() {
    vec4 p = vec4(position, 1.0);
    worldPosition = vec3(dot(worldRow0, p), dot(worldRow1, p), dot(worldRow2, p));
#ifdef SMOOTH
    worldNormal = vec3(dot(normalRow0, normal), dot(normalRow1, normal), dot(normalRow2, normal));
#endif
    uint m = materialOverride != 0xffffffffu ? materialOverride : material;
    albedo = texelFetch(materials, int(m)).rgb;
    gl_Position = clipFromWorld * vec4(worldPosition, 1.0);
}
)";

// The preview's Shaded mode: albedo/pi * (E_sun * max(0, n.l) + pi * L_sky), n turned towards
// the eye because surfaces are two-sided.
constexpr const char *kFragmentShader = R"(
in vec3 worldPosition;
#ifdef SMOOTH
in vec3 worldNormal;
#endif
flat in vec3 albedo;

uniform vec3 eye;
uniform vec3 sunDirection;
uniform vec3 sunIrradianceOverPi;
uniform vec3 skyRadiance;

out vec4 color;

void main() {
#ifdef SMOOTH
    vec3 n = normalize(worldNormal);
#else
    vec3 n = normalize(cross(dFdx(worldPosition), dFdy(worldPosition)));
#endif
    if (dot(n, worldPosition - eye) > 0.0) n = -n;
    color = vec4(albedo * (sunIrradianceOverPi * max(0.0, dot(n, sunDirection)) + skyRadiance), 1.0);
}
)";

// Per-instance attributes, as the vertex shader reads them.
struct InstanceData {
    std::array<float, 12> objectToWorld;
    std::array<float, 9> normalToWorld;
    uint32_t materialOverride;
};
static_assert(sizeof(InstanceData) == 22 * 4);
static_assert(sizeof(Vec3f) == 12);

InstanceData instanceData(const Transform &objectToWorld, MaterialId materialOverride) {
    InstanceData d{objectToWorld.m, {}, materialOverride};
    Transform n = objectToWorld.normalTransform();
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) d.normalToWorld[size_t(3 * r + c)] = n.m[size_t(4 * r + c)];
    }
    return d;
}

// A mesh as GL takes it: one material per vertex. Vertices shared by triangles of different
// materials are copied, one copy per further material; the shapes and imported meshes keep
// materials apart anyway, so this rarely adds any.
struct GpuMesh {
    std::vector<Vec3f> positions, normals;
    std::vector<uint32_t> materials, indices;
};

GpuMesh splitByMaterial(const Mesh &mesh) {
    GpuMesh out{mesh.positions, mesh.normals, std::vector<uint32_t>(mesh.vertexCount(), kNoMaterial), {}};
    bool smooth = !mesh.normals.empty();
    out.indices.reserve(mesh.indices.size());
    std::map<std::pair<uint32_t, MaterialId>, uint32_t> copies;
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        MaterialId m = mesh.triangleMaterials[t];
        for (size_t k = 0; k < 3; ++k) {
            uint32_t v = mesh.indices[3 * t + k];
            if (out.materials[v] == kNoMaterial) {
                out.materials[v] = m;
            } else if (out.materials[v] != m) {
                auto [it, fresh] = copies.try_emplace({v, m}, uint32_t(out.positions.size()));
                if (fresh) {
                    out.positions.push_back(mesh.positions[v]);
                    if (smooth) out.normals.push_back(mesh.normals[v]);
                    out.materials.push_back(m);
                }
                v = it->second;
            }
            out.indices.push_back(v);
        }
    }
    std::replace(out.materials.begin(), out.materials.end(), kNoMaterial, MaterialId(0));  // unused vertices
    return out;
}

// Row-major 4x4 that takes world points to clip space, from the camera frame CameraRays and the
// preview use; GL's pixel centres (x + 0.5, y + 0.5) then fall where theirs do.
std::array<float, 16> clipFromWorld(const Camera &c, float farPlane) {
    Vec3f forward = normalize(c.lookAt - c.position);
    Vec3f right = normalize(cross(forward, c.up));
    Vec3f up = cross(right, forward);
    float halfHeight = std::tan(radians(c.verticalFovDegrees) * 0.5f);
    float halfWidth = halfHeight * float(c.width) / float(c.height);
    // Clip w is the distance along the view axis; z maps [near, far] to [-1, 1].
    float n = kNear, f = farPlane;
    float a = (f + n) / (f - n), b = -2 * f * n / (f - n);
    auto row = [&](const Vec3f &axis, float scale, float offset) {
        Vec3f v = axis * scale;
        return std::array<float, 4>{v.x, v.y, v.z, -dot(v, c.position) + offset};
    };
    std::array<std::array<float, 4>, 4> rows{row(right, 1 / halfWidth, 0), row(up, 1 / halfHeight, 0),
                                             row(forward, a, b), row(forward, 1, 0)};
    std::array<float, 16> m{};
    for (size_t i = 0; i < 16; ++i) m[i] = rows[i / 4][i % 4];
    return m;
}

// The corners of the bounding box of a non-empty point set.
std::array<Vec3f, 8> boxCorners(const std::vector<Vec3f> &points) {
    Vec3f lo = points[0], hi = points[0];
    for (const Vec3f &p : points) {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
    std::array<Vec3f, 8> corners;
    for (size_t i = 0; i < 8; ++i) corners[i] = {i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z};
    return corners;
}

// The far plane: just beyond the farthest vertex along the view axis (for instances, the
// farthest corner of their bounding box), so that nothing the preview draws is clipped.
float farPlane(const RenderScene &scene) {
    Vec3f eye = scene.camera.position, forward = normalize(scene.camera.lookAt - eye);
    float farthest = 0;
    auto extend = [&](const Vec3f &p) { farthest = std::max(farthest, dot(forward, p - eye)); };
    for (const BakedMesh &m : scene.meshes) {
        for (const Vec3f &p : m.mesh.positions) extend(p);
    }
    std::vector<std::array<Vec3f, 8>> corners(scene.prototypes.size());
    for (size_t i = 0; i < scene.prototypes.size(); ++i) {
        if (!scene.prototypes[i].positions.empty()) corners[i] = boxCorners(scene.prototypes[i].positions);
    }
    for (const Instance &instance : scene.instances) {
        if (scene.prototypes[instance.prototype].positions.empty()) continue;
        for (const Vec3f &p : corners[instance.prototype]) extend(instance.objectToWorld.applyPoint(p));
    }
    return std::max(farthest * 1.01f + 1.0f, 2 * kNear);
}

}  // namespace

struct OsMesaRenderer::Impl {
    // One glDrawElementsInstanced: a mesh and its range in the instance buffer.
    struct Batch {
        GLuint vertexArray = 0;
        std::array<GLuint, 4> buffers{};  // positions, normals, materials, indices
        GLsizei indexCount = 0;
        GLsizei instanceCount = 0;
        bool smooth = false;
    };

    int width, height;
    std::vector<float> colour;  // OSMesa's colour buffer, RGBA float, top row first
    OSMesaContext context = nullptr;
    GlFunctions gl;
    GLuint smoothProgram = 0, facetedProgram = 0;
    GLuint instanceBuffer = 0, materialBuffer = 0, materialTexture = 0;
    std::vector<Batch> batches;  // smooth ones first, to switch programs once
    std::array<float, 4> clearColour{};

    Impl(int w, int h) : width(w), height(h), colour(size_t(w) * size_t(h) * 4, 0.0f) {}

    void makeCurrent() {
        if (OSMesaGetCurrentContext() == context) return;
        if (!OSMesaMakeCurrent(context, colour.data(), GL_FLOAT, width, height)) {
            throw std::runtime_error("OSMesaMakeCurrent failed");
        }
        // Top row first, like RgbaImage, so the image needs no flip.
        OSMesaPixelStore(OSMESA_Y_UP, 0);
    }

    void checkGl(const char *what) {
        if (GLenum e = gl.GetError(); e != GL_NO_ERROR) {
            throw std::runtime_error(std::string("GL error ") + std::to_string(e) + " in " + what);
        }
    }

    GLuint compile(GLenum stage, const char *source, bool smooth) {
        const char *parts[] = {"#version 330 core\n", smooth ? "#define SMOOTH\n" : "", source};
        GLuint shader = gl.CreateShader(stage);
        gl.ShaderSource(shader, 3, parts, nullptr);
        gl.CompileShader(shader);
        GLint ok = 0;
        gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
        if (!ok) {
            std::string log(4096, '\0');
            gl.GetShaderInfoLog(shader, GLsizei(log.size()), nullptr, log.data());
            throw std::runtime_error("shader compilation failed: " + std::string(log.c_str()));
        }
        return shader;
    }

    GLuint link(bool smooth, const RenderScene &scene, const std::array<float, 16> &clipFromWorld) {
        GLuint program = gl.CreateProgram();
        GLuint vs = compile(GL_VERTEX_SHADER, kVertexShader, smooth);
        GLuint fs = compile(GL_FRAGMENT_SHADER, kFragmentShader, smooth);
        gl.AttachShader(program, vs);
        gl.AttachShader(program, fs);
        gl.LinkProgram(program);
        gl.DeleteShader(vs);
        gl.DeleteShader(fs);
        GLint ok = 0;
        gl.GetProgramiv(program, GL_LINK_STATUS, &ok);
        if (!ok) {
            std::string log(4096, '\0');
            gl.GetProgramInfoLog(program, GLsizei(log.size()), nullptr, log.data());
            throw std::runtime_error("shader linking failed: " + std::string(log.c_str()));
        }
        // Uniforms are program state: set once here, never per frame.
        gl.UseProgram(program);
        gl.UniformMatrix4fv(gl.GetUniformLocation(program, "clipFromWorld"), 1, GL_TRUE, clipFromWorld.data());
        gl.Uniform1i(gl.GetUniformLocation(program, "materials"), 0);
        const Vec3f &eye = scene.camera.position, &sun = scene.sun.direction, &sky = scene.environment.radiance;
        Vec3f sunOverPi = scene.sun.irradiance * kInvPi;
        gl.Uniform3f(gl.GetUniformLocation(program, "eye"), eye.x, eye.y, eye.z);
        gl.Uniform3f(gl.GetUniformLocation(program, "sunDirection"), sun.x, sun.y, sun.z);
        gl.Uniform3f(gl.GetUniformLocation(program, "sunIrradianceOverPi"), sunOverPi.x, sunOverPi.y, sunOverPi.z);
        gl.Uniform3f(gl.GetUniformLocation(program, "skyRadiance"), sky.x, sky.y, sky.z);
        return program;
    }

    template <typename T>
    GLuint upload(GLenum target, const std::vector<T> &data) {
        GLuint buffer = 0;
        gl.GenBuffers(1, &buffer);
        gl.BindBuffer(target, buffer);
        gl.BufferData(target, GLsizeiptr(data.size() * sizeof(T)), data.data(), GL_STATIC_DRAW);
        return buffer;
    }

    // A vertex array for `mesh`, drawn with `instanceCount` entries of the instance buffer from
    // `firstInstance` on (set as attribute offsets: base-instance draws need GL 4.2).
    Batch makeBatch(const Mesh &mesh, size_t firstInstance, size_t instanceCount) {
        GpuMesh m = splitByMaterial(mesh);
        Batch b;
        b.smooth = !m.normals.empty();
        b.indexCount = GLsizei(m.indices.size());
        b.instanceCount = GLsizei(instanceCount);
        gl.GenVertexArrays(1, &b.vertexArray);
        gl.BindVertexArray(b.vertexArray);

        b.buffers[0] = upload(GL_ARRAY_BUFFER, m.positions);
        gl.EnableVertexAttribArray(0);
        gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
        if (b.smooth) {
            b.buffers[1] = upload(GL_ARRAY_BUFFER, m.normals);
            gl.EnableVertexAttribArray(1);
            gl.VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
        }
        b.buffers[2] = upload(GL_ARRAY_BUFFER, m.materials);
        gl.EnableVertexAttribArray(2);
        gl.VertexAttribIPointer(2, 1, GL_UNSIGNED_INT, 0, nullptr);

        gl.BindBuffer(GL_ARRAY_BUFFER, instanceBuffer);
        auto offset = [&](size_t field) {
            return reinterpret_cast<const void *>(firstInstance * sizeof(InstanceData) + field);
        };
        constexpr auto stride = GLsizei(sizeof(InstanceData));
        for (GLuint r = 0; r < 3; ++r) {
            gl.EnableVertexAttribArray(3 + r);
            gl.VertexAttribPointer(3 + r, 4, GL_FLOAT, GL_FALSE, stride,
                                   offset(offsetof(InstanceData, objectToWorld) + 16 * r));
            gl.VertexAttribDivisor(3 + r, 1);
            gl.EnableVertexAttribArray(6 + r);
            gl.VertexAttribPointer(6 + r, 3, GL_FLOAT, GL_FALSE, stride,
                                   offset(offsetof(InstanceData, normalToWorld) + 12 * r));
            gl.VertexAttribDivisor(6 + r, 1);
        }
        gl.EnableVertexAttribArray(9);
        gl.VertexAttribIPointer(9, 1, GL_UNSIGNED_INT, stride, offset(offsetof(InstanceData, materialOverride)));
        gl.VertexAttribDivisor(9, 1);

        b.buffers[3] = upload(GL_ELEMENT_ARRAY_BUFFER, m.indices);  // the element binding is vertex-array state
        gl.BindVertexArray(0);
        return b;
    }

    void uploadScene(const RenderScene &scene) {
        // Instance buffer: entry 0 is the identity that every baked mesh uses, then the
        // instances grouped by prototype.
        std::vector<InstanceData> instances{instanceData(Transform{}, kNoMaterial)};
        std::vector<std::vector<const Instance *>> byPrototype(scene.prototypes.size());
        for (const Instance &i : scene.instances) byPrototype[i.prototype].push_back(&i);
        std::vector<size_t> first(scene.prototypes.size());
        for (size_t p = 0; p < byPrototype.size(); ++p) {
            first[p] = instances.size();
            for (const Instance *i : byPrototype[p]) {
                instances.push_back(instanceData(i->objectToWorld, i->materialOverride));
            }
        }
        instanceBuffer = upload(GL_ARRAY_BUFFER, instances);

        std::vector<float> albedos;
        for (const Material &m : scene.materials) {
            albedos.insert(albedos.end(), {m.diffuse.x, m.diffuse.y, m.diffuse.z, 1});
        }
        if (albedos.empty()) albedos.assign(4, 0.8f);  // a texture buffer may not be empty
        materialBuffer = upload(GL_TEXTURE_BUFFER, albedos);
        gl.GenTextures(1, &materialTexture);
        gl.ActiveTexture(GL_TEXTURE0);
        gl.BindTexture(GL_TEXTURE_BUFFER, materialTexture);
        gl.TexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32F, materialBuffer);

        for (const BakedMesh &m : scene.meshes) {
            if (m.mesh.triangleCount() > 0) batches.push_back(makeBatch(m.mesh, 0, 1));
        }
        for (size_t p = 0; p < scene.prototypes.size(); ++p) {
            if (scene.prototypes[p].triangleCount() > 0 && !byPrototype[p].empty()) {
                batches.push_back(makeBatch(scene.prototypes[p], first[p], byPrototype[p].size()));
            }
        }
        std::stable_partition(batches.begin(), batches.end(), [](const Batch &b) { return b.smooth; });
    }

    void draw() {
        gl.Viewport(0, 0, width, height);
        gl.ClearColor(clearColour[0], clearColour[1], clearColour[2], clearColour[3]);
        gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        GLuint current = 0;
        for (const Batch &b : batches) {
            GLuint program = b.smooth ? smoothProgram : facetedProgram;
            if (program != current) gl.UseProgram(current = program);
            gl.BindVertexArray(b.vertexArray);
            gl.DrawElementsInstanced(GL_TRIANGLES, b.indexCount, GL_UNSIGNED_INT, nullptr, b.instanceCount);
        }
        // Also copies llvmpipe's colour buffer into ours (OSMesa's front-buffer flush).
        gl.Finish();
    }

    ~Impl() {
        if (!context) return;
        bool current =
            OSMesaGetCurrentContext() == context || OSMesaMakeCurrent(context, colour.data(), GL_FLOAT, width, height);
        if (current) {
            for (Batch &b : batches) {
                gl.DeleteVertexArrays(1, &b.vertexArray);
                gl.DeleteBuffers(GLsizei(b.buffers.size()), b.buffers.data());
            }
            GLuint buffers[] = {instanceBuffer, materialBuffer};
            gl.DeleteBuffers(2, buffers);
            gl.DeleteTextures(1, &materialTexture);
            gl.DeleteProgram(smoothProgram);
            gl.DeleteProgram(facetedProgram);
        }
        OSMesaDestroyContext(context);
    }
};

OsMesaRenderer::OsMesaRenderer(const RenderScene &scene) :
    impl_(std::make_unique<Impl>(scene.camera.width, scene.camera.height)) {
    Impl &r = *impl_;
    const int attributes[] = {OSMESA_FORMAT,
                              OSMESA_RGBA,
                              OSMESA_DEPTH_BITS,
                              24,
                              OSMESA_STENCIL_BITS,
                              0,
                              OSMESA_ACCUM_BITS,
                              0,
                              OSMESA_PROFILE,
                              OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION,
                              3,
                              OSMESA_CONTEXT_MINOR_VERSION,
                              3,
                              0};
    r.context = OSMesaCreateContextAttribs(attributes, nullptr);
    if (!r.context) throw std::runtime_error("OSMesa could not create a GL 3.3 core context");
    r.makeCurrent();
    r.gl.load();

    std::array<float, 16> clip = clipFromWorld(scene.camera, farPlane(scene));
    r.smoothProgram = r.link(true, scene, clip);
    r.facetedProgram = r.link(false, scene, clip);
    r.uploadScene(scene);
    const Vec3f &sky = scene.environment.radiance;
    r.clearColour = {sky.x, sky.y, sky.z, 1};
    r.gl.Enable(GL_DEPTH_TEST);
    r.gl.DepthFunc(GL_LESS);
    r.checkGl("scene upload");

    r.draw();  // compiles llvmpipe's shader variants, outside any timing
    r.checkGl("first frame");
}

OsMesaRenderer::~OsMesaRenderer() = default;

void OsMesaRenderer::drawFrame() {
    impl_->makeCurrent();
    impl_->draw();
}

RgbaImage OsMesaRenderer::image() const {
    const Impl &r = *impl_;
    RgbaImage film(r.width, r.height);
    for (int y = 0; y < r.height; ++y) {
        for (int x = 0; x < r.width; ++x) {
            const float *p = &r.colour[(size_t(y) * size_t(r.width) + size_t(x)) * 4];
            film.set(x, y, {p[0], p[1], p[2]});
        }
    }
    return film;
}

std::string OsMesaRenderer::description() const {
    impl_->makeCurrent();
    auto text = [&](GLenum name) {
        const GLubyte *s = impl_->gl.GetString(name);
        return s ? std::string(reinterpret_cast<const char *>(s)) : std::string("?");
    };
    return text(GL_RENDERER) + ", OpenGL " + text(GL_VERSION);
}

}  // namespace veduta

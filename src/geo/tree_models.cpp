#include "geo/tree_models.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/hash.h"
#include "core/random_streams.h"

namespace veduta {

namespace {

// One production of the stochastic L-system: `symbol` → `successor` with `probability` (the
// probabilities of a symbol's productions add up to 1).
struct Production {
    char symbol = 0;
    float probability = 1;
    std::string_view successor;
};

// The grammar and the turtle's parameters of one variant of a kind. Lengths are in units of
// the first trunk segment; the finished mesh is scaled to height 1.
struct Species {
    std::string_view axiom;
    std::vector<Production> productions;
    int iterations = 0;
    std::string_view foliageSymbols;     // symbols drawn as a foliage blob
    float pitch = 0, roll = 0, yaw = 0;  // the turtle's turns in degrees
    float angleJitter = 0;               // each turn is scaled by 1 ± this, hashed per symbol
    float lengthRatio = 1;               // ' scales the segment length by it
    float trunkRadius = 0;
    float widthRatio = 1;  // ! scales the radius by it
    float taper = 1;       // each segment ends this much thinner than it starts
    Vec3f tropism;
    Vec3f foliageScale;  // a blob's half-axes along heading, left and up, in segment lengths
};

// Broadleaf (after the ternary tree of Prusinkiewicz & Lindenmayer, The Algorithmic Beauty
// of Plants, fig. 2.8): a trunk, then every bud A splits in three or two, or grows on; the buds
// left after the last rewriting carry the foliage, which makes a round crown.
Species broadleaf(uint32_t variant) {
    struct Tweak {
        std::string_view axiom;
        float pitch, lengthRatio, tropismZ;
    };
    // An upright oak-like crown, a broad lime-like one, a narrower one with drooping ends.
    const std::array<Tweak, kTreeVariants> tweaks = {
        {{"FFA", 34, 0.80f, 0.06f}, {"FFA", 42, 0.78f, 0.0f}, {"FFA", 30, 0.80f, -0.06f}}};
    const Tweak &t = tweaks[variant];
    return {.axiom = t.axiom,
            .productions = {{'A', 0.6f, "![&'FA]/[&'FA]/[&'FA]"}, {'A', 0.3f, "![&'FA]//[&'FA]"}, {'A', 0.1f, "'F/A"}},
            .iterations = 5,
            .foliageSymbols = "A",
            .pitch = t.pitch,
            .roll = 120,
            .yaw = 0,
            .angleJitter = 0.25f,
            .lengthRatio = t.lengthRatio,
            .trunkRadius = 0.09f,
            .widthRatio = 0.65f,
            .taper = 0.92f,
            .tropism = {0, 0, t.tropismZ},
            .foliageScale = {1.3f, 1.3f, 1.1f}};
}

// Conifer: the leader T lays down one trunk segment and a whorl of branches B per rewriting;
// each branch grows one segment (with a needle pad N) per later rewriting, so the lower whorls
// are the longer ones and the crown is a cone. Gravity bends the branches down.
Species conifer(uint32_t variant) {
    struct Tweak {
        std::string_view axiom, leader;
        int iterations;
        float pitch, lengthRatio;
    };
    // A spruce with five branches to a whorl, a slim fir with four, a pine-like one with a
    // long bare trunk and a flatter crown.
    const std::array<Tweak, kTreeVariants> tweaks = {{{"FT", "F[&!'B]/[&!'B]/[&!'B]/[&!'B]/[&!'B]T", 8, 78, 0.32f},
                                                      {"FT", "F[&!'B]/[&!'B]/[&!'B]/[&!'B]T", 9, 70, 0.26f},
                                                      {"FFFT", "F[&!'B]/[&!'B]/[&!'B]/[&!'B]/[&!'B]T", 6, 62, 0.36f}}};
    const Tweak &t = tweaks[variant];
    return {.axiom = t.axiom,
            .productions = {{'T', 1.0f, t.leader}, {'B', 1.0f, "FNB"}},
            .iterations = t.iterations,
            .foliageSymbols = "NB",
            .pitch = t.pitch,
            .roll = 360.0f / float(std::count(t.leader.begin(), t.leader.end(), 'B')),
            .yaw = 0,
            .angleJitter = 0.2f,
            .lengthRatio = t.lengthRatio,
            .trunkRadius = 0.08f,
            .widthRatio = 0.3f,
            .taper = 0.9f,
            .tropism = {0, 0, -0.05f},
            .foliageScale = {1.3f, 1.8f, 1.1f}};
}

Species species(TreeKind kind, uint32_t variant) {
    switch (kind) {
    case TreeKind::Broadleaf: return broadleaf(variant % kTreeVariants);
    case TreeKind::Conifer: return conifer(variant % kTreeVariants);
    case TreeKind::Mixed: break;
    }
    throw std::invalid_argument("treeModel: a tree is broadleaf or conifer, not mixed");
}

// Rewrites the axiom `iterations` times, all symbols in parallel; where a symbol has several
// productions the choice is hashed from `key`, the generation and the symbol's position.
std::string rewrite(const Species &sp, int iterations, uint32_t key) {
    std::string word(sp.axiom);
    for (int g = 0; g < iterations; ++g) {
        std::string next;
        for (size_t i = 0; i < word.size(); ++i) {
            char c = word[i];
            uint32_t bits = hashValues({key, streamTag(RandomStream::TreeRewrite), uint32_t(g), uint32_t(i)});
            float u = bitsToUnitFloat(bits);
            std::string_view successor;
            bool matched = false;
            for (const Production &p : sp.productions) {
                if (p.symbol != c) continue;
                matched = true;
                successor = p.successor;
                if (u < p.probability) break;
                u -= p.probability;
            }
            if (matched) {
                next += successor;
            } else {
                next += c;
            }
        }
        word = std::move(next);
    }
    return word;
}

// `v` rotated by `degrees` about the unit `axis` (Rodrigues).
Vec3f rotate(const Vec3f &v, const Vec3f &axis, float angleDegrees) {
    float c = std::cos(radians(angleDegrees)), s = std::sin(radians(angleDegrees));
    return v * c + cross(axis, v) * s + axis * (dot(axis, v) * (1 - c));
}

struct Turtle {
    Vec3f position;
    Vec3f heading{0, 0, 1}, left{1, 0, 0}, up{0, 1, 0};  // up = heading × left
    float length = 1;
    float radius = 0;
};

class TreeBuilder {
  public:
    TreeBuilder(const Species &sp, uint32_t key, const TreeMaterials &materials) :
        sp_(sp), key_(key), materials_(materials) {}

    Mesh build(const std::string &word) {
        Turtle turtle;
        turtle.radius = sp_.trunkRadius;
        std::vector<Turtle> stack;
        for (size_t i = 0; i < word.size(); ++i) {
            char c = word[i];
            switch (c) {
            case 'F': drawSegment(turtle); break;
            case '[': stack.push_back(turtle); break;
            case ']':
                if (!stack.empty()) {
                    turtle = stack.back();
                    stack.pop_back();
                }
                break;
            case '+': turn(turtle, turtle.up, sp_.yaw, i); break;
            case '-': turn(turtle, turtle.up, -sp_.yaw, i); break;
            case '&': turn(turtle, turtle.left, sp_.pitch, i); break;
            case '^': turn(turtle, turtle.left, -sp_.pitch, i); break;
            case '/': turn(turtle, turtle.heading, sp_.roll, i); break;
            case '\\': turn(turtle, turtle.heading, -sp_.roll, i); break;
            case '!': turtle.radius *= sp_.widthRatio; break;
            case '\'': turtle.length *= sp_.lengthRatio; break;
            default:
                if (sp_.foliageSymbols.find(c) != std::string_view::npos) drawFoliage(turtle, i);
                break;
            }
        }
        return std::move(mesh_);
    }

  private:
    float unit(size_t symbol, uint32_t dimension) const {
        return bitsToUnitFloat(hashValues({key_, streamTag(RandomStream::TreeTurtle), uint32_t(symbol), dimension}));
    }

    // Turns the turtle's frame about one of its own axes, by `angle` scaled by the jitter.
    void turn(Turtle &t, Vec3f axis, float angle, size_t symbol) const {
        angle *= 1 + sp_.angleJitter * (2 * unit(symbol, 0) - 1);
        t.heading = rotate(t.heading, axis, angle);
        t.left = rotate(t.left, axis, angle);
        orthonormalize(t);
    }

    // Rounding would otherwise grow from turn to turn (each turns about the frame's own, already
    // rounded axes) until the frame collapses; Gram–Schmidt keeps it a rotation.
    static void orthonormalize(Turtle &t) {
        t.heading = normalize(t.heading);
        t.left = normalize(t.left - t.heading * dot(t.left, t.heading));
        t.up = cross(t.heading, t.left);
    }

    // Fewer sides for thinner stems: twigs are seen from afar and inside the foliage.
    int sidesFor(float radius) const {
        if (radius > 0.4f * sp_.trunkRadius) return 8;
        if (radius > 0.15f * sp_.trunkRadius) return 5;
        return 3;
    }

    // A tapered cylinder along the heading. It starts half a radius behind the turtle, so that
    // a bend leaves no gap on its outer side (and the trunk reaches into sloped ground).
    void drawSegment(Turtle &t) {
        float r0 = t.radius, r1 = t.radius * sp_.taper;
        Vec3f start = t.position - t.heading * (0.5f * r0);
        Vec3f end = t.position + t.heading * t.length;
        float span = t.length + 0.5f * r0;
        int sides = sidesFor(r0);
        float vEnd = span / (kPi * (r0 + r1));
        // Slanted by the taper, so that the normal is the cone's.
        float slope = (r0 - r1) / span;
        auto base = uint32_t(mesh_.positions.size());
        for (int k = 0; k <= sides; ++k) {
            float phi = 2 * kPi * float(k) / float(sides);
            Vec3f dir = t.left * std::cos(phi) + t.up * std::sin(phi);
            Vec3f normal = normalize(dir + t.heading * slope);
            float u = float(k) / float(sides);
            addVertex(start + dir * r0, normal, {u, 0});
            addVertex(end + dir * r1, normal, {u, vEnd});
        }
        for (int k = 0; k < sides; ++k) {
            uint32_t a = base + 2 * uint32_t(k), b = a + 2, c = a + 3, d = a + 1;
            addTriangle(a, b, c, materials_.bark);
            addTriangle(a, c, d, materials_.bark);
        }
        t.position = end;
        t.radius = r1;
        bendTowardsTropism(t);
    }

    void bendTowardsTropism(Turtle &t) const {
        Vec3f axis = cross(t.heading, sp_.tropism);
        float len = length(axis);
        if (len < 1e-6f) return;
        axis = axis / len;
        Vec3f h = applyTropism(t.heading, sp_.tropism);
        // The rotation that took the heading to h, applied to the rest of the frame.
        float angle = degrees(std::atan2(dot(cross(t.heading, h), axis), dot(t.heading, h)));
        t.heading = h;
        t.left = rotate(t.left, axis, angle);
        orthonormalize(t);
    }

    // A jittered icosahedron stretched to an ellipsoid in the turtle's frame, reaching beyond
    // the bud it sits on. Radial jitter keeps it star-shaped, so every face stays outward.
    void drawFoliage(const Turtle &t, size_t symbol) {
        static const float g = (1 + std::sqrt(5.0f)) / 2;
        static const std::array<Vec3f, 12> corners = {Vec3f{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0},
                                                      {0, -1, g},      {0, 1, g}, {0, -1, -g}, {0, 1, -g},
                                                      {g, 0, -1},      {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
        static const std::array<std::array<uint32_t, 3>, 20> faces = {
            {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
             {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
             {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}}};
        Vec3f s = sp_.foliageScale * t.length;
        Vec3f center = t.position + t.heading * (0.5f * s.x);
        auto base = uint32_t(mesh_.positions.size());
        for (uint32_t k = 0; k < corners.size(); ++k) {
            Vec3f d = normalize(corners[k]);
            float rho = 0.85f + 0.3f * unit(symbol, 1 + k);
            Vec3f offset = t.heading * (d.x * s.x) + t.left * (d.y * s.y) + t.up * (d.z * s.z);
            Vec3f normal = normalize(t.heading * (d.x / s.x) + t.left * (d.y / s.y) + t.up * (d.z / s.z));
            addVertex(center + offset * rho, normal, {0.5f + 0.5f * d.x, 0.5f + 0.5f * d.y});
        }
        for (const auto &f : faces) addTriangle(base + f[0], base + f[1], base + f[2], materials_.foliage);
    }

    void addVertex(const Vec3f &p, const Vec3f &n, Vec2f uv) {
        mesh_.positions.push_back(p);
        mesh_.normals.push_back(n);
        mesh_.uvs.push_back(uv);
    }
    void addTriangle(uint32_t a, uint32_t b, uint32_t c, MaterialId material) {
        mesh_.indices.insert(mesh_.indices.end(), {a, b, c});
        mesh_.triangleMaterials.push_back(material);
    }

    const Species &sp_;
    uint32_t key_;
    TreeMaterials materials_;
    Mesh mesh_;
};

// Scales the tree to height 1; it stands on the origin already.
void scaleToUnitHeight(Mesh &mesh) {
    float top = 0;
    for (const Vec3f &p : mesh.positions) top = std::max(top, p.z);
    for (Vec3f &p : mesh.positions) p *= 1 / top;
}

}  // namespace

float tropismAngle(const Vec3f &heading, const Vec3f &tropism) {
    return 90 * (1 - 1 / (1 + length(cross(heading, tropism))));
}

Vec3f applyTropism(const Vec3f &heading, const Vec3f &tropism) {
    Vec3f axis = cross(heading, tropism);
    float len = length(axis);
    if (len < 1e-12f) return heading;
    float between = degrees(std::atan2(len, dot(heading, tropism)));
    return normalize(rotate(heading, axis / len, std::min(tropismAngle(heading, tropism), between)));
}

Mesh treeModel(TreeKind kind, uint32_t variant, uint32_t seed, const TreeMaterials &materials) {
    Species sp = species(kind, variant);
    uint32_t key = hashValues({seed, streamTag(RandomStream::TreeModel), uint32_t(kind), variant % kTreeVariants});
    // A seed whose rewriting branches unusually often gets one generation fewer rather than
    // more triangles than the budget.
    for (int iterations = sp.iterations;; --iterations) {
        Mesh mesh = TreeBuilder(sp, key, materials).build(rewrite(sp, iterations, key));
        if (mesh.triangleCount() <= kTreeTriangleBudget || iterations == 1) {
            scaleToUnitHeight(mesh);
            return mesh;
        }
    }
}

TreeMaterials treeMaterials(RenderSceneBuilder &builder, TreeKind kind) {
    MaterialId bark = builder.findOrAddMaterial(Material::lambertian("land/bark", {0.16f, 0.12f, 0.09f}));
    if (kind == TreeKind::Conifer)
        return {bark, builder.findOrAddMaterial(Material::lambertian("land/needles", {0.04f, 0.1f, 0.04f}))};
    return {bark, builder.findOrAddMaterial(Material::lambertian("land/foliage", {0.09f, 0.19f, 0.04f}))};
}

}  // namespace veduta

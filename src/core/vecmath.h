// Small fixed-size vector and affine-transform types. Render geometry is float and relative
// to the scene origin (DESIGN.md: Z up, X east, Y north, metres).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace veduta {

inline constexpr float kPi = 3.14159265358979323846f;
inline constexpr float kInvPi = 1.0f / kPi;

inline float radians(float degrees) { return degrees * (kPi / 180.0f); }
inline float degrees(float radians) { return radians * (180.0f / kPi); }

struct Vec2f {
    float x = 0, y = 0;
};

inline Vec2f operator+(Vec2f a, Vec2f b) { return {a.x + b.x, a.y + b.y}; }
inline Vec2f operator-(Vec2f a, Vec2f b) { return {a.x - b.x, a.y - b.y}; }
inline Vec2f operator*(Vec2f a, float s) { return {a.x * s, a.y * s}; }
inline Vec2f operator/(Vec2f a, float s) { return {a.x / s, a.y / s}; }
inline float dot(Vec2f a, Vec2f b) { return a.x * b.x + a.y * b.y; }
inline float cross(Vec2f a, Vec2f b) { return a.x * b.y - a.y * b.x; }
inline float length(Vec2f a) { return std::sqrt(dot(a, a)); }
inline Vec2f normalize(Vec2f a) { return a / length(a); }

// A point or direction of a plan or the local frame kept in double: outlines are cut and
// compared in double, and only the finished vertices are made float.
struct Vec2d {
    double x = 0, y = 0;
    Vec2d operator+(Vec2d o) const { return {x + o.x, y + o.y}; }
    Vec2d operator-(Vec2d o) const { return {x - o.x, y - o.y}; }
    Vec2d operator*(double s) const { return {x * s, y * s}; }
    bool operator==(const Vec2d &) const = default;
};

inline double dot(Vec2d a, Vec2d b) { return a.x * b.x + a.y * b.y; }
inline double cross(Vec2d a, Vec2d b) { return a.x * b.y - a.y * b.x; }
inline double length(Vec2d v) { return std::hypot(v.x, v.y); }

struct Vec3f {
    float x = 0, y = 0, z = 0;

    constexpr Vec3f() = default;
    constexpr Vec3f(float x_, float y_, float z_) : x(x_), y(y_), z(z_) {}
    constexpr explicit Vec3f(float v) : x(v), y(v), z(v) {}

    float operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
    float &operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }

    Vec3f operator-() const { return {-x, -y, -z}; }
    Vec3f &operator+=(const Vec3f &o) {
        x += o.x;
        y += o.y;
        z += o.z;
        return *this;
    }
    Vec3f &operator*=(const Vec3f &o) {
        x *= o.x;
        y *= o.y;
        z *= o.z;
        return *this;
    }
    Vec3f &operator*=(float s) {
        x *= s;
        y *= s;
        z *= s;
        return *this;
    }
    bool operator==(const Vec3f &) const = default;
};

inline Vec3f operator+(Vec3f a, const Vec3f &b) { return a += b; }
inline Vec3f operator-(const Vec3f &a, const Vec3f &b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3f operator*(Vec3f a, const Vec3f &b) { return a *= b; }
inline Vec3f operator*(Vec3f a, float s) { return a *= s; }
inline Vec3f operator*(float s, Vec3f a) { return a *= s; }
inline Vec3f operator/(const Vec3f &a, float s) { return a * (1.0f / s); }

// Sums that must stay exact over many samples (film accumulators).
struct Vec3d {
    double x = 0, y = 0, z = 0;
};

inline float dot(const Vec3f &a, const Vec3f &b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3f cross(const Vec3f &a, const Vec3f &b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline float length(const Vec3f &a) { return std::sqrt(dot(a, a)); }
inline Vec3f normalize(const Vec3f &a) { return a / length(a); }
inline float maxComponent(const Vec3f &a) { return std::max(a.x, std::max(a.y, a.z)); }
inline Vec3f faceForward(const Vec3f &n, const Vec3f &towards) { return dot(n, towards) < 0 ? -n : n; }

// An orthonormal basis around a unit normal (Duff et al. 2017, "Building an Orthonormal
// Basis, Revisited"): branch-free and continuous except at one pole.
struct Frame {
    Vec3f s, t, n;

    static Frame fromNormal(const Vec3f &n) {
        float sign = std::copysign(1.0f, n.z);
        float a = -1.0f / (sign + n.z);
        float b = n.x * n.y * a;
        return {{1 + sign * n.x * n.x * a, sign * b, -sign * n.x}, {b, sign + n.y * n.y * a, -n.y}, n};
    }
    Vec3f toWorld(const Vec3f &v) const { return s * v.x + t * v.y + n * v.z; }
    Vec3f toLocal(const Vec3f &v) const { return {dot(v, s), dot(v, t), dot(v, n)}; }
};

// Affine transform stored as a 3x4 row-major matrix, the layout Embree's
// RTC_FORMAT_FLOAT3X4_ROW_MAJOR takes.
struct Transform {
    std::array<float, 12> m{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};

    static Transform translate(const Vec3f &t) { return {{1, 0, 0, t.x, 0, 1, 0, t.y, 0, 0, 1, t.z}}; }
    static Transform scale(const Vec3f &s) { return {{s.x, 0, 0, 0, 0, s.y, 0, 0, 0, 0, s.z, 0}}; }
    // Rotation about a coordinate axis (0 = x, 1 = y, 2 = z), counter-clockwise seen from +axis.
    static Transform rotate(int axis, float degrees);

    Vec3f applyPoint(const Vec3f &p) const {
        return {m[0] * p.x + m[1] * p.y + m[2] * p.z + m[3], m[4] * p.x + m[5] * p.y + m[6] * p.z + m[7],
                m[8] * p.x + m[9] * p.y + m[10] * p.z + m[11]};
    }
    Vec3f applyVector(const Vec3f &v) const {
        return {m[0] * v.x + m[1] * v.y + m[2] * v.z, m[4] * v.x + m[5] * v.y + m[6] * v.z,
                m[8] * v.x + m[9] * v.y + m[10] * v.z};
    }
    // The transform normals take: the inverse transpose of the linear part, no translation.
    // Apply it with applyVector.
    Transform normalTransform() const;
    Transform inverse() const;
    float determinant() const;
    bool operator==(const Transform &) const = default;
};

// a * b applies b first.
Transform operator*(const Transform &a, const Transform &b);

}  // namespace veduta

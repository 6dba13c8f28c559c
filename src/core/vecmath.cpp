#include "core/vecmath.h"

namespace veduta {

Transform Transform::rotate(int axis, float degrees) {
    float c = std::cos(radians(degrees)), s = std::sin(radians(degrees));
    switch (axis) {
    case 0: return {{1, 0, 0, 0, 0, c, -s, 0, 0, s, c, 0}};
    case 1: return {{c, 0, s, 0, 0, 1, 0, 0, -s, 0, c, 0}};
    default: return {{c, -s, 0, 0, s, c, 0, 0, 0, 0, 1, 0}};
    }
}

Transform operator*(const Transform &a, const Transform &b) {
    Transform r;
    for (int row = 0; row < 3; ++row) {
        for (int col = 0; col < 4; ++col) {
            float v = col == 3 ? a.m[row * 4 + 3] : 0.0f;
            for (int k = 0; k < 3; ++k) v += a.m[row * 4 + k] * b.m[k * 4 + col];
            r.m[row * 4 + col] = v;
        }
    }
    return r;
}

float Transform::determinant() const {
    return m[0] * (m[5] * m[10] - m[6] * m[9]) - m[1] * (m[4] * m[10] - m[6] * m[8]) +
        m[2] * (m[4] * m[9] - m[5] * m[8]);
}

Transform Transform::inverse() const {
    float inv = 1.0f / determinant();
    Transform r;
    r.m[0] = (m[5] * m[10] - m[6] * m[9]) * inv;
    r.m[1] = (m[2] * m[9] - m[1] * m[10]) * inv;
    r.m[2] = (m[1] * m[6] - m[2] * m[5]) * inv;
    r.m[4] = (m[6] * m[8] - m[4] * m[10]) * inv;
    r.m[5] = (m[0] * m[10] - m[2] * m[8]) * inv;
    r.m[6] = (m[2] * m[4] - m[0] * m[6]) * inv;
    r.m[8] = (m[4] * m[9] - m[5] * m[8]) * inv;
    r.m[9] = (m[1] * m[8] - m[0] * m[9]) * inv;
    r.m[10] = (m[0] * m[5] - m[1] * m[4]) * inv;
    for (int row = 0; row < 3; ++row) {
        r.m[row * 4 + 3] = -(r.m[row * 4 + 0] * m[3] + r.m[row * 4 + 1] * m[7] + r.m[row * 4 + 2] * m[11]);
    }
    return r;
}

Transform Transform::normalTransform() const {
    Transform inv = inverse();
    return {{inv.m[0], inv.m[4], inv.m[8], 0, inv.m[1], inv.m[5], inv.m[9], 0, inv.m[2], inv.m[6], inv.m[10], 0}};
}

}  // namespace veduta

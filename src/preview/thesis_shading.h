// Bilke's per-pixel shader PPSUNS (Bilke 2009, §2.3; thesis L987–1131) as a plain function:
// per-pixel Phong with a normal map, a specular map and a pre-blurred "diffuse" environment
// cubemap, in OpenGL's fixed-function light and material colours. It is the thesis's real-time
// look, for comparison with the path tracer; nothing in the renderer depends on it.
#pragma once

#include "core/vecmath.h"

namespace veduta {

// gl_LightSource[0]'s colours.
struct ThesisLight {
    Vec3f ambient, diffuse, specular;
};

// gl_FrontMaterial's colours (Bilke's base: ambient 0.4, diffuse 0.65, specular
// (1, 1, 0.85) × intensity, L1190).
struct ThesisMaterial {
    Vec3f ambient, diffuse, specular;
    float shininess = 32;
};

// What the fragment shader reads at one pixel. The vectors are in tangent space (x along the
// tangent, y the bitangent, z the normal) and need not be unit length: the shader normalises
// them.
struct PpsunsInputs {
    Vec3f baseColor;      // texture2D(colorMap, texCoord)
    Vec3f normalTexel;    // texture2D(normalMap, texCoord), each channel in [0, 1]
    float specularTexel;  // texture2D(specularMap, …).x
    Vec3f lightVec;       // towards the light
    Vec3f eyeVec;         // towards the eye
    Vec3f environment;    // textureCube(DiffuseEnvMap, world normal)
};

// gl_FragColor = (vAmbient·1.5 + env·0.5 + vDiffuse·0.5)·base + vSpecular (L1127), with the
// specular term as the shader computes it, Phong's R·V (L1102), not the Blinn half-vector
// of the text (L847). The shader never declares vAmbient; it is taken as light ambient ×
// material ambient, the ambient term A = Al·Am of its lighting model (L822–851).
Vec3f ppsunsShade(const ThesisLight &light, const ThesisMaterial &material, const PpsunsInputs &in);

}  // namespace veduta

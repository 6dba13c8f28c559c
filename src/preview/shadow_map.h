// The preview's sun shadows: a depth map of the scene seen from the sun, orthographic over
// the scene's extent, looked up with a slope-scaled bias.
#pragma once

#include <vector>

#include "scene/render_scene.h"

namespace veduta {

class ShadowMap {
  public:
    // `size` texels on a side, covering every mesh and instance of the scene.
    ShadowMap(const RenderScene &scene, int size);

    // Whether geometry stands between world point `p` (on a surface with unit normal `n`)
    // and the sun.
    bool shadowed(const Vec3f &p, const Vec3f &n) const;

  private:
    Vec3f lightSpace(const Vec3f &p) const;  // (texel x, texel y, height towards the sun)
    void draw(const std::vector<Vec3f> &lightVertices, const Mesh &mesh, std::vector<float> &map) const;

    Frame frame_;  // n points to the sun
    float originU_ = 0, originV_ = 0, texelsPerMetre_ = 1;
    int size_;
    std::vector<float> height_;  // highest surface towards the sun per texel; -inf where none
};

}  // namespace veduta

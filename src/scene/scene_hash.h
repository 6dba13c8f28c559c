// A fingerprint of everything a render depends on: geometry, ids, materials (textures by their
// file, size, time and colour space), camera, sun, environment texels and the settings that decide each sample's value
// (not how many samples are taken). Recorded in every EXR and checkpoint, so that `veduta merge` and `--resume` refuse
// parts of different scenes. Not cryptographic: it guards against mistakes, not attacks.
#pragma once

#include <cstdint>
#include <string>

#include "scene/render_scene.h"

namespace veduta {

uint64_t sceneHash(const RenderScene &scene);

// 16 lowercase hex digits.
std::string hashText(uint64_t hash);

}  // namespace veduta

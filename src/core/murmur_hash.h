// MurmurHash3_x86_32 (Austin Appleby's reference, public domain): the hash Cryptomatte names its
// ids and layers with, so that Blender, Nuke and veduta agree on the id of a name.
#pragma once

#include <cstdint>
#include <string_view>

namespace veduta {

// The 32-bit hash of `bytes`, as MurmurHash3_x86_32(bytes, size, seed) in little-endian order.
uint32_t murmurHash3(std::string_view bytes, uint32_t seed = 0);

}  // namespace veduta

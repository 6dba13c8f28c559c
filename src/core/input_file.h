// Opening what users name as input. Only regular files are read: a device (/dev/zero) or a
// FIFO would be read for ever, a directory fails obscurely. Whole-file readers also check the
// size before they allocate, against a limit that docs/reliability.md lists.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace veduta {

// The most a text input (scene, rules, materials, CityData, EDBS, XYZ) may hold.
inline constexpr uint64_t kTextInputLimit = uint64_t(4) << 30;  // 4 GiB

// Throws InputError naming the file when it does not exist or is not a regular file.
void checkInputFile(const std::filesystem::path &file);

// The whole file, after checkInputFile and a check of its size against `limit`.
std::string readInputFile(const std::filesystem::path &file, uint64_t limit = kTextInputLimit);

}  // namespace veduta

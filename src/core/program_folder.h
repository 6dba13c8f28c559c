// Where the running program lives, to find the files installed beside it: the veduta-diff
// program and the image plugin (as git finds git-foo).
#pragma once

#include <filesystem>
#include <optional>

namespace veduta {

// The folder of the running executable, from /proc/self/exe; nothing where /proc is missing.
std::optional<std::filesystem::path> runningProgramFolder();

}  // namespace veduta

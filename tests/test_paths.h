// Where the tests find the project's own files. The folders are compiled into
// test_paths.cpp alone: no other test object holds the checkout's path, so the compiler
// cache serves them to every clone of the project.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace veduta::test {

// The root of the source tree.
const std::filesystem::path &sourceDir();

// tests/data: the inputs the tests bring along.
const std::filesystem::path &testData();

// sourceDir() / relative, as the string that readers taking a file name want.
std::string sourceFile(std::string_view relative);

// The image plugin the build made, and the build tree's folder for converted textures.
const std::string &imagePluginFile();
const std::string &textureCache();

}  // namespace veduta::test

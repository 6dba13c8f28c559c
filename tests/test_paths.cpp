#include "test_paths.h"

namespace veduta::test {

const std::filesystem::path &sourceDir() {
    static const std::filesystem::path dir = VEDUTA_SOURCE_DIR;
    return dir;
}

const std::filesystem::path &testData() {
    static const std::filesystem::path dir = VEDUTA_TEST_DATA;
    return dir;
}

std::string sourceFile(std::string_view relative) { return (sourceDir() / relative).string(); }

const std::string &imagePluginFile() {
    static const std::string file = VEDUTA_IMAGE_PLUGIN_FILE;
    return file;
}

const std::string &textureCache() {
    static const std::string dir = VEDUTA_TEST_CACHE;
    return dir;
}

}  // namespace veduta::test

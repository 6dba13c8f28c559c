// The test program's surroundings, set before any test runs: it does not stand beside the
// image plugin, so it is told where the plugin is, and converted textures go to the build
// tree rather than the user's cache. Values already in the environment win.
#include <cstdlib>

#include "test_paths.h"

namespace {

const bool kEnvironmentSet = [] {
    setenv("VEDUTA_IMAGE_PLUGIN", veduta::test::imagePluginFile().c_str(), 0);
    setenv("VEDUTA_CACHE_DIR", veduta::test::textureCache().c_str(), 0);
    return true;
}();

}  // namespace

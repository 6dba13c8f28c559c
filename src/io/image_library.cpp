#include "io/image_library.h"

#include <cstdlib>
#include <mutex>
#include <stdexcept>

#include <dlfcn.h>
#include <fmt/format.h>

#include "core/program_folder.h"

namespace veduta {

namespace {

constexpr const char *kPluginFile = "veduta-images.so";

// One library for the process. A test installs its own with setImageLibrary; otherwise the
// first use loads the plugin. (Installing rather than registering a linked-in fallback keeps
// a single path for the program: it always loads the plugin, so the plugin is what runs.)
struct Installed {
    std::mutex mutex;
    std::unique_ptr<ImageLibrary> library;
};

Installed &installed() {
    static Installed instance;
    return instance;
}

std::string environment(const char *name) {
    const char *value = std::getenv(name);
    return value ? value : "";
}

}  // namespace

std::filesystem::path imagePluginPath() {
    std::string overridden = environment("VEDUTA_IMAGE_PLUGIN");
    if (!overridden.empty()) return overridden;
    if (auto found = findProgramPart(ProgramPart::Helper, kPluginFile)) return *found;
    // Missing everywhere: the first place, for loadImageLibrary's message.
    if (auto folder = runningProgramFolder()) return *folder / kPluginFile;
    return kPluginFile;  // dlopen searches the library path
}

std::unique_ptr<ImageLibrary> loadImageLibrary(const std::filesystem::path &file) {
    // Never closed: the library's objects run code from the plugin until the process ends.
    void *plugin = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!plugin) {
        throw std::runtime_error(fmt::format(
            "cannot load the image plugin {}: {} (veduta looks for {} in {}; set VEDUTA_IMAGE_PLUGIN to its path)",
            file.string(), dlerror(), kPluginFile, programPartFolderList(ProgramPart::Helper)));
    }
    auto *create = reinterpret_cast<CreateImageLibraryFunction *>(dlsym(plugin, kImagePluginEntry));
    if (!create) {
        throw std::runtime_error(fmt::format("{} is not a veduta image plugin: {}", file.string(), dlerror()));
    }
    return std::unique_ptr<ImageLibrary>(create());
}

ImageLibrary &imageLibrary() {
    Installed &state = installed();
    std::lock_guard lock(state.mutex);
    if (!state.library) state.library = loadImageLibrary(imagePluginPath());
    return *state.library;
}

void setImageLibrary(std::unique_ptr<ImageLibrary> library) {
    Installed &state = installed();
    std::lock_guard lock(state.mutex);
    state.library = std::move(library);
}

std::filesystem::path defaultTextureCacheDirectory() {
    std::string cache = environment("VEDUTA_CACHE_DIR");
    if (!cache.empty()) return cache;
    std::string xdg = environment("XDG_CACHE_HOME");
    if (!xdg.empty()) return std::filesystem::path(xdg) / "veduta" / "textures";
    return std::filesystem::path(environment("HOME")) / ".cache" / "veduta" / "textures";
}

}  // namespace veduta
